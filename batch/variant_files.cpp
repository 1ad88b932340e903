#include "batch/variant_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "batch/file_names.hpp"
#include "grader/student_id.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace fs = std::filesystem;

std::string variant_name(const std::string& student) { return file_name_for(student); }

std::string variant_file(const std::string& dir, const std::string& set_path,
                         const std::string& name) {
  return (fs::path(dir) / (fs::path(set_path).stem().string() + "-" + name + ".yaml")).string();
}

std::string variant_key_file(const std::string& dir, const std::string& set_path,
                             const std::string& name) {
  return (fs::path(dir) / "answers" / (fs::path(set_path).stem().string() + "-" + name + ".yaml"))
      .string();
}

std::vector<std::string> read_roster(const std::string& path) {
  // Bounded and a regular file, as every input is (a FIFO or /dev/zero once read forever).
  std::string contents;
  if (const std::optional<Diagnostic> d = read_text_file(path, kMaxRosterBytes, contents))
    throw InputError(*d);
  std::vector<std::tuple<int, int, std::string>> ids;  // line, column, id
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (ext == ".csv") {
    // A roster that names 'student' in more than one column takes its ids from the last.
    const CsvRoster roster = parse_csv_roster(path, contents);
    require_student_column(path, roster);
    const CsvTable& table = roster.table;
    const std::size_t col = roster.student_columns.back();
    for (std::size_t r = 1; r < table.rows.size(); ++r) {
      const CsvRow& row = table.rows[r];
      if (col < row.fields.size() && !row.fields[col].empty())
        ids.emplace_back(row.line, static_cast<int>(col) + 1, row.fields[col]);
    }
  } else {
    std::istringstream lines(contents);
    std::string line;
    for (int n = 1; std::getline(lines, line); ++n) {
      const auto first = line.find_first_not_of(" \t\r");
      if (first == std::string::npos || line[first] == '#') continue;
      if (ids.size() == kMaxCsvRows)
        throw InputError(Diagnostic{
            SourceLocation{path, n, 1}, "student",
            fmt::format("more than {} students (the limit is {} rows)", kMaxCsvRows, kMaxCsvRows)});
      const auto last = line.find_last_not_of(" \t\r");
      ids.emplace_back(n, static_cast<int>(first) + 1, line.substr(first, last - first + 1));
    }
  }
  if (ids.empty())
    throw InputError(
        Diagnostic{SourceLocation{path, 1, 1}, "student", "the roster names no student"});
  // Ids as every reader of ids takes them (trimmed, refused when no student can have them), and
  // one student up to case, spaces and Unicode form (student_id_key).
  std::map<std::string, std::pair<int, std::string>> first;  // key → line, id
  std::vector<std::string> out;
  for (const auto& [line, column, written] : ids) {
    const StudentId read = read_student_id(written);
    const SourceLocation where{path, line, column};
    if (read.problem) throw InputError(Diagnostic{where, "student", *read.problem});
    const std::string& id = read.id;
    if (const auto [it, fresh] = first.emplace(student_id_key(id), std::pair{line, id}); !fresh)
      throw InputError(Diagnostic{
          where, "student",
          fmt::format("'{}' is listed twice (first on line {}{})", id, it->second.first,
                      it->second.second == id ? "" : " as '" + it->second.second + "'")});
    out.push_back(id);
  }
  return out;
}

}  // namespace frustum
