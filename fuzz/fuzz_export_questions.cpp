// libFuzzer target: whatever the problems' ids, every export keeps every question under a name
// of its own. The bytes are up to eight ids separated by NUL, each written as it is when it is
// text without control characters (any code point), else byte by byte as YAML \u escapes (C0,
// DEL, C1); a set of that many small z-buffer problems is
// exported to PrairieLearn (a directory per question: as many as problems, distinct without
// case, each one plain file name), QTI (an item per answer field), Moodle XML (a category per
// problem, read back as Moodle splits its path), Gradescope's results (a test per problem) and
// the exam sheets (a section per problem). Aborts, naming the export, when one loses a question.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <vector>

#include "export/export_moodle.hpp"
#include "export/export_prairielearn.hpp"
#include "export/export_qti.hpp"
#include "export/paper.hpp"
#include "export/quiz_items.hpp"
#include "fuzz/fuzz_records.hpp"
#include "grader/visible_text.hpp"
#include "report/gradescope.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/util/words.hpp"

namespace {

[[noreturn]] void lost(const char* where, std::size_t got, std::size_t want) {
  std::fprintf(stderr, "fuzz_export_questions: %s has %zu questions of %zu\n", where, got, want);
  std::abort();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Moodle's reading of a category path: levels split at a '/' that is not doubled, "//" a '/'.
std::string moodle_path(const std::string& path) {
  std::string out;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i] == '/' && i + 1 < path.size() && path[i + 1] == '/') {
      out += "\x01";  // a slash inside a name
      ++i;
    } else {
      out += path[i];
    }
  }
  return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 512) return 0;
  const std::vector<std::string> ids = frustum::fuzz::records(data, size, 8);
  std::string yaml = "title: t\nproblems:\n";
  for (std::size_t i = 0; i < ids.size(); ++i) {
    // Text as it is (any code point), or every byte a \u escape (C0, DEL, C1).
    const bool plain = !frustum::first_hidden(ids[i]);
    std::string id;
    for (const char c : ids[i]) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04X", static_cast<unsigned char>(c));
      id += plain ? (c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c))
                  : std::string(buf);
    }
    yaml += "  - {id: \"" + id + "\", kind: depth_at_pixel, given: {triangle: [[0,0," +
            std::to_string(i + 1) + "],[4,0,1],[0,4,1]], pixel: [1,1]}}\n";
  }
  const frustum::YamlDocument doc = frustum::parse_yaml(yaml, "t.yaml");
  const frustum::ProblemSet set = frustum::load_problem_set(doc, "t.yaml");
  if (!set.all_errors().empty()) return 0;  // an empty or repeated id: refused, as it must be
  const std::size_t n = set.problems.size();

  const auto pl = frustum::export_prairielearn(doc.root, set, {set}, "t", {});
  std::set<std::string> dirs;
  for (const auto& [dir, files] : pl) {
    if (dir.empty() || dir.size() > 255 || dir.find('/') != std::string::npos || dir[0] == '.')
      lost("PrairieLearn (a directory name that is not one plain name)", 0, n);
    dirs.insert(frustum::ascii_lower(dir));
  }
  if (pl.size() != n) lost("PrairieLearn", pl.size(), n);
  if (dirs.size() != n) lost("PrairieLearn (without case)", dirs.size(), n);

  const std::vector<frustum::QuizQuestion> qs = frustum::quiz_questions(set);
  if (qs.size() != n) lost("the quiz questions", qs.size(), n);
  // QTI: one item per problem with a field a quiz can check.
  std::size_t asked = 0;
  for (const frustum::QuizQuestion& q : qs) asked += !q.answers.empty();
  const std::string qti = frustum::export_qti({{"", qs}}, "t", "frustum_t").at("frustum_t.xml");
  if (count(qti, "<item ident=") != asked) lost("QTI (items)", count(qti, "<item ident="), asked);

  const std::string moodle = frustum::export_moodle({{"", qs}}, "t");
  std::set<std::string> categories;
  const std::string open = "<category><text>";
  for (std::size_t at = moodle.find(open); at != std::string::npos;
       at = moodle.find(open, at + 1)) {
    const std::size_t start = at + open.size();
    categories.insert(moodle_path(moodle.substr(start, moodle.find("</text>", start) - start)));
  }
  if (categories.size() != n) lost("Moodle (categories)", categories.size(), n);
  for (const std::string& c : categories)
    if (count(c, "/") != 3) lost("Moodle (a category nested in another)", 0, n);

  const frustum::GradeReport report = frustum::grade(
      set, frustum::load_submission_from_string("student: s\nanswers: {}\n", "a.yaml"));
  std::set<std::string> tests;
  const nlohmann::ordered_json results = frustum::gradescope_results(report);
  for (const auto& t : results["tests"]) tests.insert(t["name"].get<std::string>());
  if (tests.size() != n) lost("Gradescope (tests)", tests.size(), n);

  const std::string sheets = frustum::exam_sheets_latex({{"s", set}}, "t");
  if (count(sheets, "\\subsection*") != n)
    lost("the exam sheets", count(sheets, "\\subsection*"), n);
  return 0;
}
