// The scalar vocabulary of the whole solver: the few operations it needs beyond + − × ÷, for
// every backend (float, double, long double and Exact run the same code): square root, sine
// and cosine, magnitude, sign, angles, π, and stable lengths. Nothing here includes upward.
#pragma once

#include <Eigen/Dense>
#include <cmath>
#include <type_traits>

#include "solver/core/exact.hpp"

namespace frustum {

template <typename T>
inline constexpr bool kIsExact = std::is_same_v<T, Exact>;

// Square root, sine and cosine.
inline double scalar_sqrt(double v) { return std::sqrt(v); }
inline float scalar_sqrt(float v) { return std::sqrt(v); }
inline long double scalar_sqrt(long double v) { return std::sqrt(v); }
inline Exact scalar_sqrt(const Exact& v) { return GiNaC::sqrt(v); }
inline double scalar_cos(double v) { return std::cos(v); }
inline double scalar_sin(double v) { return std::sin(v); }
inline float scalar_cos(float v) { return std::cos(v); }
inline float scalar_sin(float v) { return std::sin(v); }
inline long double scalar_cos(long double v) { return std::cos(v); }
inline long double scalar_sin(long double v) { return std::sin(v); }
inline Exact scalar_cos(const Exact& v) { return GiNaC::cos(v); }
inline Exact scalar_sin(const Exact& v) { return GiNaC::sin(v); }

inline float scalar_abs(float v) { return std::abs(v); }
inline double scalar_abs(double v) { return std::abs(v); }
inline long double scalar_abs(long double v) { return std::abs(v); }
inline Exact scalar_abs(const Exact& v) { return exact_sign(v) < 0 ? Exact(-v) : v; }

// −1, 0, +1 of the value as computed (exactly for the exact backend).
template <typename T>
int scalar_sign(const T& v) {
  if constexpr (kIsExact<T>)
    return exact_sign(v);
  else
    return v > T(0) ? 1 : v < T(0) ? -1 : 0;
}

// The angle θ ∈ [0, π] with sin θ ∝ s ≥ 0 and cos θ ∝ c. Floating point uses atan2, which stays
// accurate near 0 and π where acos(c) loses half its digits; exact uses arccos of the exact
// cosine so special angles come out as multiples of π.
inline float scalar_angle(float s, float c) { return std::atan2(s, c); }
inline double scalar_angle(double s, double c) { return std::atan2(s, c); }
inline long double scalar_angle(long double s, long double c) { return std::atan2(s, c); }
inline Exact scalar_angle(const Exact& s, const Exact& c) {
  return exact_acos(canonical(c / GiNaC::sqrt(s * s + c * c)));
}

inline Exact scalar_pi(const Exact&) { return GiNaC::Pi; }
template <typename T>
T scalar_pi(const T&) {
  return static_cast<T>(3.141592653589793238462643383279502884L);
}

// ‖v‖ without overflow or underflow in the squares (Eigen's stableNorm scales by the largest
// component), exact for the exact backend.
template <typename T, int N>
T stable_norm(const Eigen::Matrix<T, N, 1>& v) {
  if constexpr (kIsExact<T>)
    return scalar_sqrt(T(v.dot(v)));
  else
    return v.stableNorm();
}

}  // namespace frustum
