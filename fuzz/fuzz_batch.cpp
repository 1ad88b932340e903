// libFuzzer target: a class directory built from the bytes (answer files, symlinks to each
// other, to themselves and to missing files, subdirectories, FIFOs, hostile names and ids) is
// collected and graded as a batch into a fresh output directory, twice (the second run
// replaces the first). Whatever the class holds, the batch must finish with one row per entry
// and a gradebook whose `file` column names a feedback page for every row.
//
// Input: records separated by a NUL byte; each record's first byte picks what it becomes
// ('l' symlink to the record named by the next byte, 's' symlink to itself, 'm' dangling
// symlink, 'd' directory, 'p' FIFO, anything else a file whose content is the rest).
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "fuzz/fuzz_records.hpp"

namespace {

namespace fs = std::filesystem;

const frustum::ProblemSet& set() {
  static const frustum::ProblemSet s = frustum::load_problem_set_from_string(
      "problems:\n  - id: zbuf\n    kind: depth_at_pixel\n"
      "    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}\n"
      "    ask: [plane, z]\n",
      "set.yaml");
  return s;
}

std::string name_of(std::size_t i) {
  return "s" + std::to_string(i) + (i % 3 == 2 ? ".yml" : ".yaml");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 64 * 1024) return 0;
  char root_template[] = "/tmp/frustum-fuzz-batch-XXXXXX";
  if (!mkdtemp(root_template)) return 0;
  const fs::path root(root_template), in = root / "class";
  fs::create_directories(in);
  const std::vector<std::string> records = frustum::fuzz::records(data, size, 24);
  for (std::size_t i = 0; i < records.size(); ++i) {
    const std::string& r = records[i];
    const fs::path p = in / name_of(i);
    const char kind = r.empty() ? 'f' : r[0];
    std::error_code ec;
    if (kind == 'l' && r.size() > 1)
      fs::create_symlink(name_of(static_cast<unsigned char>(r[1]) % records.size()), p, ec);
    else if (kind == 's')
      fs::create_symlink(p.filename(), p, ec);
    else if (kind == 'm')
      fs::create_symlink("missing.yaml", p, ec);
    else if (kind == 'd')
      fs::create_directories(p, ec);
    else if (kind == 'p')
      mkfifo(p.c_str(), 0600);
    else
      std::ofstream(p, std::ios::binary) << r.substr(r.empty() ? 0 : 1);
  }
  try {
    const std::vector<frustum::BatchEntry> entries = frustum::collect_submissions(in.string());
    frustum::BatchOptions options;
    options.out_dir = (root / "out").string();
    options.timeout_seconds = 5;
    for (int run = 0; run < 2; ++run) {
      const frustum::BatchResult result = frustum::grade_batch(set(), entries, options);
      if (result.rows.size() != entries.size()) std::abort();
      std::ifstream book(root / "out" / "gradebook.csv", std::ios::binary);
      const std::string text((std::istreambuf_iterator<char>(book)),
                             std::istreambuf_iterator<char>());
      const frustum::CsvTable table = frustum::parse_csv(text);
      if (table.error || table.rows.size() != entries.size() + 1) std::abort();
      std::set<std::string> names;
      for (std::size_t r = 1; r < table.rows.size(); ++r) {
        const std::string& file = table.rows[r].fields.back();
        if (!names.insert(file).second) std::abort();  // two rows, one file
        if (!fs::exists(root / "out" / "feedback" / (file + ".md"))) std::abort();
      }
    }
  } catch (const frustum::InputError&) {
  }
  std::error_code ec;
  fs::remove_all(root, ec);
  return 0;
}
