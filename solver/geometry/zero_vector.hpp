// Whether a cross product or a polygon's normal is exactly the zero vector — parallel vectors,
// a degenerate polygon — decided like every other discrete answer (predicates.hpp): the vector
// computed in the backend is nonzero when one of its components is proven nonzero by its
// forward error bound; otherwise the vector is computed exactly on the exact inputs. A rounded
// backend alone gets both directions wrong: three collinear decimal points (0.1, 0.2, 0.3 on a
// line) round to a tiny nonzero normal, and inputs flushed to 0 give a zero one.
#pragma once

#include "solver/core/matrix.hpp"
#include "solver/geometry/predicates.hpp"

namespace frustum {

// The permanent of a cross product: the magnitudes a × b could have with |a|, |b| for a, b,
// (a_y b_z + a_z b_y, a_z b_x + a_x b_z, a_x b_y + a_y b_x).
template <typename T>
Vec3<T> cross_permanent(const Vec3<T>& a, const Vec3<T>& b) {
  return Vec3<T>(a.y() * b.z() + a.z() * b.y(), a.z() * b.x() + a.x() * b.z(),
                 a.x() * b.y() + a.y() * b.x());
}

// The componentwise bound of a cross product computed from operands whose magnitudes are at
// most `a`, `b` and which carry at most `roundings` roundings each (relative u, inputs
// included): γ_k of the permanent with k = 2·roundings + 4 (the product, the difference, and as
// many again for the bound's own arithmetic), plus a product in the subnormal range per term.
template <typename T>
Vec3<T> cross_error_bound(const Vec3<T>& a, const Vec3<T>& b, int roundings) {
  const T g = Rounding<T>::gamma(2 * roundings + 4);
  return g * cross_permanent(a, b) + Vec3<T>::Constant(Rounding<T>::underflow(T(4)));
}

// An exact vector is zero.
inline bool is_zero_vector(const Vec3<Exact>& v) {
  return exact_sign(v.x()) == 0 && exact_sign(v.y()) == 0 && exact_sign(v.z()) == 0;
}

// A zero-or-not decision: `zero` and whether the exact fallback took it.
struct ZeroDecision {
  bool zero = false;
  bool exact = false;
};

// `v` computed in T with the componentwise `bound`; `exact_is_zero()` runs only when no
// component is proven nonzero (or an input left T's normal range: `inputs_relative` false).
template <typename T, typename ExactIsZero>
ZeroDecision decide_zero(const Vec3<T>& v, const Vec3<T>& bound, bool inputs_relative,
                         ExactIsZero&& exact_is_zero) {
  if constexpr (kIsExact<T>) {
    return {is_zero_vector(v), false};
  } else {
    if (inputs_relative)
      for (int i = 0; i < 3; ++i)
        if (sign_is_proven(v(i), bound(i))) return {false, false};
    return {exact_is_zero(), true};
  }
}

}  // namespace frustum
