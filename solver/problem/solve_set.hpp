// Solving loaded problems: each problem alone, so one failure never stops the rest.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "solver/derivation/problem_result.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// What every solving run fills in first: the problem's id, kind, text (placeholders filled
// with the given values), conventions and what it asks; no answers and no error yet.
ProblemResult unsolved_result(const ProblemSpec& spec);

// Runs `solve`, turning what it throws into r.error: a DomainError located at its given
// field, an InputError where it says, anything else as "cannot solve: …" at the problem.
void solve_located(const ProblemSpec& spec, const std::string& file, ProblemResult& r,
                   const std::function<void()>& solve);

// Solves one problem; with_steps = false takes the fast path without derivation text.
ProblemResult solve_problem(const ProblemSpec& spec, const std::string& file, bool with_steps);

// Solves the set (only `only_id` when given). Unknown only_id gives a set error.
SetResult solve_set(const ProblemSet& set, bool with_steps,
                    const std::optional<std::string>& only_id = std::nullopt);

}  // namespace frustum
