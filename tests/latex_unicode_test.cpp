// solver/derivation/latex_unicode.cpp: a formula written once in LaTeX, read into its Unicode
// form; and no formula in the solver's sources is written twice where one LaTeX string would
// give both notations (math(unicode, latex) whose Unicode is the LaTeX's own reading).
#include "solver/derivation/latex_unicode.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "solver/derivation/math_text.hpp"
#include "test_util.hpp"

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
  EXPECT_EQ(unicode_of_latex("t = n\\tan\\frac{\\text{fovy}}{2}"), "t = n tan(fovy/2)");
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

// The text of C++ string literals written one after another ("a" "b"), unescaped.
std::string literal_text(const std::string& literals) {
  std::string out;
  bool in = false;
  for (std::size_t i = 0; i < literals.size(); ++i) {
    const char c = literals[i];
    if (!in) {
      in = c == '"';
      continue;
    }
    if (c == '"') {
      in = false;
    } else if (c == '\\' && i + 1 < literals.size()) {
      const char e = literals[++i];
      out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
    } else {
      out += c;
    }
  }
  return out;
}

TEST(LatexUnicode, NoFormulaIsWrittenTwiceWhereOnceWouldDo) {
  const std::string lit = R"("(?:[^"\\]|\\.)*")";
  const std::string lits = lit + R"((?:\s*)" + lit + ")*";
  const std::regex pair("\\bmath\\(\\s*(" + lits + ")\\s*,\\s*(" + lits + ")\\s*\\)");
  int pairs = 0;
  std::vector<std::string> twice;
  for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_path("solver"))) {
    if (e.path().extension() != ".cpp") continue;
    const std::string source = test::read_file(e.path());
    for (auto m = std::sregex_iterator(source.begin(), source.end(), pair);
         m != std::sregex_iterator(); ++m) {
      ++pairs;
      const std::string unicode = literal_text((*m)[1]), latex = literal_text((*m)[2]);
      int depth = 0;
      bool balanced = true;
      for (const char c : latex) {
        depth += c == '{' ? 1 : c == '}' ? -1 : 0;
        balanced = balanced && depth >= 0;
      }
      // A piece around a value (an open \frac{, a closing brace) stays a pair.
      if (!balanced || depth != 0 || unicode.empty()) continue;
      if (unicode_of_latex(latex) == unicode)
        twice.push_back(e.path().filename().string() + ": " + latex);
    }
  }
  EXPECT_GT(pairs, 50);
  for (const std::string& t : twice)
    ADD_FAILURE() << "written twice where tex(\"…\") would write it once: " << t;
}

}  // namespace
}  // namespace frustum
