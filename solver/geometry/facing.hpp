// seed 003's back-face discriminant D_f = (p_eye − p₀)·n in any scalar, and its sign decided by
// the filtered predicate of predicates.hpp: the computed sign when the forward error bound
// proves it, else the exact sign on the problem's exact inputs. The naive sign is kept beside
// it for the hard-case study.
#pragma once

#include <limits>

#include "solver/core/matrix.hpp"
#include "solver/core/scalar.hpp"
#include "solver/geometry/polygon_normal.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/geometry/zero_vector.hpp"

namespace frustum {

template <typename T>
struct Facing {
  Vec3<T> normal;      // Newell's n (e₀ × e₁ for a triangle)
  Vec3<T> view;        // p_eye − p₀
  T df{};              // v·n as computed
  int naive_sign = 0;  // sign of the computed D_f
  int sign = 0;        // the exact sign of D_f for the exact inputs
  bool used_exact = false;
};

// D_f's forward error bound for inputs each within a relative u of the exact ones: the seed
// formula on the inputs' magnitudes (every difference pᵢ − p₀ becomes |pᵢ| + |p₀|) times γ_k
// with k = 2m + 12: m + 5 roundings on the longest path (input, difference, product, the m − 2
// Newell terms, the cross difference, the dot product's product and sum) and as many again for
// the bound's own arithmetic and |x| ≤ |x̃|/(1 − u), plus the
// products that fall in the subnormal range: 2(m − 2) per component of n, each off by η/2 and
// then multiplied by |vᵢ|, and three in the dot product.
template <typename T>
T facing_error_bound(const Polygon3<T>& p, const Vec3<T>& eye) {
  const Vec3<T> a0 = p[0].cwiseAbs();
  Vec3<T> terms = Vec3<T>::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec3<T> a = p[i].cwiseAbs() + a0, b = p[i + 1].cwiseAbs() + a0;
    terms += cross_permanent(a, b);
  }
  const Vec3<T> view = eye.cwiseAbs() + a0;
  const int m = static_cast<int>(p.size());
  const T k = Rounding<T>::gamma(2 * m + 12);
  return k * T(view.dot(terms)) + Rounding<T>::underflow(T(2 * (m - 2)) * view.sum() + T(4));
}

// The same bound from the largest input magnitude S alone (each |pᵢ| + |p₀| ≤ 2S, so the
// permanent is at most 48(m − 2)S³): looser, but a few operations; tried first.
template <typename T>
T facing_error_bound_fast(const Polygon3<T>& p, const Vec3<T>& eye) {
  T s = eye.cwiseAbs().maxCoeff();
  for (const Vec3<T>& v : p) s = std::max(s, v.cwiseAbs().maxCoeff());
  const T m2 = T(p.size() - 2);
  const T k = Rounding<T>::gamma(2 * static_cast<int>(p.size()) + 12);
  return k * T(48) * m2 * (s * s * s) + Rounding<T>::underflow(T(12) * m2 * s + T(4));
}

// D_f = (eye − p₀)·n with n Newell's normal, in T (exact for the exact backend).
template <typename T>
T facing_discriminant(const Polygon3<T>& p, const Vec3<T>& eye) {
  return T((eye - p[0]).dot(newell_normal(p)));
}

// The part of facing() that runs when the cheap bound cannot prove the sign: the sharper
// bound, then the exact sign. Out of line, so the common path stays a few instructions.
template <typename T>
[[gnu::noinline, gnu::cold]] SignDecision facing_near_plane(
    const Facing<T>& f, const Polygon3<T>& p, const Vec3<T>& eye,
    const Polygon3<Exact>& exact_points, const Vec3<Exact>& exact_eye, bool inputs_relative) {
  return decide_sign(f.df, facing_error_bound(p, eye), inputs_relative,
                     [&] { return exact_sign(facing_discriminant(exact_points, exact_eye)); });
}

// `exact_points`, `exact_eye`: the problem's exact inputs, which `p` and `eye` were rounded
// from; `inputs_relative`: every one of them converted within a relative u (converts_relatively);
// `fast_bound`: facing_error_bound_fast(p, eye) when the caller computed it once beforehand
// (a prepared solve: the inputs do not change between runs), else NaN.
// Inlined: called out of line it costs 1.6× the plain sign (the Facing returned through
// memory); inlined the filter costs about nothing (bench/predicate_bench.cpp).
template <typename T>
[[gnu::always_inline]] inline Facing<T> facing(const Polygon3<T>& p, const Vec3<T>& eye,
                                               const Polygon3<Exact>& exact_points,
                                               const Vec3<Exact>& exact_eye, bool inputs_relative,
                                               T fast_bound = std::numeric_limits<T>::quiet_NaN()) {
  Facing<T> f;
  f.normal = newell_normal(p);
  f.view = eye - p[0];
  f.df = f.view.dot(f.normal);
  if constexpr (kIsExact<T>) {
    f.naive_sign = f.sign = exact_sign(f.df);
  } else {
    // The cheap bound settles ordinary input; the sharper one is computed only near the plane.
    if (std::isnan(fast_bound)) fast_bound = facing_error_bound_fast(p, eye);
    if (inputs_relative && sign_is_proven(f.df, fast_bound)) [[likely]] {
      f.naive_sign = f.sign = f.df > T(0) ? 1 : -1;  // proven nonzero: one comparison
    } else {
      f.naive_sign = scalar_sign(f.df);
      const SignDecision d = facing_near_plane(f, p, eye, exact_points, exact_eye, inputs_relative);
      f.sign = d.sign;
      f.used_exact = d.exact;
    }
  }
  return f;
}

}  // namespace frustum
