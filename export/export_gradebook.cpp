#include "export/export_gradebook.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <vector>

#include "batch/csv.hpp"
#include "grader/student_id.hpp"
#include "grader/visible_text.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/expression.hpp"

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

// A row of the import: every cell as visible text (a score or an assignment name from a
// hand-edited gradebook is text from outside too).
std::string import_row(std::vector<std::string> cells) {
  return csv_row(visible_cells(std::move(cells)));
}

}  // namespace

std::string export_gradebook(const std::string& text, const std::string& file,
                             GradebookFormat format, const std::string& assignment, StudentKey key,
                             std::vector<std::string>* left_out) {
  const CsvTable table = parse_csv(text);
  if (table.error) throw InputError(Diagnostic{SourceLocation{file, 0, 0}, "", *table.error});
  if (table.rows.empty())
    throw InputError(Diagnostic{SourceLocation{file, 1, 1}, "", "the gradebook is empty"});
  const CsvRow& header = table.rows[0];
  const std::size_t student = column(header, "student", file),
                    score = column(header, "score", file),
                    max_score = column(header, "max_score", file),
                    status = column(header, "status", file);
  std::map<std::string, std::pair<int, std::string>> seen;  // student_id_key → line, id
  std::string points_possible;
  std::vector<std::pair<std::string, std::string>> grades;  // student, score or ""
  for (std::size_t i = 1; i < table.rows.size(); ++i) {
    const CsvRow& row = table.rows[i];
    const auto field = [&](std::size_t c) {
      return c < row.fields.size() ? row.fields[c] : std::string();
    };
    if (field(student).empty())
      continue;  // a submission whose id was refused: nobody to file it under
    // The id as `frustum grade` reads ids: one that could name no student is refused, and ids
    // that are one student up to case, spaces or Unicode form are that student's two rows.
    const StudentId read = read_student_id(field(student));
    const SourceLocation where{file, row.line, static_cast<int>(student) + 1};
    if (read.problem) throw InputError(Diagnostic{where, "student", *read.problem});
    const std::string& id = read.id;
    if (const auto [it, fresh] = seen.emplace(student_id_key(id), std::pair{row.line, id}); !fresh)
      throw InputError(Diagnostic{
          where, "student",
          fmt::format(
              "student {} is also on line {}{}; keep one row per student before importing",
              quote_excerpt(id), it->second.first,
              it->second.second == id ? "" : " (as " + quote_excerpt(it->second.second) + ")")});
    const bool graded = field(status) == "graded";
    grades.emplace_back(id, graded ? field(score) : "");
    if (graded && points_possible.empty()) points_possible = field(max_score);
  }
  // An id that a spreadsheet would run as a formula (=, +, -, @ …) cannot be written as it is,
  // and with the spreadsheet's guard (') it names no student the LMS knows: such a row is left
  // out and named, for the grade to be entered by hand.
  std::vector<std::pair<std::string, std::string>> kept;
  for (const auto& [id, s] : grades) {
    if (csv_neutralise(id) == id) {
      kept.emplace_back(id, s);
    } else if (left_out) {
      left_out->push_back(fmt::format(
          "student {} left out: an id starting with {} would run as a formula in a spreadsheet, "
          "and with the guard ' the LMS would match no student; enter the grade ({}) by hand",
          quote_excerpt(id), id.substr(0, 1), s.empty() ? "none" : s));
    }
  }
  std::string out;
  if (format == GradebookFormat::Canvas) {
    out = import_row({"Student", "ID", "SIS User ID", "SIS Login ID", "Section", assignment});
    out += import_row({"Points Possible", "", "", "", "", points_possible});
    for (const auto& [id, s] : kept)
      out += key == StudentKey::SisUserId ? import_row({"", "", id, "", "", s})
                                          : import_row({"", "", "", id, "", s});
  } else {
    out = import_row({"ID number", assignment});
    for (const auto& [id, s] : kept) out += import_row({id, s});
  }
  return out;
}

}  // namespace frustum
