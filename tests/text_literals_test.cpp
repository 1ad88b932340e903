// A drawn variant never shows a text whose literal values contradict its given: literals of the
// given's values become placeholders, or the set is refused.
#include "solver/problem/text_literals.hpp"

#include <gtest/gtest.h>

#include <set>
#include <tuple>
#include <vector>

#include "solver/problem/variants.hpp"
#include "typeset_corpus.hpp"

namespace frustum {
namespace {

TemplatedText templ(const std::string& text, const std::string& given) {
  return template_literals(text, YAML::Load(given));
}

TEST(TextLiterals, PointsInAnySpacingAndBrackets) {
  const char* g = "{A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9]}";
  EXPECT_EQ(templ("A(0,0,6), B( 3 , 0 , 9 ), C[0, 3, 9]", g).text,
            "A({A.0},{A.1},{A.2}), B( {B.0} , {B.1} , {B.2} ), C[{C.0}, {C.1}, {C.2}]");
  const TemplatedText t = templ("A(0,0,6)", g);
  EXPECT_FALSE(t.error);
  EXPECT_EQ(t.tied, 1);
}

TEST(TextLiteralsTest, NegativeNumbersFractionsAndDecimals) {
  // A text that writes − (U+2212) gets placeholders that print − too ({p.0|−}).
  EXPECT_EQ(templ("p(−1, 1) to q(5, -2.5)", "{p: [-1, 1], q: [5, -2.5]}").text,
            "p({p.0|−}, {p.1|−}) to q({q.0|−}, {q.1|−})");
  EXPECT_EQ(fill_text("p({p.0|−}, {p.1|−}) to {q|−}", YAML::Load("{p: [-7, 1], q: [5, -2.5]}")),
            "p(−7, 1) to (5, −2.5)");
  EXPECT_EQ(templ("p(-1, 1)", "{p: [-1, 1]}").text, "p({p.0}, {p.1})");
  EXPECT_EQ(templ("(½,½), (4½,½), (1/2, 9/2)",
                  "{triangle: [['1/2', '1/2'], ['9/2', '1/2'], ['1/2', '9/2']]}")
                .text,
            "({triangle.0.0},{triangle.0.1}), ({triangle.1.0},{triangle.1.1}), "
            "({triangle.2.0}, {triangle.2.1})");
  EXPECT_EQ(templ("a = (0.1, 0.2, 0.3)", "{a: [0.1, 0.2, 0.3]}").text, "a = ({a.0}, {a.1}, {a.2})");
}

TEST(TextLiteralsTest, ScalarsAfterEqualsOrWithDegrees) {
  const char* g = "{perspective: {fovy: 90, aspect: 1, near: 1, far: 3}}";
  EXPECT_EQ(templ("fovy = 90°, aspect = 1, near = 1, far = 3.", g).text,
            "fovy = {perspective.fovy}°, aspect = {perspective.aspect}, near = "
            "{perspective.near}, far = {perspective.far}.");
  EXPECT_EQ(templ("perspective(60°, 1, 10, 10000)",
                  "{perspective: {fovy: 60, aspect: 1, near: 10, far: 10000}}")
                .text,
            "perspective({perspective.fovy}°, {perspective.aspect}, {perspective.near}, "
            "{perspective.far})");
  // A result after a computation is not a field's value.
  EXPECT_EQ(templ("x = 0.7/0.7 = 1", g).text, "x = 0.7/0.7 = 1");
  // The same angle three times for three fields: tied in order.
  EXPECT_EQ(templ("R_x(30°), R_y(30°) and R_z(30°)",
                  "{steps: [{rotate_x: 30}, {rotate_y: 30}, {rotate_z: 30}]}")
                .text,
            "R_x({steps.0.rotate_x}°), R_y({steps.1.rotate_y}°) and R_z({steps.2.rotate_z}°)");
}

TEST(TextLiteralsTest, SizesMappingsAndPartsOfThem) {
  EXPECT_EQ(templ("a 640×480 window", "{viewport: {width: 640, height: 480}}").text,
            "a {viewport.width}×{viewport.height} window");
  EXPECT_EQ(templ("x ∈ [−100, 100], y ∈ [−100, 100], z_min = 10",
                  "{ortho: {left: -100, right: 100, bottom: -100, top: 100, near: 10, far: 1000}}")
                .text,
            "x ∈ [{ortho.left|−}, {ortho.right|−}], y ∈ [{ortho.bottom|−}, {ortho.top|−}], z_min = "
            "{ortho.near|−}");
  EXPECT_EQ(templ("camera(-150, -500, 1500, 0, 0, 0, 0, 1, 0)",
                  "{eye: [-150, -500, 1500], center: [0, 0, 0], up: [0, 1, 0]}")
                .text,
            "camera({eye.0}, {eye.1}, {eye.2}, {center.0}, {center.1}, {center.2}, {up.0}, "
            "{up.1}, {up.2})");
}

TEST(TextLiteralsTest, OtherNumbersAreLeftAlone) {
  const char* g = "{a: [2, 0, 1], b: [1, 2, 0]}";
  // Numbering, the origin, a constant, a number alone, words with digits, powers.
  const std::string text =
      "1. a × b  2. the plane through (0,0,0), (7, 8) and 3D; 10⁻³⁰ or 1e-18·n, 9.10's p0";
  const TemplatedText t = templ(text, g);
  EXPECT_FALSE(t.error) << *t.error;
  EXPECT_EQ(t.text, text);
  EXPECT_EQ(templ("no numbers", g).text, "no numbers");
  EXPECT_EQ(templ("(1e99999, 2)", "{p: [1, 2]}").text, "(1e99999, 2)");
  // A list inside brackets that do not close around it is numbering, not a point ...
  const char* polygon = "{polygons: [{label: 1, points: [[1, 2, 3], [4, 2, 3], [4, 5, 3]]}]}";
  EXPECT_EQ(templ("(1, 2, 3 の順と同じ結果になるか)", polygon).text,
            "(1, 2, 3 の順と同じ結果になるか)");
  // ... but the last arguments of a call are named fields (and PI/3 the field of view, in
  // radians: AnglesWrittenAsMultiplesOfPi).
  EXPECT_EQ(templ("perspective(PI/3, width/height, 10, 10000)",
                  "{perspective: {fovy: 60, aspect: 1, near: 10, far: 10000}}")
                .text,
            "perspective({perspective.fovy|PI}, width/height, {perspective.near}, "
            "{perspective.far})");
  EXPECT_EQ(templ("A(0,0,6)", "{solid: cube}").text, "A(0,0,6)");
}

TEST(TextLiteralsTest, AmbiguousLiteralsAreRefused) {
  // Two points with the same value, one mention: which one does the text state?
  const TemplatedText twice = templ("the point (1, 2)", "{p: [1, 2], q: [1, 2]}");
  ASSERT_TRUE(twice.error);
  EXPECT_NE(twice.error->find("\"(1, 2)\" could state any of several values"), std::string::npos)
      << *twice.error;
  EXPECT_NE(twice.error->find("{p.0}, {p.1}"), std::string::npos) << *twice.error;
  // Numbers of the given that no field holds together (a corner of the window).
  const TemplatedText corner =
      templ("through the corner (0.4, 0.3)", "{window: {xmin: 0, xmax: 0.4, ymin: 0, ymax: 0.3}}");
  ASSERT_TRUE(corner.error);
  EXPECT_NE(corner.error->find("\"(0.4, 0.3)\" states values of the given but not one of its"),
            std::string::npos)
      << *corner.error;
  // A scalar two fields hold, named by neither.
  // "n = 1" is read as near (a field starting with n); "k = 1" names none of the two.
  EXPECT_TRUE(templ("k = 1", "{perspective: {fovy: 90, aspect: 1, near: 1, far: 3}}").error);
}

const char* kStale = R"yaml(variants: per_student
problems:
  - id: tri
    kind: normal
    text:
      en: "The triangle A(0,0,6), B(3,0,9), C(0,3,9)."
      ja: "三角形 A(0,0,6), B(3,0,9), C(0,3,9)"
    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9]}
  - id: twins
    kind: vectors
    text:
      en: "The vector (1, 2, 3)."
    given: {a: [1, 2, 3], b: [1, 2, 3]}
)yaml";

// The seen case: a variant's text states its own values, in every language.
// An angle the text writes in radians as Processing does (perspective(PI/3, …) for fovy: 60):
// tied to {field|PI}, which prints the drawn degrees as a multiple of π in the same style.
TEST(TextLiteralsTest, AnglesWrittenAsMultiplesOfPi) {
  const char* g = "{perspective: {fovy: 60, aspect: 1, near: 10, far: 100}}";
  const TemplatedText t = templ("perspective(PI/3, width/height, 10, 100)", g);
  EXPECT_FALSE(t.error) << *t.error;
  EXPECT_EQ(t.text,
            "perspective({perspective.fovy|PI}, width/height, {perspective.near}, "
            "{perspective.far})");
  EXPECT_EQ(templ("a field of view of π/3", g).text,
            "a field of view of {perspective.fovy|\u03c0}");
  for (const auto& [degrees, pi, shown] :
       std::vector<std::tuple<int, std::string, std::string>>{{60, "PI", "PI/3"},
                                                              {90, "PI", "PI/2"},
                                                              {120, "PI", "2*PI/3"},
                                                              {180, "PI", "PI"},
                                                              {-45, "PI", "-PI/4"},
                                                              {150, "\u03c0", "5\u03c0/6"},
                                                              {0, "PI", "0"}}) {
    const YAML::Node drawn = YAML::Load("{perspective: {fovy: " + std::to_string(degrees) + "}}");
    EXPECT_EQ(fill_text("{perspective.fovy|" + pi + "}", drawn), shown) << degrees;
  }
  EXPECT_EQ(templ("rotate 2*PI/3 about z", "{rotate_z: 120}").text, "rotate {rotate_z|PI} about z");
  // Not an angle of the given, or not a multiple of π on its own: left as written.
  EXPECT_EQ(templ("HALF_PI and PIXEL and PI/4", g).text, "HALF_PI and PIXEL and PI/4");
  EXPECT_EQ(templ("PI/3 of a window", "{window: [60, 60]}").text, "PI/3 of a window");
  // Two angles of that size: which one it states is the instructor's to write.
  EXPECT_TRUE(templ("PI/2", "{rotate_x: 90, rotate_y: 90}").error);
  // A placeholder of an angle that is not whole degrees cannot print as a multiple of π.
  EXPECT_TRUE(placeholder_error("{a|PI}", YAML::Load("{a: 'pi/3'}")));
  EXPECT_FALSE(placeholder_error("{a|PI}", YAML::Load("{a: 30}")));
}

TEST(TextLiteralsTest, VariantTextStatesDrawnValues) {
  ProblemSet set = load_problem_set_from_string(kStale, "set.yaml");
  const std::vector<Diagnostic> stale = stale_text_errors(set, false);
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_NE(stale[0].format().find("problems[1].text.en: problem twins (en): the literal "
                                   "\"(1, 2, 3)\""),
            std::string::npos)
      << stale[0].format();
  const ProblemSet v = variant_for_student(set, "s1", false);
  ASSERT_FALSE(v.problems[0].error);
  EXPECT_TRUE(v.problems[1].error);
  const SetResult r = solve_set(v, false);
  const YAML::Node a = v.problems[0].given_node["A"];
  const std::string point = "(" + a[0].Scalar() + "," + a[1].Scalar() + "," + a[2].Scalar() + ")";
  EXPECT_NE(r.problems[0].text.in(Lang::En).find("A" + point), std::string::npos)
      << r.problems[0].text.in(Lang::En);
  EXPECT_NE(r.problems[0].text.in(Lang::Ja).find("A" + point), std::string::npos)
      << r.problems[0].text.in(Lang::Ja);
}

// The un-drawn set prints its text as written.
TEST(TextLiteralsTest, UndrawnSetUnchanged) {
  const ProblemSet set = load_problem_set_from_string(kStale, "set.yaml");
  const SetResult r = solve_set(set, false);
  EXPECT_EQ(r.problems[0].text.text, "The triangle A(0,0,6), B(3,0,9), C(0,3,9).");
}

// Every placeholder a text holds, as written ({A.0}).
std::set<std::string> placeholders_of(const std::string& text) {
  std::set<std::string> out;
  for (std::size_t open = text.find('{'); open != std::string::npos;
       open = text.find('{', open + 1))
    if (const std::size_t close = text.find('}', open); close != std::string::npos)
      out.insert(text.substr(open, close - open + 1));
  return out;
}

// Over every bundled set, every problem drawn by its default generator: each language's text of
// each variant states the variant's drawn value wherever the written text stated a given value,
// and the rest of the text is as written.
TEST(TextLiteralsTest, EveryBundledVariantStatesItsDrawnValues) {
  int tied = 0, texts = 0;
  for (const std::string& file : test::bundled_sets()) {
    const ProblemSet set = load_problem_set(file);
    EXPECT_TRUE(stale_text_errors(set, true).empty()) << stale_text_errors(set, true)[0].format();
    for (const ProblemSet& v : variants_from_seed(set, 7, 3, true))
      for (std::size_t i = 0; i < v.problems.size(); ++i) {
        const ProblemSpec& base = set.problems[i];
        const ProblemSpec& drawn = v.problems[i];
        if (drawn.error || base.error) continue;
        const ProblemResult r = solve_problem(drawn, file, false);
        for (const auto& [lang, written] : base.text.all()) {
          const TemplatedText t = template_literals(written, base.given_node);
          ASSERT_FALSE(t.error) << file << " " << base.id << ": " << *t.error;
          const std::string shown = r.text.in(lang);
          EXPECT_EQ(shown, fill_text(t.text, drawn.given_node)) << file << " " << base.id;
          // The value as the text prints it (its minus signs in the text's own style).
          const auto ascii_minus = [](std::string x) {
            for (std::size_t k; (k = x.find("\u2212")) != std::string::npos;) x.replace(k, 3, "-");
            return x;
          };
          for (const std::string& ph : placeholders_of(t.text)) {
            const std::string value = fill_text(ph, drawn.given_node);
            EXPECT_NE(value, ph) << file << " " << base.id << ": " << ph << " names nothing";
            EXPECT_NE(ascii_minus(shown).find(ascii_minus(value)), std::string::npos)
                << file << " " << base.id << " " << ph;
          }
          tied += t.tied;
          ++texts;
        }
      }
  }
  EXPECT_GT(texts, 300);
  EXPECT_GT(tied, 300);  // most bundled texts state their values
}

}  // namespace
}  // namespace frustum
