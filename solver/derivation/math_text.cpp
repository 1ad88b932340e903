#include "solver/derivation/math_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "solver/derivation/latex_unicode.hpp"
#include "solver/derivation/line_breaks.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

// Whether LaTeX text ends with a control word (\quad, \cdot): a letter written right after it
// would be read as part of its name (\quadj).
bool ends_with_control_word(const std::string& latex) {
  std::size_t i = latex.size();
  while (i > 0 && std::isalpha(static_cast<unsigned char>(latex[i - 1]))) --i;
  return i < latex.size() && i > 0 && latex[i - 1] == '\\';
}

}  // namespace

MathText& MathText::operator+=(const MathText& other) {
  unicode += other.unicode;
  if (!other.latex.empty() && std::isalpha(static_cast<unsigned char>(other.latex[0])) &&
      ends_with_control_word(latex))
    latex += ' ';
  latex += other.latex;
  for (const Said& w : other.words)
    if (std::find(words.begin(), words.end(), w) == words.end()) words.push_back(w);
  return *this;
}

MathText operator+(MathText a, const MathText& b) { return a += b; }

MathText math(std::string_view both) { return {std::string(both), std::string(both)}; }

namespace {

// The two notations written separately: only for the builders below, whose pieces (a matrix's
// brackets and separators) are not formulas of their own.
MathText math_pair(std::string_view unicode, std::string_view latex) {
  return {std::string(unicode), std::string(latex)};
}

}  // namespace

MathText tex(std::string_view latex) { return {unicode_of_latex(latex), std::string(latex)}; }

MathText frac(const MathText& numerator, const MathText& denominator) {
  MathText m{fraction_unicode(numerator.unicode, denominator.unicode),
             "\\frac{" + numerator.latex + "}{" + denominator.latex + "}"};
  m += MathText{"", "", numerator.words};
  m += MathText{"", "", denominator.words};
  return m;
}

std::string latex_text(std::string_view text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '\\':
        out += "\\textbackslash{}";
        break;
      case '_':
      case '#':
      case '%':
      case '&':
      case '{':
      case '}':
      case '$':
        out += '\\';
        out += c;
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      default:
        out += c;
    }
  }
  return out;
}

MathText word(const Said& said) {
  MathText m{said.en(), "\\text{" + latex_text(said.en()) + "}", {}};
  m.words.push_back(said);
  return m;
}

MathText word(const Phrase& phrase) { return word(Said(phrase)); }

MathText counts(const std::vector<std::pair<long, std::string>>& items) {
  MathText m;
  for (const auto& [n, what] : items)
    m += (m.empty() ? MathText{} : math_pair(", ", ",\\; ")) +
         math_pair(std::to_string(n) + " ", std::to_string(n) + "\\,") +
         word(words::vocabulary_word(what));
  return m;
}

bool needs_approx(const Exact& e) {
  return !GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer();
}

namespace {

// Unicode text uses the minus sign U+2212, never an ASCII hyphen.
std::string unicode_minus(std::string s) {
  std::string out;
  for (char c : s) out += c == '-' ? std::string("−") : std::string(1, c);
  return out;
}

// A decimal in LaTeX: an exponent as a power of ten ("1.26e-18" → 1.26 \times 10^{-18}).
std::string latex_decimal(const std::string& d) {
  const std::size_t e = d.find_first_of("eE");
  if (e == std::string::npos) return d;
  std::string exponent = d.substr(e + 1);
  if (!exponent.empty() && exponent[0] == '+') exponent.erase(0, 1);
  while (exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
  if (exponent.size() > 2 && exponent[0] == '-' && exponent[1] == '0') exponent.erase(1, 1);
  return d.substr(0, e) + " \\times 10^{" + exponent + "}";
}

}  // namespace

namespace {

// An exact form longer than this (characters) is not one a student can read or check: a
// derivation shows its decimal expansion instead, cut after six significant digits and
// followed by "…" (the digits shown are the value's own; the exact value stays in the JSON).
constexpr std::size_t kReadableExact = 40;

// e's first six significant digits, cut (not rounded), as a plain decimal between 10⁻⁴ and
// 10⁶ and in e-notation beyond; from the double nearest e (its 17 digits settle the first six
// unless e lies within 10⁻¹⁶ of a six-digit boundary).
std::string cut_decimal(const Exact& e) {
  const double d = to_double(e);
  if (!std::isfinite(d) || d == 0) return format_exact_approx(e, 6);
  const std::string sci = fmt::format("{:.16e}", std::abs(d));  // "5.3370212345678901e-01"
  const std::string digits = sci.substr(0, 1) + sci.substr(2, 5);
  const int exponent = std::stoi(sci.substr(sci.find('e') + 1));
  std::string out = d < 0 ? "-" : "";
  if (exponent < -4 || exponent > 5)
    return out + digits.substr(0, 1) + "." + digits.substr(1) + (exponent < 0 ? "e-" : "e+") +
           std::to_string(std::abs(exponent));
  if (exponent < 0)
    return out + "0." + std::string(static_cast<std::size_t>(-exponent - 1), '0') + digits;
  const auto point = static_cast<std::size_t>(exponent + 1);
  return out + digits.substr(0, point) + (point < digits.size() ? "." + digits.substr(point) : "");
}

MathText cut(const Exact& e) {
  const std::string d = cut_decimal(e);
  return {unicode_minus(d) + "…", latex_decimal(d) + "\\ldots"};
}

}  // namespace

MathText exact(const Exact& e, bool with_approx) {
  const Exact c = canonical(e);
  MathText m{format_exact(c, MathStyle::Unicode), format_exact(c, MathStyle::Latex)};
  if (with_approx && needs_approx(c) && characters(m.unicode) > kReadableExact) return cut(c);
  if (with_approx && needs_approx(c)) {
    const std::string d = format_exact_approx(c);
    m.unicode += " ≈ " + unicode_minus(d);
    m.latex += " \\approx " + latex_decimal(d);
  }
  return m;
}

MathText number(double v) {
  return math_pair(unicode_minus(format_double(v)), latex_decimal(format_double(v)));
}

MathText long_number(long double v) {
  return math_pair(unicode_minus(format_long_double(v)), latex_decimal(format_long_double(v)));
}

MathText vec(const std::vector<Exact>& v, bool with_approx) {
  std::vector<MathText> entries;
  bool any_approx = false;
  std::size_t length = 0;
  for (const Exact& e : v) {
    entries.push_back(exact(e));
    length += characters(entries.back().unicode);
    any_approx = any_approx || needs_approx(canonical(e));
  }
  // Too long to read as exact forms: the decimals, cut after six digits.
  if (with_approx && any_approx && length > 2 * kReadableExact) {
    MathText m = tex("\\left(");
    for (std::size_t i = 0; i < v.size(); ++i)
      m += (i ? math(", ") : math("")) +
           (needs_approx(canonical(v[i])) ? cut(canonical(v[i])) : exact(v[i]));
    return m + tex("\\right)");
  }
  // A long vector may break after its commas: \left( … \right) is one unbreakable box, so its
  // brackets are then \bigl( \bigr).
  const bool breakable = length > 40;
  const std::string open = breakable ? "\\bigl(" : "\\left(";
  const std::string close = breakable ? "\\bigr)" : "\\right)";
  const std::string comma = breakable ? ", \\allowbreak " : ", ";
  MathText m = math_pair("(", open);
  for (std::size_t i = 0; i < entries.size(); ++i)
    m += (i ? math_pair(", ", comma) : math("")) + entries[i];
  m += math_pair(")", close);
  if (with_approx && any_approx) {
    std::string d = "(", dl = open;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (i) d += ", ", dl += comma;
      d += format_exact_approx(v[i]);
      dl += latex_decimal(format_exact_approx(v[i]));
    }
    m += math_pair(" ≈ " + unicode_minus(d + ")"), " \\approx " + dl + close);
  }
  return m;
}

MathText matrix(const std::vector<std::vector<Exact>>& rows) {
  std::vector<MathText> entries;
  for (const auto& row : rows)
    for (const Exact& e : row) entries.push_back(exact(e));
  return matrix_of(entries, rows.empty() ? 0 : rows[0].size());
}

MathText tuple_of(const std::vector<MathText>& entries) {
  MathText m = math("(");
  for (std::size_t i = 0; i < entries.size(); ++i) m += (i ? math(", ") : math("")) + entries[i];
  return m + math(")");
}

MathText matrix_of(const std::vector<MathText>& entries, std::size_t cols) {
  MathText m = math_pair("[", "\\begin{bmatrix}");
  for (std::size_t k = 0; k < entries.size(); ++k) {
    if (k > 0) m += cols > 0 && k % cols == 0 ? math_pair("; ", " \\\\ ") : math_pair(", ", " & ");
    m += entries[k];
  }
  m += math_pair("]", "\\end{bmatrix}");
  return m;
}

MathText linear_expression(const std::vector<std::pair<Exact, std::string>>& terms) {
  MathText m;
  bool first = true;
  for (const auto& [raw, name] : terms) {
    const Exact coef = canonical(raw);
    if (coef.is_zero()) continue;
    const bool negative = exact_sign(coef) < 0;
    const Exact mag = negative ? Exact(-coef) : coef;
    if (first) {
      if (negative) m += tex("-");
    } else {
      m += negative ? tex(" - ") : math(" + ");
    }
    if (name.empty() || mag != 1) {
      const bool sum = GiNaC::is_a<GiNaC::add>(mag) && !name.empty();
      if (sum) m += tex("\\left(");
      m += exact(mag);
      if (sum) m += tex("\\right)");
      if (!name.empty() && !sum && !GiNaC::is_a<GiNaC::numeric>(mag))
        m += math_pair("·", " \\cdot ");
    }
    m += math(name);
    first = false;
  }
  if (first) m += math("0");
  return m;
}

MathText linear_equation(const std::vector<std::pair<Exact, std::string>>& terms,
                         const Exact& rhs) {
  return linear_expression(terms) + math(" = ") + exact(rhs);
}

MathText plane_equation(const Exact& a, const Exact& b, const Exact& c, const Exact& d) {
  return linear_equation({{a, "x"}, {b, "y"}, {c, "z"}}, d);
}

}  // namespace frustum
