// The barycentric kind: z = Σ λᵢ zᵢ is the plane method's z and `inside` is depth_at_pixel's
// decision, over many generated triangles and pixels; and its answers grade.
#include <fmt/format.h>

#include <random>

#include "report/feedback.hpp"
#include "report/report.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::error_text;
using test::exact_text;

TEST(Barycentric, SeedTriangle) {
  const ProblemResult r = test::solve_yaml(
      test::one("barycentric", "{triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "edges"), "3, 3, 3");
  EXPECT_EQ(exact_text(r, "total"), "9");
  EXPECT_EQ(exact_text(r, "lambda"), "1/3, 1/3, 1/3");
  EXPECT_EQ(exact_text(r, "z"), "8");
  EXPECT_TRUE(r.answers.find("inside")->flag);
}

TEST(Barycentric, AgreesWithThePlaneMethod) {
  std::mt19937 gen(17);
  std::uniform_int_distribution<int> xy(-6, 10), depth(1, 20);
  int compared = 0;
  for (int i = 0; i < 150; ++i) {
    std::string triangle = "[";
    for (int v = 0; v < 3; ++v)
      triangle += fmt::format("{}[{}, {}, {}]", v ? ", " : "", xy(gen), xy(gen), depth(gen));
    triangle += "]";
    const std::string given =
        fmt::format("{{triangle: {}, pixel: [{}, {}]}}", triangle, xy(gen), xy(gen));
    const ProblemResult b = test::solve_yaml(test::one("barycentric", given), false);
    const ProblemResult p = test::solve_yaml(test::one("depth_at_pixel", given), false);
    ASSERT_EQ(bool(b.error), bool(p.error)) << given << error_text(b) << error_text(p);
    if (b.error) continue;
    EXPECT_EQ(exact_text(b, "z"), exact_text(p, "z")) << given;
    EXPECT_EQ(b.answers.find("inside")->flag, p.answers.find("inside")->flag) << given;
    ++compared;
  }
  EXPECT_GT(compared, 100);
}

TEST(Barycentric, CollinearTriangleIsADomainError) {
  const ProblemResult r = test::solve_yaml(
      test::one("barycentric", "{triangle: [[0, 0, 1], [1, 1, 2], [2, 2, 3]], pixel: [1, 0]}"));
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "problems[0].given.triangle");
}

TEST(Barycentric, GradesACorrectAndAWrongAnswer) {
  const char* set =
      "problems:\n  - id: b\n    kind: barycentric\n    given: {triangle: [[0, 0, 6], [3, 0, "
      "9], [0, 3, 9]], pixel: [1, 1]}\n";
  const GradeReport right =
      grade(load_problem_set_from_string(set, "set.yaml"),
            load_submission_from_string("answers:\n  b: {edges: [3, 3, 3], total: 9, lambda: "
                                        "[\"1/3\", 0.33333, \"1/3\"], inside: true, z: 8}\n",
                                        "answers.yaml"));
  EXPECT_TRUE(right.errors.empty());
  EXPECT_DOUBLE_EQ(right.score, right.max_score);
  const GradeReport wrong =
      grade(load_problem_set_from_string(set, "set.yaml"),
            load_submission_from_string("answers:\n  b: {lambda: [0.5, 0.25, 0.25], z: 7}\n",
                                        "answers.yaml"));
  EXPECT_DOUBLE_EQ(wrong.score, 0);
  for (const ProblemGrade& p : wrong.problems)
    for (const AnswerGrade& a : p.answers) {
      if (a.name == "lambda" || a.name == "z") {
        EXPECT_EQ(a.verdict, Verdict::Incorrect) << a.name;
      }
    }
}

}  // namespace
}  // namespace frustum
