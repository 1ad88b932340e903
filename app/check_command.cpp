// `frustum check SET.yaml|DIR`: every error of a set, located; no solutions.
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/set_files.hpp"
#include "batch/file_names.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/unstated_givens.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::app {

int run_check(const std::string& path, const Output& o) {
  int errors = 0;
  for (const std::string& file : set_files(path)) {
    const ProblemSet set = load_problem_set(file);
    // `solve` can also fail on well-formed input (collinear points): check solves too.
    const SetResult result = solve_set(set, false);
    int here = 0;
    for (const Diagnostic& d : result.errors) {
      o.out << d.format() << "\n";
      ++here;
    }
    for (const ProblemResult& p : result.problems)
      if (p.error) {
        o.out << p.error->format() << "\n";
        ++here;
      }
    // A varied problem whose text states a given value that its variants cannot restate: an
    // error, as `generate` and per-student grading refuse it.
    for (const Diagnostic& d : stale_text_errors(set, false)) {
      o.out << d.format() << "\n";
      ++here;
    }
    // Ids a student may take for each other (not errors: every export keeps both).
    for (const Diagnostic& d : look_alike_problem_ids(set)) o.out << d.format() << "\n";
    // Givens the text never states (warnings: the set still solves and grades).
    for (const Diagnostic& d : unstated_given_warnings(set)) o.out << d.format() << "\n";
    if (here == 0)
      o.out << file << ": " << set.problems.size() << " problem"
            << (set.problems.size() == 1 ? "" : "s") << ", no errors\n";
    errors += here;
  }
  if (errors) o.out << errors << " error" << (errors == 1 ? "" : "s") << "\n";
  return errors == 0 ? 0 : 1;
}

Command add_check_command(CLI::App& cli) {
  auto set = std::make_shared<std::string>();
  auto* check = cli.add_subcommand("check", "Report every error in a problem set; no solutions");
  check->add_option("set", *set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  check->footer(examples({"frustum check problems/seeds"}));
  return {check, [set](const Output& o) { return run_check(*set, o); }};
}

}  // namespace frustum::app
