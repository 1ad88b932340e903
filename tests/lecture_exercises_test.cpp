// The bundled lecture exercises (problems/examples/lecture_exercises.yaml) give the lectures'
// answers: the Z-buffer's frame does not depend on the drawing order, and back-face culling
// alone suffices for the convex polyhedra (a), (c) and not for the concave (b).
#include <gtest/gtest.h>

#include "grader/grade.hpp"
#include "solver/kinds/problem_set.hpp"
#include "solver/kinds/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const ProblemResult& find(const SetResult& set, const std::string& id) {
  for (const ProblemResult& p : set.problems)
    if (p.id == id) return p;
  throw std::runtime_error("no problem " + id);
}

TEST(LectureExercises, ZBufferFrameDoesNotDependOnTheDrawingOrder) {
  const SetResult lecture = solve_set(
      load_problem_set(test::source_path("problems/examples/lecture_exercises.yaml")), false, {});
  const SetResult pipeline =
      solve_set(load_problem_set(test::source_path("problems/examples/pipeline.yaml")), false, {});
  const Value* reversed = find(lecture, "zbuffer-order-321").answers.find("frame");
  const Value* in_order = find(pipeline, "zbuffer-three").answers.find("frame");
  ASSERT_TRUE(reversed && in_order);
  EXPECT_EQ(reversed->words, in_order->words);
  EXPECT_EQ(reversed->shown().unicode, "1133, 1222, 1222");
}

TEST(LectureExercises, BackFaceCullingSufficesForConvexPolyhedraOnly) {
  const SetResult set = solve_set(
      load_problem_set(test::source_path("problems/examples/lecture_exercises.yaml")), false, {});
  for (const auto& [id, convex] :
       {std::pair{"polyhedron-a-cube", true}, std::pair{"polyhedron-b-l-prism", false},
        std::pair{"polyhedron-c-octahedron", true}}) {
    const ProblemResult& p = find(set, id);
    ASSERT_FALSE(p.error) << id;
    EXPECT_EQ(p.answers.find("convex")->flag, convex) << id;
    EXPECT_EQ(p.answers.find("backface_sufficient")->flag, convex) << id;
  }
}

// A course declaring `z_planes: coordinates` once gets the orthographic matrix in its own form
// (+2/(z_max − z_min) = +1/495) and the grader accepts that form; without the declaration the
// same numbers are glOrtho's distances (−1/495), and the course's form is wrong there.
TEST(LectureExercises, CourseConventionForOrthoZPlanesIsHonoured) {
  const ProblemSet course =
      load_problem_set(test::source_path("problems/examples/course_conventions.yaml"));
  const SetResult solved = solve_set(course, true, {});
  const Value* m = solved.problems.at(0).answers.find("matrix");
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->numbers[10], 1.0 / 495, 1e-15);
  EXPECT_NEAR(m->numbers[11], -1010.0 / 990, 1e-12);
  const std::string note = solved.problems.at(0).derivation.steps().back().note;
  EXPECT_NE(note.find("−2/(f − n)"), std::string::npos)
      << "the derivation relates the two readings";
  const std::string answers =
      "student: s\nanswers:\n  ortho-z-coordinates:\n    matrix: [[0.01, 0, 0, 0], [0, 0.01, 0, "
      "0], "
      "[0, 0, \"1/495\", \"-101/99\"], [0, 0, 0, 1]]\n";
  const SolvedSet key = solve_for_grading(course);
  EXPECT_EQ(grade(course, load_submission_from_string(answers, "a.yaml"), &key)
                .problems.at(0)
                .answers.at(0)
                .verdict,
            Verdict::Correct);
  const std::string yaml =
      "conventions: {api: opengl}\nproblems:\n  - id: ortho-z-coordinates\n    kind: "
      "projection_matrix\n    given:\n      ortho: {left: -100, right: 100, bottom: -100, top: "
      "100, near: 10, far: 1000}\n";
  const ProblemSet plain = load_problem_set_from_string(yaml, "plain.yaml");
  const SolvedSet plain_key = solve_for_grading(plain);
  EXPECT_NEAR(plain_key.results.at(0).answers.find("matrix")->numbers[10], -1.0 / 495, 1e-15);
  EXPECT_NE(grade(plain, load_submission_from_string(answers, "a.yaml"), &plain_key)
                .problems.at(0)
                .answers.at(0)
                .verdict,
            Verdict::Correct);
}

}  // namespace
}  // namespace frustum
