#include "solver/util/exact_format.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace frustum {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

ex root(long radicand, long index) { return GiNaC::pow(ex(radicand), ex(numeric(1, index))); }
ex sqrt_of(long radicand) { return GiNaC::sqrt(ex(radicand)); }

struct Case {
  ex value;  // canonicalised before formatting
  std::string plain;
  std::string unicode;
  std::string latex;
};

void expect_formats(const Case& c) {
  const ex v = canonical(c.value);
  EXPECT_EQ(format_exact(v, MathStyle::Plain), c.plain) << c.value;
  EXPECT_EQ(format_exact(v, MathStyle::Unicode), c.unicode) << c.value;
  EXPECT_EQ(format_exact(v, MathStyle::Latex), c.latex) << c.value;
}

// Reads Plain output back with GiNaC's parser (trusted text: our own output).
ex parse_plain(const std::string& text) {
  GiNaC::symtab table;
  table["pi"] = GiNaC::Pi;
  GiNaC::parser reader(table, /*strict=*/true);
  return reader(text);
}

void expect_reparses(const ex& value) {
  const std::string text = format_exact(value, MathStyle::Plain);
  const ex back = parse_plain(text);
  EXPECT_TRUE(canonical(back - value).is_zero()) << value << " printed as " << text;
}

TEST(ExactFormat, Numbers) {
  expect_formats({8, "8", "8", "8"});
  expect_formats({-6, "-6", "−6", "-6"});
  expect_formats({0, "0", "0", "0"});
  expect_formats({numeric(1, 3), "1/3", "1/3", "\\frac{1}{3}"});
  expect_formats({numeric(-2, 3), "-2/3", "−2/3", "-\\frac{2}{3}"});
}

// Integers that fit in a machine word are written without GiNaC's printer: the same digits as
// GiNaC prints, at the word's edges and beyond them, in numbers, fractions and coefficients.
TEST(ExactFormat, IntegersAtTheWordsEdgesPrintAsGinacPrintsThem) {
  const numeric two62 = numeric(2).power(62), two63 = numeric(2).power(63);
  for (const numeric& n : {numeric(0), numeric(-1), two62 - 1, two62, -two62, -two62 + 1, two63 - 1,
                           two63, -two63, numeric(10).power(30), -numeric(10).power(30)}) {
    std::ostringstream ginac;
    ginac << ex(n);
    EXPECT_EQ(format_exact(n, MathStyle::Plain), ginac.str());
    std::ostringstream fraction;
    fraction << ex(n) << "/13";
    if (!n.is_zero()) {  // 13 divides none of them
      EXPECT_EQ(format_exact(ex(n) / 13, MathStyle::Plain), fraction.str());
    }
  }
}

TEST(ExactFormat, SquareRoots) {
  expect_formats({1 / sqrt_of(3), "sqrt(3)/3", "√3/3", "\\frac{\\sqrt{3}}{3}"});
  expect_formats({-1 / sqrt_of(3), "-sqrt(3)/3", "−√3/3", "-\\frac{\\sqrt{3}}{3}"});
  expect_formats({9 / sqrt_of(243), "sqrt(3)/3", "√3/3", "\\frac{\\sqrt{3}}{3}"});
  expect_formats({sqrt_of(243), "9*sqrt(3)", "9√3", "9\\sqrt{3}"});
  expect_formats({-sqrt_of(243), "-9*sqrt(3)", "−9√3", "-9\\sqrt{3}"});
  expect_formats({100 * sqrt_of(3), "100*sqrt(3)", "100√3", "100\\sqrt{3}"});
  expect_formats({-100 * sqrt_of(3), "-100*sqrt(3)", "−100√3", "-100\\sqrt{3}"});
  expect_formats({sqrt_of(21) / 5, "sqrt(21)/5", "√21/5", "\\frac{\\sqrt{21}}{5}"});
  expect_formats({-2 / sqrt_of(21), "-2*sqrt(21)/21", "−2√21/21", "-\\frac{2\\sqrt{21}}{21}"});
  expect_formats({GiNaC::sqrt(ex(numeric(8, 3))), "2*sqrt(6)/3", "2√6/3", "\\frac{2\\sqrt{6}}{3}"});
}

TEST(ExactFormat, Seed001UnitNormalComponents) {
  // n = (1, 1, -1) / sqrt(3); |n| = sqrt(243) for n = (9, 9, -9).
  expect_formats({ex(1) / sqrt_of(3), "sqrt(3)/3", "√3/3", "\\frac{\\sqrt{3}}{3}"});
  expect_formats({ex(-9) / sqrt_of(243), "-sqrt(3)/3", "−√3/3", "-\\frac{\\sqrt{3}}{3}"});
  expect_formats({GiNaC::sqrt(ex(81 + 81 + 81)), "9*sqrt(3)", "9√3", "9\\sqrt{3}"});
}

TEST(ExactFormat, PiMultiples) {
  expect_formats({GiNaC::Pi / 6, "pi/6", "π/6", "\\frac{\\pi}{6}"});
  expect_formats({-GiNaC::Pi / 3, "-pi/3", "−π/3", "-\\frac{\\pi}{3}"});
  expect_formats({2 * GiNaC::Pi / 3, "2*pi/3", "2π/3", "\\frac{2\\pi}{3}"});
  expect_formats({GiNaC::Pi, "pi", "π", "\\pi"});
  expect_formats({GiNaC::Pi * sqrt_of(3) / 6, "pi*sqrt(3)/6", "π√3/6", "\\frac{\\pi\\sqrt{3}}{6}"});
  expect_formats({GiNaC::pow(GiNaC::Pi, 2), "pi^2", "π²", "\\pi^{2}"});
  expect_formats({1 / GiNaC::Pi, "1/pi", "1/π", "\\frac{1}{\\pi}"});
  expect_formats({1 / (2 * GiNaC::Pi), "1/(2*pi)", "1/(2π)", "\\frac{1}{2\\pi}"});
}

TEST(ExactFormat, SumsLeadWithAPositiveTerm) {
  expect_formats({1 + sqrt_of(3), "1 + sqrt(3)", "1 + √3", "1 + \\sqrt{3}"});
  expect_formats({sqrt_of(3) - 1, "sqrt(3) - 1", "√3 − 1", "\\sqrt{3} - 1"});
  expect_formats({-1 - sqrt_of(3), "-1 - sqrt(3)", "−1 − √3", "-1 - \\sqrt{3}"});
  expect_formats({(1 + sqrt_of(3)) / 2, "1/2 + sqrt(3)/2", "1/2 + √3/2",
                  "\\frac{1}{2} + \\frac{\\sqrt{3}}{2}"});
  expect_formats({1 + sqrt_of(2) - sqrt_of(3), "1 + sqrt(2) - sqrt(3)", "1 + √2 − √3",
                  "1 + \\sqrt{2} - \\sqrt{3}"});
  expect_formats({GiNaC::Pi / 6 - 1, "pi/6 - 1", "π/6 − 1", "\\frac{\\pi}{6} - 1"});
}

TEST(ExactFormat, HigherRootsAndFunctions) {
  expect_formats({root(2, 3), "2^(1/3)", "∛2", "\\sqrt[3]{2}"});
  expect_formats({root(16, 3), "2*2^(1/3)", "2∛2", "2\\sqrt[3]{2}"});
  expect_formats({root(3, 4), "3^(1/4)", "∜3", "\\sqrt[4]{3}"});
  expect_formats({root(2, 5), "2^(1/5)", "⁵√2", "\\sqrt[5]{2}"});
  expect_formats({sqrt_of(2) * root(3, 3), "sqrt(2)*3^(1/3)", "√2·∛3", "\\sqrt{2}\\sqrt[3]{3}"});
  expect_formats({GiNaC::cos(ex(1)), "cos(1)", "cos(1)", "\\cos(1)"});
  expect_formats({2 * GiNaC::sin(ex(1)), "2*sin(1)", "2·sin(1)", "2\\sin(1)"});
  expect_formats({GiNaC::sqrt(GiNaC::Pi), "sqrt(pi)", "√(π)", "\\sqrt{\\pi}"});
  expect_formats({GiNaC::Pi * GiNaC::cos(ex(1)) * sqrt_of(2), "pi*cos(1)*sqrt(2)", "π·cos(1)√2",
                  "\\pi\\cos(1)\\sqrt{2}"});
}

TEST(ExactFormat, FallbacksStayParenthesised) {
  // A square-root sum in a denominator is rationalised (√3/2 − 1/2); a cube-root sum is not.
  expect_formats({1 / (1 + sqrt_of(3)), "sqrt(3)/2 - 1/2", "√3/2 − 1/2",
                  "\\frac{\\sqrt{3}}{2} - \\frac{1}{2}"});
  expect_formats(
      {1 / (1 + root(2, 3)), "1/(1 + 2^(1/3))", "1/(1 + ∛2)", "\\frac{1}{1 + \\sqrt[3]{2}}"});
  expect_formats({GiNaC::pow(1 + GiNaC::Pi, 2) * 3, "3 + 6*pi + 3*pi^2", "3 + 6π + 3π²",
                  "3 + 6\\pi + 3\\pi^{2}"});
  expect_formats({GiNaC::pow(ex(-8), ex(numeric(1, 3))), "(-8)^(1/3)", "∛(−8)", "\\sqrt[3]{-8}"});
  expect_formats(
      {GiNaC::sqrt(1 + sqrt_of(3)), "sqrt(1 + sqrt(3))", "√(1 + √3)", "\\sqrt{1 + \\sqrt{3}}"});
  // Formatting without canonical() still never prints a negative fractional exponent.
  EXPECT_EQ(format_exact(GiNaC::pow(GiNaC::Pi, ex(numeric(-1, 2))), MathStyle::Plain),
            "1/sqrt(pi)");
}

TEST(ExactFormat, PlainOutputReparsesToTheSameValue) {
  const std::vector<ex> values = {1 / sqrt_of(3),
                                  -2 / sqrt_of(21),
                                  GiNaC::Pi / 6,
                                  -2 * GiNaC::Pi / 3,
                                  sqrt_of(3) - 1,
                                  -1 - sqrt_of(3),
                                  root(2, 3),
                                  root(5, 7) / 3,
                                  GiNaC::cos(ex(1)),
                                  1 / (1 + sqrt_of(3)),
                                  sqrt_of(2) * root(3, 3),
                                  GiNaC::pow(GiNaC::Pi, 2) / 4,
                                  GiNaC::pow(ex(-8), ex(numeric(1, 3))),
                                  1 / (2 * GiNaC::Pi),
                                  GiNaC::sqrt(1 + sqrt_of(3))};
  for (const ex& v : values) expect_reparses(canonical(v));
}

TEST(ExactFormat, PlainRadicalsOfRandomRationalsReparse) {
  std::mt19937 rng(314159);  // fixed seed: reproducible property loop
  std::uniform_int_distribution<long> pick(-3000, 3000);
  std::uniform_int_distribution<long> pick_den(1, 3000);
  for (int i = 0; i < 1000; ++i) {
    const numeric q(pick(rng), pick_den(rng));
    const numeric r(pick(rng), pick_den(rng));
    // r + q*sqrt(|q|): sums, signs, fractions and radicals together.
    const ex v = canonical(r + q * GiNaC::sqrt(GiNaC::abs(ex(q))));
    expect_reparses(v);
    const std::string unicode = format_exact(v, MathStyle::Unicode);
    EXPECT_EQ(unicode.find('^'), std::string::npos) << unicode;
    EXPECT_EQ(unicode.find("+ −"), std::string::npos) << unicode;
  }
}

// A key far beyond double's range is written as its digits and power of ten, never
// as a 380-digit fraction, and its approximation is its own leading digits, never 0 or inf.
TEST(ExactFormat, PowersOfTenBeyondDoublesRange) {
  const numeric tiny = numeric(1) / numeric(10).power(380);
  expect_formats({-tiny, "-1e-380", "−10⁻³⁸⁰", "-10^{-380}"});
  expect_formats({17 * tiny * 10, "1.7e-378", "1.7·10⁻³⁷⁸", "1.7 \\cdot 10^{-378}"});
  expect_formats({numeric(10).power(400), "1e400", "10⁴⁰⁰", "10^{400}"});
  expect_formats(
      {sqrt_of(21) * tiny, "sqrt(21)*1e-380", "√21·10⁻³⁸⁰", "\\sqrt{21} \\cdot 10^{-380}"});
  // Short fractions and a long one that is no power of ten keep their form.
  expect_formats({numeric(1, 1000), "1/1000", "1/1000", "\\frac{1}{1000}"});
  EXPECT_NE(format_exact(tiny / 3, MathStyle::Plain).find("/3"), std::string::npos);
  EXPECT_EQ(format_exact_approx(-tiny), "-1e-380");
  EXPECT_EQ(format_exact_approx(17 * tiny), "1.7e-379");
  EXPECT_EQ(format_exact_approx(numeric(10).power(400) * 3), "3e+400");
  EXPECT_EQ(format_exact_approx(sqrt_of(21) * tiny), "4.583e-380");
  EXPECT_EQ(format_exact_approx(numeric(1, 3)), format_approx(1.0 / 3));
}

TEST(ExactFormat, FormatDouble) {
  EXPECT_EQ(format_double(8.0), "8");
  EXPECT_EQ(format_double(-6.0), "-6");
  EXPECT_EQ(format_double(0.5773502691896258), "0.5773502691896258");
  EXPECT_EQ(format_double(0.1), "0.1");
  EXPECT_EQ(format_double(-0.0), "0");
  EXPECT_EQ(format_double(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_double(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(format_double(-std::numeric_limits<double>::infinity()), "-inf");
  for (const double v : {1.0 / 3.0, 1e308, 4.9e-324, -173.20508075688772, 1e16}) {
    // strtod, not stod: stod rejects the subnormal 4.9e-324 as out of range.
    EXPECT_EQ(std::strtod(format_double(v).c_str(), nullptr), v) << format_double(v);
  }
}

TEST(ExactFormat, FormatApprox) {
  EXPECT_EQ(format_approx(0.57735), "0.5774");
  EXPECT_EQ(format_approx(173.205), "173.2");
  EXPECT_EQ(format_approx(-173.205), "-173.2");
  EXPECT_EQ(format_approx(8.0), "8");
  EXPECT_EQ(format_approx(0.5), "0.5");
  EXPECT_EQ(format_approx(-0.0), "0");
  EXPECT_EQ(format_approx(1e-7), "1e-07");
  EXPECT_EQ(format_approx(3.14159265, 6), "3.14159");
  EXPECT_EQ(format_approx(std::numeric_limits<double>::quiet_NaN()), "nan");
}

}  // namespace
}  // namespace frustum
