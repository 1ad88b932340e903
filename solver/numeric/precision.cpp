#include "solver/numeric/precision.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace frustum {

std::string_view to_string(Precision p) {
  switch (p) {
    case Precision::Float: return "float";
    case Precision::Double: return "double";
    case Precision::LongDouble: return "long-double";
    case Precision::Exact: break;
  }
  return "exact";
}

std::optional<Precision> parse_precision(std::string_view text) {
  for (Precision p : kAllPrecisions)
    if (text == to_string(p)) return p;
  if (text == "long_double" || text == "longdouble") return Precision::LongDouble;
  return std::nullopt;
}

namespace {

int significand_bits(Precision p) {
  switch (p) {
    case Precision::Float: return std::numeric_limits<float>::digits;
    case Precision::Double: return std::numeric_limits<double>::digits;
    case Precision::LongDouble: return std::numeric_limits<long double>::digits;
    case Precision::Exact: break;
  }
  return 0;
}

}  // namespace

double unit_roundoff(Precision p) {
  return p == Precision::Exact ? 0.0 : std::ldexp(1.0, -significand_bits(p));
}

double decimal_digits(Precision p) {
  return p == Precision::Exact ? std::numeric_limits<double>::infinity()
                               : -std::log10(unit_roundoff(p));
}

std::string describe(Precision p) {
  if (p == Precision::Exact)
    return "exact (GiNaC: rationals and radicals, no rounding anywhere)";
  const char* format = p == Precision::Float    ? "IEEE 754 binary32"
                       : p == Precision::Double ? "IEEE 754 binary64"
                                                : "x87 80-bit extended";
  return fmt::format("{} ({}, {}-bit significand, unit roundoff {:.1e}, about {:.1f} decimal digits)",
                     to_string(p), format, significand_bits(p), unit_roundoff(p), decimal_digits(p));
}

namespace {

// e ≈ hi + lo with hi the nearest double and lo the nearest double of the rest: about 106
// bits, more than a long double's 64.
void split_double_double(const Exact& e, double& hi, double& lo) {
  hi = to_double(e);
  lo = std::isfinite(hi) ? to_double(e - exact_from_double(hi)) : 0.0;
}

}  // namespace

template <>
double from_exact<double>(const Exact& e) {
  return to_double(e);
}

template <>
float from_exact<float>(const Exact& e) {
  // Rounding through double could round twice; rounding hi + lo once avoids it in practice.
  double hi = 0, lo = 0;
  split_double_double(e, hi, lo);
  return static_cast<float>(static_cast<long double>(hi) + static_cast<long double>(lo));
}

template <>
long double from_exact<long double>(const Exact& e) {
  double hi = 0, lo = 0;
  split_double_double(e, hi, lo);
  return static_cast<long double>(hi) + static_cast<long double>(lo);
}

long double to_long_double(const Exact& e) { return from_exact<long double>(e); }

Exact exact_of(double v) { return exact_from_double(v); }
Exact exact_of(float v) { return exact_from_double(static_cast<double>(v)); }

Exact exact_of(long double v) {
  if (!std::isfinite(v)) throw std::domain_error("exact_of: not a finite number");
  int exponent = 0;
  const long double fraction = std::frexp(v, &exponent);  // v = fraction · 2^exponent
  constexpr int kBits = std::numeric_limits<long double>::digits;
  const long double mantissa = std::ldexp(std::abs(fraction), kBits);  // an integer < 2^64
  const auto m = static_cast<unsigned long long>(mantissa);
  const Exact e = GiNaC::numeric(static_cast<unsigned long>(m)) * GiNaC::numeric(2).power(exponent - kBits);
  return v < 0 ? Exact(-e) : e;
}

}  // namespace frustum
