#include "solver/numeric/precision.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace frustum {

std::string_view to_string(Precision p) {
  switch (p) {
    case Precision::Float:
      return "float";
    case Precision::Double:
      return "double";
    case Precision::LongDouble:
      return "long-double";
    case Precision::Exact:
      break;
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
    case Precision::Float:
      return std::numeric_limits<float>::digits;
    case Precision::Double:
      return std::numeric_limits<double>::digits;
    case Precision::LongDouble:
      return std::numeric_limits<long double>::digits;
    case Precision::Exact:
      break;
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
  if (p == Precision::Exact) return "exact (GiNaC: rationals and radicals, no rounding anywhere)";
  const char* format = p == Precision::Float    ? "IEEE 754 binary32"
                       : p == Precision::Double ? "IEEE 754 binary64"
                                                : "x87 80-bit extended";
  return fmt::format(
      "{} ({}, {}-bit significand, unit roundoff {:.1e}, about {:.1f} decimal digits)",
      to_string(p), format, significand_bits(p), unit_roundoff(p), decimal_digits(p));
}

namespace {

// The nearest T of a rational q, ties to even, in one rounding: subnormals kept (not flushed),
// beyond the largest finite value ±∞. With p significand bits and 2^emin the least normal,
// q = whole·2^(e−p+1) with whole an integer of at most p bits.
template <typename T>
T round_rational(const GiNaC::numeric& q) {
  using GiNaC::numeric;
  if (q.is_zero()) return T(0);
  constexpr int p = std::numeric_limits<T>::digits;
  constexpr int emin = std::numeric_limits<T>::min_exponent - 1;
  constexpr int emax = std::numeric_limits<T>::max_exponent;
  const numeric a = GiNaC::abs(q);
  // 2^k ≤ a < 2^(k+1)
  int k = a.numer().int_length() - a.denom().int_length();
  while (a < numeric(2).power(k)) --k;
  while (a >= numeric(2).power(k + 1)) ++k;
  T magnitude = std::numeric_limits<T>::infinity();
  if (k < emax) {
    const int e = std::max(k, emin);
    const numeric scaled = a * numeric(2).power(p - 1 - e);
    const numeric num = scaled.numer(), den = scaled.denom();
    numeric whole = GiNaC::iquo(num, den);
    const numeric twice_rem = 2 * (num - whole * den);
    if (twice_rem > den || (twice_rem == den && !whole.is_even())) whole += 1;
    // whole < 2^64: its two 32-bit halves are exact in double, their sum exact in T.
    const numeric high = GiNaC::iquo(whole, numeric(4294967296));
    const T w = T(high.to_double()) * T(4294967296) + T((whole - high * 4294967296).to_double());
    magnitude = std::ldexp(w, e - (p - 1));
  }
  return q.is_negative() ? -magnitude : magnitude;
}

}  // namespace

template <>
double from_exact<double>(const Exact& e) {
  // Rationals by CLN (correctly rounded, subnormals too); other values from their rational
  // approximation, so a subnormal √2·10⁻³¹⁰ is not flushed.
  if (GiNaC::is_a<GiNaC::numeric>(e)) return to_double(e);
  return round_rational<double>(rational_near(e));
}

// Float and long double round the exact value once (through double they would round twice,
// and long double would lose the range beyond double's: 1e-400 is not 0).
template <>
float from_exact<float>(const Exact& e) {
  return round_rational<float>(rational_near(e));
}

template <>
long double from_exact<long double>(const Exact& e) {
  return round_rational<long double>(rational_near(e));
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
  const Exact e =
      GiNaC::numeric(static_cast<unsigned long>(m)) * GiNaC::numeric(2).power(exponent - kBits);
  return v < 0 ? Exact(-e) : e;
}

}  // namespace frustum
