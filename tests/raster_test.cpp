// Rasterization and the Z-buffer: the top-left rule on hand-made ties, watertight meshes
// (every pixel exactly once), depth against the plane method, and the scan_convert and
// zbuffer kinds.
#include <fmt/format.h>

#include <cmath>
#include <random>

#include "solver/raster/filtered_depth.hpp"
#include "solver/raster/zbuffer.hpp"
#include "solver/util/diagnostic.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::error_text;
using test::exact_text;
using test::one;
using test::same;
using test::solve_yaml;

TriangleSetup tri(double ax, double ay, double bx, double by, double cx, double cy) {
  return setup_triangle({Vec2<double>(ax, ay), Vec2<double>(bx, by), Vec2<double>(cx, cy)});
}

std::vector<std::pair<int, int>> pixels(const TriangleSetup& t) {
  std::vector<std::pair<int, int>> out;
  for (const Fragment& f : rasterize(t)) out.emplace_back(f.i, f.j);
  return out;
}

using PixelList = std::vector<std::pair<int, int>>;

TEST(TopLeftRule, CentresOnLeftEdgesAreCoveredOnBottomAndRightEdgesNot) {
  // Left edge x = ½, bottom edge y = ½, hypotenuse x + y = 5 (a right edge): all through centres.
  const TriangleSetup lower = tri(0.5, 0.5, 4.5, 0.5, 0.5, 4.5);
  EXPECT_TRUE(lower.edge[1].left) << "C → A runs down";
  EXPECT_FALSE(lower.edge[2].top_left()) << "A → B is the bottom edge";
  EXPECT_FALSE(covers(lower, 0, 0)) << "(½, ½) is a vertex on the bottom edge";
  EXPECT_TRUE(covers(lower, 0, 2)) << "(½, 2½) is on the left edge";
  EXPECT_FALSE(covers(lower, 1, 0)) << "(1½, ½) is on the bottom edge";
  EXPECT_FALSE(covers(lower, 1, 3)) << "(1½, 3½) is on the hypotenuse, a right edge";
  EXPECT_EQ(pixels(lower), (PixelList{{0, 1}, {1, 1}, {2, 1}, {0, 2}, {1, 2}, {0, 3}}));
  // The other half of the square: the hypotenuse is its left edge, y = 4½ its top edge.
  const TriangleSetup upper = tri(4.5, 0.5, 4.5, 4.5, 0.5, 4.5);
  EXPECT_TRUE(covers(upper, 1, 3));
  EXPECT_TRUE(covers(upper, 2, 4)) << "on the top edge";
  EXPECT_FALSE(covers(upper, 4, 2)) << "on the right edge";
  // Together: the square's pixels i = 0..3, j = 1..4, each once.
  std::map<std::pair<int, int>, int> count;
  for (const auto& p : pixels(lower)) ++count[p];
  for (const auto& p : pixels(upper)) ++count[p];
  EXPECT_EQ(count.size(), 16u);
  for (const auto& [p, n] : count) {
    EXPECT_EQ(n, 1);
    EXPECT_TRUE(p.first >= 0 && p.first <= 3 && p.second >= 1 && p.second <= 4);
  }
}

TEST(TopLeftRule, ClockwiseInputCoversTheSamePixels) {
  EXPECT_EQ(pixels(tri(0.5, 0.5, 0.5, 4.5, 4.5, 0.5)), pixels(tri(0.5, 0.5, 4.5, 0.5, 0.5, 4.5)));
  EXPECT_TRUE(tri(0.5, 0.5, 0.5, 4.5, 4.5, 0.5).reordered);
}

TEST(Rasterizer, SnappingRoundsLikeLlround) {
  // to_fixed avoids the library call; it must round exactly as llround(v·2⁸) does, halves
  // away from zero included, over the whole accepted range.
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> any(-kMaxWindowCoordinate, kMaxWindowCoordinate);
  std::uniform_int_distribution<std::int64_t> grid(-(std::int64_t{1} << 28), std::int64_t{1} << 28);
  for (int n = 0; n < 200000; ++n) {
    const double v =
        n % 2 ? any(rng) : (static_cast<double>(grid(rng)) + 0.5) / 256.0;  // even n: exact halves
    ASSERT_EQ(to_fixed(v), std::llround(v * 256.0)) << fmt::format("{:.17g}", v);
  }
  for (const double v :
       {0.0, -0.0, 1.0 / 512, -1.0 / 512, 3.0 / 512, -3.0 / 512, kMaxWindowCoordinate,
        -kMaxWindowCoordinate, std::nextafter(1.0 / 512, 0.0), std::nextafter(-1.0 / 512, 0.0)})
    EXPECT_EQ(to_fixed(v), std::llround(v * 256.0)) << fmt::format("{:.17g}", v);
}

// Snapping an exact coordinate decides by its exact value: 1/512 − 10⁻³⁰ rounds down though its
// nearest double, 1/512, rounds up; the same for −, for irrational values and for every double.
TEST(Rasterizer, ExactSnappingDecidesByTheExactValue) {
  const Exact tiny = GiNaC::pow(Exact(10), -30), half = Exact(1) / 512;
  bool off = false;
  EXPECT_EQ(to_fixed(half - tiny, off), 0);
  EXPECT_TRUE(off);
  EXPECT_EQ(to_fixed(1.0 / 512), 1);
  EXPECT_EQ(to_fixed(half, off), 1);
  EXPECT_EQ(to_fixed(-half + tiny, off), 0);
  EXPECT_EQ(to_fixed(-half, off), -1);
  EXPECT_EQ(to_fixed(Exact(3) + half + tiny, off), 3 * 256 + 1);
  // √2·256 = 362.0387…: +½ − 0.039 is just below 362.5, +½ − 0.038 just above.
  EXPECT_EQ(to_fixed(GiNaC::sqrt(Exact(2)), off), 362);
  EXPECT_EQ(to_fixed(GiNaC::sqrt(Exact(2)) + Exact(1) / 512 - Exact(39) / 1000 / 256, off), 362);
  EXPECT_EQ(to_fixed(GiNaC::sqrt(Exact(2)) + Exact(1) / 512 - Exact(38) / 1000 / 256, off), 363);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::int64_t> grid(-(std::int64_t{1} << 28), std::int64_t{1} << 28);
  for (int n = 0; n < 2000; ++n) {
    const double v = (static_cast<double>(grid(rng)) + (n % 2 ? 0.5 : 0.25)) / 256.0;
    bool grid_off = false;
    ASSERT_EQ(to_fixed(exact_from_double(v), grid_off), to_fixed(v)) << fmt::format("{:.17g}", v);
    EXPECT_TRUE(grid_off);
  }
  bool on = false;
  EXPECT_EQ(to_fixed(Exact(5) / 256, on), 5);
  EXPECT_FALSE(on);
}

// The rule (halves away from zero) for every kind of exact value, on both sides of every half:
// k/512 exactly and k/512 ± 10⁻³⁰, for odd k of both signs, each written as a rational, as a
// product of radicals that is rational ((√2 + 1)(√2 − 1) = 1), as a nested radical
// (√(5 + 2√6) − √2 − √3 = 0), as a trigonometric value (2·sin(π/12)·cos(π/12) − ½ = 0,
// sin²(π/8) + cos²(π/8) − 1 = 0) and with an irrational offset (10⁻³⁰·√2 instead of 10⁻³⁰).
// An irrational exact half on the negative side goes away from zero too, not toward it.
TEST(Rasterizer, ExactSnappingRoundsHalvesAwayFromZeroInEveryForm) {
  const Exact r2 = GiNaC::sqrt(Exact(2)), r3 = GiNaC::sqrt(Exact(3));
  const Exact pi = GiNaC::Pi;
  const std::vector<std::pair<std::string, Exact>> zeros = {
      {"rational", 0},
      {"radical product", (r2 + 1) * (r2 - 1) - 1},
      {"nested radical", GiNaC::sqrt(5 + 2 * GiNaC::sqrt(Exact(6))) - r2 - r3},
      {"sin pi/12", 2 * GiNaC::sin(pi / 12) * GiNaC::cos(pi / 12) - Exact(1) / 2},
      {"sin pi/8", GiNaC::pow(GiNaC::sin(pi / 8), 2) + GiNaC::pow(GiNaC::cos(pi / 8), 2) - 1},
      {"tan 7.5°", GiNaC::tan(pi / 24) - GiNaC::sqrt(Exact(6)) + r3 - r2 + 2}};
  const Exact tiny = GiNaC::pow(Exact(10), -30);
  const std::vector<std::pair<std::string, Exact>> offsets = {{"0", 0},
                                                              {"+tiny", tiny},
                                                              {"-tiny", -tiny},
                                                              {"+tiny*sqrt2", tiny * r2},
                                                              {"-tiny*sqrt2", -tiny * r2}};
  for (const long k : {-1001L, -3L, -1L, 1L, 3L, 1001L})
    for (const auto& [zero_name, zero] : zeros)
      for (const auto& [offset_name, offset] : offsets) {
        const Exact v = zero + Exact(k) / 512 + offset;
        // Expected: k/512 exactly rounds away from zero; an offset toward zero rounds toward it.
        const int offset_sign = exact_sign(offset);
        const long toward_zero = (k - (k > 0 ? 1 : -1)) / 2, away = (k + (k > 0 ? 1 : -1)) / 2;
        const bool away_from_zero = offset_sign == 0 || (offset_sign > 0) == (k > 0);
        bool off = false;
        EXPECT_EQ(to_fixed(v, off), away_from_zero ? away : toward_zero)
            << k << "/512 " << zero_name << " " << offset_name;
        EXPECT_TRUE(off) << k << "/512 " << zero_name << " " << offset_name;
      }
  // On the grid in every form: not snapped.
  for (const auto& [zero_name, zero] : zeros) {
    bool off = false;
    EXPECT_EQ(to_fixed(zero - Exact(3) / 256, off), -3) << zero_name;
    EXPECT_FALSE(off) << zero_name;
    EXPECT_EQ(to_fixed(zero, off), 0) << zero_name;
    EXPECT_FALSE(off) << zero_name;
  }
}

TEST(Rasterizer, DegenerateTriangleCoversNothing) {
  const TriangleSetup t = tri(0, 0, 2, 2, 5, 5);
  EXPECT_TRUE(t.degenerate);
  EXPECT_TRUE(rasterize(t).empty());
  EXPECT_THROW(tri(0, 0, 1e9, 0, 0, 1), DomainError);
}

// A rectangle [x0, x1] × [y0, y1] split into a jittered grid of quads, each cut into two
// triangles along a random diagonal. Under the top-left rule the rectangle covers the centres
// with x0 ≤ cx < x1 and y0 < cy ≤ y1, and every one of them exactly once.
void check_watertight(unsigned seed, double step) {
  std::mt19937 rng(seed);
  const int n = 5;
  const double cell = 4, x0 = 2.5, y0 = 1.5;  // corners on pixel centres: ties everywhere
  std::uniform_int_distribution<int> jitter(-static_cast<int>(0.75 / step),
                                            static_cast<int>(0.75 / step));
  std::uniform_int_distribution<int> coin(0, 1);
  std::vector<std::vector<Vec2<double>>> v(n + 1, std::vector<Vec2<double>>(n + 1));
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= n; ++b) {
      const double jx = (a == 0 || a == n) ? 0 : jitter(rng) * step;
      const double jy = (b == 0 || b == n) ? 0 : jitter(rng) * step;
      v[a][b] = Vec2<double>(x0 + a * cell + jx, y0 + b * cell + jy);
    }
  std::map<std::pair<int, int>, int> count;
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) {
      const Vec2<double> p00 = v[a][b], p10 = v[a + 1][b], p11 = v[a + 1][b + 1], p01 = v[a][b + 1];
      const std::array<std::array<Vec2<double>, 3>, 2> halves =
          coin(rng)
              ? std::array<std::array<Vec2<double>, 3>, 2>{{{p00, p10, p11}, {p00, p11, p01}}}
              : std::array<std::array<Vec2<double>, 3>, 2>{{{p00, p10, p01}, {p10, p11, p01}}};
      for (const auto& h : halves)
        for (const Fragment& f : rasterize(setup_triangle(h))) ++count[{f.i, f.j}];
    }
  const double x1 = x0 + n * cell, y1 = y0 + n * cell;
  int expected = 0;
  for (int j = -2; j < 30; ++j)
    for (int i = -2; i < 30; ++i) {
      const double cx = i + 0.5, cy = j + 0.5;
      const bool inside = x0 <= cx && cx < x1 && y0 < cy && cy <= y1;
      expected += inside;
      const auto it = count.find({i, j});
      ASSERT_EQ(it == count.end() ? 0 : it->second, inside ? 1 : 0)
          << "pixel " << i << ", " << j << " seed " << seed;
    }
  EXPECT_EQ(static_cast<int>(count.size()), expected);
}

TEST(Rasterizer, SharedEdgesCoverEveryPixelExactlyOnceFineJitter) {
  for (unsigned s = 0; s < 100; ++s) check_watertight(s, 1.0 / 256);
}

TEST(Rasterizer, SharedEdgesCoverEveryPixelExactlyOnceWithTiesAtCentres) {
  for (unsigned s = 0; s < 100; ++s) check_watertight(1000 + s, 0.5);
}

TEST(Rasterizer, FanAroundAVertexOnAPixelCentreCoversItOnce) {
  // Eight triangles around (3½, 3½): the centre pixel belongs to exactly one of them.
  const Vec2<double> c(3.5, 3.5);
  const std::array<Vec2<double>, 8> ring{Vec2<double>(6.5, 3.5), Vec2<double>(6.5, 6.5),
                                         Vec2<double>(3.5, 6.5), Vec2<double>(0.5, 6.5),
                                         Vec2<double>(0.5, 3.5), Vec2<double>(0.5, 0.5),
                                         Vec2<double>(3.5, 0.5), Vec2<double>(6.5, 0.5)};
  int hits = 0;
  for (int k = 0; k < 8; ++k) hits += covers(setup_triangle({c, ring[k], ring[(k + 1) % 8]}), 3, 3);
  EXPECT_EQ(hits, 1);
}

TEST(Rasterizer, DepthEqualsThePlaneMethod) {
  std::mt19937 rng(9);
  std::uniform_int_distribution<int> coord(0, 20 * 256);
  std::uniform_real_distribution<double> depth(-5, 5);
  int checked = 0;
  for (int c = 0; c < 300; ++c) {
    std::array<Vec3<double>, 3> p;
    for (auto& v : p) v = Vec3<double>(coord(rng) / 256.0, coord(rng) / 256.0, depth(rng));
    const TriangleSetup t = setup_triangle({p[0].head<2>(), p[1].head<2>(), p[2].head<2>()});
    if (t.degenerate) continue;
    // Plane a x + b y + c z = d through the vertices (window coordinates).
    const Vec3<double> nrm = (p[1] - p[0]).cross(p[2] - p[0]);
    const double d = nrm.dot(p[0]);
    const std::array<double, 3> z{p[0](2), p[1](2), p[2](2)};
    for (const Fragment& f : rasterize(t)) {
      const double x = f.i + 0.5, y = f.j + 0.5;
      const double plane_z = (d - nrm(0) * x - nrm(1) * y) / nrm(2);
      ASSERT_NEAR(interpolate(t, f, z), plane_z, 1e-6) << "case " << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(ZBufferStage, SmallerZWinsAndTiesKeepTheFirst) {
  DepthBuffer<double> depth(2, 1, std::nullopt);
  FrameBuffer frame(2, 1, kBackground);
  const TriangleSetup t =
      tri(0, 0, 2, 0, 0, 2);  // (1½, ½) lies on its right edge: covers (0, 0) only
  const TriangleSetup full =
      setup_triangle({Vec2<double>(0, 0), Vec2<double>(4, 0), Vec2<double>(0, 4)});
  draw_triangle<double>(full, {5, 5, 5}, "1", depth, frame);
  EXPECT_EQ(frame_rows(frame), (std::vector<std::string>{"11"}));
  EXPECT_EQ(draw_triangle<double>(full, {5, 5, 5}, "2", depth, frame).written, 0)
      << "equal z keeps the first";
  EXPECT_EQ(draw_triangle<double>(t, {1, 1, 1}, "3", depth, frame).written, 1);
  EXPECT_EQ(frame_rows(frame), (std::vector<std::string>{"31"}));
  EXPECT_EQ(*depth.at(0, 0), 1);
}

TEST(ScanConvertKind, ListsPixelsRowByRow) {
  const ProblemResult r =
      solve_yaml(one("scan_convert", "{triangle: [[0.5, 0.5], [4.5, 0.5], [0.5, 4.5]]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "pixels"), "0, 1, 1, 1, 2, 1, 0, 2, 1, 2, 0, 3");
  EXPECT_EQ(r.answers.find("pixels")->rows, 6);
  EXPECT_EQ(r.answers.find("pixels")->cols, 2);
}

TEST(ScanConvertKind, DegenerateTriangleCoversNoPixelsAndSaysSo) {
  const ProblemResult r =
      solve_yaml(one("scan_convert", "{triangle: [[0, 0, 1], [2, 2, 1], [4, 4, 1]]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(r.answers.find("pixels")->rows, 0);
  EXPECT_TRUE(r.derivation.has_warnings());
}

TEST(ScanConvertKind, HugeTriangleIsRefused) {
  const ProblemResult r =
      solve_yaml(one("scan_convert", "{triangle: [[0, 0], [1000, 0], [0, 1000]]}"));
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "problems[0].given.triangle");
}

const char* kThreePolygons = R"({size: [4, 3], polygons: [
    {label: "1", points: [[0, 0, 5], [3, 0, 5], [3, 3, 5], [0, 3, 5]]},
    {label: "2", points: [[1, 0, 3], [4, 0, 3], [4, 2, 3], [1, 2, 3]]},
    {label: "3", points: [[2, 1, 4], [4, 1, 4], [4, 3, 4], [2, 3, 4]]}]})";

// The filtered exact depth test decides every fragment as the plain exact one does: random
// triangles on an 8 × 8 grid whose depths are small integers, √2, √3 and sums of them, equal
// across triangles or 10⁻³⁰ apart (ties and near-ties the ranges cannot separate), drawn both
// ways; frames and exact depths agree, and the exact comparisons happened only at ties.
TEST(ZBufferStage, FilteredExactDepthTestMatchesThePlainExactTest) {
  std::mt19937_64 rng(42);
  std::uniform_int_distribution<int> coord(-2, 10), small(1, 2), pick(0, 5);
  const Exact tiny = GiNaC::pow(Exact(10), -30);
  const auto depth = [&] {
    const Exact r2 = GiNaC::sqrt(Exact(2)), r3 = GiNaC::sqrt(Exact(3));
    switch (pick(rng)) {
      case 0:
        return Exact(small(rng));
      case 1:
        return Exact(small(rng)) * r2;
      case 2:
        return Exact(small(rng)) + r3;
      case 3:
        return Exact(small(rng)) + r2 + tiny;
      case 4:
        return r2 + r3;
      default:
        return Exact(small(rng)) + r2 - tiny;
    }
  };
  long exact_comparisons = 0;
  for (int scene = 0; scene < 60; ++scene) {
    FrameBuffer plain_frame(8, 8, kBackground), filtered_frame(8, 8, kBackground);
    DepthBuffer<Exact> plain(8, 8, std::nullopt);
    FilteredDepthBuffer filtered(8, 8);
    for (int k = 0; k < 5; ++k) {
      std::array<Vec2<Exact>, 3> xy;
      std::array<Exact, 3> z;
      const bool flat = k % 2 == 0;  // one depth for the whole triangle: ties across triangles
      const Exact flat_depth = depth();
      for (int c = 0; c < 3; ++c) {
        xy[c] = Vec2<Exact>(Exact(coord(rng)), Exact(coord(rng)));
        z[c] = flat ? flat_depth : depth();
      }
      const TriangleSetup t = setup_triangle_exact(xy);
      const std::string label = std::to_string(k + 1);
      const DrawCount a = draw_triangle<Exact>(
          t, z, label, plain, plain_frame,
          [](const Exact& x, const Exact& y) { return exact_sign(x - y) < 0; });
      const DrawCount b = draw_triangle_filtered(t, z, label, filtered, filtered_frame);
      EXPECT_EQ(a.covered, b.covered);
      EXPECT_EQ(a.written, b.written);
    }
    EXPECT_EQ(frame_rows(plain_frame), frame_rows(filtered_frame)) << scene;
    for (std::size_t c = 0; c < plain.data.size(); ++c) {
      ASSERT_EQ(plain.data[c].has_value(), filtered.exact.data[c].has_value());
      if (plain.data[c]) {
        EXPECT_EQ(exact_sign(*plain.data[c] - *filtered.exact.data[c]), 0);
      }
    }
    exact_comparisons += filtered.exact_comparisons;
  }
  EXPECT_GT(exact_comparisons, 0);  // the ties reached the exact test
}

TEST(ZBufferKind, ThreeOverlappingPolygonsLikeSeed001) {
  const ProblemResult r = solve_yaml(one("zbuffer", kThreePolygons));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(r.answers.find("frame")->words, (std::vector<std::string>{"1133", "1222", "1222"}));
  EXPECT_EQ(r.answers.find("steps")->words,
            (std::vector<std::string>{"111./111./111.", "111./1222/1222", "1133/1222/1222"}));
  EXPECT_EQ(exact_text(r, "depth"), "5, 5, 4, 4, 5, 3, 3, 3, 5, 3, 3, 3");
  int polygons = 0;
  for (const Step& s : r.derivation.steps()) polygons += s.title.en().rfind("Polygon", 0) == 0;
  EXPECT_EQ(polygons, 3);
}

TEST(ZBufferKind, SlopedTriangleTakesThePlaneDepthAndBackgroundIsInfinite) {
  const ProblemResult r = solve_yaml(
      one("zbuffer",
          "{size: [3, 3], polygons: [{label: A, points: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]}]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(r.answers.find("frame")->words, (std::vector<std::string>{"...", "A..", "AA."}));
  const Value& d = *r.answers.find("depth");
  EXPECT_EQ(d.numbers[6], 7);  // pixel (0, 0): z = x + y + 6 at (½, ½)
  EXPECT_EQ(d.numbers[7], 8);  // pixel (1, 0)
  EXPECT_EQ(d.numbers[0], 1e30);
}

TEST(ZBufferKind, BadInput) {
  const ProblemResult big = solve_yaml(
      one("zbuffer",
          "{size: [300, 10], polygons: [{label: \"1\", points: [[0,0,0],[1,0,0],[0,1,0]]}]}"));
  ASSERT_TRUE(big.error);
  EXPECT_EQ(big.error->field, "problems[0].given.size");
  EXPECT_NE(big.error->message.find("256"), std::string::npos);
  const ProblemResult dot = solve_yaml(one(
      "zbuffer", "{size: [3, 3], polygons: [{label: \".\", points: [[0,0,0],[1,0,0],[0,1,0]]}]}"));
  ASSERT_TRUE(dot.error);
  EXPECT_EQ(dot.error->field, "problems[0].given.polygons[0].label");
  const ProblemResult flat = solve_yaml(one(
      "zbuffer", "{size: [3, 3], polygons: [{label: \"1\", points: [[0,0,0],[1,1,0],[2,2,0]]}]}"));
  ASSERT_FALSE(flat.error) << error_text(flat);
  EXPECT_TRUE(flat.derivation.has_warnings());
  EXPECT_EQ(flat.answers.find("frame")->words, (std::vector<std::string>{"...", "...", "..."}));
}

TEST(PipelineExamples, EveryProblemSolves) {
  const ProblemSet set = load_problem_set(test::source_path("problems/examples/pipeline.yaml"));
  ASSERT_TRUE(set.errors.empty());
  const SetResult r = solve_set(set, true);
  ASSERT_EQ(r.problems.size(), 4u);
  for (const ProblemResult& p : r.problems) EXPECT_FALSE(p.error) << p.id << ": " << error_text(p);
}

}  // namespace
}  // namespace frustum
