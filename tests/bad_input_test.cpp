// The catalogue of bad inputs (tests/bad_inputs/): one YAML file per case, its expected message
// in its header. Every case must give exactly that located message, never a crash or a hang,
// and the rest of the set must still solve (or the rest of the answers still grade).
//
// Problem sets (tests/bad_inputs/*.yaml):
//   # expect: LINE:COL: FIELD: FRAGMENT   an error of the set or of a problem at that place and
//                                         field (empty for the file), its message containing
//                                         FRAGMENT; one line per error, the case has no others
//                                         ("none": no error at all)
//   # warns: TITLE                        problem `bad` solves with a warning step TITLE
//   # solves: ID ...                      these problems solve cleanly (default: fine;
//                                         "none": nothing can be solved)
// Answer files (tests/bad_inputs/answers/*.yaml), graded against seed 001:
//   # expect: ID.ANSWER: VERDICT: FRAGMENT   that answer's verdict, its feedback containing
//   FRAGMENT # expect: LINE:COL: FIELD: FRAGMENT      an error of the answer file # correct:
//   ID.ANSWER                     graded correct despite the bad neighbours
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "grader/grade.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

struct Case {
  std::string path;
  std::vector<std::string> expect, warns, solves, correct;
};

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

Case read_case(const fs::path& path) {
  Case c;
  c.path = path.string();
  std::ifstream in(path, std::ios::binary);
  bool solves_given = false;
  for (std::string line; std::getline(in, line) && line.rfind("#", 0) == 0;) {
    const auto value = [&](const std::string& key) -> std::optional<std::string> {
      const std::string tag = "# " + key + ": ";
      if (line.rfind(tag, 0) != 0) return std::nullopt;
      return line.substr(tag.size());
    };
    if (auto v = value("expect")) c.expect.push_back(*v);
    if (auto v = value("warns")) c.warns.push_back(*v);
    if (auto v = value("correct")) c.correct.push_back(*v);
    if (auto v = value("solves")) {
      solves_given = true;
      if (*v != "none") c.solves = words(*v);
    }
  }
  if (!solves_given) c.solves = {"fine"};
  return c;
}

std::vector<Case> cases(const std::string& dir) {
  std::vector<Case> out;
  for (const auto& entry : fs::directory_iterator(test::source_path(dir)))
    if (entry.is_regular_file() && entry.path().extension() == ".yaml")
      out.push_back(read_case(entry.path()));
  std::sort(out.begin(), out.end(), [](const Case& a, const Case& b) { return a.path < b.path; });
  return out;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// "LINE:COL: FIELD: FRAGMENT" (FIELD may be empty) matches a diagnostic at that line and
// column of `file`, with that field, whose message contains FRAGMENT.
bool matches(const Diagnostic& d, const std::string& file, const std::string& expect) {
  const std::size_t loc_end = expect.find(": ");
  const std::size_t field_end = expect.find(": ", loc_end + 2);
  if (loc_end == std::string::npos || field_end == std::string::npos) return false;
  const std::string loc = expect.substr(0, loc_end);
  const std::string field = expect.substr(loc_end + 2, field_end - loc_end - 2);
  const std::string fragment = expect.substr(field_end + 2);
  return d.where.file == file &&
         loc == std::to_string(d.where.line) + ":" + std::to_string(d.where.column) &&
         d.field == field && contains(d.message, fragment) &&
         d.format().rfind(file + ":" + loc + ": ", 0) == 0;
}

std::string listing(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const Diagnostic& d : ds) s += "\n  " + d.format();
  return s.empty() ? " (none)" : s;
}

TEST(BadInput, CatalogueCoversEveryRequiredCase) {
  for (const char* name :
       {"malformed_yaml", "wrong_type_number", "missing_field", "unknown_kind", "duplicate_id",
        "nan", "infinity", "huge_1e308", "subnormal", "empty_polygon", "repeated_vertex",
        "non_planar", "camera_eye_is_center", "camera_up_parallel", "zbuffer_huge_grid",
        "deep_expression", "long_expression", "invalid_utf8_text", "invalid_utf8_number"})
    EXPECT_TRUE(fs::exists(test::source_path(std::string("tests/bad_inputs/") + name + ".yaml")))
        << name;
  for (const char* name : {"deep_nesting", "enormous", "invalid_utf8", "nan", "malformed_yaml"})
    EXPECT_TRUE(
        fs::exists(test::source_path(std::string("tests/bad_inputs/answers/") + name + ".yaml")))
        << name;
}

TEST(BadInput, ProblemSetsGiveTheirLocatedMessageAndTheRestSolves) {
  const std::vector<Case> all = cases("tests/bad_inputs");
  ASSERT_GE(all.size(), 25u);
  for (const Case& c : all) {
    SCOPED_TRACE(c.path);
    ASSERT_FALSE(c.expect.empty()) << "every case has '# expect:'";
    const ProblemSet set = load_problem_set(c.path);
    const SetResult result = solve_set(set, true);
    std::vector<Diagnostic> errors = result.errors;
    for (const ProblemResult& p : result.problems)
      if (p.error) errors.push_back(*p.error);
    if (c.expect[0] == "none") {
      EXPECT_TRUE(errors.empty()) << listing(errors);
    } else {
      EXPECT_EQ(errors.size(), c.expect.size()) << "exactly the expected errors" << listing(errors);
      for (const std::string& e : c.expect)
        EXPECT_TRUE(std::any_of(errors.begin(), errors.end(),
                                [&](const Diagnostic& d) { return matches(d, c.path, e); }))
            << "expected " << c.path << ":" << e << "\ngot:" << listing(errors);
    }
    for (const std::string& id : c.solves) {
      const auto it = std::find_if(result.problems.begin(), result.problems.end(),
                                   [&](const ProblemResult& p) { return p.id == id; });
      ASSERT_NE(it, result.problems.end()) << id;
      EXPECT_FALSE(it->error) << id << " still solves: " << test::error_text(*it);
      EXPECT_FALSE(it->answers.items().empty()) << id;
    }
    if (c.solves.empty()) {
      for (const ProblemResult& p : result.problems) EXPECT_TRUE(p.error) << p.id;
    }
    for (const std::string& title : c.warns) {
      const auto bad = std::find_if(result.problems.begin(), result.problems.end(),
                                    [](const ProblemResult& p) { return p.id == "bad"; });
      ASSERT_NE(bad, result.problems.end());
      const auto& steps = bad->derivation.steps();
      EXPECT_TRUE(std::any_of(
          steps.begin(), steps.end(),
          [&](const Step& s) { return s.level == Step::Level::Warning && s.title.en() == title; }))
          << "warning '" << title << "'";
    }
    // Every renderer copes with what was loaded (invalid UTF-8 included).
    EXPECT_FALSE(json_text(render_json(result)).empty());  // what solve --format json writes
    EXPECT_FALSE(render_text(result, TextStyle{}).empty());
  }
}

// "ID.ANSWER" of a grade report.
const AnswerGrade* find_answer(const GradeReport& r, const std::string& path) {
  const std::size_t dot = path.rfind('.');
  for (const ProblemGrade& p : r.problems)
    if (p.id == path.substr(0, dot))
      for (const AnswerGrade& a : p.answers)
        if (a.name == path.substr(dot + 1)) return &a;
  return nullptr;
}

TEST(BadInput, AnswerFilesGiveTheirMessageAndTheRestGrades) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  ASSERT_TRUE(set.all_errors().empty());
  const std::vector<Case> all = cases("tests/bad_inputs/answers");
  ASSERT_GE(all.size(), 10u);
  for (const Case& c : all) {
    SCOPED_TRACE(c.path);
    ASSERT_FALSE(c.expect.empty());
    const GradeReport r = grade(set, load_submission(c.path));
    for (const std::string& e : c.expect) {
      const std::vector<std::string> parts = [&] {
        std::vector<std::string> out;
        std::size_t start = 0;
        for (int k = 0; k < 2; ++k) {
          const std::size_t colon = e.find(": ", start);
          out.push_back(e.substr(start, colon - start));
          start = colon + 2;
        }
        out.push_back(e.substr(start));
        return out;
      }();
      if (const AnswerGrade* a = find_answer(r, parts[0])) {
        EXPECT_EQ(to_string(a->verdict), parts[1]) << parts[0];
        EXPECT_TRUE(contains(a->feedback.en(), parts[2]))
            << parts[0] << " feedback '" << a->feedback << "' lacks '" << parts[2] << "'";
        EXPECT_LT(a->feedback.en().size(), 1000u) << "the message quotes a bounded excerpt";
      } else {
        EXPECT_TRUE(std::any_of(r.errors.begin(), r.errors.end(),
                                [&](const Diagnostic& d) { return matches(d, c.path, e); }))
            << "expected " << c.path << ":" << e << "\ngot:" << listing(r.errors);
      }
    }
    for (const std::string& ok : c.correct) {
      const AnswerGrade* a = find_answer(r, ok);
      ASSERT_NE(a, nullptr) << ok;
      EXPECT_EQ(a->verdict, Verdict::Correct) << ok << ": " << a->feedback;
    }
    // Every problem of the set is in the report, graded or missing.
    EXPECT_EQ(r.problems.size(), set.problems.size());
    EXPECT_FALSE(json_text(render_grade_json(r)).empty());  // what grade --format json writes
  }
}

TEST(BadInput, InvisibleSpacingAfterAnAnswerLeavesItsVerdict) {
  // A form feed or a Unicode line separator pasted after a right answer: the answer is still
  // right (the character is read as a space and named once), an escape character is not text.
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const GradeReport ok = grade(
      set,
      load_submission_from_string(
          "student: s1\nanswers:\n  seed001-pixel-z: {z: 8\x0c, plane: \"x + y - z = -6\u2028\"}\n",
          "ff.yaml"));
  EXPECT_EQ(find_answer(ok, "seed001-pixel-z.z")->verdict, Verdict::Correct);
  EXPECT_EQ(find_answer(ok, "seed001-pixel-z.plane")->verdict, Verdict::Correct);
  ASSERT_EQ(ok.errors.size(), 1u) << listing(ok.errors);
  EXPECT_NE(ok.errors[0].message.find("U+000C"), std::string::npos);
  const GradeReport bad =
      grade(set, load_submission_from_string(
                     "student: s1\nanswers:\n  seed001-pixel-z: {z: 8\x1b}\n", "esc.yaml"));
  EXPECT_NE(find_answer(bad, "seed001-pixel-z.z")->verdict, Verdict::Correct);
}

TEST(BadInput, YamlEscapesForNelAndNoBreakSpaceAreCharactersInValidJson) {
  // The YAML escapes \N (NEL) and \_ (no-break space) are the characters U+0085 and U+00A0.
  // yaml-cpp once decoded them to the single bytes 0x85 and 0xA0, not UTF-8, and a message
  // quoting such a key aborted `grade --format json` (found by fuzz_grade with a fixed seed);
  // libyaml decodes them to UTF-8, and the JSON carries the characters.
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const GradeReport r =
      grade(set, load_submission_from_string(
                     "student: s1\nanswers:\n  seed001-pixel-z: {z: 8}\n\"bad\\Nkey\": 1\n"
                     "\"nb\\_sp\": 2\n",
                     "nel.yaml"));
  ASSERT_EQ(r.errors.size(), 2u) << listing(r.errors);
  EXPECT_EQ(r.errors[0].field, "bad\u0085key");
  const std::string text = json_text(render_grade_json(r));
  const nlohmann::json back = nlohmann::json::parse(text);  // valid UTF-8 all through
  EXPECT_NE(back["errors"][0].get<std::string>().find("bad\u0085key"), std::string::npos) << text;
  EXPECT_NE(back["errors"][1].get<std::string>().find("nb\u00A0sp"), std::string::npos) << text;
  // The answers that could be read are still graded.
  EXPECT_EQ(find_answer(r, "seed001-pixel-z.z")->verdict, Verdict::Correct);
}

}  // namespace
}  // namespace frustum
