#include "batch/csv.hpp"

#include <fmt/format.h>

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
  int field_line = 1, field_column = 1;  // where the current field starts
  std::size_t cells = 0;
  const auto fail = [&](int at_line, int at_column, const std::string& what) {
    table.rows.clear();
    table.error = fmt::format("line {}: {}", at_line, what);
    table.error_line = at_line;
    table.error_column = at_column;
  };
  const auto too_long = [&] {
    fail(field_line, field_column,
         fmt::format("a field of more than {} bytes (the limit is {} bytes a field)",
                     kMaxCsvCellBytes, kMaxCsvCellBytes));
  };
  const auto end_field = [&] {
    if (field.size() > kMaxCsvCellBytes) {
      too_long();
      return false;
    }
    if (row.fields.size() == kMaxCsvColumns) {
      fail(field_line, field_column,
           fmt::format("more than {} fields in one row (the limit is {} columns)", kMaxCsvColumns,
                       kMaxCsvColumns));
      return false;
    }
    if (++cells > kMaxCsvCells) {
      fail(field_line, field_column,
           fmt::format("more than {} fields in all (the limit is {} cells)", kMaxCsvCells,
                       kMaxCsvCells));
      return false;
    }
    row.fields.push_back(std::move(field));
    field.clear();
    field_started = false;
    field_line = line;
    field_column = column + 1;
    return true;
  };
  const auto end_row = [&] {
    if (!end_field()) return false;
    // A blank line is no row.
    if (!(row.fields.size() == 1 && row.fields[0].empty())) {
      if (table.rows.size() == kMaxCsvRows) {
        fail(row.line, 1,
             fmt::format("more than {} rows (the limit is {} rows)", kMaxCsvRows, kMaxCsvRows));
        return false;
      }
      table.rows.push_back(std::move(row));
    } else {
      --cells;
    }
    row = CsvRow{line, {}};
    field_line = line;
    field_column = 1;
    return true;
  };
  for (; i < text.size(); ++i, ++column) {
    const char c = text[i];
    if (field.size() > kMaxCsvCellBytes) {
      too_long();
      return table;
    }
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
        if (!end_field()) return table;
        break;
      case '\r':
        break;
      case '\n':
        ++line;
        column = 0;
        if (!end_row()) return table;
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
