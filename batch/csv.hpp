// CSV as RFC 4180 writes it: comma-separated fields, double quotes around fields that hold a
// comma, quote or line break, quotes doubled inside. Used for class rosters of answers and for
// the gradebook.
#pragma once

#include <cstddef>
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
  std::optional<std::string> error;      // "line N: unterminated quoted field"
  int error_line = 0, error_column = 0;  // where the error is (1-based)
};

// Limits of a CSV text, checked while it is read (one pass, linear in its bytes): a roster of
// answers has a column per answer of the set and a row per student, so these are far beyond
// any class, and they keep the rows' memory small (an empty field costs 32 bytes, and without
// kMaxCsvCells the 64 MiB a roster may hold could make 32 million of them).
inline constexpr std::size_t kMaxCsvColumns = 10'000;      // fields in one row
inline constexpr std::size_t kMaxCsvRows = 100'000;        // rows, the header included
inline constexpr std::size_t kMaxCsvCells = 4'000'000;     // fields in all the rows
inline constexpr std::size_t kMaxCsvCellBytes = 1u << 16;  // bytes in one field (64 KiB)

// Reads a whole CSV text; a UTF-8 byte-order mark and CRLF line ends are accepted. Going past a
// limit above is an error at the field where it happens, naming the limit.
CsvTable parse_csv(const std::string& text);

// A roster in CSV: a header row that names a 'student' column, then one row per student
// (class rosters of student ids for generate/grade --roster, and rosters of answers).
struct CsvRoster {
  CsvTable table;                            // rows[0] is the header
  std::vector<std::size_t> student_columns;  // header fields named 'student' (any case)
};

// Parses `text`, the contents of the CSV file `path`. A CSV syntax error and a file without a
// header row are InputErrors located in `path`.
CsvRoster parse_csv_roster(const std::string& path, const std::string& text);

// Throws the InputError for a roster whose header names no 'student' column (located at the
// header), so that a caller checking other header fields first can report those first.
void require_student_column(const std::string& path, const CsvRoster& roster);

// One field, quoted when it needs to be; and a whole row ending in "\n", every field
// neutralised (csv_neutralise) first.
std::string csv_field(const std::string& field);
std::string csv_row(const std::vector<std::string>& fields);

// A cell a spreadsheet will show, not run: text that starts with =, +, -, @, a tab or a
// carriage return gets a leading ' (OWASP's rule against CSV formula injection: a student id
// "=HYPERLINK(...)" would otherwise be a live formula in the instructor's gradebook). Plain
// numbers ("-6", "+1.5e3") are left as they are.
std::string csv_neutralise(const std::string& field);

}  // namespace frustum
