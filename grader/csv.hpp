// CSV as RFC 4180 writes it: comma-separated fields, double quotes around fields that hold a
// comma, quote or line break, quotes doubled inside. Used for class rosters of answers and for
// the gradebook.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frustum {

struct CsvRow {
  int line = 0;  // 1-based line where the row starts
  std::vector<std::string> fields;
};

struct CsvTable {
  std::vector<CsvRow> rows;
  std::optional<std::string> error;  // "line N: unterminated quoted field"
};

// Reads a whole CSV text; a UTF-8 byte-order mark and CRLF line ends are accepted.
CsvTable parse_csv(const std::string& text);

// One field, quoted when it needs to be; and a whole row ending in "\n".
std::string csv_field(const std::string& field);
std::string csv_row(const std::vector<std::string>& fields);

}  // namespace frustum
