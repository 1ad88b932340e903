// Derivations as a textbook prints them: every formula is real LaTeX (no Unicode operators or
// words left in math mode) that KaTeX renders in strict mode.
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/latex_check.hpp"
#include "solver/problem/problem_figure.hpp"
#include "typeset_corpus.hpp"

namespace frustum {
namespace {

TEST(LatexCheck, FindsUnicodeOperatorsAndWordsInMathMode) {
  EXPECT_TRUE(latex_problems("x_{\\min} = 0,\\; \\lVert\\mathbf{n}\\rVert \\cdot 2fn").empty());
  EXPECT_TRUE(
      latex_problems("\\text{outcode}(p) \\mathbin{\\mathrm{OR}} \\text{outcode}(q)").empty());
  EXPECT_TRUE(latex_problems("\\begin{bmatrix}1 & 0 \\\\ 0 & 1\\end{bmatrix}").empty());
  EXPECT_EQ(latex_problems("outcode(p) = 0").size(), 1u);
  EXPECT_EQ(latex_problems("xmin = 0").size(), 1u);
  EXPECT_TRUE(latex_problems("E_{AB}(x, y) = 4y - 2").empty()) << "capitals name points";
  EXPECT_EQ(latex_problems("f = (c − e)/‖c − e‖").size(), 4u);  // −, ‖, −, ‖
  EXPECT_EQ(latex_problems("no").size(), 1u);
  EXPECT_EQ(latex_problems("\\text{unclosed").size(), 1u);
}

TEST(Typeset, EveryFormulaOfEveryKindIsLatexWithoutWordsOrUnicode) {
  std::set<std::string> kinds;
  int strings = 0;
  for (const ProblemResult& p : test::typeset_corpus()) {
    kinds.insert(p.kind);
    for (const std::string& latex : test::latex_strings(p)) {
      ++strings;
      for (const std::string& problem : latex_problems(latex))
        ADD_FAILURE() << p.id << " (" << p.kind << "): " << problem << "\n    " << latex;
    }
  }
  EXPECT_EQ(kinds.size(), builtin_kinds().all().size()) << "a kind has no derivation in the corpus";
  EXPECT_GT(strings, 1000);
}

constexpr const char* kKatex = "/usr/share/javascript/katex/katex.js";  // Debian's libjs-katex
constexpr const char* kNode = "/usr/bin/node";

// Runs a program and returns what it printed (stderr too unless `options` says otherwise) and its
// exit status.
std::pair<std::string, int> run(const std::vector<std::string>& argv, RunOptions options = {}) {
  const ProgramRun r = run_program(argv, options);
  return {r.output, r.status};
}

// Chromium, headless, with its profile in `profile`, on the page; `more` before the URL.
std::vector<std::string> chromium(const std::string& profile, const std::string& page,
                                  std::vector<std::string> more) {
  std::vector<std::string> argv = {"/usr/bin/chromium",
                                   "--headless",
                                   "--no-sandbox",
                                   "--disable-gpu",
                                   "--disable-background-networking",
                                   "--disable-component-update",
                                   "--no-first-run",
                                   "--disable-dev-shm-usage",
                                   "--user-data-dir=" + profile};
  argv.insert(argv.end(), more.begin(), more.end());
  argv.push_back("file://" + page);
  return argv;
}

TEST(Typeset, KatexRendersEveryFormulaInStrictMode) {
  ASSERT_TRUE(std::filesystem::exists(kKatex))
      << kKatex << " is missing: tools/setup.sh installs libjs-katex";
  ASSERT_TRUE(std::filesystem::exists(kNode))
      << kNode << " is missing: tools/setup.sh installs nodejs";
  std::set<std::string> unique;
  for (const ProblemResult& p : test::typeset_corpus())
    for (const std::string& latex : test::latex_strings(p)) unique.insert(latex);
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("frustum-latex-" + std::to_string(getpid()) + ".json"))
                               .string();
  std::ofstream(file)
      << nlohmann::json(std::vector<std::string>(unique.begin(), unique.end())).dump();
  const auto [out, status] =
      run({kNode, test::source_path("tests/katex/render_all.js"), kKatex, file});
  std::filesystem::remove(file);
  EXPECT_EQ(status, 0) << out.substr(0, 6000);
  EXPECT_NE(out.find(std::to_string(unique.size()) + " formulas, 0 failed"), std::string::npos)
      << out.substr(0, 2000);
}

// `solve --format html` in headless Chromium: the page typesets every formula with the inlined
// KaTeX, shows its pictures, and a screenshot is taken (look at build/typeset-pipeline.png).
TEST(Typeset, HtmlPageTypesetsInChromiumAndScreenshots) {
  constexpr const char* kChromium = "/usr/bin/chromium";
  ASSERT_TRUE(std::filesystem::exists(kChromium)) << "tools/setup.sh installs chromium";
  const ProblemSet source = load_problem_set(test::source_path("problems/examples/pipeline.yaml"));
  const SetResult set = solve_set(source, true);
  const Figures figures = problem_figures(source);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("frustum-html-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "profile");
  const std::string page = (dir / "pipeline.html").string(),
                    png = std::string(FRUSTUM_BINARY_DIR) + "/typeset-pipeline.png";
  std::ofstream(page) << render_html(set, Lang::En, &figures);
  RunOptions quiet;
  quiet.err = OutputTo::Null;
  quiet.seconds = 120;
  const std::string profile = (dir / "profile").string();
  const auto [dom, status] = run(chromium(profile, page, {"--dump-dom"}), quiet);
  EXPECT_NE(dom.find("data-math=\"yes\""), std::string::npos) << "the page's script did not run";
  EXPECT_NE(dom.find("class=\"katex-display\""), std::string::npos);
  EXPECT_EQ(dom.find("data-typeset=\"error\""), std::string::npos);
  EXPECT_NE(dom.find("<figure class=\"figure\"><img"), std::string::npos);
  std::filesystem::remove(png);
  run(chromium(profile, page, {"--window-size=1000,1400", "--screenshot=" + png}), quiet);
  ASSERT_TRUE(std::filesystem::exists(png));
  EXPECT_GT(std::filesystem::file_size(png), 20000u) << "a typeset page is more than a blank image";
  std::filesystem::remove_all(dir);
}

// `tex` written to DIR/set.tex and compiled there with LuaLaTeX (its fonts cached in DIR/var):
// the log and the exit status; DIR/set.pdf is the document.
std::pair<std::string, int> lualatex(const std::filesystem::path& dir, const std::string& tex) {
  std::ofstream((dir / "set.tex").string()) << tex;
  std::filesystem::remove(dir / "set.pdf");
  RunOptions in_dir;
  in_dir.cwd = dir.string();
  in_dir.environment = {"TEXMFVAR=" + (dir / "var").string()};
  in_dir.seconds = 300;
  return run({"lualatex", "-interaction=nonstopmode", "-halt-on-error", "set.tex"}, in_dir);
}

// Exact values too long to read (nested radicals of several hundred characters) and long
// formulas stay within the page: LuaLaTeX reports no overfull line, and in Chromium no formula
// of the HTML page is wider than its box (800 pixels wide), and the values are shown as their
// decimals cut after six digits.
TEST(Typeset, LongExactValuesStayWithinThePage) {
  const char* yaml = R"yaml(title: long exact values
problems:
  - id: v
    kind: vectors
    given: {a: [3, "sqrt(2)", "7/3"], b: ["5/7", "11/13", "sqrt(5)"]}
  - id: pl
    kind: plane
    given: {points: [[1, "2/7", 3], ["sqrt(3)", 5, "1/9"], [7, "13/11", "sqrt(2)"]]}
)yaml";
  const SetResult set = solve_set(load_problem_set_from_string(yaml, "long.yaml"), true);
  const std::string text = render_text(set, TextStyle{});
  EXPECT_NE(text.find("sin θ = 0.533707…"), std::string::npos) << text.substr(0, 3000);
  EXPECT_NE(text.find("n̂ = (−0.150903…, −0.499370…, −0.853145…)"), std::string::npos);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("frustum-long-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "var");
  std::filesystem::create_directories(dir / "profile");
  const auto [log, status] = lualatex(dir, render_latex(set, Lang::En));
  ASSERT_EQ(status, 0) << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
  const std::string tex_log = test::read_file((dir / "set.log").string());
  EXPECT_EQ(tex_log.find("Overfull \\hbox"), std::string::npos) << tex_log.substr(
      tex_log.find("Overfull") == std::string::npos ? 0 : tex_log.find("Overfull"), 400);
  // The page, with a script after KaTeX's that counts the formulas wider than their box.
  std::string html = render_html(set, Lang::En);
  html.insert(html.rfind("</body>"),
              "<script>var n = 0; document.querySelectorAll('.math, td').forEach(function (e) { "
              "if (e.scrollWidth > e.clientWidth + 1) n++; }); "
              "document.body.setAttribute('data-overflow', String(n));</script>\n");
  const std::string page = (dir / "long.html").string();
  std::ofstream(page) << html;
  RunOptions quiet;
  quiet.err = OutputTo::Null;
  quiet.seconds = 120;
  const auto [dom, dom_status] = run(
      chromium((dir / "profile").string(), page, {"--window-size=800,1200", "--dump-dom"}), quiet);
  EXPECT_NE(dom.find("data-math=\"yes\""), std::string::npos) << "the page's script did not run";
  EXPECT_NE(dom.find("data-overflow=\"0\""), std::string::npos) << dom.substr(
      dom.find("data-overflow") == std::string::npos ? 0 : dom.find("data-overflow"), 40);
  std::filesystem::remove_all(dir);
}

// `solve --format latex` compiles with Debian's LuaLaTeX for every seed set.
TEST(Typeset, LatexDocumentsCompileWithLualatex) {
  ASSERT_TRUE(std::filesystem::exists("/usr/bin/lualatex"))
      << "tools/setup.sh installs texlive-luatex";
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("frustum-tex-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "var");
  // The seeds, and the pipeline example for the pictures of clipping, scan conversion and the
  // z-buffer (TikZ on the pixel grid).
  for (const std::string& file : test::bundled_sets()) {
    if (file.find("/seeds/") == std::string::npos &&
        file.find("/pipeline.yaml") == std::string::npos)
      continue;
    const ProblemSet set = load_problem_set(file);
    const Figures figures = problem_figures(set);
    const auto [log, status] =
        lualatex(dir, render_latex(solve_set(set, true), Lang::En, &figures));
    EXPECT_EQ(status, 0) << file << "\n" << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
    EXPECT_TRUE(std::filesystem::exists(dir / "set.pdf")) << file;
  }
  std::filesystem::remove_all(dir);
}

// `solve --format latex --lang ja|ru` prints its Japanese and Russian: the PDF's text (pdftotext)
// holds the problem's own words, and LuaLaTeX reports no missing character.
TEST(Typeset, JapaneseAndRussianLatexKeepTheirGlyphs) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("frustum-tex-lang-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir / "var");
  const std::pair<const char*, Lang> cases[] = {{"003_polygons_backface.yaml", Lang::Ja},
                                                {"004_placing_and_projecting.yaml", Lang::Ru}};
  for (const auto& [name, lang] : cases) {
    const ProblemSet set =
        load_problem_set(test::source_path(std::string("problems/seeds/") + name));
    const auto [log, status] = lualatex(dir, render_latex(solve_set(set, true), lang));
    ASSERT_EQ(status, 0) << name << "\n" << log.substr(log.size() > 3000 ? log.size() - 3000 : 0);
    const std::string tex_log = test::read_file((dir / "set.log").string());
    EXPECT_EQ(tex_log.find("Missing character"), std::string::npos) << name;
    RunOptions in_dir;
    in_dir.cwd = dir.string();
    const auto [text, text_status] = run({"pdftotext", "-enc", "UTF-8", "set.pdf", "-"}, in_dir);
    ASSERT_EQ(text_status, 0);
    // The set's title in the reader's language, as typeset (a line break may split it).
    const auto squeezed = [](std::string t) {
      t.erase(std::remove_if(t.begin(), t.end(), [](char c) { return c == ' ' || c == '\n'; }),
              t.end());
      return t;
    };
    const std::string title = set.title.in(lang);
    EXPECT_NE(squeezed(text).find(squeezed(title)), std::string::npos)
        << name << ": " << title << "\n"
        << text.substr(0, 600);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace frustum
