// Dot products and lengths of exact 3-vectors in canonical form. Most vectors of an exercise
// are rational, or a rational vector over one radical (a unit normal n/‖n‖ = (q₀, q₁, q₂)·√k):
// their dot products and lengths are found in rational arithmetic, and the one radical is
// put back once, with the value and the form canonical() gives.
#pragma once

#include "solver/core/exact.hpp"
#include "solver/core/matrix.hpp"

namespace frustum {

// canonical(a·b).
Exact canonical_dot(const Vec3<Exact>& a, const Vec3<Exact>& b);

// canonical(‖v‖) = canonical(√(v·v)).
Exact canonical_norm(const Vec3<Exact>& v);

}  // namespace frustum
