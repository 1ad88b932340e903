// `frustum check`'s warning for a text that does not state what is asked: a given field that
// the problem's text neither names with a placeholder ({point}, {viewport.width}) nor states
// literally (the literals text_literals.hpp ties, a lone number of a one-number field). Only the
// givens a sentence can state are checked (a dozen numbers at most: points, a triangle, a volume,
// a camera, transform steps) — not words (an order, a solid), the dimension, or a mesh, polygon
// list or statements, which are shown beside the text. A given the asked answers do not depend on
// (they stay the same when its numbers change) is not reported. The answers are computed from the
// givens, so a student who reads only the text could not compute them.
#pragma once

#include <vector>

#include "solver/problem/problem_set.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

// One warning per given field left unstated, at that field, for each problem with a text (in the
// set's own language; placeholders are checked in every language by the loader).
std::vector<Diagnostic> unstated_given_warnings(const ProblemSet& set);

}  // namespace frustum
