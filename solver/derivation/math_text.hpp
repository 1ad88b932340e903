// A piece of mathematics kept in the two notations the formatters need: Unicode for the
// terminal and JSON ("√3/3", "x + y − z = −6") and LaTeX for Markdown ("\frac{\sqrt{3}}{3}").
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/core/matrix.hpp"
#include "solver/util/said.hpp"

namespace frustum {

struct MathText {
  std::string unicode;
  std::string latex;
  // English words written inside the mathematics (each once, as given to word()): a formatter
  // in another language translates them (i18n.hpp); the LaTeX holds each as \text{word}.
  std::vector<Said> words = {};

  bool empty() const { return unicode.empty() && latex.empty(); }
  MathText& operator+=(const MathText& other);
};

MathText operator+(MathText a, const MathText& b);

// Literal text, the same in both notations (a number, a name written plainly).
MathText math(std::string_view both);
// A formula written once, in LaTeX: its Unicode is read from it (latex_unicode.hpp), so the two
// cannot drift apart. Pieces around values are joined with + and frac(); only this file's
// builders (vectors, matrices, counts) write the two notations separately, through
// math_pair().
MathText tex(std::string_view latex);

// A fraction of two pieces already written (values, or formulas around them): \frac{a}{b} in
// LaTeX, a/b on one line with the parentheses that reading needs ((a + b)/c, d/(a·z)).
MathText frac(const MathText& numerator, const MathText& denominator);

// Words inside mathematics ("yes", "front", "background"): Unicode as written, LaTeX as
// \text{…} with LaTeX's special characters escaped; translated by the formatters.
MathText word(const Said& said);
MathText word(const Phrase& phrase);
// Text escaped for LaTeX's text mode (\text{…}, and the LaTeX document's prose).
std::string latex_text(std::string_view text);

// Counts with their words, "3 front, 3 back, 0 edge-on" (LaTeX: 3\,\text{front},\; …).
MathText counts(const std::vector<std::pair<long, std::string>>& items);

// An exact value in paper form ("9√3"); with_approx adds the decimal ("9√3 ≈ 15.59") when
// the value is not an integer.
MathText exact(const Exact& e, bool with_approx = false);
MathText number(double v);
// A long double with all the digits it holds (not rounded to a double's).
MathText long_number(long double v);

// (a, b, c) of exact values.
MathText vec(const std::vector<Exact>& v, bool with_approx = false);
template <int N>
MathText vec(const Eigen::Matrix<Exact, N, 1>& v, bool with_approx = false) {
  return vec(std::vector<Exact>(v.data(), v.data() + N), with_approx);
}
// A matrix as on paper (rows), bracketed.
MathText matrix(const std::vector<std::vector<Exact>>& rows);
// (a, b, c) of entries already written (decimals of a numeric backend).
MathText tuple_of(const std::vector<MathText>& entries);
// A matrix of entries already written, `cols` to a row.
MathText matrix_of(const std::vector<MathText>& entries, std::size_t cols);

// Σ coefᵢ·nameᵢ = rhs written as on paper: unit coefficients dropped, signs as " − ", zero
// terms left out; an empty name is a constant term ("1 + 1 − z = −6").
MathText linear_expression(const std::vector<std::pair<Exact, std::string>>& terms);
MathText linear_equation(const std::vector<std::pair<Exact, std::string>>& terms, const Exact& rhs);

// a x + b y + c z = d, with unit coefficients and signs written as on paper.
MathText plane_equation(const Exact& a, const Exact& b, const Exact& c, const Exact& d);

// Whether an exact value is worth a decimal beside it (not an integer).
bool needs_approx(const Exact& e);

}  // namespace frustum
