// Normals, Newell's method and the exact orientation predicate.
#include <gtest/gtest.h>

#include <random>

#include "solver/geometry/polygon_normal.hpp"
#include "solver/geometry/predicates.hpp"

namespace frustum {
namespace {

Vec3<Exact> ev(long x, long y, long z) { return Vec3<Exact>(x, y, z); }

// exact_edge_sign computes rational inputs with GiNaC's numbers directly; it must give
// exact_sign of the edge function built as an expression, for integers, fractions, huge values,
// collinear points (0) and inputs with a root (which take the expression route).
TEST(Geometry, ExactEdgeSignOfRationalsIsTheExpressionsSign) {
  std::mt19937 rng(9001);
  std::uniform_int_distribution<long> small(-40, 40), den(1, 12);
  int zeros = 0;
  for (int k = 0; k < 4000; ++k) {
    const auto value = [&] {
      Exact v = Exact(small(rng)) / den(rng);
      if (k % 5 == 4) v = v * GiNaC::pow(Exact(10), 30) + 1;
      return v;
    };
    Vec2<Exact> a(value(), value()), b(value(), value()), p(value(), value());
    if (k % 4 == 1) p = a + (b - a) * (Exact(small(rng)) / den(rng));  // on the line through a, b
    if (k % 50 == 7) p(0) = GiNaC::sqrt(Exact(2)) * small(rng);
    const int expected = exact_sign(edge_function<Exact>(a, b, p));
    ASSERT_EQ(exact_edge_sign(a, b, p), expected) << a << " " << b << " " << p;
    zeros += expected == 0;
  }
  EXPECT_GT(zeros, 500);
}

TEST(Geometry, NewellEqualsEdgePairForTriangles) {
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> d(-50, 50);
  for (int i = 0; i < 300; ++i) {
    const Polygon3<Exact> t = {ev(d(rng), d(rng), d(rng)), ev(d(rng), d(rng), d(rng)),
                               ev(d(rng), d(rng), d(rng))};
    const Vec3<Exact> a = newell_normal(t), b = edge_pair_normal(t, 0);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE((a(k) - b(k)).expand().is_zero());
  }
}

TEST(Geometry, NewellIsParallelToEveryEdgePairOfAConvexPolygon) {
  // A planar convex pentagon in the plane x + 2y + 3z = 6 (lifted from the xy-plane).
  Polygon3<Exact> p;
  for (auto [x, y] : std::vector<std::pair<int, int>>{{0, 0}, {4, 0}, {5, 3}, {2, 5}, {-1, 3}})
    p.push_back(Vec3<Exact>(x, y, Exact(6 - x - 2 * y) / 3));
  const Vec3<Exact> n = newell_normal(p);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3<Exact> m = edge_pair_normal(p, i);
    const Vec3<Exact> c = n.cross(m);
    for (int k = 0; k < 3; ++k) EXPECT_TRUE(canonical(c(k)).is_zero());
    EXPECT_GT(exact_sign(n.dot(m)), 0) << "same orientation at pair " << i;
  }
  // The normal is along (1, 2, 3).
  EXPECT_TRUE(canonical(n(1) - 2 * n(0)).is_zero());
  EXPECT_TRUE(canonical(n(2) - 3 * n(0)).is_zero());
}

TEST(Geometry, AnalysisFindsDegenerateRepeatedAndNearParallel) {
  EXPECT_TRUE(analyse_polygon({ev(0, 0, 0), ev(1, 1, 1), ev(2, 2, 2)}).degenerate);
  const PolygonAnalysis repeated =
      analyse_polygon({ev(0, 0, 0), ev(1, 0, 0), ev(1, 0, 0), ev(0, 1, 0)});
  EXPECT_FALSE(repeated.degenerate);
  ASSERT_EQ(repeated.zero_edges.size(), 1u);
  EXPECT_EQ(repeated.zero_edges[0], 1u);
  const Polygon3<Exact> thin = {ev(0, 0, 0), Vec3<Exact>(100000000, 0, 0),
                                Vec3<Exact>(200000000, GiNaC::numeric(1, 100000000), 0)};
  const PolygonAnalysis a = analyse_polygon(thin);
  EXPECT_FALSE(a.degenerate);
  EXPECT_LT(a.min_sine, kNearParallelSine);
  EXPECT_GT(a.condition, 1e6);
  EXPECT_FALSE(analyse_polygon({ev(0, 0, 0), ev(1, 0, 0), ev(1, 1, 1), ev(0, 1, 0)}).planar);
}

TEST(Geometry, Orient3dSignOfSeed003BackfaceIsNegative) {
  // D_f = (eye − p0)·((p1 − p0) × (p2 − p0)) = −2 < 0.
  const Eigen::Vector3d p0(1, 0, 0), p1(1, 1, 1), p2(0, 1, 2), eye(0, 1, 0);
  EXPECT_EQ(orient3d_sign(p0, p1, p2, eye), -1);
  EXPECT_EQ(orient3d_sign(ev(1, 0, 0), ev(1, 1, 1), ev(0, 1, 2), ev(0, 1, 0)), -1);
}

TEST(Geometry, Orient3dIsExactWhereNaiveDoublesFail) {
  // Points on the plane z = 0.5·x + 0.25·y (exactly representable), and eyes nudged off it by
  // one unit in the last place: the exact sign follows the nudge; doubles alone cannot tell.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  auto on_plane = [](double x, double y) { return Eigen::Vector3d(x, y, 0.5 * x + 0.25 * y); };
  PredicateStats stats;
  int checked = 0;
  for (int i = 0; i < 2000; ++i) {
    const double xs[4] = {std::round(u(rng)), std::round(u(rng)), std::round(u(rng)), u(rng)};
    const double ys[4] = {std::round(u(rng)), std::round(u(rng)), std::round(u(rng)), u(rng)};
    const Eigen::Vector3d a = on_plane(xs[0], ys[0]), b = on_plane(xs[1], ys[1]),
                          c = on_plane(xs[2], ys[2]);
    Eigen::Vector3d d = on_plane(xs[3], ys[3]);
    const int nudge = (i % 3) - 1;  // −1, 0, +1
    if (nudge) d.z() = std::nextafter(d.z(), nudge > 0 ? INFINITY : -INFINITY);
    // The exact truth from rationals.
    const auto ex = [](const Eigen::Vector3d& p) {
      return Vec3<Exact>(exact_from_double(p.x()), exact_from_double(p.y()),
                         exact_from_double(p.z()));
    };
    const int truth = orient3d_sign(ex(a), ex(b), ex(c), ex(d));
    EXPECT_EQ(orient3d_sign(a, b, c, d, &stats), truth);
    ++checked;
  }
  EXPECT_EQ(checked, 2000);
  EXPECT_GT(stats.exact, 0) << "near-coplanar cases must reach the exact fallback";
}

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// Short edges are not parallel edges: perpendicular edges of length 1e-160 (whose cross
// product underflows in double) have sine 1 and lose no digit.
TEST(PolygonAnalysis, TinyPerpendicularEdgesAreNotNearlyParallel) {
  const Exact tiny = GiNaC::pow(Exact(10), -160);
  const PolygonAnalysis a =
      analyse_polygon({Vec3<Exact>(0, 0, 0), Vec3<Exact>(tiny, 0, 0), Vec3<Exact>(0, tiny, 0)});
  EXPECT_NEAR(a.min_sine, std::sqrt(0.5), 1e-12);  // the 45° corners
  EXPECT_LT(a.condition, 2);
  const PolygonAnalysis thin = analyse_polygon(
      {Vec3<Exact>(0, 0, 0), Vec3<Exact>(tiny, 0, 0), Vec3<Exact>(2 * tiny, tiny / 1000000000, 0)});
  EXPECT_LT(thin.min_sine, 1e-8);
}

}  // namespace
}  // namespace frustum
