// `frustum check SET.yaml|DIR`: every error of a set, located, and every sample answer whose
// grade is not the one its author expects; no solutions.
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/set_files.hpp"
#include "batch/set_check.hpp"

namespace frustum::app {

int run_check(const std::string& path, const Output& o) {
  std::size_t errors = 0;
  for (const std::string& file : set_files(path)) {
    const ProblemSet set = load_problem_set(file);
    const SetCheck check = check_set(set);
    const std::vector<Diagnostic> mismatches = check.sample_mismatches();
    for (const Diagnostic& d : check.errors) o.out << d.format() << "\n";
    for (const Diagnostic& d : mismatches) o.out << d.format() << "\n";
    // Ids a student may take for each other (not errors: every export keeps both).
    for (const Diagnostic& d : check.warnings) o.out << d.format() << "\n";
    const std::size_t here = check.errors.size() + mismatches.size();
    if (here == 0) {
      o.out << file << ": " << set.problems.size() << " problem"
            << (set.problems.size() == 1 ? "" : "s") << ", no errors";
      if (!check.samples.empty())
        o.out << ", " << check.samples.size() << " sample" << (check.samples.size() == 1 ? "" : "s")
              << " graded as expected";
      o.out << "\n";
    }
    errors += here;
  }
  if (errors) o.out << errors << " error" << (errors == 1 ? "" : "s") << "\n";
  return errors == 0 ? 0 : 1;
}

Command add_check_command(CLI::App& cli) {
  auto set = std::make_shared<std::string>();
  auto* check = cli.add_subcommand(
      "check",
      "Report every error in a problem set and every sample answer graded otherwise "
      "than expected; no solutions");
  check->add_option("set", *set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  check->footer(examples({"frustum check problems/seeds"}));
  return {check, [set](const Output& o) { return run_check(*set, o); }};
}

}  // namespace frustum::app
