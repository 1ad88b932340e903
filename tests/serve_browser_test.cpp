// The served pages as people use them, in Debian's chromium driven by playwright-core:
// a student (tests/browser/serve_flow.mjs: the link, the preview, a submission's named mistake
// and carried credit, drafts and results kept over a reload, another student's page refused) and
// an instructor (tests/browser/dashboard_flow.mjs: the class at a glance updating live while 200
// students submit, the counts and the frequent mistake, one student's submissions, a regrade's
// dry run and apply; tests/browser/author_flow.mjs: an error marked at its line, fixed, the key
// and derivation following, saved). Screenshots are kept in build/serve_browser/,
// build/dashboard_browser/ and build/author_browser/.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

// Runs the flow `script` (in tests/browser) with the binary, a work and a screenshot directory
// under build/OUT, and `more` arguments; expects it to pass and to have saved `shots`.
void run_flow(const std::string& script, const std::string& out_name,
              const std::vector<std::string>& more, const std::vector<std::string>& shots) {
  ASSERT_TRUE(fs::exists("/usr/bin/chromium")) << "tools/setup.sh --tests installs chromium";
  const fs::path dir = fs::path(FRUSTUM_SOURCE_DIR) / "tests/browser";
  ASSERT_TRUE(fs::exists(dir / "node_modules/playwright-core"))
      << "run tools/setup.sh --tests (npm ci in tests/browser)";
  const fs::path out = fs::path(FRUSTUM_BINARY_DIR) / out_name;
  RunOptions options;
  options.seconds = 240;
  std::vector<std::string> args = {"node", (dir / script).string(), FRUSTUM_BINARY,
                                   (out / "work").string(), (out / "screenshots").string()};
  args.insert(args.end(), more.begin(), more.end());
  const ProgramRun run = run_program(args, options);
  ASSERT_TRUE(run.started) << run.start_error;
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("checks passed"), std::string::npos) << run.output;
  for (const std::string& shot : shots) EXPECT_TRUE(fs::exists(out / "screenshots" / shot)) << shot;
}

TEST(ServeBrowser, AStudentAnswersSubmitsAndSeesTheFeedback) {
  run_flow("serve_flow.mjs", "serve_browser", {},
           {"1-set.png", "2-preview.png", "3-result.png", "4-reloaded.png", "5-refused.png"});
}

TEST(ServeBrowser, AnInstructorWatchesTheClassSubmitAndRegrades) {
  run_flow("dashboard_flow.mjs", "dashboard_browser", {"200"},
           {"1-empty.png", "2-class.png", "3-student.png", "4-dry-run.png", "5-applied.png"});
}

TEST(AuthorBrowser, AnAuthorBreaksFixesAndSavesASet) {
  ASSERT_TRUE(fs::exists("/usr/share/javascript/codemirror/lib/codemirror.js"))
      << "tools/setup.sh installs libjs-codemirror";
  run_flow("author_flow.mjs", "author_browser", {}, {"1-error.png", "2-fixed.png", "3-saved.png"});
}

}  // namespace
}  // namespace frustum
