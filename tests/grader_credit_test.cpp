// The grader's judgement: tolerance modes and windows, weights and partial credit, error carried
// forward (with its guard against trivial earlier answers), named misconceptions, and the
// answer-kind equivalences.
#include <fmt/format.h>

#include <algorithm>

#include "report/report.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const char* kDepth = R"Y(problems:
  - id: z
    kind: depth_at_pixel
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
    ask: [normal, plane, z]
)Y";

GradeReport grade_text(const std::string& set, const std::string& answers) {
  return grade(load_problem_set_from_string(set, "set.yaml"),
               load_submission_from_string(answers, "answers.yaml"));
}

const AnswerGrade& answer(const GradeReport& r, const std::string& name,
                          const std::string& id = "z") {
  for (const ProblemGrade& p : r.problems)
    if (p.id == id)
      for (const AnswerGrade& a : p.answers)
        if (a.name == name) return a;
  ADD_FAILURE() << "no answer " << id << "." << name;
  static const AnswerGrade none;
  return none;
}

TEST(GraderCredit, ErrorCarriedForwardFromAWrongNormal) {
  // Normal (1, 2, −1) is wrong; the plane through A with it is x + 2y − z = −6 and its z at
  // pixel (1, 1) is 9: both follow correctly from the student's own normal.
  const GradeReport r =
      grade_text(kDepth, "answers:\n  z: {normal: [1, 2, -1], plane: \"x + 2y - z = -6\", z: 9}\n");
  EXPECT_EQ(answer(r, "normal").verdict, Verdict::Incorrect);
  const AnswerGrade& plane = answer(r, "plane");
  EXPECT_EQ(plane.verdict, Verdict::Partial);
  EXPECT_TRUE(plane.carried_forward);
  EXPECT_DOUBLE_EQ(plane.score, kEcfCreditDefault);
  EXPECT_NE(plane.feedback.en().find("earlier"), std::string::npos) << plane.feedback;
  const AnswerGrade& z = answer(r, "z");
  EXPECT_EQ(z.verdict, Verdict::Partial);
  EXPECT_TRUE(z.carried_forward);
  EXPECT_DOUBLE_EQ(r.score, 2 * kEcfCreditDefault);
  // A z that does not follow from the student's plane earns nothing.
  const GradeReport r2 = grade_text(
      kDepth, "answers:\n  z: {normal: [1, 2, -1], plane: \"x + 2y - z = -6\", z: 10}\n");
  EXPECT_EQ(answer(r2, "z").verdict, Verdict::Incorrect);
  EXPECT_FALSE(answer(r2, "z").carried_forward);
}

TEST(GraderCredit, EcfFractionIsConfigurableAndCanBeTurnedOff) {
  const std::string answers =
      "answers:\n  z: {normal: [1, 2, -1], plane: \"x + 2y - z = -6\", z: 9}\n";
  const GradeReport quarter = grade_text(std::string("grading: {ecf: 0.25}\n") + kDepth, answers);
  EXPECT_DOUBLE_EQ(answer(quarter, "plane").score, 0.25);
  const GradeReport off = grade_text(std::string("grading: {ecf: 0}\n") + kDepth, answers);
  EXPECT_EQ(answer(off, "plane").verdict, Verdict::Incorrect);
  EXPECT_DOUBLE_EQ(off.score, 0);
}

TEST(GraderCredit, ATrivialEarlierAnswerEarnsNothingForward) {
  // A zero normal makes "every plane" follow; no credit is carried from it.
  const GradeReport r =
      grade_text(kDepth, "answers:\n  z: {normal: [0, 0, 0], plane: [0, 0, 0, 0], z: 0}\n");
  EXPECT_EQ(answer(r, "plane").verdict, Verdict::Incorrect);
  EXPECT_EQ(answer(r, "z").verdict, Verdict::Incorrect);
  EXPECT_DOUBLE_EQ(r.score, 0);
}

TEST(GraderCredit, ReversedCrossProductIsNamedWithItsStep) {
  // seed 001: AB × AC instead of AC × AB, the projection space being left-handed.
  const GradeReport r = grade_text(kDepth, "answers:\n  z: {normal: [-1, -1, 1]}\n");
  const AnswerGrade& n = answer(r, "normal");
  EXPECT_EQ(n.verdict, Verdict::Incorrect);
  EXPECT_EQ(n.misconception.en(), "reversed cross product");
  EXPECT_EQ(n.wrong_step.en(), "Normal");
  EXPECT_NE(n.feedback.en().find("left-handed"), std::string::npos) << n.feedback;
  const std::string json = render_grade_json(r).dump();
  EXPECT_NE(json.find("\"misconception\":\"reversed cross product\""), std::string::npos);
}

TEST(GraderCredit, ProjectionMistakesAreDiagnosed) {
  const std::string set = R"Y(problems:
  - id: pp
    kind: project_point
    given:
      point: [1, 2, -5]
      perspective: {fovy: 60, aspect: 1, near: 1, far: 10}
      viewport: {width: 100, height: 100}
    ask: [clip, ndc, window]
)Y";
  const ProblemSet s = load_problem_set_from_string(set, "set.yaml");
  ASSERT_TRUE(s.errors.empty());
  const ProblemResult right = solve_problem(s.problems[0], s.file, false);
  const KindInfo* kind = builtin_kinds().find("project_point");
  ASSERT_NE(kind, nullptr);
  // Each named mistake's answers (from the kind itself), written by a student, are diagnosed by
  // name.
  const std::vector<Misconception> mistakes = kind->misconceptions(s.problems[0].given);
  std::vector<std::string> names;
  for (const Misconception& m : mistakes) names.push_back(m.name.en());
  for (const char* expected :
       {"missing perspective divide", "degrees taken as radians", "fovx for fovy", "near/far sign"})
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  for (const Misconception& m : mistakes) {
    const Value* ndc = m.answers.find("ndc");
    if (!ndc || ndc->numbers.size() != 3) continue;
    const std::string answers =
        fmt::format("answers:\n  pp: {{ndc: [{:.17g}, {:.17g}, {:.17g}]}}\n", ndc->numbers[0],
                    ndc->numbers[1], ndc->numbers[2]);
    const GradeReport r = grade_text(set, answers);
    const AnswerGrade& a = answer(r, "ndc", "pp");
    if (a.verdict == Verdict::Correct) continue;  // a mistake that happens to give the right NDC
    EXPECT_EQ(a.misconception, m.name) << answers;
    EXPECT_FALSE(a.wrong_step.empty());
  }
  EXPECT_TRUE(right.answers.find("ndc"));
}

TEST(GraderCredit, CompositionInTheWrongOrder) {
  const std::string set = R"Y(problems:
  - id: t
    kind: transform
    given: {dim: 2, steps: [{translate: [2, 0]}, {rotate: 90}], points: [[1, 0]]}
    ask: [matrix]
)Y";
  // Translate then rotate: M = R·T. A₁·A₂ = T·R is the wrong order.
  const GradeReport r =
      grade_text(set, "answers:\n  t: {matrix: [[0, -1, 2], [1, 0, 0], [0, 0, 1]]}\n");
  EXPECT_EQ(answer(r, "matrix", "t").misconception.en(), "composition in the wrong order");
  const GradeReport ok =
      grade_text(set, "answers:\n  t: {matrix: [[0, -1, 0], [1, 0, 2], [0, 0, 1]]}\n");
  EXPECT_EQ(answer(ok, "matrix", "t").verdict, Verdict::Correct);
}

TEST(GraderCredit, ToleranceModesAndTheirWindows) {
  const std::string base = R"Y(problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [1, 1, 0]}
    ask: [angle]
)Y";  // angle = 45°
  const auto verdict = [&](const std::string& tolerance, const std::string& got) {
    const GradeReport r = grade_text(tolerance + base, "answers:\n  v: {angle: " + got + "}\n");
    return answer(r, "angle", "v").verdict;
  };
  EXPECT_EQ(verdict("", "45.04"), Verdict::Correct);  // rel 1e-3: window 0.045
  EXPECT_EQ(verdict("", "45.05"), Verdict::Incorrect);
  EXPECT_EQ(verdict("tolerance: {rel: 0, abs: 0.5}\n", "45.4"), Verdict::Correct);
  EXPECT_EQ(verdict("tolerance: {rel: 0, abs: 0.5}\n", "45.6"), Verdict::Incorrect);
  EXPECT_EQ(verdict("tolerance: {sigfigs: 2}\n", "45.4"),
            Verdict::Correct);  // half a unit of the 2nd digit
  EXPECT_EQ(verdict("tolerance: {sigfigs: 2}\n", "45.6"), Verdict::Incorrect);
  EXPECT_EQ(verdict("tolerance: {decimals: 1}\n", "45.04"), Verdict::Correct);
  EXPECT_EQ(verdict("tolerance: {decimals: 1}\n", "45.06"), Verdict::Incorrect);
  // Per-answer tolerance overrides the set's.
  const std::string per = R"Y(problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [1, 1, 0]}
    ask: [angle]
    tolerance: {answers: {angle: {abs: 1, rel: 0}}}
)Y";
  const GradeReport r = grade_text(per, "answers:\n  v: {angle: 45.9}\n");
  EXPECT_EQ(answer(r, "angle", "v").verdict, Verdict::Correct);
  // Exact answers are compared exactly: π/4 rad is not 45 in a degrees set.
  EXPECT_EQ(verdict("", "\"pi/4\""), Verdict::Incorrect);
  EXPECT_EQ(verdict("", "\"90/2\""), Verdict::Correct);
}

TEST(GraderCredit, WeightsAndPartialCreditPerComponent) {
  const std::string set = R"Y(problems:
  - id: v
    kind: vectors
    given: {a: [1, 2, 3], b: [4, 5, 6]}
    ask: [dot, cross]
    points: {dot: 1, cross: 3}
)Y";  // a × b = (−3, 6, −3), a·b = 32
  // Component credit is asked for (all-or-nothing is the default, as in WeBWorK).
  const GradeReport r = grade_text("grading: {partial: true}\n" + set,
                                   "answers:\n  v: {dot: 32, cross: [-3, 6, 3]}\n");
  EXPECT_DOUBLE_EQ(answer(r, "dot", "v").score, 1);
  EXPECT_EQ(answer(r, "cross", "v").verdict, Verdict::Partial);
  EXPECT_DOUBLE_EQ(answer(r, "cross", "v").score, 2);  // 2 of 3 components, of 3 points
  EXPECT_DOUBLE_EQ(r.max_score, 4);
  for (const std::string& setting : {std::string(""), std::string("grading: {partial: false}\n")}) {
    const GradeReport all_or_nothing =
        grade_text(setting + set, "answers:\n  v: {cross: [-3, 6, 3]}\n");
    EXPECT_EQ(answer(all_or_nothing, "cross", "v").verdict, Verdict::Incorrect) << setting;
    EXPECT_DOUBLE_EQ(all_or_nothing.score, 0);
  }
}

TEST(GraderCredit, PlanesUpToScaleAndNormalsUpToPositiveScale) {
  const auto verdicts = [&](const std::string& normal, const std::string& plane) {
    const GradeReport r =
        grade_text(kDepth, "answers:\n  z: {normal: " + normal + ", plane: " + plane + "}\n");
    return std::pair{answer(r, "normal").verdict, answer(r, "plane").verdict};
  };
  EXPECT_EQ(verdicts("[2, 2, -2]", "\"-3x - 3y + 3z = 18\""),
            std::pair(Verdict::Correct, Verdict::Correct));
  EXPECT_EQ(verdicts("[\"√3/3\", \"√3/3\", \"-√3/3\"]", "[0.5, 0.5, -0.5, -3]"),
            std::pair(Verdict::Correct, Verdict::Correct));
  EXPECT_EQ(verdicts("[-2, -2, 2]", "\"x + y - z = 6\"").second, Verdict::Incorrect);
}

TEST(GraderCredit, HostileAnswersAreUnparseableAtOnce) {
  const std::vector<std::string> hostile = {
      "\"2^2^2^2^2^2^2^2^2\"",
      "\"" + std::string(20000, '(') + "1" + std::string(20000, ')') + "\"", "\"10^(10^9)\"",
      "\"1/0\"", "\"x +\""};
  for (const std::string& got : hostile) {
    const GradeReport r = grade_text(kDepth, "answers:\n  z: {z: " + got + "}\n");
    EXPECT_EQ(answer(r, "z").verdict, Verdict::Unparseable) << got.substr(0, 40);
    EXPECT_FALSE(answer(r, "z").feedback.empty());
  }
}

}  // namespace
}  // namespace frustum
