// Clipping: Cohen–Sutherland against an exact parametric (Liang–Barsky) reference,
// Sutherland–Hodgman areas and containment, homogeneous clipping before the divide, and the
// clip_line / clip_polygon kinds.
#include <fmt/format.h>

#include <random>

#include "solver/clipping/line_clip.hpp"
#include "solver/clipping/polygon_clip.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::error_text;
using test::exact_text;
using test::one;
using test::same;
using test::solve_yaml;

// Random rational in [−range, range] with denominators up to 4.
Exact random_rational(std::mt19937& rng, int range) {
  std::uniform_int_distribution<int> num(-4 * range, 4 * range), den(1, 4);
  return GiNaC::numeric(num(rng)) / GiNaC::numeric(den(rng));
}

// The visible part of pq by the parametric method, exactly: t ∈ [0, 1] ∩ slabs.
template <int N>
std::optional<std::array<Eigen::Matrix<Exact, N, 1>, 2>> reference_clip(
    const Eigen::Matrix<Exact, N, 1>& p, const Eigen::Matrix<Exact, N, 1>& q,
    const ClipBox<Exact, N>& box) {
  Exact t0 = 0, t1 = 1;
  for (int a = 0; a < N; ++a) {
    const Exact d = canonical(q(a) - p(a));
    if (d.is_zero()) {
      if (exact_sign(p(a) - box.lo(a)) < 0 || exact_sign(p(a) - box.hi(a)) > 0) return std::nullopt;
      continue;
    }
    Exact ta = canonical((box.lo(a) - p(a)) / d), tb = canonical((box.hi(a) - p(a)) / d);
    if (exact_sign(ta - tb) > 0) std::swap(ta, tb);
    if (exact_sign(ta - t0) > 0) t0 = ta;
    if (exact_sign(tb - t1) < 0) t1 = tb;
  }
  if (exact_sign(t0 - t1) > 0) return std::nullopt;
  using V = Eigen::Matrix<Exact, N, 1>;
  return std::array<V, 2>{V(p + (q - p) * t0), V(p + (q - p) * t1)};
}

template <int N>
void check_random_segments(unsigned seed, int cases) {
  std::mt19937 rng(seed);
  using V = Eigen::Matrix<Exact, N, 1>;
  int visible = 0, clipped_both = 0;
  for (int c = 0; c < cases; ++c) {
    ClipBox<Exact, N> box;
    for (int a = 0; a < N; ++a) {
      box.lo(a) = random_rational(rng, 2) - 1;
      box.hi(a) = box.lo(a) + 1 + canonical(GiNaC::abs(random_rational(rng, 2)));
    }
    V p, q;
    for (int a = 0; a < N; ++a) {
      p(a) = random_rational(rng, N == 2 ? 4 : 2);
      q(a) = random_rational(rng, N == 2 ? 4 : 2);
    }
    const LineClipResult<Exact, N> r = cohen_sutherland(p, q, box);
    const auto ref = reference_clip(p, q, box);
    ASSERT_EQ(r.clipped.has_value(), ref.has_value()) << "case " << c;
    EXPECT_EQ(r.trivial_accept, (outcode(p, box) | outcode(q, box)) == 0);
    if (r.trivial_reject) {
      EXPECT_FALSE(ref.has_value());
    }
    if (!ref) continue;
    ++visible;
    clipped_both += r.iterations.size() >= 2;
    for (int e = 0; e < 2; ++e)
      for (int a = 0; a < N; ++a)
        EXPECT_TRUE(same((*r.clipped)[e](a), (*ref)[e](a))) << "case " << c << " endpoint " << e;
    // The double version agrees.
    const Eigen::Matrix<double, N, 1> pd = to_double(p), qd = to_double(q);
    const ClipBox<double, N> bd{to_double(box.lo), to_double(box.hi)};
    const LineClipResult<double, N> rd = cohen_sutherland(pd, qd, bd);
    EXPECT_TRUE(rd.clipped.has_value());
    if (rd.clipped) {
      for (int e = 0; e < 2; ++e)
        for (int a = 0; a < N; ++a) EXPECT_NEAR((*rd.clipped)[e](a), to_double((*ref)[e](a)), 1e-9);
    }
  }
  EXPECT_GT(visible, cases / 10) << "the generator exercises visible segments";
  EXPECT_GT(clipped_both, 0) << "and segments clipped at both ends";
}

TEST(Outcode, BitOrderIsTopBottomRightLeft) {
  const ClipBox<Exact, 2> w{Vec2<Exact>(0, 0), Vec2<Exact>(4, 3)};
  EXPECT_EQ(outcode_string(outcode(Vec2<Exact>(-1, 5), w), 2), "1001");
  EXPECT_EQ(outcode_string(outcode(Vec2<Exact>(5, -1), w), 2), "0110");
  EXPECT_EQ(outcode_string(outcode(Vec2<Exact>(4, 3), w), 2), "0000")
      << "a boundary point is inside";
  const ClipBox<Exact, 3> cube = ndc_cube<Exact>();
  EXPECT_EQ(outcode_string(outcode(Vec3<Exact>(0, 0, 2), cube), 3), "100000");
  EXPECT_EQ(outcode_string(outcode(Vec3<Exact>(-2, 0, -2), cube), 3), "010001");
  EXPECT_EQ(outcode_meaning(outcode_bit(1, true) | outcode_bit(0, false)),
            "top (y > ymax), left (x < xmin)");
}

TEST(CohenSutherland, MatchesExactParametricReference2D) { check_random_segments<2>(7, 600); }
TEST(CohenSutherland, MatchesExactParametricReference3D) { check_random_segments<3>(11, 400); }

TEST(CohenSutherland, RecordsEachIteration) {
  const ClipBox<Exact, 2> w{Vec2<Exact>(0, 0), Vec2<Exact>(4, 3)};
  const auto r = cohen_sutherland(Vec2<Exact>(-1, 1), Vec2<Exact>(5, 2), w);
  ASSERT_EQ(r.iterations.size(), 2u);
  EXPECT_EQ(r.iterations[0].endpoint, 0);
  EXPECT_EQ(r.iterations[0].bit, outcode_bit(0, false));
  EXPECT_TRUE(same(r.iterations[0].after(1), GiNaC::numeric(7, 6)));
  EXPECT_EQ(r.iterations[1].endpoint, 1);
  EXPECT_EQ(r.iterations[1].bit, outcode_bit(0, true));
}

TEST(SutherlandHodgman, KnownAreasAndContainment) {
  const ClipBox<Exact, 2> w{Vec2<Exact>(1, 1), Vec2<Exact>(3, 3)};
  const std::vector<Vec2<Exact>> tri{Vec2<Exact>(0, 0), Vec2<Exact>(4, 0), Vec2<Exact>(0, 4)};
  const auto r = clip_polygon_box(tri, w);
  EXPECT_EQ(r.stages.size(), 4u);
  EXPECT_TRUE(same(twice_signed_area(r.clipped), 4))
      << "area 2: the square minus the corner beyond x + y = 4";
  const std::vector<Vec2<Exact>> big{Vec2<Exact>(-1, -1), Vec2<Exact>(5, -1), Vec2<Exact>(5, 5),
                                     Vec2<Exact>(-1, 5)};
  const auto all = clip_polygon_box(big, w);
  EXPECT_EQ(all.clipped.size(), 4u);
  EXPECT_TRUE(same(twice_signed_area(all.clipped), 8));
  const std::vector<Vec2<Exact>> away{Vec2<Exact>(5, 5), Vec2<Exact>(6, 5), Vec2<Exact>(6, 6)};
  EXPECT_TRUE(clip_polygon_box(away, w).empty());
}

// The intersection of two convex polygons is symmetric: clipping P by the window equals
// clipping the window by P's edges, in area.
TEST(SutherlandHodgman, RandomConvexPolygonsInsideTheWindowWithTheRightArea) {
  std::mt19937 rng(3);
  const ClipBox<Exact, 2> w{Vec2<Exact>(-1, -1), Vec2<Exact>(2, 1)};
  const std::vector<Vec2<Exact>> window{Vec2<Exact>(-1, -1), Vec2<Exact>(2, -1), Vec2<Exact>(2, 1),
                                        Vec2<Exact>(-1, 1)};
  int nonempty = 0;
  for (int c = 0; c < 150; ++c) {
    // A random triangle, made counter-clockwise.
    std::vector<Vec2<Exact>> p;
    for (int k = 0; k < 3; ++k) p.emplace_back(random_rational(rng, 3), random_rational(rng, 3));
    const int s = exact_sign(twice_signed_area(p));
    if (s == 0) continue;
    if (s < 0) std::swap(p[1], p[2]);
    const auto r = clip_polygon_box(p, w);
    for (const auto& v : r.clipped)
      for (int a = 0; a < 2; ++a) {
        EXPECT_GE(exact_sign(v(a) - w.lo(a)), 0);
        EXPECT_LE(exact_sign(v(a) - w.hi(a)), 0);
      }
    std::vector<Vec2<Exact>> other = window;
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Vec2<Exact> a = p[e], b = p[(e + 1) % p.size()];
      other = clip_polygon_stage(
          other,
          [&](const Vec2<Exact>& v) {
            return Exact((b(0) - a(0)) * (v(1) - a(1)) - (b(1) - a(1)) * (v(0) - a(0)));
          },
          [](Vec2<Exact>&) {});
    }
    const Exact area = r.empty() ? Exact(0) : twice_signed_area(r.clipped);
    const Exact expected = other.size() < 3 ? Exact(0) : twice_signed_area(other);
    EXPECT_TRUE(same(area, expected)) << "case " << c;
    nonempty += !r.empty();
  }
  EXPECT_GT(nonempty, 20);
}

TEST(SutherlandHodgman, ThreeDBoxKeepsVerticesInside) {
  const ClipBox<Exact, 3> cube = ndc_cube<Exact>();
  const std::vector<Vec3<Exact>> tri{Vec3<Exact>(0, 0, -3), Vec3<Exact>(3, 0, 0),
                                     Vec3<Exact>(0, 0, 3)};
  const auto r = clip_polygon_box(tri, cube);
  EXPECT_EQ(r.stages.size(), 6u);
  ASSERT_FALSE(r.empty());
  for (const auto& v : r.clipped)
    for (int a = 0; a < 3; ++a) EXPECT_LE(exact_sign(GiNaC::abs(v(a)) - 1), 0);
}

TEST(HomogeneousClip, NeverProducesVerticesWithWAtOrBelowZero) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3), uw(-2, 2);
  const double eps = 1e-5;
  int kept = 0;
  for (int c = 0; c < 2000; ++c) {
    std::vector<Vec4<double>> tri;
    for (int k = 0; k < 3; ++k) tri.emplace_back(u(rng), u(rng), u(rng), uw(rng));
    const auto r = clip_polygon_homogeneous(tri, eps);
    EXPECT_EQ(r.stages.size(), 7u);
    // The renderer's variant, which keeps no stages: the same polygon, bit for bit, in both
    // conventions of z.
    for (const bool z_from_zero : {false, true}) {
      const auto plain = clip_polygon_homogeneous<double, false>(tri, eps, z_from_zero);
      EXPECT_TRUE(plain.stages.empty());
      ASSERT_EQ(plain.clipped, clip_polygon_homogeneous(tri, eps, z_from_zero).clipped) << c;
    }
    for (const auto& s : r.stages)
      for (const auto& v : s.vertices) ASSERT_GE(v(3), eps) << "case " << c << " at " << s.plane;
    for (const auto& v : r.clipped)
      for (int a = 0; a < 3; ++a) EXPECT_LE(std::abs(v(a)), v(3) * (1 + 1e-12) + 1e-12);
    kept += !r.empty();
  }
  EXPECT_GT(kept, 100);
  // Exact: a triangle crossing the eye plane keeps only its w ≥ ε part.
  const std::vector<Vec4<Exact>> tri{Vec4<Exact>(0, 0, 0, -1), Vec4<Exact>(1, 0, 0, 2),
                                     Vec4<Exact>(0, 1, 0, 2)};
  const auto r = clip_polygon_homogeneous(tri, Exact(GiNaC::numeric(1, 100)));
  for (const auto& v : r.clipped) EXPECT_GT(exact_sign(v(3)), 0);
  EXPECT_EQ(r.stages.front().vertices.size(), 4u);
}

TEST(ClipLineKind, TwoDimensionalSegmentClippedAtBothEnds) {
  const ProblemResult r = solve_yaml(
      one("clip_line", "{p: [-1, 1], q: [5, 2], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(r.answers.find("outcode_p")->word, "0001");
  EXPECT_EQ(r.answers.find("outcode_q")->word, "0010");
  EXPECT_FALSE(r.answers.find("accept")->flag);
  EXPECT_FALSE(r.answers.find("reject")->flag);
  EXPECT_EQ(exact_text(r, "clipped"), "0, 7/6, 4, 11/6");
  int iterations = 0;
  for (const Step& s : r.derivation.steps()) iterations += s.title.en().rfind("Iteration", 0) == 0;
  EXPECT_EQ(iterations, 2);
}

TEST(ClipLineKind, ThreeDimensionalDefaultsToTheNdcCube) {
  const ProblemResult r = solve_yaml(one("clip_line", "{p: [0, 0, -3], q: [\"1/2\", 0, 3]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(r.answers.find("outcode_p")->word, "010000");
  EXPECT_EQ(r.answers.find("outcode_q")->word, "100000");
  EXPECT_EQ(exact_text(r, "clipped"), "1/6, 0, -1, 1/3, 0, 1");
}

TEST(ClipLineKind, TrivialAcceptAndReject) {
  const ProblemResult in = solve_yaml(
      one("clip_line", "{p: [1, 1], q: [2, 2], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}"));
  EXPECT_TRUE(in.answers.find("accept")->flag);
  EXPECT_EQ(exact_text(in, "clipped"), "1, 1, 2, 2");
  const ProblemResult out = solve_yaml(
      one("clip_line", "{p: [5, 5], q: [6, 7], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}"));
  EXPECT_EQ(out.answers.find("outcode_p")->word, "1010");
  EXPECT_TRUE(out.answers.find("reject")->flag);
  EXPECT_EQ(out.answers.find("clipped")->shape, Value::Shape::Null);
}

TEST(ClipLineKind, BadWindowNamesTheField) {
  const ProblemResult r = solve_yaml(
      one("clip_line", "{p: [0, 0], q: [1, 1], window: {xmin: 4, xmax: 4, ymin: 0, ymax: 3}}"));
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "problems[0].given.window.xmin");
  EXPECT_NE(r.error->message.find("less than xmax"), std::string::npos);
  const ProblemResult mixed = solve_yaml(
      one("clip_line", "{p: [0, 0], q: [1, 1, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}"));
  ASSERT_TRUE(mixed.error);
  EXPECT_EQ(mixed.error->field, "problems[0].given.q");
  const ProblemResult wrong = solve_yaml(one(
      "clip_line", "{p: [0, 0, 0], q: [1, 1, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 3}}"));
  ASSERT_TRUE(wrong.error);
  EXPECT_EQ(wrong.error->field, "problems[0].given.window");
}

TEST(ClipPolygonKind, OneStepPerClipPlane) {
  const ProblemResult r = solve_yaml(
      one("clip_polygon",
          "{points: [[0, 0], [4, 0], [0, 4]], window: {xmin: 1, xmax: 3, ymin: 1, ymax: 3}}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "clipped"), "1, 1, 3, 1, 1, 3");
  int stages = 0;
  for (const Step& s : r.derivation.steps()) stages += s.title.en().rfind("Clip against", 0) == 0;
  EXPECT_EQ(stages, 4);
  const ProblemResult none =
      solve_yaml(one("clip_polygon", "{points: [[5, 5, 5], [6, 5, 5], [6, 6, 5]]}"));
  ASSERT_FALSE(none.error) << error_text(none);
  EXPECT_EQ(none.answers.find("clipped")->shape, Value::Shape::Null);
}

}  // namespace
}  // namespace frustum
