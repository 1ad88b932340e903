// The accepted window of each number of an expected answer, for platforms that grade by
// themselves (Canvas, Moodle, PrairieLearn's elements). It asks the grader's own window() with
// the answer's tolerance, so an exported quiz accepts what `frustum grade` accepts.
#pragma once

#include <string>
#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/kinds/problem_set.hpp"

namespace frustum {

// One half-width per number of `expected` (|got − expected| ≤ window is accepted): relative to
// the largest component for vectors, to each entry for matrices, as compare() does.
std::vector<double> accepted_windows(const ProblemSpec& problem, const std::string& answer,
                                     const Value& expected);

}  // namespace frustum
