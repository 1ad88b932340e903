// Problem ids in every export: each question keeps its own name whatever its id —
// PrairieLearn directories, QTI items, Moodle categories, Gradescope tests, exam sections —
// `frustum check` warns of ids a student may take for each other, and a problem that cannot be
// solved stops the export.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <sstream>

#include "app/commands.hpp"
#include "batch/file_names.hpp"
#include "export/export_moodle.hpp"
#include "export/export_prairielearn.hpp"
#include "export/export_qti.hpp"
#include "export/paper.hpp"
#include "export/quiz_items.hpp"
#include "export/xml_text.hpp"
#include "grader/grade.hpp"
#include "report/gradescope.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/words.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

const char* const kSet = test::kOneDepthProblemSet;

// Problem ids that a directory name cannot keep apart: every export keeps each question.
const char* kHostileIds = R"(title: q
problems:
  - {id: "q 1", kind: depth_at_pixel, given: {triangle: [[0,0,1],[4,0,1],[0,4,1]], pixel: [1,1]}}
  - {id: "q/1", kind: depth_at_pixel, given: {triangle: [[0,0,2],[4,0,2],[0,4,2]], pixel: [1,1]}}
  - {id: "q_1", kind: depth_at_pixel, given: {triangle: [[0,0,3],[4,0,3],[0,4,3]], pixel: [1,1]}}
  - {id: "Q_1", kind: depth_at_pixel, given: {triangle: [[0,0,4],[4,0,4],[0,4,4]], pixel: [1,1]}}
  - {id: "q%201", kind: depth_at_pixel, given: {triangle: [[0,0,5],[4,0,5],[0,4,5]], pixel: [1,1]}}
  - {id: "../q", kind: depth_at_pixel, given: {triangle: [[0,0,6],[4,0,6],[0,4,6]], pixel: [1,1]}}
)";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(ExportNames, EveryQuestionKeepsItsOwnNameInEveryExport) {
  const YamlDocument doc = parse_yaml(kHostileIds, "q.yaml");
  const ProblemSet set = load_problem_set(doc, "q.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  const std::size_t n = set.problems.size();
  // PrairieLearn: a directory per question, distinct even without case, none outside -o.
  const auto pl = export_prairielearn(doc.root, set, {set}, "q", PrairieLearnOptions{});
  std::set<std::string> dirs, uuids;
  for (const auto& [d, files] : pl) {
    dirs.insert(ascii_lower(d));
    EXPECT_EQ(d.find('/'), std::string::npos) << d;
    EXPECT_NE(d.rfind('.', 0), 0u) << d;
    uuids.insert(files.at("info.json").substr(files.at("info.json").find("\"uuid\"")));
  }
  EXPECT_EQ(pl.size(), n);
  EXPECT_EQ(dirs.size(), n);
  EXPECT_EQ(uuids.size(), n);
  EXPECT_EQ(pl.count("q-q%201") + pl.count("q-q%2F1") + pl.count("q-q_1") + pl.count("q-Q_1~2") +
                pl.count("q-q%25201") + pl.count("q-..%2Fq"),
            n);
  // QTI: one item per problem a quiz can ask, titled by its id; Moodle: one category per problem.
  const std::vector<QuizQuestion> qs = quiz_questions(set);
  ASSERT_EQ(qs.size(), n);
  const std::string qti = export_qti({{"", qs}}, "q", "frustum_q").at("frustum_q.xml");
  const std::string moodle = export_moodle({{"", qs}}, "q");
  std::set<std::string> categories;
  for (std::size_t at = moodle.find("<category><text>"); at != std::string::npos;
       at = moodle.find("<category><text>", at + 1))
    categories.insert(moodle.substr(at, moodle.find("</text>", at) - at));
  EXPECT_EQ(categories.size(), n);
  EXPECT_NE(moodle.find("$course$/top/q/q//1<"), std::string::npos);
  EXPECT_NE(moodle.find("$course$/top/q/..//q<"), std::string::npos);
  std::size_t asked = 0;
  for (const QuizQuestion& q : qs) asked += !q.answers.empty();
  EXPECT_EQ(count(qti, "<item ident=\"frustum_q_q"), asked);
  for (const QuizQuestion& q : qs) {
    if (q.answers.empty()) continue;
    EXPECT_EQ(count(qti, "title=\"" + xml_escape(q.id) + "\""), 1u) << q.id;
  }
  EXPECT_EQ(count(moodle, "<question type=\"cloze\">"), n);
  // Gradescope: a test per problem; paper: a section per problem.
  const GradeReport report =
      grade(set, load_submission_from_string("student: s\nanswers: {}\n", "a.yaml"));
  const nlohmann::ordered_json gs = gradescope_results(report);
  std::set<std::string> tests;
  for (const auto& t : gs["tests"]) tests.insert(t["name"].get<std::string>());
  EXPECT_EQ(tests.size(), n);
  EXPECT_EQ(count(exam_sheets_latex({{"s", set}}, "q"), "\\subsection*"), n);
}

// `frustum check` warns of ids a student may take for each other; they are not errors.
TEST(ExportNames, CheckWarnsOfProblemIdsThatDifferOnlyInCaseOrSigns) {
  const ProblemSet set = load_problem_set_from_string(kHostileIds, "q.yaml");
  const std::vector<Diagnostic> w = look_alike_problem_ids(set);
  ASSERT_EQ(w.size(), 3u);  // q/1, q_1 and Q_1 after q 1; q%201 and ../q look like no other
  EXPECT_EQ(w[0].format(),
            "q.yaml:4:5: problems[1].id: warning: problem id 'q/1' differs from 'q 1' "
            "(problems[0]) only in case, spaces or signs: each export keeps both, but a student "
            "may answer one for the other");
  EXPECT_EQ(w[2].field, "problems[3].id");
  EXPECT_TRUE(look_alike_problem_ids(load_problem_set_from_string(kSet, "s.yaml")).empty());
}

// A problem without a key (a degenerate triangle) was left out of every export, exit status 0;
// the export is refused, naming it, and writes nothing.
TEST(ExportNames, AProblemThatCannotBeSolvedStopsTheExportNotItsQuestion) {
  const fs::path dir = test::scratch_dir("export-unsolved");
  test::write_file(
      dir / "b.yaml",
      "title: b\nproblems:\n"
      "  - {id: ok, kind: depth_at_pixel, given: {triangle: [[0,0,1],[4,0,1],[0,4,1]], "
      "pixel: [1,1]}}\n"
      "  - {id: flat, kind: depth_at_pixel, given: {triangle: [[0,0,1],[1,1,1],"
      "[2,2,1]], pixel: [1,1]}}\n");
  for (const char* format : {"prairielearn", "qti", "moodle"}) {
    std::ostringstream out, err;
    app::ExportOptions e;
    e.format = format;
    e.input = (dir / "b.yaml").string();
    e.out = (dir / format).string();
    EXPECT_EQ(app::run_export(e, app::Output{out, err, false}), 1) << format;
    EXPECT_NE(err.str().find("problems[1]"), std::string::npos) << err.str();
    EXPECT_NE(err.str().find("nothing was exported"), std::string::npos) << err.str();
    EXPECT_FALSE(fs::exists(dir / format)) << format;
  }
  // `check` prints the look-alike ids' warnings and still passes.
  test::write_file(dir / "q.yaml", kHostileIds);
  std::ostringstream out, err;
  EXPECT_EQ(app::run_check((dir / "q.yaml").string(), app::Output{out, err, false}), 0);
  EXPECT_EQ(count(out.str(), ": warning: problem id "), 3u) << out.str();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
