#include "grader/csv.hpp"

namespace frustum {

CsvTable parse_csv(const std::string& text) {
  CsvTable table;
  std::size_t i = text.rfind("\xEF\xBB\xBF", 0) == 0 ? 3 : 0;
  int line = 1;
  CsvRow row{line, {}};
  std::string field;
  bool quoted = false, field_started = false;
  int quote_line = 0;
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
  for (; i < text.size(); ++i) {
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
        if (c == '\n') ++line;
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
        end_row();
        break;
      default:
        field += c;
        field_started = true;
    }
  }
  if (quoted) {
    table.error = "line " + std::to_string(quote_line) + ": unterminated quoted field";
    return table;
  }
  if (field_started || !row.fields.empty()) end_row();
  return table;
}

std::string csv_field(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string out = "\"";
  for (const char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_row(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + csv_field(fields[i]);
  return out + "\n";
}

}  // namespace frustum
