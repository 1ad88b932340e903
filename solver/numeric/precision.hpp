// The arithmetic a numeric solve runs in: float, double, long double, or the exact GiNaC
// backend. The numeric core is templated on its scalar; this file names the backends, their
// unit roundoff, and converts exact values to and from them.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "solver/core/exact.hpp"

namespace frustum {

enum class Precision { Float, Double, LongDouble, Exact };

inline constexpr Precision kAllPrecisions[] = {Precision::Float, Precision::Double,
                                               Precision::LongDouble, Precision::Exact};

std::string_view to_string(Precision p);  // "float", "double", "long-double", "exact"
std::optional<Precision> parse_precision(std::string_view text);
// One sentence for the derivation: "double (IEEE 754 binary64, 53-bit significand, unit
// roundoff 1.1e-16, about 15.9 decimal digits)".
std::string describe(Precision p);

// Unit roundoff u = 2^−p (half the machine epsilon); 0 for the exact backend.
double unit_roundoff(Precision p);
// Decimal digits the backend carries, −log10 u (infinite for the exact backend).
double decimal_digits(Precision p);

// Calls f.template operator()<T>() with T the backend's scalar (float, double, long double,
// Exact), so one generic lambda serves every backend.
template <typename F>
decltype(auto) with_scalar(Precision p, F&& f) {
  switch (p) {
    case Precision::Float:
      return f.template operator()<float>();
    case Precision::Double:
      return f.template operator()<double>();
    case Precision::LongDouble:
      return f.template operator()<long double>();
    case Precision::Exact:
      break;
  }
  return f.template operator()<Exact>();
}

// Exact values into a backend's scalar (the nearest value, rounded once from the exact value
// or a 40-digit approximation of it, over the backend's whole range: subnormals kept) and back.
template <typename T>
T from_exact(const Exact& e);
template <>
inline Exact from_exact<Exact>(const Exact& e) {
  return e;
}
template <>
double from_exact<double>(const Exact& e);
template <>
float from_exact<float>(const Exact& e);
template <>
long double from_exact<long double>(const Exact& e);

// The exact value of a finite float, double or long double (a dyadic rational).
Exact exact_of(float v);
Exact exact_of(double v);
Exact exact_of(long double v);
inline Exact exact_of(const Exact& v) { return v; }

// A real constant as long double with about 30 significant digits behind it (enough to measure
// the error of a long double result against it).
long double to_long_double(const Exact& e);
inline long double to_long_double(float v) { return v; }
inline long double to_long_double(double v) { return v; }
inline long double to_long_double(long double v) { return v; }

}  // namespace frustum
