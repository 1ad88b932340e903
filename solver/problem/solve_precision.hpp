// Solving in a chosen backend (`frustum solve --precision`): the kind's numeric path gives the
// answers (values only), and the derivation states the backend, the formulation used and the
// ill-conditioning found. A kind without a numeric path is solved exactly, with a note.
#pragma once

#include <optional>
#include <string>

#include "solver/numeric/precision.hpp"
#include "solver/problem/solve_set.hpp"

namespace frustum {

ProblemResult solve_problem(const ProblemSpec& spec, const std::string& file, bool with_steps,
                            Precision precision);

SetResult solve_set(const ProblemSet& set, bool with_steps,
                    const std::optional<std::string>& only_id, Precision precision);

}  // namespace frustum
