// Grading: verdicts, equivalences, unparseable and missing answers, and the JSON report.
#include <fmt/format.h>

#include "report/feedback.hpp"
#include "report/report.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const char* kSet = R"Y(problems:
  - id: zbuf-pixel
    kind: depth_at_pixel
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
    ask: [normal, unit_normal, plane, z]
    points: 4
  - id: bf
    kind: backface
    given: {points: [[1,0,0],[1,1,1],[0,1,2]], eye: [0,1,0]}
    ask: [df, facing]
)Y";

GradeReport grade_answers(const std::string& answers) {
  return grade(load_problem_set_from_string(kSet, "set.yaml"),
               load_submission_from_string(answers, "answers.yaml"));
}

const AnswerGrade& answer(const GradeReport& r, const std::string& id, const std::string& name) {
  for (const ProblemGrade& p : r.problems)
    if (p.id == id)
      for (const AnswerGrade& a : p.answers)
        if (a.name == name) return a;
  throw std::runtime_error("no answer " + id + "." + name);
}

// Scores as a teacher writes them: whole marks straight from the integer, others to two
// decimals with trailing zeros dropped, the same text either way.
TEST(Grader, ScoreTextIsTwoDecimalsWithoutTrailingZeros) {
  for (const double v : {0.0, -0.0, 1.0, 20.0, -3.0, 60.0, 123456789012.0})
    EXPECT_EQ(score_text(v), fmt::format("{:.0f}", v == 0 ? 0.0 : v)) << v;
  EXPECT_EQ(score_text(0.5), "0.5");
  EXPECT_EQ(score_text(2.0 / 3.0), "0.67");
  EXPECT_EQ(score_text(21.333333), "21.33");
  EXPECT_EQ(score_text(0.1 + 0.2), "0.3");
  EXPECT_EQ(score_text(1.999), "2");
  EXPECT_EQ(score_text(-0.001), "0");
  EXPECT_EQ(score_text(1e20), "100000000000000000000");
}

TEST(Grader, EquivalentFormsAreCorrect) {
  const GradeReport r = grade_answers(R"Y(student: s1
answers:
  zbuf-pixel:
    normal: [1, 1, -1]
    unit_normal: ["√3/3", "0.57735", "-1/sqrt(3)"]
    plane: "-2x - 2y + 2z = 12"
    z: "16/2"
  bf: {df: -2.0, facing: 裏}
)Y");
  EXPECT_TRUE(r.errors.empty());
  EXPECT_EQ(r.student, "s1");
  EXPECT_DOUBLE_EQ(r.score, 6);
  EXPECT_DOUBLE_EQ(r.max_score, 6);
}

TEST(Grader, WrongAnswerCarriesItsDerivation) {
  const GradeReport r = grade_answers("answers:\n  zbuf-pixel: {z: 9}\n");
  const AnswerGrade& z = answer(r, "zbuf-pixel", "z");
  EXPECT_EQ(z.verdict, Verdict::Incorrect);
  EXPECT_EQ(z.score, 0);
  ASSERT_FALSE(z.derivation.empty());
  EXPECT_EQ(z.derivation.back().answers, std::vector<std::string>{"z"});
  EXPECT_EQ(answer(r, "zbuf-pixel", "plane").verdict, Verdict::Missing);
  EXPECT_DOUBLE_EQ(r.score, 0);
}

TEST(Grader, ReversedNormalIsIncorrectWithFeedback) {
  const GradeReport r =
      grade_answers("answers:\n  zbuf-pixel: {normal: [-9, -9, 9], unit_normal: [9, 9, -9]}\n");
  const AnswerGrade& n = answer(r, "zbuf-pixel", "normal");
  EXPECT_EQ(n.verdict, Verdict::Incorrect);
  EXPECT_NE(n.feedback.en().find("opposite"), std::string::npos);
  const AnswerGrade& u = answer(r, "zbuf-pixel", "unit_normal");
  EXPECT_EQ(u.verdict, Verdict::Incorrect);
  // Its own length, 9√3 ≈ 15.59 (not a ratio between rescaled vectors), and the mistake named.
  EXPECT_NE(u.feedback.en().find("the length is 15.59"), std::string::npos) << u.feedback;
  EXPECT_EQ(u.misconception.en(), "unnormalised normal") << "n itself: the kind's own mistake";
  // Every positive multiple is told its own length: 1/10 of the unit normal has length 0.1.
  const AnswerGrade tenth =
      answer(grade_answers("answers:\n  zbuf-pixel: {unit_normal: [\"sqrt(3)/30\", \"sqrt(3)/30\", "
                           "\"-sqrt(3)/30\"]}\n"),
             "zbuf-pixel", "unit_normal");
  EXPECT_NE(tenth.feedback.en().find("the length is 0.1 "), std::string::npos) << tenth.feedback;
  EXPECT_EQ(tenth.misconception.en(), "not normalised");
}

TEST(Grader, ToleranceIsRelativeOneInAThousand) {
  EXPECT_EQ(
      answer(grade_answers("answers:\n  zbuf-pixel: {z: 8.007}\n"), "zbuf-pixel", "z").verdict,
      Verdict::Correct);
  EXPECT_EQ(
      answer(grade_answers("answers:\n  zbuf-pixel: {z: 8.009}\n"), "zbuf-pixel", "z").verdict,
      Verdict::Incorrect);
}

TEST(Grader, UnparseableAnswersNeverStopTheRest) {
  const GradeReport r = grade_answers(R"Y(answers:
  zbuf-pixel:
    normal: "(((("
    unit_normal: [1, 2]
    plane: "x + y = z = 3"
    z: "2^2^2^2^2^2^2^2^2"
  bf: {df: -2, facing: sideways}
)Y");
  EXPECT_EQ(answer(r, "zbuf-pixel", "normal").verdict, Verdict::Unparseable);
  EXPECT_EQ(answer(r, "zbuf-pixel", "unit_normal").verdict, Verdict::Incorrect);
  EXPECT_EQ(answer(r, "zbuf-pixel", "plane").verdict, Verdict::Unparseable);
  const AnswerGrade& z = answer(r, "zbuf-pixel", "z");
  EXPECT_EQ(z.verdict, Verdict::Unparseable);
  EXPECT_NE(z.feedback.en().find("exponent"), std::string::npos);
  EXPECT_EQ(answer(r, "bf", "df").verdict, Verdict::Correct);
  EXPECT_EQ(answer(r, "bf", "facing").verdict, Verdict::Unparseable);
  EXPECT_DOUBLE_EQ(r.score, 1);
}

TEST(Grader, UnknownIdsAndAnswerNamesAreWarnings) {
  const GradeReport r = grade_answers("answers:\n  zbuf-pixle: {z: 8}\n  bf: {dff: 3}\n");
  ASSERT_EQ(r.errors.size(), 2u);
  std::string all = r.errors[0].format() + r.errors[1].format();
  EXPECT_NE(all.find("did you mean 'zbuf-pixel'"), std::string::npos) << all;
  EXPECT_NE(all.find("did you mean 'df'"), std::string::npos) << all;
}

TEST(Grader, JsonFollowsTheFormat) {
  const GradeReport r =
      grade_answers("student: s1234567\nanswers:\n  zbuf-pixel: {z: 8, plane: [1, 1, -1, -6]}\n");
  const auto j = render_grade_json(r);
  EXPECT_EQ(j["student"], "s1234567");
  EXPECT_EQ(j["score"], 2);
  EXPECT_EQ(j["max_score"], 6);
  const auto& z = j["problems"][0]["answers"]["z"];
  EXPECT_EQ(z["verdict"], "correct");
  EXPECT_EQ(z["score"], 1);
  EXPECT_EQ(z["expected"], 8);
  EXPECT_EQ(z["got"], 8);
  EXPECT_TRUE(z.contains("feedback"));
  EXPECT_EQ(j["problems"][0]["answers"]["normal"]["verdict"], "missing");
  // A problem the file does not mention at all: every answer missing, no error.
  ASSERT_EQ(j["problems"].size(), 2u);
  EXPECT_FALSE(j["problems"][1].contains("error")) << j["problems"][1].dump();
  for (const auto& [name, a] : j["problems"][1]["answers"].items())
    EXPECT_EQ(a["verdict"], "missing") << name;
  EXPECT_FALSE(j["problems"][1]["answers"].empty());
}

TEST(Grader, FeedbackEchoesWhatTheStudentWrote) {
  // 0.948683 stays 0.948683 beside the key, not our exact reading 948683/1000000.
  const GradeReport r =
      grade(load_problem_set_from_string("problems:\n  - {id: v, kind: vectors, given: {a: [1, 0, "
                                         "0], b: [3, 1, 0]}, ask: [cos, cross]}\n",
                                         "set.yaml"),
            load_submission_from_string("answers:\n  v: {cos: 0.948683, cross: \"(0, 0, 1.0)\"}\n",
                                        "a.yaml"));
  for (const std::string& page : {render_feedback_markdown(r), render_feedback_html(r)}) {
    EXPECT_NE(page.find("0.948683"), std::string::npos);
    EXPECT_EQ(page.find("948683/1000000"), std::string::npos);
    EXPECT_NE(page.find("(0, 0, 1.0)"), std::string::npos);
    EXPECT_NE(page.find("3√10/10"), std::string::npos) << "the key beside it, exact";
  }
}

TEST(Grader, BrokenAnswerFileIsReportedNotFatal) {
  const GradeReport r = grade_answers("answers: [1, 2\n");
  ASSERT_FALSE(r.errors.empty());
  EXPECT_NE(r.errors[0].format().find("answers.yaml:"), std::string::npos);
  EXPECT_EQ(r.problems.size(), 2u);
  EXPECT_DOUBLE_EQ(r.max_score, 6);
}

}  // namespace
}  // namespace frustum
