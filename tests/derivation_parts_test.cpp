// paper_plane's fast path (coefficients that are rational multiples of one root divided as
// rationals) against its plain reading (canonical() of every quotient), over many planes: the
// plane method's (a unit normal and d = n̂·A from integer triangles), rational ones, planes with
// zero coefficients and planes mixing roots, where the fast path must step aside.
#include "solver/shared/derivation_parts.hpp"

#include <gtest/gtest.h>

#include "solver/geometry/plane_depth.hpp"
#include "solver/problem/rng.hpp"
#include "solver/util/exact_format.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

std::string text(const std::array<Exact, 4>& p) {
  std::string out;
  for (const Exact& x : p) out += format_exact(x, MathStyle::Plain) + "; ";
  return out;
}

void expect_same(const Vec3<Exact>& n, const Exact& d) {
  const std::array<Exact, 4> fast = paper_plane(n, d), plain = paper_plane(n, d, true);
  for (int i = 0; i < 4; ++i)
    ASSERT_TRUE(fast[i].is_equal(plain[i])) << text(fast) << " vs " << text(plain);
}

TEST(PaperPlane, FastPathAgreesWithTheQuotients) {
  Rng rng(2026);
  const auto small = [&](std::int64_t lo, std::int64_t hi) { return Exact(rng.integer(lo, hi)); };
  for (int k = 0; k < 3000; ++k) {
    // The plane method: n = AC × AB of an integer triangle, n̂ = n/‖n‖, d = n̂·A.
    Vec3<Exact> a, b, c;
    for (int i = 0; i < 3; ++i) {
      a(i) = small(-20, 20);
      b(i) = small(-20, 20);
      c(i) = small(-20, 20);
    }
    const Vec3<Exact> n = (c - a).cross(b - a);
    if (n.isZero()) continue;
    const Vec3<Exact> u = unit(n);
    expect_same(u, canonical(u.dot(a)));
    expect_same(n, canonical(n.dot(a)));
    // Rationals, zeros among them.
    const Vec3<Exact> q(small(-3, 3) / small(1, 4), small(-3, 3) / small(1, 4), small(-1, 1));
    expect_same(q, small(-5, 5) / small(1, 7));
    // Mixed roots: √2 beside √3 (no shared root) and a root beside a rational.
    expect_same(Vec3<Exact>(GiNaC::sqrt(Exact(2)) * small(1, 3), GiNaC::sqrt(Exact(3)), 0),
                small(-2, 2));
    expect_same(Vec3<Exact>(small(1, 3), GiNaC::sqrt(Exact(8)) * small(-2, 2), 1), small(0, 2));
  }
}

// unit() builds nᵢ/‖n‖ of a rational vector from ‖n‖ = c·√r directly (nᵢ/(c·r)·√r); it must be
// the canonical form of each quotient, printed the same, for integer and fractional vectors,
// zeros among the components and lengths that are rational (3, 4, 0) or not.
TEST(PaperPlane, UnitVectorOfARationalVectorIsEachQuotientCanonical) {
  Rng rng(4477);
  const auto small = [&](std::int64_t lo, std::int64_t hi) { return Exact(rng.integer(lo, hi)); };
  std::vector<Vec3<Exact>> vectors = {{3, 4, 0}, {2, 3, 6}, {0, 0, -5}, {1, 1, 1}};
  for (int k = 0; k < 3000; ++k) {
    Vec3<Exact> n(small(-30, 30), small(-30, 30), small(-30, 30));
    if (k % 3 == 1) n = n / small(1, 9);
    if (k % 7 == 2) n(k % 3) = 0;
    vectors.push_back(n);
  }
  for (const Vec3<Exact>& n : vectors) {
    if (n.isZero()) continue;
    const Vec3<Exact> u = unit(n);
    const Exact length = canonical(norm(n));
    for (int i = 0; i < 3; ++i) {
      const Exact quotient = canonical(n(i) / length);
      ASSERT_TRUE(u(i).is_equal(quotient)) << format_exact(u(i), MathStyle::Plain) << " vs "
                                           << format_exact(quotient, MathStyle::Plain);
      ASSERT_EQ(format_exact(u(i), MathStyle::Plain), format_exact(quotient, MathStyle::Plain));
    }
  }
}

// depth_at_pixel's exact z is found on the plane scaled by ‖n‖ (rationals only) when n, A and the
// pixel are rational: it must be the z of the plane method's own reading, canonical() of
// (d − n̂ₓxₛ − n̂_y yₛ)/n̂_z with n̂ = n/‖n‖ and d = n̂·A, over many triangles and pixels (rational
// ones with fractions, and a pixel with a root, where the scaled plane steps aside).
TEST(PaperPlane, ExactDepthOnTheScaledPlaneIsThePlaneMethodsZ) {
  Rng rng(1811);
  const auto small = [&](std::int64_t lo, std::int64_t hi) { return Exact(rng.integer(lo, hi)); };
  int solved = 0;
  for (int k = 0; k < 400; ++k) {
    std::array<Vec3<Exact>, 3> t;
    for (Vec3<Exact>& v : t)
      v = Vec3<Exact>(small(-20, 20), small(-20, 20),
                      small(1, 40) / (k % 3 == 0 ? small(1, 5) : 1));
    Vec2<Exact> pixel(small(-5, 5) / small(1, 3), small(-5, 5));
    if (k % 10 == 0) pixel(1) = GiNaC::sqrt(Exact(2));
    const Vec3<Exact> n = (t[2] - t[0]).cross(t[1] - t[0]);  // AC × AB, the default order
    if (n(2).is_zero()) continue;
    const Exact plain = canonical(plane_method_z(plane_through(n, t[0]), pixel));
    std::string given = "{triangle: [";
    for (const Vec3<Exact>& v : t)
      given += "[" + format_exact(v(0), MathStyle::Plain) + ", " +
               format_exact(v(1), MathStyle::Plain) + ", " + format_exact(v(2), MathStyle::Plain) +
               "], ";
    given += "], pixel: [" + format_exact(pixel(0), MathStyle::Plain) + ", " +
             format_exact(pixel(1), MathStyle::Plain) + "]}";
    const ProblemResult r =
        test::solve_yaml(test::one("depth_at_pixel", given, "", "    ask: [z]\n"), false);
    if (r.error) continue;  // edge-on in the plane of the screen: refused, as it should be
    ++solved;
    const Value* z = r.answers.find("z");
    ASSERT_TRUE(z && z->exact.size() == 1) << given;
    EXPECT_TRUE(z->exact[0].is_equal(plain))
        << given << ": " << format_exact(z->exact[0], MathStyle::Plain) << " vs "
        << format_exact(plain, MathStyle::Plain);
  }
  EXPECT_GT(solved, 300);
}

}  // namespace
}  // namespace frustum
