// The `statements` kind ("which of these statements are true?"): the lecture's back-face culling
// quiz as bundled, the set's checks, the derivation in three languages, grading per statement,
// variants that keep it as written, and each quiz export as a multiple-answer question.
#include <fmt/format.h>

#include <algorithm>
#include <random>

#include "export/export_moodle.hpp"
#include "export/export_prairielearn.hpp"
#include "export/export_qti.hpp"
#include "export/paper.hpp"
#include "export/quiz_items.hpp"
#include "grader/grade.hpp"
#include "grader/statement_choice.hpp"
#include "report/gradescope.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

const char* kSeed003 = "problems/seeds/003_polygons_backface.yaml";
const char* kId = "seed003-culling-statements";

const ProblemResult& culling(const SetResult& r) {
  for (const ProblemResult& p : r.problems)
    if (p.id == kId) return p;
  throw std::runtime_error("no culling statements in seed 003");
}

const AnswerGrade& graded(const ProblemSet& set, const std::string& answer) {
  static GradeReport r;
  r = grade(set,
            load_submission_from_string(
                fmt::format("student: s\nanswers:\n  {}:\n    true_statements: {}\n", kId, answer),
                "answers.yaml"));
  for (const ProblemGrade& p : r.problems)
    if (p.id == kId) return p.answers.at(0);
  throw std::runtime_error("not graded");
}

TEST(Seed003, CullingStatementsKeyIsOneTrueThreeFalse) {
  const ProblemSet set = load_problem_set(test::source_path(kSeed003));
  ASSERT_TRUE(set.all_errors().empty());
  const SetResult solved = solve_set(set, true);
  const ProblemResult& p = culling(solved);
  ASSERT_FALSE(p.error);
  const Value* key = p.answers.find("true_statements");
  ASSERT_NE(key, nullptr);
  EXPECT_EQ(key->entries, (std::vector<std::pair<std::string, std::string>>{
                              {"1", "true"}, {"2", "false"}, {"3", "false"}, {"4", "false"}}));
  EXPECT_EQ(key->shown().unicode, "1 ○, 2 ×, 3 ×, 4 ×");
  // The lecture's answer [1] is full marks; [1, 3] picks a false one too.
  const AnswerGrade& full = graded(set, "[1]");
  EXPECT_EQ(full.verdict, Verdict::Correct);
  EXPECT_DOUBLE_EQ(full.score, full.max_score);
  const AnswerGrade& half = graded(set, "[1, 3]");
  EXPECT_EQ(half.verdict, Verdict::Partial);
  EXPECT_NEAR(half.score, 2.0 / 3.0, 1e-12);
  EXPECT_NE(half.feedback.en().find("Statement 3 is false, not true (see step 3)."),
            std::string::npos)
      << half.feedback;
  // The wrong answer comes with the derivation that holds the reasons.
  ASSERT_FALSE(half.derivation.empty());
  EXPECT_EQ(half.derivation[2].note.in(Lang::Ja), "理由: 頂点ではなく、面の法線が必要である.");
  // An English reader reads the set's English text of the reason.
  EXPECT_EQ(half.derivation[2].note.en(),
            "Reason: It needs the normals of the faces, not of the vertices.");
}

TEST(Statements, DerivationListsEachStatementWithItsMarkAndReason) {
  const ProblemSet set = load_problem_set(test::source_path(kSeed003));
  const SetResult solved = solve_set(set, true);
  const ProblemResult& p = culling(solved);
  const std::vector<Step>& steps = p.derivation.steps();
  ASSERT_EQ(steps.size(), 5u);
  EXPECT_EQ(steps[0].title.en(),
            "Statement 1: Back-face culling is effective for hidden-surface removal of a single "
            "convex polyhedron.");
  EXPECT_EQ(steps[0].result.unicode, "○ True");
  EXPECT_EQ(steps[1].result.unicode, "× False");
  EXPECT_EQ(steps[1].result.latex, "\\mathord{\\times}\\;\\text{False}");  // a mark
  EXPECT_EQ(steps[4].title.en(), "The true statements");
  EXPECT_EQ(steps[4].result.unicode, "1");
  // In Japanese the lecture's own words; in Russian, Russian ones.
  EXPECT_EQ(steps[0].title.in(Lang::Ja),
            "記述 1: 1つの凸多面体の陰面消去にはバックフェースカリングが効果的である.");
  EXPECT_EQ(tr(steps[0].result, Lang::Ja).unicode, "○ 正しい");
  EXPECT_EQ(tr(steps[3].result, Lang::Ru).unicode, "× неверно");
  EXPECT_EQ(steps[4].title.in(Lang::Ru), "Верные утверждения");
  const SetResult one{set.file, {}, "", {p}, {}};
  const std::string ja = render_text(one, TextStyle{false, Lang::Ja});
  EXPECT_NE(ja.find("記述 3: バックフェースカリングを実行するためには頂点の法線が必要である."),
            std::string::npos)
      << ja;
  EXPECT_NE(ja.find("理由: 頂点ではなく、面の法線が必要である."), std::string::npos) << ja;
}

std::string set_with(const std::string& statements) {
  return "problems:\n  - id: q\n    kind: statements\n    given:\n      statements:\n" + statements;
}

// The error of a set with these statements, as `check` prints it.
std::string error_of(const std::string& statements) {
  const ProblemSet set = load_problem_set_from_string(set_with(statements), "q.yaml");
  const std::vector<Diagnostic> errors = set.all_errors();
  return errors.empty() ? "" : errors[0].format();
}

TEST(Statements, CheckNamesFileLineAndFieldOfEveryBadStatement) {
  EXPECT_EQ(
      error_of("        - {text: a, truth: true}\n        - {text: b}\n"),
      "q.yaml:7:11: problems[0].given.statements[1].truth: missing: every statement needs its "
      "truth (true or false) for the key");
  EXPECT_EQ(error_of("        - {text: a, truth: maybe}\n"),
            "q.yaml:6:28: problems[0].given.statements[0].truth: expected true or false (also "
            "yes/no, ○/×)");
  EXPECT_EQ(error_of("        - {truth: true}\n"),
            "q.yaml:6:11: problems[0].given.statements[0].text: missing required field");
  EXPECT_EQ(
      error_of("        - {text: a, truth: true, reasn: b}\n"),
      "q.yaml:6:34: problems[0].given.statements[0].reasn: unknown field (did you mean 'reason'?)");
  EXPECT_NE(error_of("        - just a sentence\n").find("statement 1 is not a mapping"),
            std::string::npos);
  EXPECT_NE(error_of("        []\n").find("expected at least 1 items"), std::string::npos);
  std::string many;
  for (int i = 0; i < 51; ++i) many += "        - {text: s, truth: false}\n";
  EXPECT_NE(error_of(many).find("at most 50 items"), std::string::npos);
  EXPECT_NE(error_of("        - {text: " + std::string(2001, 'a') + ", truth: true}\n")
                .find("longer than 2000 bytes"),
            std::string::npos);
  // A statements problem has nothing to draw: `vary` is refused, not ignored.
  const ProblemSet varied = load_problem_set_from_string(
      set_with("        - {text: a, truth: true}\n") + "    vary: default\n", "q.yaml");
  ASSERT_FALSE(varied.all_errors().empty());
  EXPECT_EQ(varied.all_errors()[0].message,
            "statements has nothing to vary: every variant keeps it as written");
}

TEST(Statements, TruthsTakeTheWordsOfEachLanguage) {
  const ProblemSet set =
      load_problem_set_from_string(set_with("        - {text: a, truth: ○}\n        - {text: b, "
                                            "truth: ×}\n        - {text: c, truth: 正しい}\n"
                                            "        - {text: d, truth: неверно}\n        - {text: "
                                            "e, truth: yes}\n        - {text: f, truth: false}\n"),
                                   "q.yaml");
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  const ProblemResult r = solve_problem(set.problems[0], set.file, false);
  EXPECT_EQ(r.answers.find("true_statements")->shown().unicode, "1 ○, 2 ×, 3 ○, 4 ×, 5 ○, 6 ×");
}

// Variants (per student, from a seed, every problem drawn) keep the statements as written, and
// their keys grade the lecture's answer full.
TEST(Statements, VariantsKeepTheProblemAsWritten) {
  const ProblemSet set = load_problem_set(test::source_path(kSeed003));
  const ProblemSpec* base = set.find(kId);
  ASSERT_NE(base, nullptr);
  std::vector<ProblemSet> variants = variants_from_seed(set, 5, 4, true);
  variants.push_back(variant_for_student(set, "s1", true));
  ASSERT_EQ(variants.size(), 5u);
  for (const ProblemSet& v : variants) {
    ASSERT_TRUE(v.all_errors().empty()) << v.all_errors()[0].format();
    const ProblemSpec* p = v.find(kId);
    ASSERT_NE(p, nullptr);
    EXPECT_EQ(emit_flow(p->given_node), emit_flow(base->given_node));
    EXPECT_EQ(graded(v, "[1]").verdict, Verdict::Correct);
  }
  // The answer key `generate` writes grades full.
  const GradeReport key =
      grade(set, load_submission_from_string(emit_answer_key(set, "s", ""), "key.yaml"));
  ASSERT_TRUE(key.errors.empty()) << key.errors[0].format();
  EXPECT_DOUBLE_EQ(key.score, key.max_score);
}

std::vector<QuizQuestion> culling_questions() {
  const ProblemSet set = load_problem_set(test::source_path(kSeed003));
  std::vector<QuizQuestion> out;
  for (const QuizQuestion& q : quiz_questions(set, Lang::Ja))  // in the lecture's own words
    if (q.id == kId) out.push_back(q);
  return out;
}

TEST(Statements, QuizFieldIsOneCheckboxPerStatementAndHidesTheKey) {
  const std::vector<QuizQuestion> qs = culling_questions();
  ASSERT_EQ(qs.size(), 1u);
  EXPECT_TRUE(qs[0].given.empty()) << "the given holds the truths: it is never shown";
  ASSERT_EQ(qs[0].answers.size(), 1u);
  const QuizField& f = qs[0].answers[0].fields.at(0);
  EXPECT_EQ(f.type, QuizField::Type::Checkboxes);
  EXPECT_EQ(f.right, (std::vector<bool>{true, false, false, false}));
  EXPECT_EQ(f.correct, "1");
  EXPECT_EQ(f.choices[2], "バックフェースカリングを実行するためには頂点の法線が必要である.");
  EXPECT_EQ(f.reasons[2], "頂点ではなく、面の法線が必要である.");
}

TEST(Statements, MoodleExportIsAMultipleAnswerQuestion) {
  const std::string xml = export_moodle({{"", culling_questions()}}, "Seed 3");
  EXPECT_NE(xml.find("<question type=\"multichoice\">"), std::string::npos) << xml;
  EXPECT_NE(xml.find("<single>false</single>"), std::string::npos);
  EXPECT_NE(xml.find("<answernumbering>123</answernumbering>"), std::string::npos);
  EXPECT_NE(xml.find("<answer fraction=\"100\" format=\"html\"><text><![CDATA[1つの凸多面体"),
            std::string::npos)
      << xml;
  std::size_t wrong = 0;
  for (std::size_t at = 0; (at = xml.find("fraction=\"-33.333\"", at)) != std::string::npos; ++at)
    ++wrong;
  EXPECT_EQ(wrong, 3u) << xml;
  EXPECT_NE(xml.find("<feedback format=\"html\"><text><![CDATA[頂点ではなく"), std::string::npos);
  EXPECT_EQ(xml.find("truth"), std::string::npos) << "the key is not printed";
  // Beside other answers, the same checkboxes are a Cloze MULTIRESPONSE field.
  std::vector<QuizQuestion> qs = culling_questions();
  QuizAnswer extra = qs[0].answers[0];
  extra.fields[0].type = QuizField::Type::Choice;
  qs[0].answers.push_back(extra);
  const std::string cloze = export_moodle({{"", qs}}, "Seed 3");
  // Two answers of equal points: equal whole weights (Moodle marks the question out of their sum).
  const std::size_t at = cloze.find(":MULTIRESPONSE:%100%1つの凸多面体");
  ASSERT_NE(at, std::string::npos) << cloze;
  EXPECT_EQ(cloze.substr(cloze.rfind('{', at), at - cloze.rfind('{', at)),
            fmt::format("{{{}", cloze_weights(qs[0]).front()));
  EXPECT_NE(cloze.find("~%-33.333%バックフェースカリングを実行する"), std::string::npos) << cloze;
}

TEST(Statements, CanvasExportIsAMultipleAnswersQuestion) {
  const auto files = export_qti({{"", culling_questions()}}, "Seed 3", "seed3");
  ASSERT_TRUE(files.count("seed3.xml"));
  const std::string& xml = files.at("seed3.xml");
  EXPECT_NE(xml.find("<fieldentry>multiple_answers_question</fieldentry>"), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("rcardinality=\"Multiple\""), std::string::npos);
  EXPECT_NE(xml.find("texttype=\"text/plain\">3. バックフェースカリング"), std::string::npos)
      << xml;
  EXPECT_NE(xml.find("<and><varequal respident=\"response1\">c0</varequal><not><varequal "
                     "respident=\"response1\">c1</varequal></not>"),
            std::string::npos)
      << xml;
  EXPECT_EQ(xml.find("truth"), std::string::npos);
  // Canvas's own rule for multiple answers (−1/T a wrong box), stated to the students.
  EXPECT_NE(xml.find("each wrong one ticked loses 1/1"), std::string::npos) << xml;
}

TEST(Statements, PrairieLearnExportIsACheckboxGradedByFrustum) {
  const std::string path = test::source_path(kSeed003);
  const ProblemSet set = load_problem_set(path);
  PrairieLearnOptions japanese;  // the lecture's own words
  japanese.lang = Lang::Ja;
  const auto out = export_prairielearn(load_yaml_file(path).root, set, {set}, "003", japanese);
  ASSERT_TRUE(out.count("003-seed003-culling-statements"));
  const auto& files = out.at("003-seed003-culling-statements");
  const std::string& html = files.at("question.html");
  EXPECT_NE(html.find("<pl-checkbox answers-name=\"true_statements\" fixed-order=\"true\" "
                      "hide-letter-keys=\"true\">"),
            std::string::npos)
      << html;
  // Some statement is true here, so the last option, "none is true", is a wrong one.
  EXPECT_NE(html.find("<pl-answer correct=\"false\">上の記述はどれも正しくない</pl-answer>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<pl-answer correct=\"true\">1. 1つの凸多面体"), std::string::npos) << html;
  EXPECT_NE(html.find("<pl-answer correct=\"false\">4. 凹多面体を描画する場合"), std::string::npos)
      << html;
  EXPECT_NE(files.at("server.py").find("\\\"true_statements\\\":\\\"checkbox\\\""),
            std::string::npos)
      << files.at("server.py");
}

// Over many keys and answers: the numbers and the truths say the same; order and repeats do
// not matter; full marks exactly for the key; nothing for a constant answer; the credit is
// +1/T per true statement ticked and −1/F per false one, within [0, 1].
TEST(Statements, CreditPropertiesOverManyKeysAndAnswers) {
  std::mt19937 rng(16);
  for (int round = 0; round < 3000; ++round) {
    const std::size_t n = 1 + rng() % 8;
    std::vector<std::pair<std::string, std::string>> entries;
    std::vector<bool> truth(n), ticked(n);
    std::size_t trues = 0;
    for (std::size_t i = 0; i < n; ++i) {
      truth[i] = rng() % 2;
      ticked[i] = rng() % 2;
      trues += truth[i];
      entries.emplace_back(std::to_string(i + 1), truth[i] ? "true" : "false");
    }
    const Value key = Value::word_map(entries);
    YAML::Node numbers(YAML::NodeType::Sequence), truths(YAML::NodeType::Sequence);
    std::size_t a = 0, b = 0;
    for (std::size_t i = n; i-- > 0;)  // backwards, with repeats
      if (ticked[i]) {
        numbers.push_back(std::to_string(i + 1));
        if (rng() % 3 == 0) numbers.push_back(std::to_string(i + 1));
      }
    for (std::size_t i = 0; i < n; ++i) {
      truths.push_back(ticked[i] ? "○" : "×");
      a += ticked[i] && truth[i];
      b += ticked[i] && !truth[i];
    }
    const StatementChoice by_number = read_statement_choice(numbers),
                          by_truth = read_statement_choice(truths);
    ASSERT_TRUE(by_number.error.empty()) << by_number.error;
    ASSERT_TRUE(by_truth.error.empty()) << by_truth.error;
    const Comparison c = compare_statement_choice(key, by_number.value);
    const Comparison d = compare_statement_choice(key, by_truth.value);
    EXPECT_EQ(c.verdict, d.verdict);
    EXPECT_DOUBLE_EQ(c.credit, d.credit);
    const std::size_t falses = n - trues;
    const double expected = std::max(0.0, (trues ? double(a) / double(trues) : 1.0) -
                                              (falses ? double(b) / double(falses) : 0.0));
    EXPECT_NEAR(c.credit, expected, 1e-12);
    EXPECT_EQ(c.verdict == Verdict::Correct, ticked == truth);
    EXPECT_EQ(c.verdict == Verdict::Correct, c.credit == 1.0);
    EXPECT_GE(c.credit, 0.0);
    // Constant answers ("none", "all") earn nothing unless they are the key.
    if (trues > 0) {
      EXPECT_EQ(compare_statement_choice(key, Value::null()).credit, 0.0);
    }
    if (falses > 0) {
      std::vector<std::string> all;
      for (std::size_t i = 0; i < n; ++i) all.push_back(std::to_string(i + 1));
      EXPECT_EQ(compare_statement_choice(key, Value::word_list(all)).credit, 0.0);
    }
  }
}

// On a paper exam the statements are listed, numbered, and their truths are not.
TEST(Statements, PaperExamListsTheStatementsNotTheKey) {
  ProblemSet set = load_problem_set(test::source_path(kSeed003));
  const std::string exam = exam_sheets_latex({{"s1", set}}, "Seed 3", Lang::Ja);
  EXPECT_NE(exam.find("\\begin{enumerate}\n\\item 1つの凸多面体の陰面消去には"), std::string::npos)
      << exam;
  EXPECT_NE(exam.find("\\item 凹多面体を描画する場合はバックフェースカリングを使うべきではない."),
            std::string::npos);
  EXPECT_EQ(exam.find("truth"), std::string::npos);
  EXPECT_EQ(exam.find("頂点ではなく"), std::string::npos) << "no reason on the exam";
  EXPECT_EQ(exam.find("\\begin{itemize}\\setlength{\\itemsep}{0pt}\n\\end{itemize}"),
            std::string::npos);
  const std::string key = answer_key_latex({{"s1", set}}, "Seed 3");
  EXPECT_NE(key.find("1\\,\\bigcirc,\\;2\\,\\mathord{\\times}"), std::string::npos) << key;
}

TEST(Statements, GradescopeScoresPerStatement) {
  const ProblemSet set = load_problem_set(test::source_path(kSeed003));
  const GradeReport r =
      grade(set, load_submission_from_string(
                     fmt::format("student: s\nanswers:\n  {}:\n    true_statements: [1, 2]\n", kId),
                     "answers.yaml"));
  const nlohmann::ordered_json results = gradescope_results(r, Lang::Ja);
  bool found = false;
  for (const auto& t : results["tests"])
    if (t["name"].get<std::string>().find(kId) != std::string::npos) {
      found = true;
      EXPECT_NEAR(t["score"].get<double>(), 2.0 / 3.0, 1e-9);
      EXPECT_NE(t["output"].get<std::string>().find(
                    "記述 2 は誤り (×). 正しい (○) ではない (ステップ 2 参照)."),
                std::string::npos)
          << t["output"];
    }
  EXPECT_TRUE(found) << results.dump(2);
}

}  // namespace
}  // namespace frustum
