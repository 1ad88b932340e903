#include "server/instructors.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "batch/csv.hpp"
#include "grader/student_id.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::server {

namespace {

constexpr std::size_t kMaxInstructorsBytes = 1u << 20;

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

}  // namespace

std::vector<std::string> read_instructors(const std::string& path) {
  std::string text;
  if (const auto error = read_text_file(path, kMaxInstructorsBytes, text)) throw InputError(*error);
  const CsvTable table = parse_csv(text);
  if (table.error)
    throw InputError(
        Diagnostic{SourceLocation{path, table.error_line, table.error_column}, "", *table.error});
  std::size_t column = 0;
  bool found = false;
  if (!table.rows.empty())
    for (std::size_t c = 0; c < table.rows[0].fields.size(); ++c)
      if (lower(table.rows[0].fields[c]) == "instructor") {
        column = c;
        found = true;
      }
  if (!found)
    throw InputError(Diagnostic{SourceLocation{path, 1, 1}, "instructor",
                                "the header names no 'instructor' column"});
  std::vector<std::string> out;
  std::set<std::string> seen;
  for (std::size_t r = 1; r < table.rows.size(); ++r) {
    const CsvRow& row = table.rows[r];
    if (column >= row.fields.size() || row.fields[column].empty()) continue;
    const SourceLocation at{path, row.line, static_cast<int>(column) + 1};
    const StudentId id = read_student_id(row.fields[column]);
    if (id.problem) throw InputError(Diagnostic{at, "instructor", *id.problem});
    if (!seen.insert(student_id_key(id.id)).second)
      throw InputError(Diagnostic{at, "instructor", "'" + id.id + "' is listed twice"});
    if (out.size() == kMaxInstructors)
      throw InputError(Diagnostic{at, "instructor",
                                  "more than " + std::to_string(kMaxInstructors) + " instructors"});
    out.push_back(id.id);
  }
  return out;
}

}  // namespace frustum::server
