// paper_plane's fast path (coefficients that are rational multiples of one root divided as
// rationals) against its plain reading (canonical() of every quotient), over many planes: the
// plane method's (a unit normal and d = n̂·A from integer triangles), rational ones, planes with
// zero coefficients and planes mixing roots, where the fast path must step aside.
#include <gtest/gtest.h>

#include "solver/problem/rng.hpp"
#include "solver/steps/kind_steps.hpp"
#include "solver/util/exact_format.hpp"

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

}  // namespace
}  // namespace frustum
