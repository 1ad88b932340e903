// Printing exact values as on paper: "9*sqrt(3)", "√3/3", "\frac{\sqrt{3}}{3}".
#include "solver/util/exact_format.hpp"

#include <cln/integer.h>
#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string_view>
#include <vector>

namespace frustum {
namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// Roots with a larger index print as powers; beyond this GiNaC's own form is clearer.
constexpr long kMaxRadicalIndex = 64;

// A rational whose numerator or denominator has more digits than this is written as a
// decimal times a power of ten when it is one ("10⁻³⁸⁰", not 1/1000…0).
constexpr std::size_t kMaxPlainDigits = 40;
// The most significant digits such a decimal keeps exactly (a double's 17).
constexpr std::size_t kMaxScientificDigits = 17;

std::string superscript(long n) {
  static constexpr std::string_view kDigits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = n < 0 ? "⁻" : "";
  for (const char c : std::to_string(n < 0 ? -n : n)) out += kDigits[c - '0'];
  return out;
}

// GiNaC prints a numeric or constant through its stream operator; an integer that fits in a
// machine word is written straight away, in the same digits.
std::string ginac_text(const ex& e) {
  if (is_a<numeric>(e)) {
    const numeric& n = ex_to<numeric>(e);
    if (n.is_integer() && cln::integer_length(cln::the<cln::cl_I>(n.to_cl_N())) < 63)
      return std::to_string(n.to_long());
  }
  std::ostringstream out;
  out << e;
  return out.str();
}

bool is_ascii_digit(char c) { return c >= '0' && c <= '9'; }
bool is_ascii_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

bool is_negative_numeric(const ex& e) {
  return is_a<numeric>(e) && ex_to<numeric>(e).is_real() && ex_to<numeric>(e).is_negative();
}

// A term of a sum is printed as sign and magnitude so that sums read "a - b".
bool has_negative_sign(const ex& e) {
  if (is_a<numeric>(e)) return is_negative_numeric(e);
  if (is_a<GiNaC::mul>(e)) return is_negative_numeric(e.op(e.nops() - 1));
  return false;
}

bool is_positive_integer(const ex& e) {
  return is_a<numeric>(e) && ex_to<numeric>(e).is_pos_integer();
}

// d^(1/r) with d a positive integer: the radicals canonical() leaves.
bool is_numeric_radical(const ex& e) {
  if (!is_a<GiNaC::power>(e) || !is_positive_integer(e.op(0)) || !is_a<numeric>(e.op(1)))
    return false;
  const numeric& x = ex_to<numeric>(e.op(1));
  return x.is_rational() && !x.is_integer() && x.numer().is_equal(1);
}

bool has_negative_exponent(const ex& e) {
  return is_a<GiNaC::power>(e) && is_negative_numeric(e.op(1));
}

// Sums list the rational constant first, then radicals by index and radicand, then powers
// of pi by degree, then anything else.
struct TermKey {
  int rank;
  numeric degree;  // of pi
  long index;
  numeric radicand;
};

TermKey term_key(const ex& term) {
  if (is_a<numeric>(term)) return {0, 0, 0, 0};
  std::vector<ex> factors;
  if (is_a<GiNaC::mul>(term)) {
    for (std::size_t i = 0; i < term.nops(); ++i) factors.push_back(term.op(i));
  } else {
    factors.push_back(term);
  }
  bool only_radicals = true;
  bool only_pi = true;
  TermKey key{1, 0, 0, 0};
  for (const ex& f : factors) {
    if (is_a<numeric>(f)) continue;
    if (is_numeric_radical(f)) {
      const long index = ex_to<numeric>(f.op(1)).denom().to_long();
      if (index > key.index || (index == key.index && ex_to<numeric>(f.op(0)) > key.radicand)) {
        key.index = index;
        key.radicand = ex_to<numeric>(f.op(0));
      }
      continue;
    }
    only_radicals = false;
    const bool is_power = is_a<GiNaC::power>(f);
    const ex base = is_power ? f.op(0) : f;
    const ex degree = is_power ? f.op(1) : ex(1);
    if (base.is_equal(GiNaC::Pi) && is_a<numeric>(degree)) {
      key.degree += ex_to<numeric>(degree);
    } else {
      only_pi = false;
    }
  }
  key.rank = only_radicals ? 1 : (only_pi ? 2 : 3);
  return key;
}

// Factors of a product: constants, symbols, functions, other powers, sums, then radicals
// last so that "π√3" never reads as √(3π).
int factor_rank(const ex& f) {
  if (is_a<GiNaC::constant>(f)) return 0;
  if (is_a<GiNaC::symbol>(f)) return 1;
  if (is_a<GiNaC::function>(f)) return 2;
  if (is_numeric_radical(f)) return 5;
  if (is_a<GiNaC::power>(f)) return 3;
  if (is_a<GiNaC::add>(f)) return 4;
  return 3;
}

class Formatter {
 public:
  explicit Formatter(MathStyle style) : style_(style) {}

  std::string text(const ex& e) const {
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (is_a<GiNaC::add>(e)) return sum(e);
    if (is_a<GiNaC::mul>(e) || has_negative_exponent(e)) return product(e);
    if (is_a<GiNaC::power>(e)) return power(e.op(0), e.op(1));
    if (is_a<GiNaC::constant>(e)) return constant(e);
    if (is_a<GiNaC::symbol>(e)) return symbol(e);
    if (is_a<GiNaC::function>(e)) return function(e);
    return fallback(e);
  }

 private:
  std::string_view minus() const { return style_ == MathStyle::Unicode ? "−" : "-"; }

  std::string fraction(const std::string& num, const std::string& den) const {
    if (style_ == MathStyle::Latex) return "\\frac{" + num + "}{" + den + "}";
    return num + "/" + den;
  }

  // A positive rational with a long numerator or denominator that is m·10ᵏ with a short m:
  // "1.7·10⁻³⁷⁹" (Unicode), "1.7e-379" (Plain), "1.7 \cdot 10^{-379}" (LaTeX); "10⁻³⁸⁰" when
  // m = 1.
  std::optional<std::string> scientific(const numeric& n) const {
    if (!n.is_rational() || !n.is_positive()) return std::nullopt;
    const std::string num = ginac_text(n.numer()), den = ginac_text(n.denom());
    if (num.size() <= kMaxPlainDigits && den.size() <= kMaxPlainDigits) return std::nullopt;
    // n = m·10ᵏ: the denominator must be 2ᵃ5ᵇ; m = n·10^max(a, b) is then an integer.
    numeric d = n.denom();
    long twos = 0, fives = 0;
    while (GiNaC::irem(d, 2).is_zero()) d = GiNaC::iquo(d, 2), ++twos;
    while (GiNaC::irem(d, 5).is_zero()) d = GiNaC::iquo(d, 5), ++fives;
    if (!d.is_equal(1)) return std::nullopt;
    long k = -std::max(twos, fives);
    numeric m = n * numeric(10).power(-k);
    while (!m.is_zero() && GiNaC::irem(m, 10).is_zero()) m = GiNaC::iquo(m, 10), ++k;
    const std::string digits = ginac_text(m);
    if (digits.size() > kMaxScientificDigits) return std::nullopt;
    const long exponent = k + static_cast<long>(digits.size()) - 1;
    std::string mantissa = digits.substr(0, 1);
    if (digits.size() > 1) mantissa += "." + digits.substr(1);
    if (style_ == MathStyle::Plain) return mantissa + "e" + std::to_string(exponent);
    const std::string power = style_ == MathStyle::Unicode
                                  ? "10" + superscript(exponent)
                                  : "10^{" + std::to_string(exponent) + "}";
    if (mantissa == "1") return power;
    return mantissa + (style_ == MathStyle::Unicode ? "·" : " \\cdot ") + power;
  }

  std::string number(const numeric& n) const {
    if (!n.is_real()) return fallback(n);
    if (n.is_negative()) return std::string(minus()) + number(-n);
    if (const auto s = scientific(n)) return *s;
    if (n.is_integer()) return ginac_text(n);
    if (n.is_rational()) return fraction(ginac_text(n.numer()), ginac_text(n.denom()));
    return format_double(n.to_double());
  }

  std::string sum(const ex& e) const {
    std::vector<ex> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(e.op(i));
    struct Keyed {
      TermKey key;
      std::string text;
      ex term;
    };
    std::vector<Keyed> keyed;
    for (const ex& t : terms) keyed.push_back({term_key(t), text(t), t});
    std::stable_sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) {
      if (a.key.rank != b.key.rank) return a.key.rank < b.key.rank;
      if (!a.key.degree.is_equal(b.key.degree)) return a.key.degree < b.key.degree;
      if (a.key.index != b.key.index) return a.key.index < b.key.index;
      if (!a.key.radicand.is_equal(b.key.radicand)) return a.key.radicand < b.key.radicand;
      return a.text < b.text;
    });
    terms.clear();
    for (const Keyed& k : keyed) terms.push_back(k.term);
    // A teacher writes "√3 − 1", not "−1 + √3": lead with a positive term when there is one.
    const auto positive =
        std::find_if(terms.begin(), terms.end(), [](const ex& t) { return !has_negative_sign(t); });
    if (positive != terms.end()) std::rotate(terms.begin(), positive, positive + 1);

    std::string out;
    for (std::size_t i = 0; i < terms.size(); ++i) {
      const bool negative = has_negative_sign(terms[i]);
      const std::string magnitude = text(negative ? ex(-terms[i]) : terms[i]);
      if (i == 0) {
        out += negative ? std::string(minus()) + magnitude : magnitude;
      } else {
        out += (negative ? " " + std::string(minus()) + " " : std::string(" + ")) + magnitude;
      }
    }
    return out;
  }

  // A factor inside a product or a denominator: sums need parentheses.
  std::string factor(const ex& f) const {
    if (is_a<GiNaC::add>(f)) return "(" + text(f) + ")";
    if (is_a<numeric>(f) && !is_positive_integer(f)) return "(" + text(f) + ")";
    return text(f);
  }

  // Juxtaposition on paper ("2√3", "π√3"), "*" in Plain, and "·" where digits would run
  // together ("√2·∛3") or before a function name ("2·sin(1)"). The first item is the coefficient
  // when has_coeff is set.
  std::string join(const std::vector<std::string>& items, bool has_coeff) const {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
      const std::string& item = items[i];
      if (i > 0 && !item.empty()) {
        const bool after_coeff = i == 1 && has_coeff;
        const bool digits_meet =
            is_ascii_digit(item.front()) || (!after_coeff && is_ascii_digit(out.back()));
        if (style_ == MathStyle::Plain) {
          out += "*";
        } else if (style_ == MathStyle::Unicode) {
          // A function name run into what precedes it ("πcos(1)") reads as one word.
          const bool word = item.size() > 1 && is_ascii_letter(item[0]) && is_ascii_letter(item[1]);
          if (digits_meet || word) out += "·";
        } else if (digits_meet) {
          out += " \\cdot ";
        } else if (is_ascii_letter(out.back()) && is_ascii_letter(item.front())) {
          out += " ";
        }
      }
      out += item;
    }
    return out;
  }

  std::string product(const ex& e) const {
    numeric coeff = 1;
    std::vector<ex> up;
    std::vector<ex> down;
    const auto add_factor = [&](const ex& f) {
      if (is_a<numeric>(f) && ex_to<numeric>(f).is_real()) {
        coeff *= ex_to<numeric>(f);
      } else if (has_negative_exponent(f)) {
        down.push_back(GiNaC::pow(f.op(0), -f.op(1)));
      } else {
        up.push_back(f);
      }
    };
    if (is_a<GiNaC::mul>(e)) {
      for (std::size_t i = 0; i < e.nops(); ++i) add_factor(e.op(i));
    } else {
      add_factor(e);
    }
    const auto by_rank = [this](const ex& a, const ex& b) {
      const int ra = factor_rank(a);
      const int rb = factor_rank(b);
      if (ra != rb) return ra < rb;
      if (is_numeric_radical(a) && is_numeric_radical(b)) {
        const numeric ia = ex_to<numeric>(a.op(1)).denom();
        const numeric ib = ex_to<numeric>(b.op(1)).denom();
        if (!ia.is_equal(ib)) return ia < ib;
        return ex_to<numeric>(a.op(0)) < ex_to<numeric>(b.op(0));
      }
      return text(a) < text(b);
    };
    std::stable_sort(up.begin(), up.end(), by_rank);
    std::stable_sort(down.begin(), down.end(), by_rank);

    const bool negative = coeff.is_negative();
    if (negative) coeff = -coeff;
    // A coefficient such as 10⁻¹⁹⁰ goes after the other factors: √21·10⁻¹⁹⁰.
    std::optional<std::string> power_of_ten;
    if (!up.empty()) power_of_ten = scientific(coeff);
    if (power_of_ten) coeff = 1;
    const bool rational = coeff.is_rational();
    std::vector<std::string> num_items;
    std::vector<std::string> den_items;
    const numeric num_coeff = rational ? coeff.numer() : coeff;
    const bool num_has_coeff = !num_coeff.is_equal(1) || up.empty();
    if (num_has_coeff) num_items.push_back(number(num_coeff));
    for (const ex& f : up) num_items.push_back(factor(f));
    if (power_of_ten) num_items.push_back(*power_of_ten);
    const bool den_has_coeff = rational && !coeff.denom().is_equal(1);
    if (den_has_coeff) den_items.push_back(ginac_text(coeff.denom()));
    for (const ex& f : down) {
      // \frac{1}{1 + \sqrt{3}} needs no parentheses around a lone denominator.
      const bool lone = style_ == MathStyle::Latex && !den_has_coeff && down.size() == 1;
      den_items.push_back(lone ? text(f) : factor(f));
    }

    std::string out = join(num_items, num_has_coeff);
    if (!den_items.empty()) {
      std::string den = join(den_items, den_has_coeff);
      if (den_items.size() > 1 && style_ != MathStyle::Latex) den = "(" + den + ")";
      out = fraction(out, den);
    }
    return negative ? std::string(minus()) + out : out;
  }

  // A power's base: integers, constants, symbols and function calls stand alone.
  std::string base_text(const ex& base) const {
    if (is_positive_integer(base) || is_a<GiNaC::constant>(base) || is_a<GiNaC::symbol>(base) ||
        is_a<GiNaC::function>(base))
      return text(base);
    return "(" + text(base) + ")";
  }

  std::string radical(const ex& base, long index) const {
    if (style_ == MathStyle::Plain) {
      if (index == 2) return "sqrt(" + text(base) + ")";
      return base_text(base) + "^(1/" + std::to_string(index) + ")";
    }
    if (style_ == MathStyle::Latex) {
      const std::string root = index == 2 ? "\\sqrt" : "\\sqrt[" + std::to_string(index) + "]";
      return root + "{" + text(base) + "}";
    }
    const std::string sign = index == 2   ? "√"
                             : index == 3 ? "∛"
                             : index == 4 ? "∜"
                                          : superscript(index) + "√";
    if (is_positive_integer(base)) return sign + text(base);
    return sign + "(" + text(base) + ")";
  }

  std::string power(const ex& base, const ex& exponent) const {
    if (is_a<numeric>(exponent) && ex_to<numeric>(exponent).is_rational()) {
      const numeric& x = ex_to<numeric>(exponent);
      if (x.numer().is_equal(1) && x.denom() > 1 && x.denom() <= kMaxRadicalIndex)
        return radical(base, x.denom().to_long());
      if (x.is_integer()) {
        if (style_ == MathStyle::Unicode) return base_text(base) + superscript(x.to_long());
        if (style_ == MathStyle::Latex) return base_text(base) + "^{" + ginac_text(x) + "}";
        return base_text(base) + "^" + ginac_text(x);
      }
    }
    if (style_ == MathStyle::Latex) return base_text(base) + "^{" + text(exponent) + "}";
    const bool bare = is_positive_integer(exponent) || is_a<GiNaC::constant>(exponent) ||
                      is_a<GiNaC::symbol>(exponent);
    return base_text(base) + "^" + (bare ? text(exponent) : "(" + text(exponent) + ")");
  }

  std::string constant(const ex& e) const {
    if (e.is_equal(GiNaC::Pi)) {
      return style_ == MathStyle::Plain ? "pi" : (style_ == MathStyle::Unicode ? "π" : "\\pi");
    }
    if (style_ == MathStyle::Unicode && e.is_equal(GiNaC::Euler)) return "γ";
    if (style_ == MathStyle::Latex) return fallback(e);
    return ginac_text(e);
  }

  std::string symbol(const ex& e) const {
    if (style_ == MathStyle::Latex) return fallback(e);
    return ex_to<GiNaC::symbol>(e).get_name();
  }

  std::string function(const ex& e) const {
    const std::string name = ex_to<GiNaC::function>(e).get_name();
    std::string args;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      if (i > 0) args += ", ";
      args += text(e.op(i));
    }
    if (style_ == MathStyle::Plain) return name + "(" + args + ")";
    if (name == "abs") {
      return style_ == MathStyle::Unicode ? "|" + args + "|" : "\\left|" + args + "\\right|";
    }
    if (style_ == MathStyle::Unicode) return name + "(" + args + ")";
    static constexpr std::string_view kLatexNames[][2] = {
        {"sin", "\\sin"},     {"cos", "\\cos"},     {"tan", "\\tan"},   {"asin", "\\arcsin"},
        {"acos", "\\arccos"}, {"atan", "\\arctan"}, {"sinh", "\\sinh"}, {"cosh", "\\cosh"},
        {"tanh", "\\tanh"},   {"exp", "\\exp"},     {"log", "\\ln"}};
    for (const auto& [plain, latex] : kLatexNames) {
      if (name == plain) return std::string(latex) + "(" + args + ")";
    }
    return "\\operatorname{" + name + "}(" + args + ")";
  }

  // Anything the rules above do not know: GiNaC's own text, parenthesised in Plain so it
  // stays one operand.
  std::string fallback(const ex& e) const {
    std::ostringstream out;
    if (style_ == MathStyle::Latex) {
      out << GiNaC::latex << e;
      return out.str();
    }
    out << e;
    return "(" + out.str() + ")";
  }

  MathStyle style_;
};

}  // namespace

std::string format_exact(const Exact& e, MathStyle style) { return Formatter(style).text(e); }

std::string format_double(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  if (v == 0) return "0";  // also -0.0
  return fmt::format("{}", v);
}

std::string format_long_double(long double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  if (v == 0) return "0";
  char buffer[64];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
  if (error != std::errc()) return format_double(static_cast<double>(v));
  return std::string(buffer, end);
}

std::string format_approx(double v, int significant) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  if (v == 0) return "0";
  const std::string out = fmt::format("{:.{}g}", v, std::max(significant, 1));
  return out == "-0" ? "0" : out;
}

std::string format_exact_approx(const Exact& e, int significant) {
  const double d = to_double(e);
  if (std::isnan(d) || (std::isnormal(d) && std::isfinite(d))) return format_approx(d, significant);
  numeric q;
  try {
    q = rational_near(e);
  } catch (const std::exception&) {
    return "nan";
  }
  if (q.is_zero()) return "0";
  // q = x·10ᵏ with x in double's comfortable range, from the digits of q's parts.
  const long k = static_cast<long>(ginac_text(GiNaC::abs(q.numer())).size()) -
                 static_cast<long>(ginac_text(q.denom()).size());
  const double x = to_double(q * numeric(10).power(-k));
  const double lead = std::floor(std::log10(std::abs(x)));
  std::string mantissa = fmt::format("{:.{}g}", x / std::pow(10.0, lead), std::max(significant, 1));
  long exponent = k + static_cast<long>(lead);
  if (mantissa == "10" || mantissa == "-10") {  // rounded up to the next power
    mantissa = mantissa[0] == '-' ? "-1" : "1";
    ++exponent;
  }
  return mantissa + "e" + (exponent < 0 ? "-" : "+") + std::to_string(std::labs(exponent));
}

}  // namespace frustum
