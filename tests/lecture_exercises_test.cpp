// The bundled lecture exercises (problems/examples/lecture_exercises.yaml) give the lectures'
// answers: the Z-buffer's frame does not depend on the drawing order, and back-face culling
// alone suffices for the convex polyhedra (a), (c) and not for the concave (b), (d); depth sort
// fails for a long, thin polygon; seed 004's v′ = (P·V·M)·v is one problem.
#include <gtest/gtest.h>

#include <cmath>

#include "grader/grade.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const ProblemResult& find(const SetResult& set, const std::string& id) {
  for (const ProblemResult& p : set.problems)
    if (p.id == id) return p;
  throw std::runtime_error("no problem " + id);
}

// The grade of answer `name` of problem `id`, written as `value` (YAML), against `key`.
AnswerGrade graded(const ProblemSet& set, const SolvedSet& key, const std::string& id,
                   const std::string& name, const std::string& value) {
  const std::string answers =
      "student: s\nanswers:\n  " + id + ":\n    " + name + ": " + value + "\n";
  for (const ProblemGrade& p :
       grade(set, load_submission_from_string(answers, "a.yaml"), &key).problems)
    if (p.id == id)
      for (const AnswerGrade& a : p.answers)
        if (a.name == name) return a;
  ADD_FAILURE() << "no answer " << id << "." << name;
  return {};
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
        std::pair{"polyhedron-c-octahedron", true}, std::pair{"polyhedron-d-u-prism", false}}) {
    const ProblemResult& p = find(set, id);
    ASSERT_FALSE(p.error) << id;
    EXPECT_EQ(p.answers.find("convex")->flag, convex) << id;
    EXPECT_EQ(p.answers.find("backface_sufficient")->flag, convex) << id;
  }
}

// Seed 004's v′ = (P·V·M)·v as one problem: the object's vertex (1, 0, 0) rotated 90° about z
// and moved by its parent to (10, 1, 0), seen from (10, 0, 5): view (0, 1, −5), clip
// (0, 1, 305/99, 5), window (400, 360, 80/99) in the lecture's step order (M, V, P, then P·V·M).
TEST(Seed004, ModelViewProjectionChainIsOneProblem) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/004_placing_and_projecting.yaml"));
  const SetResult solved = solve_set(set, true, {});
  const ProblemResult& p = find(solved, "seed004-mvp-chain");
  ASSERT_FALSE(p.error);
  EXPECT_EQ(test::exact_text(p, "clip"), "0, 1, 305/99, 5");
  EXPECT_EQ(test::exact_text(p, "ndc"), "0, 1/5, 61/99");
  EXPECT_EQ(test::exact_text(p, "window"), "400, 360, 80/99");
  std::vector<std::string> titles;
  for (const Step& s : p.derivation.steps()) titles.push_back(s.title.en());
  const auto at = [&](const std::string& t) {
    return std::find(titles.begin(), titles.end(), t) - titles.begin();
  };
  EXPECT_LT(at("Model matrix (first step applied first)"), at("View matrix"));
  EXPECT_LT(at("View matrix"), at("Perspective projection matrix"));
  EXPECT_LT(at("Perspective projection matrix"), at("The whole chain at once"));
  EXPECT_LT(at("The whole chain at once"), static_cast<long>(titles.size()));
  EXPECT_EQ(p.derivation.steps()[at("The whole chain at once")].substitution.unicode,
            "P·V·M = [0, −1, 0, 0; 1, 0, 0, 0; 0, 0, −101/99, 305/99; 0, 0, −1, 5]");

  // The grader takes the window as a student writes it; a model multiplied in the order the
  // steps are applied (A₁·A₂) is named as that mistake.
  const SolvedSet key = solve_for_grading(set);
  const auto grade_window = [&](const std::string& window) {
    const std::string answers =
        "student: s\nanswers:\n  seed004-mvp-chain:\n    window: " + window + "\n";
    for (const ProblemGrade& g :
         grade(set, load_submission_from_string(answers, "a.yaml"), &key).problems)
      if (g.id == "seed004-mvp-chain")
        for (const AnswerGrade& a : g.answers)
          if (a.name == "window") return a;
    throw std::runtime_error("not graded");
  };
  EXPECT_EQ(grade_window("[400, 360, 0.8081]").verdict, Verdict::Correct);
  // A₁·A₂: (1, 0, 0) → (11, 0, 0) → (0, 11, 0); view (−10, 11, −5); NDC (−2, 11/5, 61/99).
  const AnswerGrade wrong = grade_window("[-400, 960, \"80/99\"]");
  EXPECT_EQ(wrong.verdict, Verdict::Incorrect);
  EXPECT_EQ(wrong.misconception.en(), "composition in the wrong order");
}

// v′ = (P·V·M)·v equals projecting the moved point M·v: every generated problem with a model,
// its points moved by the transform kind with the same steps, then projected without a model.
TEST(ProjectPoint, ModelMatrixEqualsProjectingTheMovedPoint) {
  const KindInfo* kind = builtin_kinds().find("project_point");
  ASSERT_TRUE(kind && kind->generate);
  Rng rng(11);
  int with_model = 0;
  for (int i = 0; i < 80; ++i) {
    const YAML::Node g = kind->generate(rng, GenerateOptions{});
    if (!g["model"]) continue;
    ++with_model;
    const ProblemResult moved =
        test::solve_yaml(test::one("transform", "{steps: " + emit_flow(g["model"]) + ", points: [" +
                                                    emit_flow(g["point"]) + "]}"),
                         false);
    YAML::Node plain = YAML::Clone(g);
    plain.remove("model");
    plain["point"] = YAML::Load("[" + test::exact_text(moved, "points") + "]");
    const ProblemResult chain = test::solve_yaml(test::one("project_point", emit_flow(g)), false);
    const ProblemResult direct =
        test::solve_yaml(test::one("project_point", emit_flow(plain)), false);
    ASSERT_FALSE(chain.error || direct.error) << emit_flow(g);
    for (const std::string name : {"clip", "ndc", "window"})
      EXPECT_EQ(test::exact_text(chain, name), test::exact_text(direct, name))
          << name << " of " << emit_flow(g);
    EXPECT_EQ(chain.answers.find("inside")->flag, direct.answers.find("inside")->flag)
        << emit_flow(g);
  }
  EXPECT_GT(with_model, 5);
}

// Seed 000: depth sort fails for a long, thin polygon. A's near end covers B, yet A's centroid
// (depth 11) is farther than B's (depth 8), so the centroid order draws A first and B over it.
TEST(LectureExercises, DepthSortFailsForALongThinPolygon) {
  const SetResult set = solve_set(
      load_problem_set(test::source_path("problems/examples/lecture_exercises.yaml")), false, {});
  const ProblemResult& p = find(set, "depth-sort-long-polygon");
  ASSERT_FALSE(p.error);
  EXPECT_EQ(test::exact_text(p, "depths"), "11, 8");
  EXPECT_EQ(p.answers.find("order")->shown().unicode, "0, 1");
  EXPECT_EQ(p.answers.find("conflicts")->words, std::vector<std::string>{"0-1"});
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
  const std::string note = solved.problems.at(0).derivation.steps().back().note.en();
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
  const AnswerGrade coordinates =
      grade(plain, load_submission_from_string(answers, "a.yaml"), &plain_key)
          .problems.at(0)
          .answers.at(0);
  EXPECT_NE(coordinates.verdict, Verdict::Correct);
  EXPECT_EQ(coordinates.misconception.en(), "z_min, z_max read as coordinates")
      << "the feedback says what the student did: +2/(f − n), not the planes' −n, −f";
}

// The lecture's 9.12 derives ortho(x_min, …, z_max) with z_min ↦ −1, z_max ↦ +1 (+2/(z_max −
// z_min) in the z row): the bundled problem declares that form, so the lecture's own matrix is
// the key, and glOrtho's form is named for what it is.
TEST(LectureExercises, TheLecturesOrthoMatrixIsTheKeyOfItsProblem) {
  const ProblemSet seed =
      load_problem_set(test::source_path("problems/seeds/000_projection_and_hidden_surfaces.yaml"));
  const SolvedSet key = solve_for_grading(seed);
  std::size_t index = 0;
  while (index < seed.problems.size() && seed.problems[index].id != "seed000-ortho-matrix") ++index;
  ASSERT_LT(index, seed.problems.size());
  const Value* m = key.results.at(index).answers.find("matrix");
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->numbers[10], 1.0 / 495, 1e-15);
  EXPECT_NEAR(m->numbers[11], -101.0 / 99, 1e-12);
  const auto grade_matrix = [&](const std::string& z_row) {
    return graded(seed, key, "seed000-ortho-matrix", "matrix",
                  "[[0.01, 0, 0, 0], [0, 0.01, 0, 0], " + z_row + ", [0, 0, 0, 1]]");
  };
  EXPECT_EQ(grade_matrix("[0, 0, \"1/495\", \"-101/99\"]").verdict, Verdict::Correct);
  const AnswerGrade gl = grade_matrix("[0, 0, \"-1/495\", \"-101/99\"]");
  EXPECT_NE(gl.verdict, Verdict::Correct);
  EXPECT_EQ(gl.misconception.en(), "near, far read as distances");
}

// θ = 90°, aspect 2, n = 1: perspective() gives t = 1, r = 2. The form −l = r = n·tan(θ/2),
// −b = t = n·(w/h)·tan(θ/2) gives r = 1, t = 2 — neither reading of θ — and is named; the
// derivation states both readings in neutral words.
TEST(LectureExercises, TheAspectRatioOnTheTopIsNamedAndExplainedTruly) {
  const std::string set =
      test::one("projection_matrix", "{perspective: {fovy: 90, aspect: 2, near: 1, far: 10}}");
  const ProblemSet course = load_problem_set_from_string(set, "a.yaml");
  const SolvedSet key = solve_for_grading(course);
  const auto grade_matrix = [&](const std::string& matrix) {
    return graded(course, key, "p", "matrix", matrix);
  };
  EXPECT_EQ(
      grade_matrix("[[0.5, 0, 0, 0], [0, 1, 0, 0], [0, 0, \"-11/9\", \"-20/9\"], [0, 0, -1, 0]]")
          .verdict,
      Verdict::Correct);
  const AnswerGrade on_top =
      grade_matrix("[[1, 0, 0, 0], [0, 0.5, 0, 0], [0, 0, \"-11/9\", \"-20/9\"], [0, 0, -1, 0]]");
  EXPECT_NE(on_top.verdict, Verdict::Correct);
  EXPECT_EQ(on_top.misconception.en(), "aspect ratio on the top");
  const ProblemResult solved = test::solve_yaml(set);
  std::string notes;
  for (const Step& s : solved.derivation.steps()) notes += s.note.en();
  EXPECT_NE(notes.find("t = r·h/w = n·(h/w)·tan(θ/2)"), std::string::npos) << notes;
  EXPECT_NE(notes.find("matches neither reading of θ"), std::string::npos) << notes;
  EXPECT_EQ(notes.find("reads θ as a horizontal angle"), std::string::npos)
      << "putting w/h on t does not read θ as horizontal";
  // With aspect 1 the form is the right one, so nothing is named after it.
  const ProblemSet square = load_problem_set_from_string(
      test::one("projection_matrix", "{perspective: {fovy: 90, aspect: 1, near: 1, far: 10}}"),
      "b.yaml");
  for (const Misconception& m :
       builtin_kinds().find("projection_matrix")->misconceptions(square.problems[0].given))
    EXPECT_NE(m.name.en(), "aspect ratio on the top");
}

// Processing's perspective() with no arguments: fovy = 60°, aspect = width/height, cameraZ =
// (height/2)/tan(30°), near = cameraZ/10, far = 10·cameraZ — for a 100×100 sketch n = 5√3,
// f = 500√3, so the matrix has √3 on the diagonal and −101/99, −1000√3/99 in the z row.
TEST(LectureExercises, PerspectiveWithNoArgumentsIsProcessingsDefault) {
  const ProblemResult plain =
      test::solve_yaml(test::one("projection_matrix", "{perspective: {}}", "{api: processing}"));
  ASSERT_FALSE(plain.error) << test::error_text(plain);
  const Value* m = plain.answers.find("matrix");
  ASSERT_TRUE(m);
  EXPECT_NEAR(m->numbers[0], std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(m->numbers[5], -std::sqrt(3.0), 1e-12) << "Processing negates the y row";
  EXPECT_NEAR(m->numbers[10], -101.0 / 99, 1e-12);
  EXPECT_NEAR(m->numbers[11], -1000 * std::sqrt(3.0) / 99, 1e-9);
  bool defaults_shown = false;
  for (const Step& s : plain.derivation.steps())
    defaults_shown = defaults_shown || s.title.en() == "perspective() with no arguments";
  EXPECT_TRUE(defaults_shown);
  const ProblemResult wide = test::solve_yaml(test::one(
      "projection_matrix", "{perspective: {width: 200, height: 100}}", "{api: processing}"));
  ASSERT_FALSE(wide.error) << test::error_text(wide);
  EXPECT_NEAR(wide.answers.find("matrix")->numbers[0], std::sqrt(3.0) / 2, 1e-12)
      << "aspect = width/height = 2 widens r";
  const ProblemSet partial = load_problem_set_from_string(
      test::one("projection_matrix", "{perspective: {width: 200, height: 100, fovy: 60}}"),
      "c.yaml");
  ASSERT_FALSE(partial.all_errors().empty());
  EXPECT_NE(partial.all_errors()[0].format().find("perspective.fovy"), std::string::npos)
      << partial.all_errors()[0].format();
}

// A course reading the field of view as horizontal declares `fov: horizontal` once: θ = 90°
// spans the width (r = 1, t = 1/2 for aspect 2), the derivation relates it to fovy =
// 2·atan(1/2), the grader accepts the course's matrix and names the vertical reading.
TEST(LectureExercises, CourseConventionForHorizontalFovIsHonoured) {
  const ProblemSet course =
      load_problem_set(test::source_path("problems/examples/course_fov_horizontal.yaml"));
  ASSERT_TRUE(course.all_errors().empty());
  const SetResult solved = solve_set(course, true, {});
  const ProblemResult& m = find(solved, "fov-horizontal-matrix");
  ASSERT_FALSE(m.error);
  EXPECT_EQ(test::exact_text(m, "matrix"),
            "1, 0, 0, 0, 0, 2, 0, 0, 0, 0, -11/9, -20/9, 0, 0, -1, 0");
  bool related = false;
  for (const Step& s : m.derivation.steps())
    related =
        related || (s.title.en() == "The same frustum from the vertical angle" &&
                    s.result.unicode.find("fovy = 2·arctan(1/2) ≈ 53.13°") != std::string::npos);
  EXPECT_TRUE(related) << "the derivation shows fovy = 2·arctan(tan(fovx/2)/aspect)";
  EXPECT_NE(m.derivation.steps().front().note.en().find("the field of view is horizontal"),
            std::string::npos);
  const ProblemResult& p = find(solved, "fov-horizontal-point");
  EXPECT_EQ(test::exact_text(p, "window"), "600, 300, 5/9");

  const SolvedSet key = solve_for_grading(course);
  const auto grade_matrix = [&](const std::string& matrix) {
    return graded(course, key, "fov-horizontal-matrix", "matrix", matrix);
  };
  EXPECT_EQ(
      grade_matrix("[[1, 0, 0, 0], [0, 2, 0, 0], [0, 0, \"-11/9\", \"-20/9\"], [0, 0, -1, 0]]")
          .verdict,
      Verdict::Correct);
  const AnswerGrade vertical =
      grade_matrix("[[0.5, 0, 0, 0], [0, 1, 0, 0], [0, 0, \"-11/9\", \"-20/9\"], [0, 0, -1, 0]]");
  EXPECT_NE(vertical.verdict, Verdict::Correct);
  EXPECT_EQ(vertical.misconception.en(), "fovy for fovx");

  // Without the declaration `fov` is perspective()'s vertical angle; `fovx` names its axis
  // anywhere.
  const ProblemResult plain = test::solve_yaml(
      test::one("projection_matrix", "{perspective: {fov: 90, aspect: 2, near: 1, far: 10}}"));
  EXPECT_EQ(test::exact_text(plain, "matrix"),
            "1/2, 0, 0, 0, 0, 1, 0, 0, 0, 0, -11/9, -20/9, 0, 0, -1, 0");
  const ProblemResult named = test::solve_yaml(
      test::one("projection_matrix", "{perspective: {fovx: 90, aspect: 2, near: 1, far: 10}}"));
  EXPECT_EQ(test::exact_text(named, "matrix"), test::exact_text(m, "matrix"));
  const ProblemSet both = load_problem_set_from_string(
      test::one("projection_matrix",
                "{perspective: {fovy: 90, fovx: 90, aspect: 2, near: 1, far: 10}}"),
      "b.yaml");
  EXPECT_FALSE(both.all_errors().empty());
}

}  // namespace
}  // namespace frustum
