// What students read is checked before they read it: a problem's text names only values of its
// given, and a variant keeps its exercise's structure (the same steps and kinds of givens).
#include "solver/problem/variants.hpp"

#include "solver/problem/generate.hpp"
#include "typeset_corpus.hpp"

namespace frustum {
namespace {

const char* kPlaceholders = R"(problems:
  - id: ok
    kind: look_at
    text: "The eye at {eye} looks at {center}; its x is {eye.0}."
    given: {eye: [0, 0, 5], center: [0, 0, 0], up: [0, 1, 0]}
  - id: unknown
    kind: project_point
    text: "fovy = {perspective.fov}"
    given: {point: [0, 0, -5], perspective: {fovy: 90, aspect: 1, near: 1, far: 10}, viewport: {width: 200, height: 200}}
  - id: mapping
    kind: clip_line
    text: "Clip against {window}."
    given: {p: [-1, 1], q: [5, 2], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}
  - id: other-mapping
    kind: project_point
    text: "Project with {perspective}."
    given: {point: [0, 0, -5], perspective: {fovy: 90, aspect: 1, near: 1, far: 10}, viewport: {width: 200, height: 200}}
  - id: volume
    kind: clip_line
    text: "Clip against {volume}."
    given: {p: [-1, 1, 0], q: [5, 2, 0], volume: {xmin: 0, xmax: 4, ymin: 0, ymax: 3, zmin: -1, zmax: "1/2"}}
)";

// A window or box mapping reads as on paper, [xmin, xmax] × [ymin, ymax]; any other mapping is
// refused.
TEST(Placeholders, FilledAsStudentsReadThemUnknownAndMappingsRefused) {
  const SetResult r = solve_set(load_problem_set_from_string(kPlaceholders, "set.yaml"), true);
  ASSERT_EQ(r.problems.size(), 5u);
  EXPECT_FALSE(r.problems[0].error) << test::error_text(r.problems[0]);
  EXPECT_EQ(r.problems[0].text.text, "The eye at (0, 0, 5) looks at (0, 0, 0); its x is 0.");
  ASSERT_TRUE(r.problems[1].error);
  EXPECT_NE(r.problems[1].error->format().find(
                "problems[1].text: the placeholder {perspective.fov} names no field"),
            std::string::npos)
      << r.problems[1].error->format();
  EXPECT_FALSE(r.problems[2].error) << test::error_text(r.problems[2]);
  EXPECT_EQ(r.problems[2].text.text, "Clip against [0, 4] × [0, 3].");
  ASSERT_TRUE(r.problems[3].error);
  EXPECT_NE(r.problems[3].error->format().find("{perspective} is a mapping"), std::string::npos)
      << r.problems[3].error->format();
  EXPECT_FALSE(r.problems[4].error) << test::error_text(r.problems[4]);
  EXPECT_EQ(r.problems[4].text.text, "Clip against [0, 4] × [0, 3] × [-1, 1/2].");
}

TEST(VariantShape, ShapeIgnoresValuesButNotStructure) {
  // The text itself: keys sorted, every item followed by a comma, numbers as #, words quoted.
  EXPECT_EQ(given_shape(YAML::Load("{b: [1, x, sqrt(2)], a: {c: ~}}")), "{a:{c:~,},b:[#,'x',#,],}");
  EXPECT_EQ(given_shape(YAML::Load("{dim: 2, steps: [{rotate: 90}], points: [[1, 0]]}")),
            given_shape(YAML::Load("{points: [[3, -2]], steps: [{rotate: 45}], dim: 2}")));
  EXPECT_NE(given_shape(YAML::Load("{steps: [{rotate: 90}]}")),
            given_shape(YAML::Load("{steps: [{scale: 2}]}")));
  EXPECT_NE(given_shape(YAML::Load("{solid: cube}")),
            given_shape(YAML::Load("{solid: octahedron}")));
}

// Every bundled problem varied by default keeps its structure: the given has the same shape
// (keys, list lengths, step types, words) and only its numbers are drawn again.
TEST(VariantShape, EveryBundledProblemKeepsItsStructure) {
  int varied = 0;
  for (const std::string& file : test::bundled_sets()) {
    if (file.find("/hard/") != std::string::npos) continue;  // near-degenerate on purpose
    const ProblemSet set = load_problem_set(file);
    for (const ProblemSet& v : variants_from_seed(set, 7, 2, true))
      for (std::size_t i = 0; i < v.problems.size(); ++i) {
        const ProblemSpec& base = set.problems[i];
        const ProblemSpec& drawn = v.problems[i];
        if (base.error || !base.given_node.IsMap() ||
            (base.vary.IsDefined() && !base.vary.IsNull()))
          continue;
        EXPECT_FALSE(drawn.error) << file << " " << base.id << ": " << drawn.error->format();
        if (!drawn.error) {
          EXPECT_EQ(given_shape(drawn.given_node), given_shape(base.given_node))
              << file << " " << base.id;
        }
        ++varied;
      }
  }
  EXPECT_GT(varied, 40);
}

// Variants keep their exercise's character: a segment that is clipped (neither accepted nor
// rejected whole, not cut to a point) stays one, a segment rejected whole stays rejected, a
// polygon clipped away stays clipped away (though the kind refuses such draws otherwise), and
// a pixel inside its triangle stays inside.
TEST(VariantShape, VariantsKeepTheWrittenExercisesCharacter) {
  const ProblemSet set = load_problem_set_from_string(R"yaml(problems:
  - id: clips
    kind: clip_line
    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}
  - id: rejected
    kind: clip_line
    given: {p: [5, 5], q: [7, 6], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}
  - id: gone
    kind: clip_polygon
    given: {points: [[5, 5], [8, 5], [5, 8]], window: {xmin: 0, xmax: 1, ymin: 0, ymax: 1}}
  - id: inside
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
)yaml",
                                                      "character.yaml");
  const std::vector<ProblemSet> variants = variants_from_seed(set, 11, 25, true);
  ASSERT_EQ(variants.size(), 25u);
  for (const ProblemSet& v : variants) {
    const SetResult r = solve_set(v, false);
    for (const ProblemResult& p : r.problems) ASSERT_FALSE(p.error) << test::error_text(p);
    const auto flag = [&](int i, const char* name) {
      return r.problems[i].answers.find(name)->flag;
    };
    const Value* clipped = r.problems[0].answers.find("clipped");
    EXPECT_FALSE(flag(0, "accept"));
    EXPECT_FALSE(flag(0, "reject"));
    ASSERT_TRUE(clipped && clipped->shape == Value::Shape::Matrix && clipped->rows == 2);
    EXPECT_FALSE(clipped->numbers[0] == clipped->numbers[2] &&
                 clipped->numbers[1] == clipped->numbers[3])
        << "a segment clipped to one point";
    EXPECT_TRUE(flag(1, "reject"));
    EXPECT_EQ(r.problems[2].answers.find("clipped")->shape, Value::Shape::Null);
    EXPECT_TRUE(flag(3, "inside"));
  }
}

}  // namespace
}  // namespace frustum
