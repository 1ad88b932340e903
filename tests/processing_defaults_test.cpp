// The processing_defaults kind (solver/kinds/processing_defaults.cpp): Processing's camera() and
// perspective() with no arguments, worked by hand for a 640 × 360 sketch, and the same matrices
// as the look_at kind and projection_matrix's `perspective: {width, height}` give, in every API
// and for many sketch sizes; its named mistake and the credit carried from a wrong cameraZ.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "grader/grade.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::exact_text;
using test::one;
using test::solve_yaml;

TEST(ProcessingDefaults, ASketchOf640By360WorkedByHand) {
  const ProblemResult r =
      solve_yaml(one("processing_defaults", "{width: 640, height: 360}", "{api: processing}"));
  ASSERT_FALSE(r.error) << test::error_text(r);
  // cameraZ = 180/tan(30°) = 180√3; near and far a tenth and ten times that.
  EXPECT_EQ(exact_text(r, "camera_z"), "180*sqrt(3)");
  EXPECT_EQ(exact_text(r, "eye"), "320, 180, 180*sqrt(3)");
  EXPECT_EQ(exact_text(r, "fovy"), "60");
  EXPECT_EQ(exact_text(r, "near"), "18*sqrt(3)");
  EXPECT_EQ(exact_text(r, "far"), "1800*sqrt(3)");
  // The view matrix moves the eye to the origin: its translation column is −eye (the camera's
  // axes are the world's).
  EXPECT_EQ(exact_text(r, "view"),
            "1, 0, 0, -320, 0, 1, 0, -180, 0, 0, 1, -180*sqrt(3), 0, 0, 0, 1");
  // Every answer is yielded by a step of the derivation.
  for (const char* answer : {"camera_z", "eye", "view", "fovy", "near", "far", "projection"})
    EXPECT_TRUE(std::any_of(r.derivation.steps().begin(), r.derivation.steps().end(),
                            [&](const Step& s) {
                              return std::find(s.answers.begin(), s.answers.end(), answer) !=
                                     s.answers.end();
                            }))
        << answer;
}

// The same camera through look_at and the same frustum through projection_matrix's Processing
// defaults, for sketch sizes in use and every API and angle unit.
TEST(ProcessingDefaults, MatricesAreLookAtsAndProjectionMatrixsDefaults) {
  const std::vector<std::pair<int, int>> sizes = {{100, 100}, {640, 360},  {640, 480},
                                                  {800, 600}, {1280, 720}, {37, 91}};
  // A left-handed course under OpenGL's or Processing's matrices too (DirectX is left-handed).
  for (const char* api : {"opengl", "processing", "directx", "opengl, handedness: left",
                          "processing, handedness: left"})
    for (const char* angles : {"degrees", "radians"})
      for (const auto& [w, h] : sizes) {
        const std::string conventions = fmt::format("{{api: {}, angles: {}}}", api, angles);
        const ProblemResult r = solve_yaml(one(
            "processing_defaults", fmt::format("{{width: {}, height: {}}}", w, h), conventions));
        ASSERT_FALSE(r.error) << test::error_text(r);
        const std::string eye = fmt::format("[{}, {}, \"{}*sqrt(3)/2\"]", w / 2.0, h / 2.0, h);
        const ProblemResult view = solve_yaml(one(
            "look_at",
            fmt::format("{{eye: {}, center: [{}, {}, 0], up: [0, 1, 0]}}", eye, w / 2.0, h / 2.0),
            conventions));
        const ProblemResult projection = solve_yaml(
            one("projection_matrix",
                fmt::format("{{perspective: {{width: {}, height: {}}}}}", w, h), conventions));
        ASSERT_FALSE(view.error || projection.error) << api << " " << w << "×" << h;
        EXPECT_EQ(exact_text(r, "view"), exact_text(view, "matrix")) << api << " " << w << "×" << h;
        EXPECT_EQ(exact_text(r, "projection"), exact_text(projection, "matrix"))
            << api << " " << angles << " " << w << "×" << h;
        EXPECT_EQ(exact_text(r, "fovy"),
                  std::string(angles) == std::string("degrees") ? "60" : "pi/3");
      }
}

TEST(ProcessingDefaults, ASketchOfNoSizeIsRefusedAtItsField) {
  const ProblemResult r =
      solve_yaml(one("processing_defaults", "{width: 640, height: 0}", "{api: processing}"));
  ASSERT_TRUE(r.error);
  EXPECT_NE(test::error_text(r).find("height"), std::string::npos) << test::error_text(r);
}

// tan(60°) for tan(30°) is named at the camera's step; a wrong cameraZ earns nothing itself, but
// near and far computed from it carry credit.
TEST(ProcessingDefaults, TheFullAngleMistakeIsNamedAndAWrongCameraZCarriesForward) {
  const ProblemSet set = load_problem_set_from_string(
      one("processing_defaults", "{width: 640, height: 360}", "{api: processing}"), "set.yaml");
  const auto graded = [&](const std::string& answers, const std::string& name) {
    const GradeReport g = grade(
        set,
        load_submission_from_string("student: s1\nanswers:\n  p: " + answers + "\n", "a.yaml"));
    EXPECT_EQ(g.problems.size(), 1u);
    for (const AnswerGrade& a : g.problems.at(0).answers)
      if (a.name == name) return a;
    ADD_FAILURE() << name << " not graded";
    return AnswerGrade{};
  };
  const AnswerGrade full = graded("{camera_z: \"60*sqrt(3)\"}", "camera_z");
  EXPECT_EQ(full.verdict, Verdict::Incorrect);
  EXPECT_EQ(full.score, 0);
  EXPECT_EQ(full.misconception.en(), "tan(fovy) for tan(fovy/2)");
  EXPECT_EQ(full.wrong_step.en(), "Processing's default camera");
  const std::string wrong = "{camera_z: 300, near: 30, far: 3000}";
  EXPECT_EQ(graded(wrong, "camera_z").score, 0);
  for (const char* name : {"near", "far"}) {
    const AnswerGrade a = graded(wrong, name);
    EXPECT_TRUE(a.carried_forward) << name;
    EXPECT_GT(a.score, 0) << name;
  }
}

}  // namespace
}  // namespace frustum
