// libFuzzer target, a property: a student's result depends on that student's file alone. The
// bytes make one student's answers file (the first record) and hostile neighbours (the others:
// any bytes, files claiming the same id or another, unreadable files, directories, FIFOs); the
// class is graded against a set with per-student variants, the way `frustum grade` grades it
// without --variants or --roster, and the first student's row (status, score, each problem's
// score) must equal the row of the same file graded in a class of its own. Aborts otherwise.
//
// Input: records separated by a NUL byte; a neighbour's first byte picks what it becomes
// ('d' directory, 'p' FIFO, 'c' a file claiming the first student's id with the rest as its
// answers, anything else a file whose content is the rest).
#include <sys/stat.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "fuzz/fuzz_records.hpp"
#include "solver/problem/variants.hpp"

namespace {

namespace fs = std::filesystem;

const frustum::ProblemSet& set() {
  static const frustum::ProblemSet s = frustum::load_problem_set_from_string(
      "variants: per_student\nproblems:\n  - id: v\n    kind: vectors\n"
      "    given: {a: [1, 2, 0], b: [0, 1, 3]}\n    ask: [dot, cross]\n"
      "  - id: z\n    kind: depth_at_pixel\n"
      "    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}\n"
      "    ask: [normal, z]\n",
      "set.yaml");
  return s;
}

// The row of `name` in a class graded from `dir` into `out`.
frustum::BatchRow row_of(const fs::path& dir, const fs::path& out, const std::string& name) {
  const std::vector<frustum::BatchEntry> entries = frustum::collect_submissions(dir.string());
  frustum::BatchOptions options;
  options.out_dir = out.string();
  options.timeout_seconds = 30;
  options.jobs = 1;
  options.set_for = [](const frustum::ProblemSet& s, const std::string& student, std::string&) {
    return frustum::variant_for(s, student);
  };
  const frustum::BatchResult result = frustum::grade_batch(set(), entries, options);
  if (result.rows.size() != entries.size()) std::abort();
  for (const frustum::BatchRow& row : result.rows)
    if (fs::path(row.source).filename() == name) return row;
  std::abort();  // the student's file has no row
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size > 32 * 1024) return 0;
  const std::vector<std::string> records = frustum::fuzz::records(data, size, 12);
  char root_template[] = "/tmp/frustum-fuzz-neighbours-XXXXXX";
  if (!mkdtemp(root_template)) return 0;
  const fs::path root(root_template), alone = root / "alone", with = root / "class";
  fs::create_directories(alone);
  fs::create_directories(with);
  // The student, named so that the file sorts first and cannot be confused with a neighbour.
  const std::string own = "answers: " + records[0];
  const std::string text = "student: alice\n" + own + "\n";
  std::ofstream(alone / "a-alice.yaml", std::ios::binary) << text;
  std::ofstream(with / "a-alice.yaml", std::ios::binary) << text;
  for (std::size_t i = 1; i < records.size(); ++i) {
    const std::string& r = records[i];
    const fs::path p = with / ("n" + std::to_string(i) + ".yaml");
    const char kind = r.empty() ? 'f' : r[0];
    std::error_code ec;
    if (kind == 'd')
      fs::create_directories(p, ec);
    else if (kind == 'p')
      mkfifo(p.c_str(), 0600);
    else if (kind == 'c')
      std::ofstream(p, std::ios::binary) << "student: alice\nanswers: " << r.substr(1) << "\n";
    else
      std::ofstream(p, std::ios::binary) << r.substr(r.empty() ? 0 : 1);
  }
  try {
    const frustum::BatchRow a = row_of(alone, root / "out-alone", "a-alice.yaml");
    const frustum::BatchRow b = row_of(with, root / "out-class", "a-alice.yaml");
    // A time-out says how busy the machine was, not what the neighbours hold.
    const bool timed_out = a.status == "timeout" || b.status == "timeout";
    if (!timed_out && (a.status != b.status || a.score != b.score || a.max_score != b.max_score ||
                       a.problem_scores != b.problem_scores || a.student != b.student))
      std::abort();
  } catch (const frustum::InputError&) {
  }
  std::error_code ec;
  fs::remove_all(root, ec);
  return 0;
}
