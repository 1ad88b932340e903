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

// Why a text is not read: the limits that keep it from growing without bound. Values (a
// number, a power written as GiNaC prints it, a limit) are placed as written.
constexpr Phrase kNestedTooDeeply{
    "nested too deeply (more than {0} levels of brackets, functions, signs or powers)",
    "入れ子が深すぎます (括弧, 関数, 符号, べきが {0} 段を超えています)",
    "слишком глубокая вложенность (больше {0} уровней скобок, функций, знаков или степеней)"};
constexpr Phrase kCombinedExponentTooLarge{
    "exponent too large (the powers combine to an exponent of {0}; the limit is {1})",
    "指数が大きすぎます (べきを合わせた指数は {0}, 上限は {1})",
    "слишком большой показатель (степени дают вместе показатель {0}; предел {1})"};
constexpr Phrase kNumberTooLarge{"number too large (it would have {0} bits; the limit is {1})",
                                 "数が大きすぎます ({0} ビットになります. 上限は {1})",
                                 "слишком большое число (в нём было бы {0} бит; предел {1})"};
constexpr Phrase kTooManyTerms{
    "the expression is too big (expanded it would have more than {0} terms)",
    "式が大きすぎます (展開すると {0} 項を超えます)",
    "выражение слишком велико (в раскрытом виде больше {0} членов)"};
constexpr Phrase kRootTooHigh{"roots beyond the {0}th are not supported (exponent {1})",
                              "{0} 乗根を超える根は扱えません (指数 {1})",
                              "корни степени выше {0} не поддерживаются (показатель {1})"};
// {0}^{1}: the power; {2}: how many bits (a number, or kFarMoreThan).
constexpr Phrase kPowerTooLarge{
    "exponent too large ({0}^{1} would have {2} bits; the limit is {3})",
    "指数が大きすぎます (`{0}^{1}` は {2} ビットになります. 上限は {3})",
    "слишком большой показатель (в `{0}^{1}` было бы {2} бит; предел {3})"};
constexpr Phrase kFarMoreThan{"far more than {0}", "{0} をはるかに超える", "намного больше {0}"};
constexpr Phrase kExponentTooLarge{"exponent too large ({0}; the limit is {1})",
                                   "指数が大きすぎます (`{0}`. 上限は {1})",
                                   "слишком большой показатель (`{0}`; предел {1})"};

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
    fail(say(kNestedTooDeeply, limit), offset);
  }
  ++depth_;
}

void check_value_size(const Value& v, const ExpressionOptions& options, std::size_t offset) {
  const ExactSize size = exact_size(v.value);
  // GiNaC merges powers: (x^1000)^4 is x^4000.
  if (size.max_exponent > numeric(options.max_exponent)) {
    fail(say(kCombinedExponentTooLarge, describe(size.max_exponent), options.max_exponent), offset);
  }
  // Products of big numbers are bounded like powers: 99^99*99^99*... grows without one.
  if (static_cast<std::size_t>(size.max_bits) > options.max_exact_bits) {
    fail(say(kNumberTooLarge, size.max_bits + 1, options.max_exact_bits), offset);
  }
  if (size.work > kMaxExpandedTerms) {
    fail(say(kTooManyTerms, whole_number(kMaxExpandedTerms)), offset);
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
    fail(say(kRootTooHigh, kMaxParsedRootIndex, k_text.str()), exponent_offset);
  }

  // GiNaC evaluates rational^(p/q) through rational^p: about |p| * height bits.
  const numeric abs_k = GiNaC::abs(k);
  const numeric cost_k = rational ? GiNaC::abs(exact_k.numer()) : abs_k;
  const numeric kHuge(1'000'000'000'000'000L);
  const double cost_bits =
      cost_k > kHuge ? std::numeric_limits<double>::infinity() : cost_k.to_double() * base.height;
  const double max_bits = static_cast<double>(options.max_exact_bits);
  if (cost_bits > max_bits) {
    const Said size = std::isinf(cost_bits) ? say(kFarMoreThan, whole_number(max_bits))
                                            : Said::verbatim(whole_number(cost_bits));
    fail(say(kPowerTooLarge, describe(base.value), describe(exponent.value), size,
             whole_number(max_bits)),
         offset);
  }
  if (abs_k > numeric(options.max_exponent)) {
    fail(say(kExponentTooLarge, describe(exponent.value), options.max_exponent), exponent_offset);
  }
}

}  // namespace frustum::expression_internal
