// Pictures in the derivations: every problem of a kind with a natural picture gets
// one — drawn in the plane (clipping, scan conversion, the plane method, barycentric
// coordinates, the z-buffer) as SVG and TikZ from the same strokes, or `frustum draw`'s
// picture (hidden lines, painter against z-buffer) as SVG — and `solve --format html|latex`
// shows it under the problem's text.
#include "solver/problem/problem_figure.hpp"

#include <gtest/gtest.h>

#include <regex>
#include <set>

#include "grader/grade.hpp"
#include "report/feedback.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/plane_drawing.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/util/base64.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// The numbers of every `name="…"` attribute of the SVG's elements of class `cls`.
std::vector<double> attribute_values(const std::string& svg, const std::string& cls,
                                     const std::string& name) {
  std::vector<double> out;
  const std::regex element("<[a-z]+ class=\"" + cls + "\"[^>]*>");
  const std::regex attribute(" " + name + "=\"([-0-9.e]+)\"");
  for (auto e = std::sregex_iterator(svg.begin(), svg.end(), element); e != std::sregex_iterator();
       ++e) {
    const std::string tag = e->str();
    for (auto a = std::sregex_iterator(tag.begin(), tag.end(), attribute);
         a != std::sregex_iterator(); ++a)
      out.push_back(std::stod((*a)[1]));
  }
  return out;
}

// A vertex on whole coordinates sits on a grid line in the SVG as in the TikZ (step=1 of the
// picture's units, not TikZ's default 1 cm): the pixel edges of scan conversion are the grid.
TEST(Figures, VerticesOnWholeCoordinatesSitOnTheGrid) {
  PlaneDrawing d = PlaneDrawing::around({{1, 1}, {7, 2}, {3, 6}}, true);
  d.polyline({{1, 1}, {7, 2}, {3, 6}}, PlaneDrawing::Pen::Shape);
  d.label({4, 3}, "a & b", false, PlaneDrawing::Place::BelowRight);
  const std::string svg = d.svg();
  const std::vector<double> grid_x = attribute_values(svg, "grid", "x1"),
                            grid_y = attribute_values(svg, "grid", "y1");
  const std::set<double> xs(grid_x.begin(), grid_x.end()), ys(grid_y.begin(), grid_y.end());
  EXPECT_EQ(xs.size(), 9u);  // x from 0 to 8 (the box holds the origin, 0.5 margin rounded out)
  const std::smatch m = [&] {
    std::smatch s;
    std::regex_search(svg, s, std::regex("class=\"shape\" points=\"([^\"]+)\""));
    return s;
  }();
  ASSERT_FALSE(m.empty()) << svg;
  std::istringstream points(m[1].str());
  std::string xy;
  int vertices = 0;
  while (points >> xy) {
    const double x = std::stod(xy.substr(0, xy.find(','))),
                 y = std::stod(xy.substr(xy.find(',') + 1));
    EXPECT_TRUE(xs.count(x)) << x << " is on no vertical grid line";
    EXPECT_TRUE(ys.count(y)) << y << " is on no horizontal grid line";
    ++vertices;
  }
  EXPECT_EQ(vertices, 3);
  EXPECT_NE(svg.find("a &amp; b"), std::string::npos);  // text escaped
  const std::string tikz = d.tikz();
  EXPECT_NE(tikz.find("step=1] (0,0) grid (8,7)"), std::string::npos) << tikz;
  EXPECT_NE(tikz.find("\\draw[thick] (1,1) -- (7,2) -- (3,6) -- cycle;"), std::string::npos);
  EXPECT_NE(tikz.find("{a \\& b}"), std::string::npos) << tikz;
}

// A picture at a scale nobody could read (a window 10³⁰⁰ wide) is not drawn — its grid would
// never end — and a large one is drawn without its grid; tiny coordinates are fixed-point in
// TikZ (its parser takes no exponent).
TEST(Figures, HugeAndTinyCoordinatesGiveNoPictureOrAReadableOne) {
  const auto figure = [](const std::string& xmax, const std::string& p) {
    const ProblemSet set = load_problem_set_from_string(
        "problems:\n  - {id: c, kind: clip_line, given: {window: {xmin: 0, xmax: " + xmax +
            ", ymin: 0, ymax: 3}, p: " + p + ", q: [5, 2]}}\n",
        "c.yaml");
    EXPECT_TRUE(set.all_errors().empty());
    return problem_figure(set.problems.at(0));
  };
  EXPECT_FALSE(figure("1e300", "[-1, 1]"));
  const std::optional<Figure> wide = figure("5000", "[-1, 1]");
  ASSERT_TRUE(wide);
  EXPECT_EQ(wide->svg.find("class=\"grid\""), std::string::npos);
  EXPECT_EQ(wide->tikz.find(" grid "), std::string::npos);
  const std::optional<Figure> tiny = figure("4", "[0.0000001, 1]");
  ASSERT_TRUE(tiny);
  EXPECT_EQ(tiny->tikz.find("e-"), std::string::npos) << tiny->tikz;
  EXPECT_NE(tiny->tikz.find("(0,1) -- (5,2)"), std::string::npos) << tiny->tikz;
}

// Every problem of a kind with a picture, in the bundled sets that have them, gets one; the
// HTML derivation shows each as an image of its SVG and the LaTeX one the TikZ of each plane
// picture; kinds without a picture get none.
TEST(Figures, EveryProblemOfAKindWithAPictureShowsItInTheDerivation) {
  const std::set<std::string> plane = {"clip_line",      "clip_polygon", "scan_convert",
                                       "depth_at_pixel", "barycentric",  "zbuffer",
                                       "scanline"};
  const std::set<std::string> drawn = {"edge_visibility", "depth_sort"};
  std::set<std::string> seen;
  for (const char* file :
       {"problems/examples/pipeline.yaml", "problems/examples/barycentric.yaml",
        "problems/examples/lecture_exercises.yaml", "problems/seeds/001_zbuffer_plane_method.yaml",
        "problems/seeds/003_polygons_backface.yaml"}) {
    const ProblemSet set = load_problem_set(test::source_path(file));
    ASSERT_TRUE(set.all_errors().empty()) << file;
    const Figures figures = problem_figures(set, set.lang);
    std::size_t with_tikz = 0;
    for (const ProblemSpec& p : set.problems) {
      const Figure* f = find_figure(&figures, p.id);
      const bool has = plane.count(p.kind) || drawn.count(p.kind);
      ASSERT_EQ(f != nullptr, has) << file << " " << p.id << " (" << p.kind << ")";
      if (!f) continue;
      seen.insert(p.kind);
      EXPECT_NE(f->svg.find("<svg xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
      EXPECT_EQ(!f->tikz.empty(), plane.count(p.kind) == 1) << p.id;
      if (!f->tikz.empty()) {
        ++with_tikz;
        EXPECT_NE(f->tikz.find("\\begin{tikzpicture}"), std::string::npos) << p.id;
      }
    }
    const SetResult solved = solve_set(set, true);
    const std::string html = render_html(solved, set.lang, &figures);
    std::size_t images = 0;
    for (std::size_t at = html.find("<figure class=\"figure\"><img"); at != std::string::npos;
         at = html.find("<figure class=\"figure\"><img", at + 1))
      ++images;
    EXPECT_EQ(images, figures.size()) << file;
    // The image is the figure's own SVG.
    if (!figures.empty()) {
      EXPECT_NE(html.find(base64(figures.begin()->second.svg)), std::string::npos) << file;
    }
    const std::string latex = render_latex(solved, set.lang, &figures);
    std::size_t pictures = 0;
    for (std::size_t at = latex.find("\\begin{tikzpicture}"); at != std::string::npos;
         at = latex.find("\\begin{tikzpicture}", at + 1))
      ++pictures;
    EXPECT_EQ(pictures, with_tikz) << file;
    EXPECT_EQ(latex.find("\\usepackage{tikz}") != std::string::npos, with_tikz > 0) << file;
    // Without figures, as before.
    EXPECT_EQ(render_html(solved, set.lang).find("<figure"), std::string::npos);
  }
  std::set<std::string> all = plane;
  all.insert(drawn.begin(), drawn.end());
  EXPECT_EQ(seen, all);
}

// A student's feedback page shows each problem's picture under its heading (the plane method's
// triangle and pixel); a picture that shows answers (the hidden edges) only where the key is
// shown, not in a platform's feedback that leaves the key to its own policy.
TEST(Figures, FeedbackShowsThePictureAndHidesAnswersWithTheKey) {
  for (const char* name : {"001_zbuffer_plane_method", "003_polygons_backface"}) {
    const ProblemSet set =
        load_problem_set(test::source_path(std::string("problems/seeds/") + name + ".yaml"));
    const Submission answers =
        load_submission(test::source_path(std::string("problems/seeds/answers/") + name + ".yaml"));
    const GradeReport report = grade(set, answers);
    const Figures figures = problem_figures(set, set.lang);
    ASSERT_FALSE(figures.empty()) << name;
    const std::string page = render_feedback_html(report, set.lang, "", &figures);
    for (const ProblemGrade& p : report.problems) {
      const Figure* f = find_figure(&figures, p.id);
      const std::string part =
          render_problem_feedback_html(p, set.lang, true, MathMarkup::KaTeX, f);
      EXPECT_EQ(part.find("<figure class=\"figure\">") != std::string::npos, f != nullptr) << p.id;
      if (f) {
        EXPECT_NE(page.find(base64(f->svg)), std::string::npos) << p.id;
      }
      const std::string keyless =
          render_problem_feedback_html(p, set.lang, false, MathMarkup::Delimited, f);
      EXPECT_EQ(keyless.find("<figure") != std::string::npos, f && !f->shows_answers) << p.id;
    }
    EXPECT_EQ(render_feedback_html(report, set.lang, "").find("<figure"), std::string::npos);
  }
}

// A student's wrong clipped segment or polygon is drawn over the givens (dashed), the right
// one beside it only where the key is shown; a right answer, `none` and an answer outside the
// picture draw nothing more; the caption says which line is whose, in the page's language.
TEST(Figures, FeedbackDrawsTheStudentsWrongClippingAndTheRightOneWithTheKey) {
  const ProblemSet set = load_problem_set_from_string(R"yaml(problems:
  - id: seg
    kind: clip_line
    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}
    ask: [clipped]
  - id: poly
    kind: clip_polygon
    given:
      points: [[0, 0], [4, 0], [0, 4]]
      window: {xmin: 1, xmax: 3, ymin: 1, ymax: 3}
)yaml",
                                                      "clip.yaml");
  const auto figures_for = [&](const std::string& seg, const std::string& poly) {
    const GradeReport r =
        grade(set, load_submission_from_string("student: s\nanswers:\n  seg: {clipped: " + seg +
                                                   "}\n  poly: {clipped: " + poly + "}\n",
                                               "a.yaml"));
    return std::pair{r, student_figures(set, r, Lang::Ja)};
  };
  // Wrong: both drawn, dashed, with the key's green only in svg_with_key.
  const auto [wrong, drawn] = figures_for("[[0, 3], [3, 1]]", "[[1, 1], [3, 1], [3, 3], [1, 3]]");
  for (const char* id : {"seg", "poly"}) {
    const Figure* f = find_figure(&drawn, id);
    ASSERT_TRUE(f) << id;
    EXPECT_TRUE(f->student_answer) << id;
    EXPECT_NE(f->svg.find("class=\"student\""), std::string::npos) << id;
    EXPECT_EQ(f->svg.find("class=\"key\""), std::string::npos) << id;
    EXPECT_NE(f->svg_with_key.find("class=\"key\""), std::string::npos) << id;
  }
  const ProblemGrade& seg = wrong.problems[0];
  const std::string keyless = render_problem_feedback_html(seg, Lang::Ja, false, MathMarkup::KaTeX,
                                                           find_figure(&drawn, "seg"));
  const std::string keyed = render_problem_feedback_html(seg, Lang::Ja, true, MathMarkup::KaTeX,
                                                         find_figure(&drawn, "seg"));
  EXPECT_NE(keyless.find("赤い破線: あなたの解答.</figcaption>"), std::string::npos) << keyless;
  EXPECT_NE(keyless.find(base64(find_figure(&drawn, "seg")->svg)), std::string::npos);
  EXPECT_NE(keyed.find("緑: 正しい解答"), std::string::npos);
  EXPECT_NE(keyed.find(base64(find_figure(&drawn, "seg")->svg_with_key)), std::string::npos);
  // Right (the key's own numbers), none, and far outside the picture: the plain figure.
  for (const auto& [s, p] :
       {std::pair{"[[0, 3.4], [3, 1]]", "[[1, 1], [3, 1], [1, 3]]"}, std::pair{"none", "none"},
        std::pair{"[[0, 3], [300, 1]]", "[[1, 1], [3, 1], [3, -90]]"}}) {
    const auto [r, plain] = figures_for(s, p);
    for (const char* id : {"seg", "poly"}) {
      const Figure* f = find_figure(&plain, id);
      ASSERT_TRUE(f) << id << " " << s;
      EXPECT_FALSE(f->student_answer) << id << " " << s;
      EXPECT_EQ(f->svg.find("class=\"student\""), std::string::npos) << id << " " << s;
    }
  }
}

}  // namespace
}  // namespace frustum
