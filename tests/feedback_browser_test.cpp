// The HTML feedback page in a real browser: headless Chromium (installed by tools/setup.sh)
// loads the self-contained page from disk and dumps the DOM after its script ran; the test
// reads the verdicts, the score and the math from what the browser rendered.
#include <unistd.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "batch/batch.hpp"
#include "report/feedback.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

constexpr const char* kChromium = "/usr/bin/chromium";

const char* kSet = R"Y(problems:
  - id: zbuf
    kind: depth_at_pixel
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
    ask: [unit_normal, plane, z]
  - id: bf
    kind: backface
    given: {points: [[1,0,0],[1,1,1],[0,1,2]], eye: [0,1,0]}
    ask: [df, facing]
)Y";

// Runs Chromium on the page and returns the DOM it dumped.
std::string dump_dom(const fs::path& page) {
  const fs::path profile =
      fs::temp_directory_path() / ("frustum-chromium-" + std::to_string(getpid()));
  fs::create_directories(profile);
  RunOptions quiet;
  quiet.err = OutputTo::Null;
  quiet.seconds = 120;
  const std::string out =
      run_program({kChromium, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                   "--no-first-run", "--disable-background-networking",
                   "--disable-component-update", "--disable-sync", "--disable-dev-shm-usage",
                   "--user-data-dir=" + profile.string(), "--dump-dom", "file://" + page.string()},
                  quiet)
          .output;
  fs::remove_all(profile);
  return out;
}

const char* kAnswers =
    "student: s42\nanswers:\n  zbuf: {unit_normal: [\"1/sqrt(3)\", \"1/sqrt(3)\", \"-1/sqrt(3)\"], "
    "z: 9}\n  bf: {df: -2, facing: front}\n";

// What Chromium shows of s42's page: verdicts, score, the math typeset by KaTeX.
void expect_rendered(const std::string& dom) {
  ASSERT_FALSE(dom.empty()) << "Chromium printed nothing";
  // The page's script ran in the browser: it marks the body and counts the verdicts shown.
  EXPECT_NE(dom.find("data-rendered=\"yes\""), std::string::npos) << dom.substr(0, 2000);
  EXPECT_NE(dom.find("<p id=\"summary\">correct: 2, incorrect: 2, missing: 1</p>"),
            std::string::npos)
      << dom.substr(0, 4000);
  EXPECT_NE(dom.find("Score: 2 / 5"), std::string::npos);
  // The math shows as written on paper: the exact unit normal and the plane's equation.
  EXPECT_NE(dom.find("(√3/3, √3/3, −√3/3)"), std::string::npos);
  EXPECT_NE(dom.find("x + y − z = −6"), std::string::npos);
  // The derivation under the wrong z, with the plane-method step.
  const std::size_t z_feedback = dom.find("id=\"feedback-zbuf-z\"");
  ASSERT_NE(z_feedback, std::string::npos);
  EXPECT_NE(dom.find("Depth at the pixel", z_feedback), std::string::npos);
  // The formulas were typeset by KaTeX (no network), none failed.
  EXPECT_NE(dom.find("data-math=\"yes\""), std::string::npos);
  EXPECT_NE(dom.find("data-typeset=\"yes\""), std::string::npos);
  EXPECT_EQ(dom.find("data-typeset=\"error\""), std::string::npos);
  EXPECT_NE(dom.find("class=\"katex\""), std::string::npos);
}

TEST(FeedbackBrowser, ChromiumRendersTheVerdictsScoreAndMath) {
  ASSERT_TRUE(fs::exists(kChromium))
      << kChromium << " is missing: tools/setup.sh installs Debian's chromium";
  const GradeReport r = grade(load_problem_set_from_string(kSet, "set.yaml"),
                              load_submission_from_string(kAnswers, "a.yaml"));
  const fs::path page =
      fs::temp_directory_path() / ("frustum-feedback-" + std::to_string(getpid()) + ".html");
  {
    std::ofstream out(page);
    out << render_feedback_html(r);
  }
  const std::string dom = dump_dom(page);
  fs::remove(page);
  expect_rendered(dom);
}

// A class's page links the one copy of KaTeX the batch wrote into its output directory; the
// directory, moved elsewhere as a whole (as a zip of it would be), still typesets the math.
TEST(FeedbackBrowser, ABatchPageTypesetsWithTheSharedKatexAfterTheDirectoryMoves) {
  ASSERT_TRUE(fs::exists(kChromium))
      << kChromium << " is missing: tools/setup.sh installs Debian's chromium";
  const fs::path dir =
      fs::temp_directory_path() / ("frustum-feedback-batch-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "class");
  std::ofstream(dir / "class" / "s42.yaml") << kAnswers;
  BatchOptions options;
  options.out_dir = (dir / "out").string();
  options.jobs = 1;
  grade_batch(load_problem_set_from_string(kSet, "set.yaml"),
              collect_submissions((dir / "class").string()), options);
  // Copied with the symlinks followed (what zip does), then the original removed.
  fs::copy(dir / "out", dir / "moved", fs::copy_options::recursive);
  fs::remove_all(dir / "out");
  ASSERT_TRUE(fs::is_regular_file(dir / "moved" / "katex" / "katex.min.js"));
  expect_rendered(dump_dom(dir / "moved" / "feedback" / "s42.html"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
