// Exact geometric predicates. A discrete answer (front/back, inside, covered, a winner) is the
// sign of an expression in the problem's exact inputs, never a comparison with an epsilon.
// Every backend decides it the same way (decide_sign): the expression is computed in the
// backend's scalar together with a forward error bound; when the bound proves the sign, that
// sign stands; otherwise — |value| within the bound, a value or the bound not finite, or an
// input that fell out of the normal range when it was converted — the sign is computed exactly
// on the exact inputs. The bounds stay valid for subnormal intermediates (each rounding adds an
// absolute η besides the relative u) and overflow (infinity or NaN is "unknown").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "solver/core/matrix.hpp"
#include "solver/core/scalar.hpp"
#include "solver/numeric/ranged.hpp"

namespace frustum {

// ---- The mechanism ----

// A backend's rounding: u = 2⁻ᵖ, η the smallest subnormal, γ_k = k·u/(1 − k·u) (Higham, ch. 3)
// bounds (1 + δ₁)…(1 + δ_k) − 1.
template <typename T>
struct Rounding {
  static constexpr T u = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T eta = std::numeric_limits<T>::denorm_min();
  // An upper bound of c·η computed without subnormal arithmetic (which costs a hundred cycles
  // per operation on x86): η = min_normal·2^−(p−1), so c·η ≤ min_normal·max(1, c·2^−(p−1)).
  static T underflow(T c) {
    constexpr T to_eta = std::numeric_limits<T>::epsilon();  // 2^−(p−1)
    return std::numeric_limits<T>::min() * std::max(T(1), c * to_eta);
  }
  // γ_k without a division (it sits on the filter's hot path): 1/(1 − k·u) ≤ 1 + 1/64 while
  // k·u ≤ 1/65; beyond that (absurdly long formulas) the bound is infinite, i.e. "unknown".
  static constexpr T gamma(int k) {
    const T ku = T(k) * u;
    return ku <= T(1) / T(65) ? ku * (T(1) + T(1) / T(64)) : std::numeric_limits<T>::infinity();
  }
};

// Whether an exact input, converted to T as v, is within a relative error of u of its exact
// value (the assumption of every closed-form bound below): false when it overflowed or fell
// below the normal range (a subnormal, or flushed to zero). Predicates over such inputs take
// the exact path.
template <typename T>
bool converts_relatively(const Exact& e, const T& v) {
  if constexpr (kIsExact<T>) {
    return true;
  } else {
    if (!std::isfinite(v)) return false;
    if (v == T(0)) return exact_sign(e) == 0;
    return std::abs(v) >= std::numeric_limits<T>::min();
  }
}

// A sign and who decided it: the backend's own arithmetic, proven by its bound, or the exact
// fallback on the exact inputs.
struct SignDecision {
  int sign = 0;
  bool exact = false;  // the exact fallback decided
};

// The one decision rule. `exact_sign_of()` computes the sign on the exact inputs; it runs only
// when the filter cannot prove the sign (`inputs_relative` false forces it). For the exact
// backend the value is exact already.
template <typename T, typename ExactSign>
SignDecision decide_sign(const T& value, const T& bound, bool inputs_relative,
                         ExactSign&& exact_sign_of) {
  if constexpr (kIsExact<T>) {
    return {exact_sign(value), false};
  } else {
    if (inputs_relative && sign_is_proven(value, bound)) return {value > T(0) ? 1 : -1, false};
    return {exact_sign_of(), true};
  }
}

// The same for a ranged value (ranged.hpp): its radius is the bound.
template <typename T, typename ExactSign>
SignDecision decide_sign(const Ranged<T>& value, ExactSign&& exact_sign_of) {
  return decide_sign(value.v, value.r, true, exact_sign_of);
}

// ---- The edge function (orient2d) ----

// E(a, b, p) = (b − a) × (p − a) = (bx − ax)(py − ay) − (by − ay)(px − ax): twice the signed area
// of (a, b, p), > 0 when p lies left of a → b. Only x and y of a and b are read.
template <typename T, typename A, typename B, typename P>
T edge_function(const A& a, const B& b, const P& p) {
  return (T(b(0)) - T(a(0))) * (T(p(1)) - T(a(1))) - (T(b(1)) - T(a(1))) * (T(p(0)) - T(a(0)));
}

// Forward error bound of edge_function in T for inputs each within a relative u of the exact
// ones: the same formula on the inputs' magnitudes (differences become sums) times γ₉ (the
// input, the difference, the product, the final difference, and the bound's own roundings),
// plus 4η for products in the subnormal range.
template <typename T, typename A, typename B, typename P>
T edge_function_bound(const A& a, const B& b, const P& p) {
  using std::abs;
  const T permanent = (abs(T(b(0))) + abs(T(a(0)))) * (abs(T(p(1))) + abs(T(a(1)))) +
                      (abs(T(b(1))) + abs(T(a(1)))) * (abs(T(p(0))) + abs(T(a(0))));
  return Rounding<T>::gamma(9) * permanent + Rounding<T>::underflow(T(4));
}

// The exact sign of E(a, b, p). When the six coordinates are rational (most exercises' inputs)
// the same formula runs on GiNaC's rational numbers themselves, without building and
// simplifying expressions: the same value, a tenth of the work.
struct RationalXY {
  std::array<GiNaC::numeric, 2> c;
  const GiNaC::numeric& operator()(int i) const { return c[static_cast<std::size_t>(i)]; }
};
template <typename A, typename B, typename P>
int exact_edge_sign(const A& a, const B& b, const P& p) {
  if (is_rational(a(0)) && is_rational(a(1)) && is_rational(b(0)) && is_rational(b(1)) &&
      is_rational(p(0)) && is_rational(p(1))) {
    const auto xy = [](const auto& v) {
      return RationalXY{{GiNaC::ex_to<GiNaC::numeric>(v(0)), GiNaC::ex_to<GiNaC::numeric>(v(1))}};
    };
    return edge_function<GiNaC::numeric>(xy(a), xy(b), xy(p)).csgn();
  }
  return exact_sign(edge_function<Exact>(a, b, p));
}

// The sign of E(a, b, p) for inputs in T whose exact values are ea, eb, ep.
template <typename T, int NA, int NP>
SignDecision edge_sign(const Eigen::Matrix<T, NA, 1>& a, const Eigen::Matrix<T, NA, 1>& b,
                       const Eigen::Matrix<T, NP, 1>& p, const Eigen::Matrix<Exact, NA, 1>& ea,
                       const Eigen::Matrix<Exact, NA, 1>& eb, const Eigen::Matrix<Exact, NP, 1>& ep,
                       bool inputs_relative) {
  if constexpr (kIsExact<T>) {
    return {exact_edge_sign(a, b, p), false};
  } else {
    return decide_sign(edge_function<T>(a, b, p), edge_function_bound<T>(a, b, p), inputs_relative,
                       [&] { return exact_edge_sign(ea, eb, ep); });
  }
}

// A point is in the closed triangle when its three edge signs agree (0 = on an edge).
inline bool inside_closed_triangle(int s0, int s1, int s2) {
  return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

// Whether a triangle is edge-on seen along z: c = ±E(A, B, C) over x and y (0: edge-on).
template <typename T>
SignDecision edge_on_sign(const std::array<Vec3<T>, 3>& t,
                          const std::array<Vec3<Exact>, 3>& exact_t, bool inputs_relative) {
  return edge_sign(t[0], t[1], Vec2<T>(t[2].x(), t[2].y()), exact_t[0], exact_t[1],
                   Vec2<Exact>(exact_t[2].x(), exact_t[2].y()), inputs_relative);
}

// The signs of E_AB, E_BC, E_CA at the pixel, and whether it is inside the closed triangle (the
// three signs agree, 0 = on an edge).
struct PixelSides {
  std::array<int, 3> sign{};
  bool inside = false;
  bool exact = false;  // the exact fallback decided some edge sign
};

template <typename T>
PixelSides pixel_sides(const std::array<Vec3<T>, 3>& t, const Vec2<T>& pixel,
                       const std::array<Vec3<Exact>, 3>& exact_t, const Vec2<Exact>& exact_pixel,
                       bool inputs_relative) {
  PixelSides out;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    const SignDecision d =
        edge_sign(t[k], t[j], pixel, exact_t[k], exact_t[j], exact_pixel, inputs_relative);
    out.sign[k] = d.sign;
    out.exact = out.exact || d.exact;
  }
  out.inside = inside_closed_triangle(out.sign[0], out.sign[1], out.sign[2]);
  return out;
}

// ---- Facing ----

// The side of a face the eye sees, from the sign of D_f (seed 003): > 0 front, < 0 back,
// 0 edge-on. The one mapping from a sign to a facing, and from a facing to its answer word.
enum class FacingSide { Front, Back, EdgeOn };

inline FacingSide facing_side(int sign) {
  return sign > 0 ? FacingSide::Front : sign < 0 ? FacingSide::Back : FacingSide::EdgeOn;
}

inline const char* facing_word(FacingSide f) {
  return f == FacingSide::Front ? "front" : f == FacingSide::Back ? "back" : "edge_on";
}

inline const char* facing_word(int sign) { return facing_word(facing_side(sign)); }

// ---- orient3d (hidden lines) ----

// Sign of det[b − a, c − a, d − a] = ((b − a) × (c − a)) · (d − a): +1 when d lies on the
// side the normal of triangle abc (counter-clockwise) points to, −1 behind it, 0 in its plane.
int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d);

// The same on exact values.
int orient3d_sign(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec3<Exact>& c,
                  const Vec3<Exact>& d);

// How many orient3d_sign calls on doubles needed the exact fallback (for benchmarks).
struct PredicateStats {
  long filtered = 0;
  long exact = 0;
};
int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d, PredicateStats* stats);

}  // namespace frustum
