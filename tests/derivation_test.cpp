// Derivations as data and their three renderings.
#include "solver/derivation/formats.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const char* kSeed001 = R"(problems:
  - id: zbuf-pixel
    kind: depth_at_pixel
    text: "Find the z value of pixel (1,1)."
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
)";

TEST(Derivation, StepsForAnAnswerStopAtTheStepThatYieldsIt) {
  const ProblemResult r = test::solve_yaml(kSeed001);
  const std::vector<Step> to_normal = r.derivation.steps_for("normal");
  const std::vector<Step> to_z = r.derivation.steps_for("z");
  ASSERT_FALSE(to_normal.empty());
  EXPECT_LT(to_normal.size(), to_z.size());
  EXPECT_EQ(to_z.back().answers, std::vector<std::string>{"z"});
  // The API's eye-space line is not stated: the answer does not depend on it, and
  // "right-handed" would contradict the left-handed projection coordinates stated instead.
  EXPECT_EQ(r.derivation.steps().front().title.en(), "Projection coordinates are left-handed");
}

TEST(Derivation, TextShowsExactValuesWithDecimalsAndNoColourUnlessAsked) {
  SetResult set;
  set.problems.push_back(test::solve_yaml(kSeed001));
  const std::string plain = render_text(set, TextStyle{false});
  EXPECT_NE(plain.find("x + y − z = −6"), std::string::npos) << plain;
  EXPECT_NE(plain.find("9√3 ≈ 15.59"), std::string::npos) << plain;
  EXPECT_NE(plain.find("(√3/3, √3/3, −√3/3) ≈ (0.5774, 0.5774, −0.5774)"), std::string::npos)
      << plain;
  EXPECT_NE(plain.find("z = 8"), std::string::npos);
  EXPECT_EQ(plain.find("OpenGL"), std::string::npos)
      << "a convention is stated only where it matters";
  EXPECT_NE(plain.find("left-handed"), std::string::npos);
  EXPECT_EQ(plain.find("\033["), std::string::npos);
  EXPECT_NE(render_text(set, TextStyle{true}).find("\033["), std::string::npos);
}

TEST(Derivation, TextIndentsANotesFurtherLinesUnlessTheyBringTheirOwn) {
  Derivation d;
  d.note(Said::verbatim("Backend"), Said::verbatim("first line\nsecond line\n        a trace row"));
  EXPECT_EQ(render_steps_text(d.steps(), TextStyle{false}),
            "  • Backend\n      first line\n      second line\n        a trace row\n");
}

TEST(Derivation, MarkdownUsesLatex) {
  SetResult set;
  set.problems.push_back(test::solve_yaml(kSeed001));
  const std::string md = render_markdown(set);
  EXPECT_NE(md.find("\\frac{\\sqrt{3}}{3}"), std::string::npos) << md;
  EXPECT_NE(md.find("x + y - z = -6$$"), std::string::npos) << md;
  EXPECT_NE(md.find("| `z` | $8$ |"), std::string::npos) << md;
}

TEST(Derivation, JsonCarriesValueAndExact) {
  SetResult set;
  set.problems.push_back(test::solve_yaml(kSeed001));
  const auto j = render_json(set);
  const auto& a = j["problems"][0]["answers"];
  EXPECT_EQ(a["z"]["value"], 8);
  EXPECT_EQ(a["z"]["exact"], "8");
  EXPECT_DOUBLE_EQ(a["unit_normal"]["value"][0].get<double>(), 1 / std::sqrt(3.0));
  EXPECT_EQ(a["unit_normal"]["exact"][2], "-sqrt(3)/3");
  EXPECT_EQ(a["plane"]["value"], nlohmann::ordered_json({1, 1, -1, -6}));
  EXPECT_EQ(a["inside"]["value"], true);
  EXPECT_GT(j["problems"][0]["steps"].size(), 4u);
  EXPECT_TRUE(j["problems"][0]["steps"][0].contains("title"));
  EXPECT_TRUE(j["problems"][0]["steps"][0].contains("text"));
}

TEST(Derivation, ErrorsReplaceAnswersInJson) {
  SetResult set;
  set.problems.push_back(
      test::solve_yaml("problems:\n  - id: bad\n    kind: normal\n    given: {points: "
                       "[[0,0,0],[1,1,1],[2,2,2]]}\n"));
  const auto j = render_json(set);
  EXPECT_TRUE(j["problems"][0].contains("error"));
  EXPECT_FALSE(j["problems"][0].contains("answers"));
}

// A polygon that only meets the window's boundary leaves no area: the derivation says it
// touches, not that it lies outside; one wholly outside is said to be outside.
TEST(Derivation, APolygonThatOnlyTouchesTheWindowIsNotCalledOutside) {
  const auto last_note = [](const char* yaml) {
    const ProblemResult r = test::solve_yaml(yaml);
    EXPECT_FALSE(r.error) << yaml;
    EXPECT_EQ(r.answers.find("clipped")->shape, Value::Shape::Null);
    return r.derivation.steps().back().note.en();
  };
  for (const char* touching : {
           R"(problems:
  - {id: corner, kind: clip_polygon, given: {points: [[3, 3], [4, 3], [4, 4]], window: {xmin: 0, xmax: 3, ymin: 0, ymax: 3}}})",
           R"(problems:
  - {id: edge, kind: clip_polygon, given: {points: [[3, 1], [5, 1], [5, 2], [3, 2]], window: {xmin: 0, xmax: 3, ymin: 0, ymax: 3}}})"}) {
    const std::string note = last_note(touching);
    EXPECT_NE(note.find("only touches"), std::string::npos) << note;
    EXPECT_EQ(note.find("outside"), std::string::npos) << note;
  }
  const std::string outside = last_note(R"(problems:
  - {id: far, kind: clip_polygon, given: {points: [[5, 5], [6, 5], [6, 6]], window: {xmin: 0, xmax: 3, ymin: 0, ymax: 3}}})");
  EXPECT_NE(outside.find("lies outside the region"), std::string::npos) << outside;
}

}  // namespace
}  // namespace frustum
