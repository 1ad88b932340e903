// The bundled lecture exercises (problems/examples/lecture_exercises.yaml) give the lectures'
// answers: the Z-buffer's frame does not depend on the drawing order, and back-face culling
// alone suffices for the convex polyhedra (a), (c) and not for the concave (b).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace frustum
