// The accepted window of each number of an expected answer, for platforms that grade by
// themselves (Canvas, Moodle, PrairieLearn's elements). It asks the grader's own judge
// (grader/tolerance.hpp) with the answer's tolerance and the kind's scales, so an exported quiz
// accepts what `frustum grade` accepts; a window that would reach across a sign-bearing
// threshold is narrowed so that the quiz, too, never accepts the wrong side.
#pragma once

#include <string>
#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// One half-width per number of `expected` (|got − expected| ≤ window is accepted). `key` is
// the problem's solved answers (the kind's scales are computed from them); `expected` is the
// value to export for `answer` (the key's own, or a direction scaled to length 1).
std::vector<double> accepted_windows(const ProblemSpec& problem, const Answers& key,
                                     const std::string& answer, const Value& expected);

}  // namespace frustum
