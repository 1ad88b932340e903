// libFuzzer target: a CSV roster of answers from arbitrary bytes. Reading it either fails with
// a message located in the CSV or gives one entry per row whose YAML grading can read; and
// every row written by csv_row reads back as the neutralised fields.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "grader/grade.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const frustum::CsvTable table = frustum::parse_csv(text);
  if (table.error && (table.error_line < 1 || table.error_column < 1)) std::abort();
  // Writing and reading back: any fields survive, as csv_neutralise leaves them.
  if (!table.error)
    for (const frustum::CsvRow& row : table.rows) {
      const frustum::CsvTable back = frustum::parse_csv(frustum::csv_row(row.fields));
      std::vector<std::string> expected;
      for (const std::string& f : row.fields) expected.push_back(frustum::csv_neutralise(f));
      // A row of one empty field is a blank line, which CSV does not keep; a field at the
      // length limit may be one byte longer neutralised, and then is refused.
      if (expected.size() == 1 && expected[0].empty()) continue;
      if (std::any_of(expected.begin(), expected.end(),
                      [](const std::string& f) { return f.size() > frustum::kMaxCsvCellBytes; }))
        continue;
      if (back.error || back.rows.size() != 1 || back.rows[0].fields != expected) std::abort();
    }
  const std::string path = "/tmp/frustum-fuzz-roster-" + std::to_string(getpid()) + ".csv";
  std::ofstream(path, std::ios::binary) << text;
  try {
    for (const frustum::BatchEntry& e : frustum::collect_submissions(path)) {
      if (e.error) continue;
      (void)frustum::load_submission_from_string(e.yaml, e.source);
    }
  } catch (const frustum::InputError& e) {
    if (e.diagnostic().where.file != path) std::abort();
  }
  unlink(path.c_str());
  return 0;
}
