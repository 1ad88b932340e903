// solver/derivation/latex_unicode.cpp: a formula written once in LaTeX, read into its Unicode
// form; math_text.hpp's builders give no way to write the two notations apart, and every
// derivation's formulas are their LaTeX read.
#include "solver/derivation/latex_unicode.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "solver/derivation/math_text.hpp"
#include "typeset_corpus.hpp"

namespace frustum {
namespace {

TEST(LatexUnicode, ReadsTheNotationsOfTheDerivations) {
  EXPECT_EQ(unicode_of_latex("\\mathbf{a}\\cdot\\mathbf{b} = a_x b_y"), "a·b = aₓ b_y");
  EXPECT_EQ(unicode_of_latex("\\mathbf{n}\\times\\mathbf{p}_0"), "n × p₀");
  EXPECT_EQ(unicode_of_latex("\\frac{x + 1}{2}\\cdot\\text{width}"), "(x + 1)/2·width");
  EXPECT_EQ(unicode_of_latex("\\frac{d}{c}"), "d/c");
  EXPECT_EQ(unicode_of_latex("x_{\\text{ndc}} = \\frac{x'}{w'}"), "x_ndc = x′/w′");
  EXPECT_EQ(unicode_of_latex("M^{-1} = M^T,\\; S^2"), "M⁻¹ = Mᵀ,  S²");
  EXPECT_EQ(unicode_of_latex("\\lVert\\mathbf{n}\\rVert = \\sqrt{3}"), "‖n‖ = √3");
  EXPECT_EQ(unicode_of_latex("\\hat{\\mathbf{n}} = -\\mathbf{f}"), "n̂ = −f");
  EXPECT_EQ(unicode_of_latex("30^\\circ \\le \\theta \\le \\pi"), "30° ≤ θ ≤ π");
  EXPECT_EQ(unicode_of_latex("\\text{edge-on}"), "edge-on");  // text keeps its hyphen
  EXPECT_EQ(unicode_of_latex("\\unknown{x}"), "\\unknownx");  // kept, never dropped silently
  // Named functions: a space before a bare argument, a fraction argument in parentheses.
  EXPECT_EQ(unicode_of_latex("\\sin\\theta = \\cos 30^\\circ"), "sin θ = cos 30°");
  EXPECT_EQ(unicode_of_latex("t = n\\tan\\frac{\\text{fovy}}{2}"), "t = n·tan(fovy/2)");
  EXPECT_EQ(unicode_of_latex("2\\arctan\\left(x\\right)"), "2·arctan(x)");
  EXPECT_EQ(unicode_of_latex("\\operatorname{sign} E_{AB}"), "sign E_AB");
  // A thin space between two factors is a product; after a quantifier it is a space.
  EXPECT_EQ(unicode_of_latex("z = \\frac{d - a\\,x}{c}"), "z = (d − a·x)/c");
  EXPECT_EQ(unicode_of_latex("\\le 0 \\quad \\forall\\, \\mathbf{v}"), "≤ 0  ∀ v");
  // Parentheses where a one-line fraction needs them, and only there.
  EXPECT_EQ(unicode_of_latex("\\frac{\\text{height}/2}{\\tan 30^\\circ}"), "(height/2)/(tan 30°)");
  EXPECT_EQ(unicode_of_latex("\\frac{(y - y_0)(x_1 - x_0)}{y_1 - y_0}"),
            "(y − y₀)(x₁ − x₀)/(y₁ − y₀)");
  EXPECT_EQ(unicode_of_latex("\\frac{\\mathbf{a}\\cdot\\mathbf{b}}{\\lVert\\mathbf{a}\\rVert "
                             "\\lVert\\mathbf{b}\\rVert}"),
            "a·b/(‖a‖ ‖b‖)");
  EXPECT_EQ(unicode_of_latex("\\frac{(x, y)}{w} = \\frac{x}{-z}"), "(x, y)/w = x/(−z)");
  EXPECT_EQ(unicode_of_latex("\\sqrt{n_x^2 + 1} \\ne \\sqrt{2}"), "√(nₓ² + 1) ≠ √2");
  // Indices, sums, matrices, transposes.
  EXPECT_EQ(unicode_of_latex("\\sum_i \\mathbf{p}_{i+1},\\; \\mathbf{p}_{n-1}"),
            "Σᵢ pᵢ₊₁,  p_(n−1)");
  EXPECT_EQ(unicode_of_latex("R = \\begin{bmatrix} c & -s \\\\ s & c \\end{bmatrix}"),
            "R = [c, −s; s, c]");
  EXPECT_EQ(unicode_of_latex("(x, y)^{\\mathsf{T}}"), "(x, y)ᵀ");
  EXPECT_EQ(unicode_of_latex("\\times\\;"), "× ");  // a mark, not an operator
  const MathText t = tex("\\mathbf{v} = \\mathbf{p}_{\\text{eye}} - \\mathbf{p}_0");
  EXPECT_EQ(t.unicode, "v = p_eye − p₀");
  EXPECT_EQ(t.latex, "\\mathbf{v} = \\mathbf{p}_{\\text{eye}} - \\mathbf{p}_0");
}

// The two notations cannot be written separately any more: math() takes one text (the same in
// both), tex() one LaTeX string, frac() two pieces already written.
template <typename S>
concept WritesTwoNotations = requires(S s) {
  math(s, s);
};
static_assert(!WritesTwoNotations<std::string_view>);
static_assert(!WritesTwoNotations<std::string>);

// A fraction built around values reads as the whole formula's LaTeX would.
TEST(LatexUnicode, FractionsAroundValuesReadAsTheirLatex) {
  const Exact three_root_six = 3 * GiNaC::sqrt(Exact(6));
  const std::vector<MathText> parts = {
      exact(Exact(-6)),
      exact(three_root_six),
      exact(GiNaC::numeric(1, 2)),
      vec(std::vector<Exact>{Exact(-3), Exact(6), Exact(-3)}),
      exact(GiNaC::sqrt(Exact(14))) + tex(" \\cdot ") + exact(GiNaC::sqrt(Exact(5))),
      tex("\\lvert") + exact(Exact(-6)) + tex("\\rvert")};
  for (const MathText& a : parts)
    for (const MathText& b : parts) {
      const MathText f = tex("x = ") + frac(a, b);
      EXPECT_EQ(f.unicode, unicode_of_latex(f.latex)) << f.latex;
    }
  EXPECT_EQ(frac(exact(Exact(-6)), exact(three_root_six)).unicode, "(−6)/(3√6)");
  // A piece ending in a control word keeps it apart from the letter that follows.
  EXPECT_EQ((tex(";\\quad") + tex("j = 1")).latex, ";\\quad j = 1");
  EXPECT_EQ((tex(";\\quad") + tex("j = 1")).unicode, ";  j = 1");
  EXPECT_EQ(frac(vec(std::vector<Exact>{Exact(1), Exact(2)}), exact(Exact(-2))).unicode,
            "(1, 2)/(−2)");
}

// Every formula of every derivation (bundled sets; generated problems of every kind in every
// API) is what its LaTeX reads, and no Unicode text holds a LaTeX command the reader left.
TEST(LatexUnicode, EveryDerivationsFormulaIsItsLatexRead) {
  int formulas = 0;
  for (const ProblemResult& p : test::typeset_corpus(2))
    for (const Step& s : p.derivation.steps()) {
      if (!s.formula.empty()) {
        ++formulas;
        EXPECT_EQ(s.formula.unicode, unicode_of_latex(s.formula.latex))
            << p.id << ": " << s.formula.latex;
      }
      for (const MathText* m : {&s.formula, &s.substitution, &s.result})
        EXPECT_EQ(m->unicode.find('\\'), std::string::npos) << p.id << ": " << m->unicode;
    }
  EXPECT_GT(formulas, 500);
}

}  // namespace
}  // namespace frustum
