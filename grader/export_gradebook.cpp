#include "grader/export_gradebook.hpp"

#include <algorithm>
#include <map>
#include <vector>

#include "grader/csv.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

std::size_t column(const CsvRow& header, const std::string& name, const std::string& file) {
  const auto it = std::find(header.fields.begin(), header.fields.end(), name);
  if (it == header.fields.end())
    throw InputError(Diagnostic{
        SourceLocation{file, header.line, 1}, name,
        "no '" + name + "' column: expected the gradebook.csv that `frustum grade` writes"});
  return static_cast<std::size_t>(it - header.fields.begin());
}

}  // namespace

std::string export_gradebook(const std::string& text, const std::string& file,
                             GradebookFormat format, const std::string& assignment,
                             StudentKey key) {
  const CsvTable table = parse_csv(text);
  if (table.error) throw InputError(Diagnostic{SourceLocation{file, 0, 0}, "", *table.error});
  if (table.rows.empty())
    throw InputError(Diagnostic{SourceLocation{file, 1, 1}, "", "the gradebook is empty"});
  const CsvRow& header = table.rows[0];
  const std::size_t student = column(header, "student", file),
                    score = column(header, "score", file),
                    max_score = column(header, "max_score", file),
                    status = column(header, "status", file);
  std::map<std::string, int> seen;  // student → line
  std::string points_possible;
  std::vector<std::pair<std::string, std::string>> grades;  // student, score or ""
  for (std::size_t i = 1; i < table.rows.size(); ++i) {
    const CsvRow& row = table.rows[i];
    const auto field = [&](std::size_t c) {
      return c < row.fields.size() ? row.fields[c] : std::string();
    };
    const std::string id = field(student);
    if (id.empty())
      continue;  // an unreadable submission with no student id: nobody to file it under
    if (const auto [it, fresh] = seen.emplace(id, row.line); !fresh)
      throw InputError(Diagnostic{SourceLocation{file, row.line, 1}, "student",
                                  "student " + id + " is also on line " +
                                      std::to_string(it->second) +
                                      "; keep one row per student before importing"});
    const bool graded = field(status) == "graded";
    grades.emplace_back(id, graded ? field(score) : "");
    if (graded && points_possible.empty()) points_possible = field(max_score);
  }
  std::string out;
  if (format == GradebookFormat::Canvas) {
    out = csv_row({"Student", "ID", "SIS User ID", "SIS Login ID", "Section", assignment});
    out += csv_row({"Points Possible", "", "", "", "", points_possible});
    for (const auto& [id, s] : grades)
      out += key == StudentKey::SisUserId ? csv_row({"", "", id, "", "", s})
                                          : csv_row({"", "", "", id, "", s});
  } else {
    out = csv_row({"ID number", assignment});
    for (const auto& [id, s] : grades) out += csv_row({id, s});
  }
  return out;
}

}  // namespace frustum
