// `frustum bench accuracy [-o DIR]`: speed against error of every numeric path and backend,
// on generated well-conditioned problems and on the hard-case suite, plus the hard-case
// studies. Writes DIR/accuracy_results.md and DIR/accuracy_plot.svg and prints the table.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "solver/accuracy/accuracy.hpp"
#include "solver/accuracy/hard_cases.hpp"

namespace frustum::app {

namespace {

constexpr std::uint64_t kBenchSeed = 20240531;
constexpr int kFacingCases = 2000;

// Every problem of every *.yaml directly in dir, as one set (ids prefixed by the file's stem).
ProblemSet load_dir(const std::string& dir, std::vector<std::string>& errors) {
  namespace fs = std::filesystem;
  ProblemSet all;
  all.file = dir;
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file() && e.path().extension() == ".yaml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const fs::path& f : files) {
    ProblemSet set = load_problem_set(f.string());
    for (const Diagnostic& d : set.all_errors()) errors.push_back(d.format());
    for (ProblemSpec& p : set.problems) {
      p.id = f.stem().string() + "/" + p.id;
      all.problems.push_back(std::move(p));
    }
  }
  return all;
}

bool write_file(const std::filesystem::path& path, const std::string& text, const Output& o) {
  std::ofstream f(path);
  f << text;
  if (!f) {
    o.err << path.string() << ": cannot write\n";
    return false;
  }
  return true;
}

}  // namespace

int run_bench_accuracy(const std::string& out_dir, const std::string& hard_dir, int cases,
                       const Output& o) {
  std::vector<bench::AccuracyRow> rows;
  // The generated problems as drawn, then with radicals in their givens (the exact backend's
  // cost on irrational inputs; the numeric backends round them once, as they round decimals).
  for (const char* suite : {"generated", "radical"})
    for (const std::string& kind : bench::generated_kinds()) {
      const ProblemSet set = std::string(suite) == "generated"
                                 ? bench::generated_problems(kind, cases, kBenchSeed)
                                 : bench::radical_problems(kind, cases, kBenchSeed);
      for (const Diagnostic& d : set.all_errors())
        o.err << suite << " " << kind << ": " << d.format() << "\n";
      const std::vector<bench::AccuracyRow> r = bench::measure(set, suite);
      rows.insert(rows.end(), r.begin(), r.end());
    }
  std::vector<std::string> errors;
  const ProblemSet hard = load_dir(hard_dir, errors);
  for (const std::string& e : errors) o.err << e << "\n";
  if (hard.problems.empty()) o.err << hard_dir << ": no hard-case problems found\n";
  const std::vector<bench::AccuracyRow> r = bench::measure(hard, "hard");
  rows.insert(rows.end(), r.begin(), r.end());

  const std::string table = bench::markdown_table(rows);
  const std::string report = "## Speed against error\n\n" + table + "\n## Hard cases\n\n" +
                             bench::hard_case_report(hard, kFacingCases, kBenchSeed);
  o.out << report;
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  const bool ok = write_file(fs::path(out_dir) / "accuracy_results.md", report, o) &&
                  write_file(fs::path(out_dir) / "accuracy_plot.svg",
                             bench::speed_error_svg(rows, "generated"), o) &&
                  write_file(fs::path(out_dir) / "accuracy_plot_hard.svg",
                             bench::speed_error_svg(rows, "hard"), o);
  if (ok)
    o.err << "wrote " << out_dir
          << "/accuracy_results.md, accuracy_plot.svg, accuracy_plot_hard.svg\n";
  return ok && errors.empty() ? 0 : 1;
}

Command add_bench_command(CLI::App& cli) {
  struct Options {
    std::string dir = "docs";
    int cases = 200;
    std::string hard = "problems/hard";
  };
  auto opt = std::make_shared<Options>();
  auto* bench = cli.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  auto* accuracy =
      bench->add_subcommand("accuracy", "Speed against error of every numeric backend");
  accuracy->add_option("-o,--output", opt->dir, "Directory for accuracy.md and accuracy_plot.svg");
  accuracy->add_option("--cases", opt->cases, "Generated problems per kind")
      ->check(CLI::Range(1, 100000));
  accuracy->add_option("--hard", opt->hard, "Directory of the hard-case suite")
      ->check(CLI::ExistingDirectory);
  accuracy->footer(examples({"frustum bench accuracy -o docs --cases 200"}));
  bench->footer(examples({"frustum bench accuracy -o docs --cases 200"}));

  return {accuracy, [opt](const Output& o) {
            return run_bench_accuracy(opt->dir, opt->hard, opt->cases, o);
          }};
}

}  // namespace frustum::app
