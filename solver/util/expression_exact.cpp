// From parsed pieces to exact values: GiNaC's evaluation with its exceptions turned into
// located errors, numeric approximation of constants, and plain decimal literals read as
// the exact rationals they denote.
#include <array>
#include <cctype>
#include <limits>
#include <optional>
#include <string>

#include "solver/core/exact.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/expression_internal.hpp"

namespace frustum {
namespace expression_internal {
namespace {

// Why a value is not read.
constexpr Phrase kCannotCompute{"this value cannot be computed", "この値は計算できません",
                                "это значение нельзя вычислить"};
constexpr Phrase kNotRealNumber{"not a real number", "実数ではありません",
                                "не действительное число"};

}  // namespace

// Floating approximation of a constant (no symbols).
numeric approximate(const ex& e, std::size_t offset) {
  const ex a = evaluate([&] { return e.evalf(); }, offset);
  if (!is_a<numeric>(a)) fail(say(kCannotCompute), offset);
  return ex_to<numeric>(a);
}

// The solver is real-valued: a constant must evaluate to a real number.
void require_real(const ex& e, std::size_t offset, const Said& why) {
  if (has_symbol(e)) return;
  if (!approximate(e, offset).is_real()) fail(why.empty() ? say(kNotRealNumber) : why, offset);
}

}  // namespace expression_internal

// A plain decimal literal ("-12", "0.57735", "1.5e-3") as the exact rational it denotes,
// without the lexer and parser: most numbers in problem sets and answers are these.
// Anything else (or an exponent beyond ±400) is left to the parser.
namespace {
constexpr std::array<long, 19> kPowersOfTen = [] {
  std::array<long, 19> p{};
  long v = 1;
  for (long& x : p) {
    x = v;
    v = v <= std::numeric_limits<long>::max() / 10 ? v * 10 : v;
  }
  return p;
}();
}  // namespace

std::optional<GiNaC::ex> parse_decimal_literal(std::string_view text) {
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n && text[i] == ' ') ++i;
  bool negative = false;
  if (i < n && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  std::string digits;
  long scale = 0;
  bool any = false;
  for (; i < n && std::isdigit(static_cast<unsigned char>(text[i])); ++i, any = true)
    digits += text[i];
  if (i < n && text[i] == '.') {
    for (++i; i < n && std::isdigit(static_cast<unsigned char>(text[i])); ++i, any = true) {
      digits += text[i];
      --scale;
    }
  }
  if (!any || digits.size() > 40) return std::nullopt;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < n && (text[i] == '-' || text[i] == '+')) exp_negative = text[i++] == '-';
    long e = 0;
    bool exp_digits = false;
    for (; i < n && std::isdigit(static_cast<unsigned char>(text[i])) && e < 1000;
         ++i, exp_digits = true)
      e = e * 10 + (text[i] - '0');
    if (!exp_digits || e > 400) return std::nullopt;
    scale += exp_negative ? -e : e;
  }
  while (i < n && text[i] == ' ') ++i;
  if (i != n) return std::nullopt;
  // Up to 18 digits fit a long exactly; longer mantissas go through CLN's reader.
  long small = 0;
  if (digits.size() <= 18)
    for (const char c : digits) small = small * 10 + (c - '0');
  const GiNaC::numeric mantissa =
      digits.size() <= 18 ? GiNaC::numeric(small) : GiNaC::numeric(digits.c_str());
  // A decimal of at most 18 digits after the point is small / 10^k, one rational (a class's
  // answers are mostly such decimals: no power is computed for them).
  const GiNaC::numeric value =
      scale == 0 ? mantissa
      : digits.size() <= 18 && scale < 0 && scale >= -18
          ? GiNaC::numeric(small, kPowersOfTen[static_cast<std::size_t>(-scale)])
          : mantissa * GiNaC::numeric(10).power(GiNaC::numeric(scale));
  return GiNaC::ex(negative ? -value : value);
}

}  // namespace frustum
