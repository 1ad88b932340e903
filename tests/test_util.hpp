// Helpers shared by the tests.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

#include "batch/run_program.hpp"
#include "solver/core/exact.hpp"
#include "solver/derivation/problem_result.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/said.hpp"

namespace frustum {
// A student-facing text in a test's failure message: its English.
inline std::ostream& operator<<(std::ostream& out, const Said& said) { return out << said.en(); }
}  // namespace frustum

namespace frustum::test {

// A test's command line split at white space: an argument vector, never read by a shell (a test
// whose argument holds a space builds the vector itself).
inline std::vector<std::string> words(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// `frustum` with these arguments; stdout and (unless `with_stderr` is false) stderr captured.
inline ProgramRun frustum_run(std::vector<std::string> args, bool with_stderr = true,
                              RunOptions options = {}) {
  args.insert(args.begin(), FRUSTUM_BINARY);
  if (!with_stderr) options.err = OutputTo::Null;
  return run_program(args, options);
}
inline ProgramRun frustum_run(const std::string& args, bool with_stderr = true) {
  return frustum_run(words(args), with_stderr);
}

// One depth_at_pixel problem (z = 8) that the batch and output tests grade classes against.
inline constexpr const char* kOneDepthProblemSet = R"(problems:
  - id: zbuf
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [z]
)";

inline std::string source_path(const std::string& relative) {
  return std::string(FRUSTUM_SOURCE_DIR) + "/" + relative;
}

// Solves one problem of a YAML text and returns its result.
inline ProblemResult solve_yaml(const std::string& yaml, bool with_steps = true) {
  const ProblemSet set = load_problem_set_from_string(yaml, "test.yaml");
  EXPECT_TRUE(set.errors.empty()) << (set.errors.empty() ? "" : set.errors[0].format());
  EXPECT_EQ(set.problems.size(), 1u);
  if (set.problems.empty()) return {};
  return solve_problem(set.problems[0], set.file, with_steps);
}

// The exact answer as plain text ("sqrt(3)/3"), components joined by ", ".
inline std::string exact_text(const ProblemResult& r, const std::string& answer) {
  const Value* v = r.answers.find(answer);
  if (!v) return "<missing " + answer + ">";
  std::string s;
  for (std::size_t i = 0; i < v->exact.size(); ++i)
    s += (i ? ", " : "") + format_exact(v->exact[i], MathStyle::Plain);
  return s;
}

// A one-problem set: `extra` is inserted among the problem's fields (indented four spaces,
// newline-terminated), `conventions` becomes the set's conventions mapping when not empty.
inline std::string one(const std::string& kind, const std::string& given,
                       const std::string& conventions = "", const std::string& extra = "") {
  const std::string head = conventions.empty() ? "" : "conventions: " + conventions + "\n";
  return head + "problems:\n  - id: p\n    kind: " + kind + "\n" + extra + "    given: " + given +
         "\n";
}

// Exact equality after canonical simplification.
inline bool same(const Exact& a, const Exact& b) { return canonical(a - b).is_zero(); }

inline std::string error_text(const ProblemResult& r) {
  return r.error ? r.error->format() : std::string();
}

// A fresh directory under the system's temporary directory, named after `name`, this process
// and the clock (tests that run at once never share one).
inline std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() /
      ("frustum_" + name + "_" + std::to_string(::getpid()) + "_" +
       std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
  std::filesystem::create_directories(p);
  return p;
}

// A file's bytes ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

// The published outputs of a batch's output directory, relative path → bytes, read through
// their symlinks; the runs kept under .frustum/ are not outputs.
inline std::map<std::string, std::string> published_tree(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::map<std::string, std::string> files;
  for (auto it =
           fs::recursive_directory_iterator(dir, fs::directory_options::follow_directory_symlink);
       it != fs::recursive_directory_iterator(); ++it) {
    if (it->path().filename() == ".frustum") {
      it.disable_recursion_pending();
      continue;
    }
    if (it->is_regular_file())
      files[it->path().lexically_relative(dir).string()] = read_file(it->path());
  }
  return files;
}

}  // namespace frustum::test
