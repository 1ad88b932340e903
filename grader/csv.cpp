#include "grader/csv.hpp"

#include <cctype>
#include <string_view>

#include "solver/util/diagnostic.hpp"

namespace frustum {

CsvTable parse_csv(const std::string& text) {
  CsvTable table;
  std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  int line = 1;
  CsvRow row{line, {}};
  std::string field;
  bool quoted = false, field_started = false;
  int quote_line = 0, quote_column = 0, column = 1;
  const auto end_field = [&] {
    row.fields.push_back(std::move(field));
    field.clear();
    field_started = false;
  };
  const auto end_row = [&] {
    end_field();
    // A blank line is no row.
    if (!(row.fields.size() == 1 && row.fields[0].empty())) table.rows.push_back(std::move(row));
    row = CsvRow{line, {}};
  };
  for (; i < text.size(); ++i, ++column) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        if (c == '\n') ++line, column = 0;
        field += c;
      }
      continue;
    }
    switch (c) {
      case '"':
        if (!field_started) {
          quoted = true;
          field_started = true;
          quote_line = line;
          quote_column = column;
        } else {
          field += c;  // a stray quote inside an unquoted field is kept as written
        }
        break;
      case ',':
        end_field();
        break;
      case '\r':
        break;
      case '\n':
        ++line;
        column = 0;
        end_row();
        break;
      default:
        field += c;
        field_started = true;
    }
  }
  if (quoted) {
    table.error = "line " + std::to_string(quote_line) + ": unterminated quoted field";
    table.error_line = quote_line;
    table.error_column = quote_column;
    return table;
  }
  if (field_started || !row.fields.empty()) end_row();
  return table;
}

CsvRoster parse_csv_roster(const std::string& path, const std::string& text) {
  CsvRoster roster;
  roster.table = parse_csv(text);
  const CsvTable& table = roster.table;
  if (table.error)
    throw InputError(
        Diagnostic{SourceLocation{path, table.error_line, table.error_column}, "", *table.error});
  if (table.rows.empty())
    throw InputError(
        Diagnostic{SourceLocation{path, 1, 1}, "", "empty CSV: expected a header row"});
  const CsvRow& header = table.rows[0];
  for (std::size_t i = 0; i < header.fields.size(); ++i) {
    std::string h = header.fields[i];
    for (char& c : h) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (h == "student") roster.student_columns.push_back(i);
  }
  return roster;
}

void require_student_column(const std::string& path, const CsvRoster& roster) {
  if (roster.student_columns.empty())
    throw InputError(Diagnostic{SourceLocation{path, roster.table.rows[0].line, 1}, "header",
                                "no 'student' column"});
}

std::string csv_field(const std::string& field) {
  // A field that starts with U+FEFF is quoted too: first in a file, a reader takes those bytes
  // for a byte-order mark and drops them (found by fuzz_csv_roster).
  if (field.find_first_of(",\"\r\n") == std::string::npos && field.rfind("\xEF\xBB\xBF", 0) != 0)
    return field;
  std::string out = "\"";
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_row(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i)
    out += (i ? "," : "") + csv_field(csv_neutralise(fields[i]));
  return out + "\n";
}

std::string csv_neutralise(const std::string& field) {
  if (field.empty() || std::string_view("=+-@\t\r").find(field[0]) == std::string_view::npos)
    return field;
  // A signed decimal number is data, not a formula.
  std::size_t i = 1, digits = 0;
  const auto run = [&] {
    const std::size_t start = i;
    while (i < field.size() && field[i] >= '0' && field[i] <= '9') ++i;
    return i - start;
  };
  if (field[0] == '+' || field[0] == '-') {
    digits = run();
    if (i < field.size() && field[i] == '.') ++i, digits += run();
    if (digits > 0 && i < field.size() && (field[i] == 'e' || field[i] == 'E')) {
      ++i;
      if (i < field.size() && (field[i] == '+' || field[i] == '-')) ++i;
      if (run() == 0) digits = 0;
    }
    if (digits > 0 && i == field.size()) return field;
  }
  return "'" + field;
}

}  // namespace frustum
