// Exact values printed as on paper, in the three styles.
#include "solver/util/exact_format.hpp"

#include <gtest/gtest.h>

namespace frustum {
namespace {

using GiNaC::ex;
using GiNaC::numeric;

std::string plain(const ex& e) { return format_exact(canonical(e), MathStyle::Plain); }
std::string uni(const ex& e) { return format_exact(canonical(e), MathStyle::Unicode); }
std::string latex(const ex& e) { return format_exact(canonical(e), MathStyle::Latex); }

TEST(ExactFormat, SeedValues) {
  EXPECT_EQ(plain(1 / GiNaC::sqrt(ex(3))), "sqrt(3)/3");
  EXPECT_EQ(uni(1 / GiNaC::sqrt(ex(3))), "√3/3");
  EXPECT_EQ(latex(1 / GiNaC::sqrt(ex(3))), "\\frac{\\sqrt{3}}{3}");
  EXPECT_EQ(plain(-1 / GiNaC::sqrt(ex(3))), "-sqrt(3)/3");
  EXPECT_EQ(uni(GiNaC::sqrt(ex(243))), "9√3");
  EXPECT_EQ(plain(GiNaC::sqrt(ex(243))), "9*sqrt(3)");
  EXPECT_EQ(uni(-100 * GiNaC::sqrt(ex(3))), "−100√3");
  EXPECT_EQ(uni(GiNaC::sqrt(ex(21)) / 5), "√21/5");
  EXPECT_EQ(plain(ex(-2) / GiNaC::sqrt(ex(21))), "-2*sqrt(21)/21");
  EXPECT_EQ(plain(ex(8)), "8");
  EXPECT_EQ(uni(ex(-6)), "−6");
  EXPECT_EQ(latex(numeric(-2, 3)), "-\\frac{2}{3}");
  EXPECT_EQ(plain(GiNaC::Pi / 6), "pi/6");
  EXPECT_EQ(uni(2 * GiNaC::Pi / 3), "2π/3");
}

TEST(ExactFormat, SumsPutAPositiveTermFirst) {
  EXPECT_EQ(plain(1 + GiNaC::sqrt(ex(3))), "1 + sqrt(3)");
  EXPECT_EQ(plain(GiNaC::sqrt(ex(3)) - 1), "sqrt(3) - 1");
}

TEST(ExactFormat, Doubles) {
  EXPECT_EQ(format_double(8.0), "8");
  EXPECT_EQ(format_double(-6.0), "-6");
  EXPECT_EQ(format_double(1 / std::sqrt(3.0)), "0.5773502691896258");
  EXPECT_EQ(format_double(-0.0), "0");
  EXPECT_EQ(format_approx(0.57735026), "0.5774");
  EXPECT_EQ(format_approx(-173.205), "-173.2");
  EXPECT_EQ(format_approx(8.0), "8");
}

TEST(ExactFormat, PlainOutputReparsesToTheSameValue) {
  for (int p = 1; p < 60; p += 7)
    for (int q = 1; q < 40; q += 3) {
      const ex v = canonical(GiNaC::sqrt(ex(numeric(p, q))));
      GiNaC::parser reader;
      const ex back = reader(format_exact(v, MathStyle::Plain));
      EXPECT_TRUE(canonical(back - v).is_zero()) << p << "/" << q << " → " << format_exact(v, MathStyle::Plain);
    }
}

}  // namespace
}  // namespace frustum
