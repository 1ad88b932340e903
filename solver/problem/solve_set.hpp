// Solving loaded problems: each problem alone, so one failure never stops the rest.
#pragma once

#include <optional>
#include <string>

#include "solver/derivation/problem_result.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// Solves one problem; with_steps = false takes the fast path without derivation text.
ProblemResult solve_problem(const ProblemSpec& spec, const std::string& file, bool with_steps);

// Solves the set (only `only_id` when given). Unknown only_id gives a set error.
SetResult solve_set(const ProblemSet& set, bool with_steps,
                    const std::optional<std::string>& only_id = std::nullopt);

}  // namespace frustum
