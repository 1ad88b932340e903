// What `frustum check` finds in a set, for the command line and the authoring page alike: every
// error, located (the loader's, the solver's, texts that a variant cannot restate), warnings
// (ids a student may take for each other, givens the text never states), and each sample answer
// graded against the key.
#pragma once

#include <vector>

#include "grader/samples.hpp"

namespace frustum {

struct SetCheck {
  std::vector<Diagnostic> errors;
  std::vector<Diagnostic> warnings;
  std::vector<SampleOutcome> samples;  // every sample of every problem that could be solved

  std::vector<Diagnostic> sample_mismatches() const;
  // No error and every sample graded as expected.
  bool ok() const { return errors.empty() && sample_mismatches().empty(); }
};

// For a set that varies, the samples are graded against the set as written (its base problems).
SetCheck check_set(const ProblemSet& set);

}  // namespace frustum
