// A floating-point value with a proven bound on its distance from the exact value it stands
// for (midpoint-radius arithmetic): the value is what plain T arithmetic computes, bit for bit,
// and the radius grows by every operation's rounding error, including the absolute error of a
// result in the subnormal range. A non-finite value or radius means "unknown". Used where a
// discrete answer depends on a formula too long for a closed-form error bound (a projection
// built from tan, a camera normalised by square roots): the sign is proven when
// |value| > radius (predicates.hpp), else decided exactly.
#pragma once

#include <cmath>
#include <limits>

#include "solver/core/matrix.hpp"
#include "solver/core/scalar.hpp"

namespace frustum {

// |value| > bound, both finite: a value computed within `bound` of the exact one has the exact
// one's sign. Two comparisons (a NaN or infinite bound fails the first, a NaN or infinite value
// one of them): the filters' hot path (geometry/predicates.hpp).
template <typename T>
bool sign_is_proven(const T& value, const T& bound) {
  const T magnitude = std::abs(value);
  return magnitude > bound && magnitude < std::numeric_limits<T>::infinity();
}

template <typename T>
struct Ranged {
  T v{};  // the value computed in T
  T r{};  // |exact − v| ≤ r

  // u = 2⁻ᵖ, η = the smallest subnormal: a rounded operation returns x(1 + δ) + e with
  // |δ| ≤ u and |e| ≤ η/2 (e ≠ 0 only in the subnormal range).
  static constexpr T kU = std::numeric_limits<T>::epsilon() / 2;
  static constexpr T kEta = std::numeric_limits<T>::denorm_min();
  // Library functions (sin, cos) within a few units in the last place.
  static constexpr T kLibraryUlps = 8;

  Ranged() = default;
  Ranged(int c) : v(static_cast<T>(c)) {}  // small integer constants are exact
  Ranged(T value, T radius) : v(value), r(radius) {}

  // An exact input rounded to nearest (or within an ulp) in T: relative error 2u, or η in
  // the subnormal range (a flushed input is within η of 0).
  static Ranged input(T value) { return {value, T(2) * kU * std::abs(value) + kEta}; }

  // The radius after adding the rounding of a result v and of the radius's own arithmetic
  // (a few roundings of non-negative terms: a relative 4u, and η for their underflow).
  static T widen(T radius, T v) { return (radius + kU * std::abs(v)) * (T(1) + T(4) * kU) + kEta; }

  bool proves_sign() const { return sign_is_proven(v, r); }
  // The exact value's sign when the radius proves it, else 0 ("unknown", never "zero").
  int proven_sign() const { return proves_sign() ? (v > T(0) ? 1 : -1) : 0; }
};

// Identity of the pair (Eigen asks for it); says nothing about the values' order.
template <typename T>
bool operator==(const Ranged<T>& a, const Ranged<T>& b) {
  return a.v == b.v && a.r == b.r;
}
template <typename T>
bool operator!=(const Ranged<T>& a, const Ranged<T>& b) {
  return !(a == b);
}

template <typename T>
Ranged<T> operator-(const Ranged<T>& a) {
  return {-a.v, a.r};
}
template <typename T>
Ranged<T> operator+(const Ranged<T>& a, const Ranged<T>& b) {
  const T v = a.v + b.v;
  return {v, Ranged<T>::widen(a.r + b.r, v)};
}
template <typename T>
Ranged<T> operator-(const Ranged<T>& a, const Ranged<T>& b) {
  return a + (-b);
}
template <typename T>
Ranged<T> operator*(const Ranged<T>& a, const Ranged<T>& b) {
  const T v = a.v * b.v;
  return {v, Ranged<T>::widen(std::abs(a.v) * b.r + std::abs(b.v) * a.r + a.r * b.r, v)};
}
// |a/b − a.v/b.v| ≤ (a.r + |a.v/b.v|·b.r)/(|b.v| − b.r) when |b.v| > b.r; unknown otherwise.
template <typename T>
Ranged<T> operator/(const Ranged<T>& a, const Ranged<T>& b) {
  const T v = a.v / b.v;
  const T gap = std::abs(b.v) - b.r;
  if (!(gap > T(0))) return {v, std::numeric_limits<T>::infinity()};
  return {v, Ranged<T>::widen((a.r + std::abs(v) * b.r) / gap * (T(1) + T(2) * Ranged<T>::kU), v)};
}
template <typename T>
Ranged<T>& operator+=(Ranged<T>& a, const Ranged<T>& b) {
  return a = a + b;
}
template <typename T>
Ranged<T>& operator-=(Ranged<T>& a, const Ranged<T>& b) {
  return a = a - b;
}
template <typename T>
Ranged<T>& operator*=(Ranged<T>& a, const Ranged<T>& b) {
  return a = a * b;
}
template <typename T>
Ranged<T>& operator/=(Ranged<T>& a, const Ranged<T>& b) {
  return a = a / b;
}

// √x: |√x − √x.v| ≤ x.r/√x.v (x.v > x.r), else at most √(x.v + x.r).
template <typename T>
Ranged<T> scalar_sqrt(const Ranged<T>& x) {
  const T v = std::sqrt(x.v);
  const T r = x.v > x.r ? x.r / std::sqrt(x.v - x.r) : std::sqrt(x.v + x.r);
  return {v, Ranged<T>::widen(r * (T(1) + T(4) * Ranged<T>::kU), v)};
}
// sin and cos are 1-Lipschitz; the library's own error is a few ulps.
template <typename T>
Ranged<T> scalar_sin(const Ranged<T>& x) {
  const T v = std::sin(x.v);
  return {v, Ranged<T>::widen(
                 x.r + Ranged<T>::kLibraryUlps * Ranged<T>::kU * (std::abs(v) + Ranged<T>::kU), v)};
}
template <typename T>
Ranged<T> scalar_cos(const Ranged<T>& x) {
  const T v = std::cos(x.v);
  return {v, Ranged<T>::widen(
                 x.r + Ranged<T>::kLibraryUlps * Ranged<T>::kU * (std::abs(v) + Ranged<T>::kU), v)};
}

}  // namespace frustum

namespace Eigen {
// Lets Eigen's vectors and matrices hold ranged values (M·p, cross, dot).
template <typename T>
struct NumTraits<frustum::Ranged<T>> : GenericNumTraits<frustum::Ranged<T>> {
  using Real = frustum::Ranged<T>;
  using NonInteger = frustum::Ranged<T>;
  using Nested = frustum::Ranged<T>;
  using Literal = frustum::Ranged<T>;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 2,
    AddCost = 4,
    MulCost = 8
  };
  static inline Real epsilon() { return {NumTraits<T>::epsilon(), T(0)}; }
  static inline Real dummy_precision() { return {NumTraits<T>::dummy_precision(), T(0)}; }
  static inline int digits10() { return NumTraits<T>::digits10(); }
};
}  // namespace Eigen
