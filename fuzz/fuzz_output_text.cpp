// libFuzzer target: whatever the student ids and file names, every output of a batch is UTF-8
// without a control character (but LF, and TAB in the pages), a gradebook row is one line, and
// so is every row of its Canvas import. The bytes make a small class: records separated by NUL,
// each a file name and, after a byte 0x01, its `student:` as written (the next byte picks how:
// 'r' its raw bytes in double quotes, 'u' each byte as a YAML \u escape, so that C0, DEL and C1
// reach the id, 'p' a plain scalar); a record without 0x01 has no `student:` (the name is the id).
// Aborts on the first output that breaks the rule, naming it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "export/export_gradebook.hpp"
#include "fuzz/fuzz_records.hpp"
#include "grader/visible_text.hpp"

namespace {

namespace fs = std::filesystem;

const frustum::ProblemSet& set() {
  static const frustum::ProblemSet s = frustum::load_problem_set_from_string(
      "problems:\n  - id: zbuf\n    kind: depth_at_pixel\n"
      "    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}\n"
      "    ask: [z]\n",
      "set.yaml");
  return s;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

[[noreturn]] void broken(const std::string& what, const fs::path& file) {
  std::fprintf(stderr, "fuzz_output_text: %s in %s\n", what.c_str(), file.c_str());
  std::abort();
}

void check_visible(const std::string& text, const fs::path& file, frustum::Breaks breaks) {
  if (const auto h = frustum::first_hidden(text, breaks))
    broken(frustum::describe(*h) + " at byte " + std::to_string(h->offset), file);
}

// A CSV this program wrote: visible, one line per row.
void check_csv(const std::string& text, const fs::path& file, std::size_t rows) {
  check_visible(text, file, frustum::Breaks::Kept);
  if (text.find('\t') != std::string::npos) broken("a tab", file);
  std::size_t lines = 0;
  for (const char c : text) lines += c == '\n';
  if (lines != rows) broken(std::to_string(lines) + " lines for " + std::to_string(rows), file);
}

std::string student_line(const std::string& how_and_id) {
  const char how = how_and_id.empty() ? 'r' : how_and_id[0];
  const std::string id = how_and_id.substr(how_and_id.empty() ? 0 : 1);
  std::string out = "student: ";
  if (how == 'p') return out + id + "\n";
  out += '"';
  for (const char c : id) {
    const auto u = static_cast<unsigned char>(c);
    if (how == 'u') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04X", u);
      out += buf;
    } else {
      if (c == '"' || c == '\\') out += '\\';
      out += c;
    }
  }
  return out + "\"\n";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 4096) return 0;
  char root_template[] = "/tmp/frustum-fuzz-text-XXXXXX";
  if (!mkdtemp(root_template)) return 0;
  const fs::path root(root_template), in = root / "class";
  fs::create_directories(in);
  const std::vector<std::string> records = frustum::fuzz::records(data, size, 6);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string& r = records[i];
    const std::size_t cut = r.find('\x01');
    std::string name = r.substr(0, std::min<std::size_t>(cut, 80));
    for (char& c : name)
      if (c == '/') c = '_';
    // Distinct, never hidden, never "." or "..": the record's number first.
    name = std::to_string(i) + name + ".yaml";
    const std::string head = cut == std::string::npos ? "" : student_line(r.substr(cut + 1));
    std::ofstream(in / name, std::ios::binary) << head << "answers:\n  zbuf: {z: 8}\n";
  }
  try {
    const std::vector<frustum::BatchEntry> entries = frustum::collect_submissions(in.string());
    frustum::BatchOptions options;
    options.out_dir = (root / "out").string();
    options.timeout_seconds = 5;
    options.jobs = 1;
    const frustum::BatchResult result = frustum::grade_batch(set(), entries, options);
    if (result.rows.size() != entries.size()) std::abort();
    for (const auto& e : fs::recursive_directory_iterator(root / "out")) {
      if (!e.is_regular_file() || e.path().string().find("/katex/") != std::string::npos) continue;
      // A run's record of its files (name hashes) is the transaction's state, not an output.
      if (e.path().parent_path().filename() == ".frustum" &&
          e.path().filename().string().rfind("files-", 0) == 0)
        continue;
      const std::string text = read(e.path());
      if (e.path().extension() == ".csv")
        check_csv(text, e.path(), entries.size() + 1);
      else
        check_visible(text, e.path(), frustum::Breaks::Kept);
    }
    const fs::path book = root / "out" / "gradebook.csv";
    try {
      const std::string canvas = frustum::export_gradebook(read(book), book.string(),
                                                           frustum::GradebookFormat::Canvas, "A");
      std::size_t imported = 0;
      for (const frustum::BatchRow& r : result.rows) imported += !r.student.empty();
      check_csv(canvas, "canvas import", imported + 2);
    } catch (const frustum::InputError&) {
      // Two rows of one student: refused, as it must be.
    }
  } catch (const frustum::InputError&) {
  }
  std::error_code ec;
  fs::remove_all(root, ec);
  return 0;
}
