#include "batch/set_check.hpp"

#include "batch/file_names.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/unstated_givens.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

std::vector<Diagnostic> SetCheck::sample_mismatches() const {
  std::vector<Diagnostic> out;
  for (const SampleOutcome& s : samples)
    if (!s.as_expected) out.push_back(s.mismatch);
  return out;
}

SetCheck check_set(const ProblemSet& set) {
  SetCheck c;
  // `solve` can also fail on well-formed input (collinear points): check solves too.
  const SetResult result = solve_set(set, false);
  c.errors = result.errors;
  for (const ProblemResult& p : result.problems)
    if (p.error) c.errors.push_back(*p.error);
  // A varied problem whose text states a given value that its variants cannot restate: an
  // error, as `generate` and per-student grading refuse it.
  for (Diagnostic& d : stale_text_errors(set, false)) c.errors.push_back(std::move(d));
  c.warnings = look_alike_problem_ids(set);
  // Givens the text never states (warnings: the set still solves and grades).
  for (Diagnostic& d : unstated_given_warnings(set)) c.warnings.push_back(std::move(d));
  c.samples = grade_samples(set);
  return c;
}

}  // namespace frustum
