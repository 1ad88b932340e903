// Exported quizzes accept what `frustum grade` accepts: every number of every Canvas/Moodle
// field, moved to 0.9 of its window, is still graded correct by the grader, and moved to 1.5
// windows is not; every choice and text field's right word is graded correct.
#include <fmt/format.h>

#include <algorithm>

#include "export/export_moodle.hpp"
#include "export/export_qti.hpp"
#include "export/quiz_items.hpp"
#include "grader/grade.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// One answer written from quiz fields, the field `moved` shifted by `shift` windows.
std::string answer_yaml(const QuizAnswer& a, std::size_t moved, double shift) {
  std::vector<std::string> items;
  std::size_t cols = 0;
  for (std::size_t i = 0; i < a.fields.size(); ++i) {
    const QuizField& f = a.fields[i];
    if (f.type != QuizField::Type::Number) return "\"" + f.correct + "\"";
    items.push_back(fmt::format("{}", f.value + (i == moved ? shift * f.window : 0)));
    if (f.label.rfind("row 1,", 0) == 0) ++cols;
  }
  if (items.size() == 1 && a.fields[0].label.empty()) return items[0];
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    const bool row_start = cols && i % cols == 0;
    out += (i && row_start ? "], [" : i ? ", " : "") + items[i];
  }
  return cols ? "[" + out + "]]" : out + "]";
}

Verdict verdict_of(const ProblemSet& set, const SolvedSet& solved, const std::string& id,
                   const std::string& name, const std::string& value) {
  const Submission s = load_submission_from_string(
      fmt::format("student: t\nanswers:\n  {}:\n    {}: {}\n", id, name, value), "answers.yaml");
  const GradeReport r = grade(set, s, &solved);
  for (const ProblemGrade& p : r.problems)
    if (p.id == id)
      for (const AnswerGrade& a : p.answers)
        if (a.name == name) return a.verdict;
  return Verdict::Missing;
}

TEST(Export, QuizWindowsAreTheGradersWindows) {
  int inside = 0, outside = 0;
  for (const char* file :
       {"problems/seeds/001_zbuffer_plane_method.yaml",
        "problems/seeds/002_transforms_and_view_volume.yaml",
        "problems/seeds/003_polygons_backface.yaml",
        "problems/seeds/004_placing_and_projecting.yaml", "problems/examples/pipeline.yaml"}) {
    const ProblemSet source = load_problem_set(test::source_path(file));
    ASSERT_TRUE(source.all_errors().empty()) << file;
    std::vector<ProblemSet> sets = variants_from_seed(source, 11, 3, !set_varies(source));
    sets.push_back(source);
    for (const ProblemSet& set : sets) {
      const SolvedSet solved = solve_for_grading(set);
      for (const QuizQuestion& q : quiz_questions(set))
        for (const QuizAnswer& a : q.answers) {
          EXPECT_EQ(verdict_of(set, solved, q.id, a.name, answer_yaml(a, 0, 0)), Verdict::Correct)
              << file << " " << q.id << "." << a.name;
          for (std::size_t i = 0; i < a.fields.size(); ++i) {
            if (a.fields[i].type != QuizField::Type::Number) continue;
            // A zero window is the grader's too (a transform's fixed bottom row): only the
            // exact value is right, which the first check above has shown.
            ASSERT_GE(a.fields[i].window, 0) << q.id << "." << a.name;
            if (a.fields[i].window == 0) continue;
            EXPECT_EQ(verdict_of(set, solved, q.id, a.name, answer_yaml(a, i, 0.9)),
                      Verdict::Correct)
                << file << " " << q.id << "." << a.name << " " << a.fields[i].label << ": "
                << answer_yaml(a, i, 0.9);
            ++inside;
            // Directions are right up to a positive factor: moving one component changes the
            // direction, which the grader judges on the whole vector, not per field.
            if (a.prompt.find("length 1") != std::string::npos) continue;
            EXPECT_NE(verdict_of(set, solved, q.id, a.name, answer_yaml(a, i, 1.5)),
                      Verdict::Correct)
                << file << " " << q.id << "." << a.name << " " << a.fields[i].label << ": "
                << answer_yaml(a, i, 1.5);
            ++outside;
          }
        }
    }
  }
  EXPECT_GT(inside, 200);
  EXPECT_GT(outside, 150);
}

TEST(Export, AnswersNoFieldCanCheckAreNamedNotDropped) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const std::vector<QuizQuestion> qs = quiz_questions(set);
  ASSERT_EQ(qs.size(), 3u);
  EXPECT_EQ(qs[1].left_out, std::vector<std::string>{
                                "plane: a plane's equation is right up to any non-zero factor"});
  const std::string moodle = export_moodle({{"", qs}}, "Seed 1");
  EXPECT_NE(moodle.find("Not asked here (graded by Frustum only): plane:"), std::string::npos);
  EXPECT_NE(moodle.find("{100:NUMERICAL:=8:0.008}"), std::string::npos)
      << moodle;  // z = 8, rel 1e-3, 1 point
  const auto qti = export_qti({{"", qs}}, "Seed 1", "seed1");
  ASSERT_TRUE(qti.count("seed1.xml"));
  EXPECT_NE(qti.at("seed1.xml").find("<vargte respident=\"response1\">7.992</vargte>"),
            std::string::npos);
}

// A text field (an outcode) is right on a platform for exactly the spellings the grader calls
// right: every bit string up to the field's length is tried against both.
TEST(Export, TextFieldsAcceptExactlyWhatTheGraderAccepts) {
  const ProblemSet set = load_problem_set(test::source_path("problems/hard/decisions.yaml"));
  ASSERT_TRUE(set.all_errors().empty());
  const SolvedSet solved = solve_for_grading(set);
  const std::vector<QuizQuestion> qs = quiz_questions(set);
  int fields = 0, dropped = 0;
  for (const QuizQuestion& q : qs)
    for (const QuizAnswer& a : q.answers)
      for (const QuizField& f : a.fields) {
        if (f.type != QuizField::Type::Text) continue;
        ++fields;
        std::vector<std::string> platform{f.correct};
        platform.insert(platform.end(), f.also.begin(), f.also.end());
        dropped += static_cast<int>(f.also.size());
        for (std::size_t n = 1; n <= f.correct.size(); ++n)
          for (unsigned bits = 0; bits < (1u << n); ++bits) {
            std::string s;
            for (std::size_t i = n; i-- > 0;) s += (bits >> i & 1u) ? '1' : '0';
            const bool graded =
                verdict_of(set, solved, q.id, a.name, "\"" + s + "\"") == Verdict::Correct;
            const bool listed = std::find(platform.begin(), platform.end(), s) != platform.end();
            EXPECT_EQ(graded, listed) << q.id << "." << a.name << " " << s;
          }
        QuizQuestion only = q;  // this field alone
        only.answers = {a};
        only.answers[0].fields = {f};
        const std::string moodle = export_moodle({{"", {only}}}, "t");
        std::string cloze = "SHORTANSWER:=" + f.correct;
        for (const std::string& also : f.also) cloze += "~=" + also;
        EXPECT_NE(moodle.find(cloze + "}"), std::string::npos) << moodle;
        const std::string qti = export_qti({{"", {only}}}, "t", "t").at("t.xml");
        for (const std::string& s : platform)
          EXPECT_NE(qti.find("<varequal respident=\"response1\">" + s + "</varequal>"),
                    std::string::npos)
              << s;
        EXPECT_EQ(qti.find("<or>") != std::string::npos, !f.also.empty());
      }
  EXPECT_GE(fields, 4);
  EXPECT_GT(dropped, 0);  // some outcode has a leading zero
}

}  // namespace
}  // namespace frustum
