// The expression parser's bounds, checked before GiNaC computes anything: nesting depth, the
// size of exact numbers and powers, and the expanded size of a value.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "solver/core/exact.hpp"
#include "solver/core/work_budget.hpp"
#include "solver/util/expression_internal.hpp"

namespace frustum::expression_internal {
namespace {

// expand() (here on divisors, and downstream) multiplies sums out; (a+b+c+d)^1000 or a
// product of many sums would create more terms than memory holds.
constexpr double kMaxExpandedTerms = 10'000;
// A nesting level costs about 1.5 KB of stack in an unoptimised build, so a caller's
// overridden max_depth is capped to fit a 512 KB thread stack.
constexpr int kMaxSafeDepth = 256;

// log2(max(|numerator|, denominator)) of a rational, accurate for any size.
double rational_height(const numeric& r) {
  numeric m = std::max(GiNaC::abs(r.numer()), r.denom());
  const long bits = m.int_length();
  constexpr long kKeep = 60;
  if (bits <= kKeep) return std::log2(m.to_double());
  const long shift = bits - kKeep;
  return static_cast<double>(shift) +
         std::log2(GiNaC::iquo(m, numeric(2).power(shift)).to_double());
}

}  // namespace

// Tightens the bounds when GiNaC has already reduced the value to an atom.
void settle(Value& v) {
  if (is_a<numeric>(v.value)) {
    const numeric& n = ex_to<numeric>(v.value);
    if (n.is_rational()) v.height = rational_height(n);
  } else if (is_a<GiNaC::symbol>(v.value) || is_a<GiNaC::constant>(v.value)) {
    v.height = 0;
  }
}

// Short human form of a value for messages ("2", "(1/2)", "a 1001-digit number").
std::string describe(const ex& e) {
  std::ostringstream out;
  out << e;
  std::string s = out.str();
  if (s.size() > 24) {
    if (is_a<numeric>(e) && ex_to<numeric>(e).is_integer()) {
      const std::size_t digits = s.size() - (s[0] == '-' ? 1 : 0);
      return "[a " + std::to_string(digits) + "-digit number]";
    }
    return "[a long expression]";
  }
  if (s.find_first_of("+-*/^ ") != std::string::npos) s = "(" + s + ")";
  return s;
}

std::string whole_number(double x) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << std::ceil(x);
  return out.str();
}

int nesting_limit(const ExpressionOptions& options) {
  return std::min(options.max_depth, kMaxSafeDepth);
}

Nesting::Nesting(int& depth, int limit, std::size_t offset) : depth_(depth) {
  if (depth_ >= limit) {
    fail("nested too deeply (more than " + std::to_string(limit) +
             " levels of brackets, functions, signs or powers)",
         offset);
  }
  ++depth_;
}

void check_value_size(const Value& v, const ExpressionOptions& options, std::size_t offset) {
  const ExactSize size = exact_size(v.value);
  // GiNaC merges powers: (x^1000)^4 is x^4000.
  if (size.max_exponent > numeric(options.max_exponent)) {
    fail("exponent too large (the powers combine to an exponent of " + describe(size.max_exponent) +
             "; the limit is " + std::to_string(options.max_exponent) + ")",
         offset);
  }
  // Products of big numbers are bounded like powers: 99^99*99^99*... grows without one.
  if (static_cast<std::size_t>(size.max_bits) > options.max_exact_bits) {
    fail("number too large (it would have " + std::to_string(size.max_bits + 1) +
             " bits; the limit is " + std::to_string(options.max_exact_bits) + ")",
         offset);
  }
  if (size.work > kMaxExpandedTerms) {
    fail("the expression is too big (expanded it would have more than " +
             whole_number(kMaxExpandedTerms) + " terms)",
         offset);
  }
}

void check_power(const Value& base, const Value& exponent, const numeric& k,
                 const ExpressionOptions& options, std::size_t offset,
                 std::size_t exponent_offset) {
  const bool rational = is_a<numeric>(exponent.value);  // exact numerics are rational here
  const numeric exact_k = rational ? ex_to<numeric>(exponent.value) : numeric(0);
  const bool integer = rational && exact_k.is_integer();
  if (rational && !integer && exact_k.denom() > kMaxParsedRootIndex) {
    std::ostringstream k_text;
    k_text << exact_k;
    fail("roots beyond the " + std::to_string(kMaxParsedRootIndex) +
             "th are not supported (exponent " + k_text.str() + ")",
         exponent_offset);
  }

  // GiNaC evaluates rational^(p/q) through rational^p: about |p| * height bits.
  const numeric abs_k = GiNaC::abs(k);
  const numeric cost_k = rational ? GiNaC::abs(exact_k.numer()) : abs_k;
  const numeric kHuge(1'000'000'000'000'000L);
  const double cost_bits =
      cost_k > kHuge ? std::numeric_limits<double>::infinity() : cost_k.to_double() * base.height;
  const double max_bits = static_cast<double>(options.max_exact_bits);
  if (cost_bits > max_bits) {
    const std::string size =
        std::isinf(cost_bits) ? "far more than " + whole_number(max_bits) : whole_number(cost_bits);
    fail("exponent too large (" + describe(base.value) + "^" + describe(exponent.value) +
             " would have " + size + " bits; the limit is " + whole_number(max_bits) + ")",
         offset);
  }
  if (abs_k > numeric(options.max_exponent)) {
    fail("exponent too large (" + describe(exponent.value) + "; the limit is " +
             std::to_string(options.max_exponent) + ")",
         exponent_offset);
  }
}

}  // namespace frustum::expression_internal
