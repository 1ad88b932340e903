// seed 003's back-face discriminant D_f = (p_eye − p₀)·n in any scalar, and its sign decided
// adaptively: the computed sign when a forward error bound proves it, else the exact sign of
// the same (rounded) inputs. The naive sign is kept beside it for the hard-case study.
#pragma once

#include "solver/geometry/polygon_normal.hpp"
#include "solver/numeric/precision.hpp"
#include "solver/numeric/scalar.hpp"

#include <limits>

namespace frustum {

template <typename T>
struct Facing {
  Vec3<T> normal;       // Newell's n (e₀ × e₁ for a triangle)
  Vec3<T> view;         // p_eye − p₀
  T df{};               // v·n as computed
  int naive_sign = 0;   // sign of the computed D_f
  int sign = 0;         // the exact sign of D_f for these inputs
  bool used_exact = false;
};

// D_f's forward error bound: every difference, product and sum of the m − 2 Newell terms and
// the dot product rounds once; γ_k = k·u/(1 − k·u) times the permanent (seed formula with
// absolute values) bounds the error (Higham, ch. 3).
template <typename T>
T facing_error_bound(const Polygon3<T>& p, const Vec3<T>& view) {
  const T u = std::numeric_limits<T>::epsilon() / T(2);
  Vec3<T> terms = Vec3<T>::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec3<T> a = (p[i] - p[0]).cwiseAbs(), b = (p[i + 1] - p[0]).cwiseAbs();
    terms += Vec3<T>(a.y() * b.z() + a.z() * b.y(), a.z() * b.x() + a.x() * b.z(),
                     a.x() * b.y() + a.y() * b.x());
  }
  const T k = T(p.size() + 8);
  const T gamma = k * u / (T(1) - k * u);
  // The permanent itself is computed with rounding; a factor (1 + 2γ) covers it.
  return gamma * (T(1) + T(2) * gamma) * T(view.cwiseAbs().dot(terms));
}

template <typename T>
Facing<T> facing(const Polygon3<T>& p, const Vec3<T>& eye) {
  Facing<T> f;
  f.normal = newell_normal(p);
  f.view = eye - p[0];
  f.df = f.view.dot(f.normal);
  f.naive_sign = scalar_sign(f.df);
  if constexpr (kIsExact<T>) {
    f.sign = f.naive_sign;
  } else {
    const T bound = facing_error_bound(p, f.view);
    if (std::isfinite(f.df) && std::isfinite(bound) && scalar_abs(f.df) > bound) {
      f.sign = f.naive_sign;
    } else {
      // Uncertain: the same formula on the exact values of the rounded inputs.
      Polygon3<Exact> q;
      for (const Vec3<T>& v : p) q.push_back(Vec3<Exact>(exact_of(v(0)), exact_of(v(1)), exact_of(v(2))));
      const Vec3<Exact> e(exact_of(eye(0)), exact_of(eye(1)), exact_of(eye(2)));
      f.sign = exact_sign((e - q[0]).dot(newell_normal(q)));
      f.used_exact = true;
    }
  }
  return f;
}

}  // namespace frustum
