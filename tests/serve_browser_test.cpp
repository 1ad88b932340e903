// The served pages as a student uses them, in Debian's chromium driven by playwright-core
// (tests/browser/serve_flow.mjs: the link, the preview, a submission's named mistake and
// carried credit, drafts and results kept over a reload, another student's page refused).
// Screenshots are kept in build/serve_browser/.
#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.hpp"

namespace frustum {
namespace {

TEST(ServeBrowser, AStudentAnswersSubmitsAndSeesTheFeedback) {
  namespace fs = std::filesystem;
  ASSERT_TRUE(fs::exists("/usr/bin/chromium")) << "tools/setup.sh --tests installs chromium";
  const fs::path dir = fs::path(FRUSTUM_SOURCE_DIR) / "tests/browser";
  ASSERT_TRUE(fs::exists(dir / "node_modules/playwright-core"))
      << "run tools/setup.sh --tests (npm ci in tests/browser)";
  const fs::path out = fs::path(FRUSTUM_BINARY_DIR) / "serve_browser";
  RunOptions options;
  options.seconds = 180;
  const ProgramRun run = run_program({"node", (dir / "serve_flow.mjs").string(), FRUSTUM_BINARY,
                                      (out / "work").string(), (out / "screenshots").string()},
                                     options);
  ASSERT_TRUE(run.started) << run.start_error;
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("checks passed"), std::string::npos) << run.output;
  for (const char* shot :
       {"1-set.png", "2-preview.png", "3-result.png", "4-reloaded.png", "5-refused.png"})
    EXPECT_TRUE(fs::exists(out / "screenshots" / shot)) << shot;
}

// The authoring page as an instructor uses it (tests/browser/author_flow.mjs: an error marked at
// its line, fixed, the key and derivation following, saved). Screenshots in build/author_browser/.
TEST(AuthorBrowser, AnAuthorBreaksFixesAndSavesASet) {
  namespace fs = std::filesystem;
  ASSERT_TRUE(fs::exists("/usr/bin/chromium")) << "tools/setup.sh --tests installs chromium";
  ASSERT_TRUE(fs::exists("/usr/share/javascript/codemirror/lib/codemirror.js"))
      << "tools/setup.sh installs libjs-codemirror";
  const fs::path dir = fs::path(FRUSTUM_SOURCE_DIR) / "tests/browser";
  ASSERT_TRUE(fs::exists(dir / "node_modules/playwright-core"))
      << "run tools/setup.sh --tests (npm ci in tests/browser)";
  const fs::path out = fs::path(FRUSTUM_BINARY_DIR) / "author_browser";
  RunOptions options;
  options.seconds = 180;
  const ProgramRun run = run_program({"node", (dir / "author_flow.mjs").string(), FRUSTUM_BINARY,
                                      (out / "work").string(), (out / "screenshots").string()},
                                     options);
  ASSERT_TRUE(run.started) << run.start_error;
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_NE(run.output.find("checks passed"), std::string::npos) << run.output;
  for (const char* shot : {"1-error.png", "2-fixed.png", "3-saved.png"})
    EXPECT_TRUE(fs::exists(out / "screenshots" / shot)) << shot;
}

}  // namespace
}  // namespace frustum
