// The viewing pipeline: transforms, look_at, projections and the viewport, in the three
// conventions. Seeds' worked answers, exact identities over generated cases, cross-checks
// between the kinds and the templates, and the domain errors.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "solver/problem/solve_precision.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/viewing/projection.hpp"
#include "solver/viewing/transforms.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::error_text;
using test::exact_text;
using test::one;
using test::same;
using test::solve_yaml;

std::string api_conventions(Api api) { return "{api: " + std::string(to_string(api)) + "}"; }

Exact rational(int p, int q = 1) { return Exact(GiNaC::numeric(p, q)); }

Exact degrees(int d) { return rational(d, 180) * GiNaC::Pi; }

// A Value holding an exact matrix (row by row) as a MatX.
MatX<Exact> exact_matrix(const Value& v) {
  MatX<Exact> m(v.rows, v.cols);
  for (int i = 0; i < v.rows; ++i)
    for (int j = 0; j < v.cols; ++j) m(i, j) = v.exact[static_cast<std::size_t>(i * v.cols + j)];
  return m;
}

bool is_exact_identity(const MatX<Exact>& m) {
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j)
      if (!same(m(i, j), i == j ? Exact(1) : Exact(0))) return false;
  return true;
}

bool same_matrix(const MatX<Exact>& a, const MatX<Exact>& b) {
  if (a.rows() != b.rows() || a.cols() != b.cols()) return false;
  for (int i = 0; i < a.rows(); ++i)
    for (int j = 0; j < a.cols(); ++j)
      if (!same(a(i, j), b(i, j))) return false;
  return true;
}

std::string text_of(const MatX<Exact>& m) {
  std::string s;
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j)
      s += format_exact(canonical(m(i, j)), MathStyle::Plain) + " ";
  return s;
}

// Homogeneous image of a 3D point with the divide by w.
Vec3<Exact> apply(const MatX<Exact>& m, const Vec3<Exact>& p) {
  const std::vector<Exact> q = transform_point(m, std::vector<Exact>{p(0), p(1), p(2)});
  return Vec3<Exact>(canonical(q[0]), canonical(q[1]), canonical(q[2]));
}

// Determinant by cofactor expansion: exact, with no pivoting decisions on unsimplified values.
Exact det(const MatX<Exact>& m) {
  const int n = static_cast<int>(m.rows());
  if (n == 1) return m(0, 0);
  Exact sum = 0;
  for (int j = 0; j < n; ++j) {
    MatX<Exact> minor(n - 1, n - 1);
    for (int r = 1; r < n; ++r)
      for (int c = 0, k = 0; c < n; ++c)
        if (c != j) minor(r - 1, k++) = m(r, c);
    sum += (j % 2 ? -1 : 1) * m(0, j) * det(minor);
  }
  return canonical(sum);
}

bool near_rel(double a, double b, double rel = 1e-9) {
  return std::abs(a - b) <= rel * std::max({1.0, std::abs(a), std::abs(b)});
}

// ---------------------------------------------------------------------------------------
// 1. The seeds' worked answers.

TEST(ViewingSeeds, Seed000ProjectionPlaneOfA200WindowAt60Degrees) {
  // seed 000 exercise 2: s = −(h/2)/tan(30°) = −100√3, P′ = P·s/z_P.
  const ProblemResult r =
      solve_yaml(one("projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, -300]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "plane_z"), "-100*sqrt(3)");
  EXPECT_EQ(exact_text(r, "projected"), "0, 100*sqrt(3)/3, -100*sqrt(3)");
}

TEST(ViewingSeeds, Seed002ViewVolumeMapsTheBackCornerAndTheClippingPlanes) {
  const std::string base = "{d: 1, a: 1, b: 1, z_min: 1, z_max: 100, point: ";
  const ProblemResult corner = solve_yaml(one("view_volume", base + "[50, 50, 100]}"));
  ASSERT_FALSE(corner.error) << error_text(corner);
  EXPECT_EQ(exact_text(corner, "point"), "1/2, 1/2, 1");
  EXPECT_EQ(exact_text(corner, "scale_matrix"),
            "1/100, 0, 0, 0, 0, 1/100, 0, 0, 0, 0, 1/100, 0, 0, 0, 0, 1");
  // On the axis: z_min → 0 and z_max → 1 after the divide by W′ = z.
  EXPECT_EQ(exact_text(solve_yaml(one("view_volume", base + "[0, 0, 1]}")), "point"), "0, 0, 0");
  EXPECT_EQ(exact_text(solve_yaml(one("view_volume", base + "[0, 0, 100]}")), "point"), "0, 0, 1");
  // Other volumes: the front and back planes still land on 0 and 1, the back corners on ±1.
  const ProblemResult other =
      solve_yaml(one("view_volume", "{d: 2, a: 3, b: 5, z_min: 4, z_max: 20, point: [0, 0, 4]}"));
  EXPECT_EQ(exact_text(other, "point"), "0, 0, 0");
  const ProblemResult back = solve_yaml(
      one("view_volume", "{d: 2, a: 3, b: 5, z_min: 4, z_max: 20, point: [-30, 50, 20]}"));
  EXPECT_EQ(exact_text(back, "point"), "-1, 1, 1");
}

TEST(ViewingSeeds, Seed004RotationAboutOneOneOneBy120CyclesTheAxes) {
  const ProblemResult r = solve_yaml(one("transform",
                                         "{dim: 3, steps: [{rotate: {axis: [1, 1, 1], angle: "
                                         "120}}], points: [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "points"), "0, 1, 0, 0, 0, 1, 1, 0, 0");
  EXPECT_EQ(exact_text(r, "matrix"), "0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1");
  // The template gives the same permutation.
  const MatX<Exact> m = canonical(
      rotate_about(Vec3<Exact>(Vec3<Exact>(1, 1, 1) / GiNaC::sqrt(Exact(3))), degrees(120)));
  EXPECT_TRUE(same(apply(m, Vec3<Exact>(1, 0, 0))(1), 1));
  EXPECT_EQ(text_of(m), "0 0 1 0 1 0 0 0 0 1 0 0 0 0 0 1 ");
}

// ---------------------------------------------------------------------------------------
// 2. Transform identities over generated compositions.

struct GeneratedSteps {
  std::string yaml;                   // the steps list
  std::vector<MatX<Exact>> matrices;  // each step's matrix, built with the templates
};

// Random axes: any small integer vector, or one whose length is an integer ((1, 2, 2) has
// length 3) so the unit axis stays rational. The kind's exact inverse is slow with irrational
// axes and does not finish for two of them (InverseOfTwoGeneralRotationsIsTheTranspose).
enum class Axes { Any, RationalLength };

GeneratedSteps generate_steps(std::mt19937& rng, int dim, bool rotations_only, Axes axes) {
  std::uniform_int_distribution<int> small(-5, 5), kind(0, rotations_only ? 1 : 4), turns(-6, 12);
  std::uniform_int_distribution<int> axis_c(-2, 2), factor(1, 3), count(1, 4);
  GeneratedSteps g;
  const int n = count(rng);
  for (int s = 0; s < n; ++s) {
    std::string item;
    MatX<Exact> m;
    const int k = kind(rng);
    if (k == 0) {  // rotation about a coordinate axis (2D: the plane's rotation)
      const int a = 30 * turns(rng);
      if (dim == 2) {
        item = fmt::format("{{rotate: {}}}", a);
        m = rotate_2d(degrees(a));
      } else {
        const int axis = std::uniform_int_distribution<int>(0, 2)(rng);
        item = fmt::format("{{rotate_{}: {}}}", "xyz"[axis], a);
        m = rotate_axis_index(axis, degrees(a));
      }
    } else if (k == 1) {  // rotation about a random axis (3D) or a second 2D rotation
      const int a = 30 * turns(rng);
      if (dim == 2) {
        item = fmt::format("{{rotate: {}}}", a);
        m = rotate_2d(degrees(a));
      } else {
        int x = 0, y = 0, z = 0;
        if (axes == Axes::RationalLength) {
          static const std::array<std::array<int, 3>, 4> kAxes{
              {{1, 2, 2}, {0, 3, 4}, {2, 3, 6}, {1, 4, 8}}};
          std::array<int, 3> v = kAxes[rng() % kAxes.size()];
          std::shuffle(v.begin(), v.end(), rng);
          x = v[0] * (rng() % 2 ? 1 : -1), y = v[1] * (rng() % 2 ? 1 : -1),
          z = v[2] * (rng() % 2 ? 1 : -1);
        }
        while (x == 0 && y == 0 && z == 0) x = axis_c(rng), y = axis_c(rng), z = axis_c(rng);
        item = fmt::format("{{rotate: {{axis: [{}, {}, {}], angle: {}}}}}", x, y, z, a);
        const Vec3<Exact> axis(x, y, z);
        m = rotate_about(Vec3<Exact>(axis / GiNaC::sqrt(Exact(x * x + y * y + z * z))), degrees(a));
      }
    } else if (k == 2) {
      std::vector<Exact> t;
      std::vector<int> ti;
      for (int i = 0; i < dim; ++i) ti.push_back(small(rng)), t.push_back(ti.back());
      item = dim == 2 ? fmt::format("{{translate: [{}, {}]}}", ti[0], ti[1])
                      : fmt::format("{{translate: [{}, {}, {}]}}", ti[0], ti[1], ti[2]);
      m = translate(t);
    } else if (k == 3) {
      std::vector<Exact> sc;
      std::vector<std::string> st;
      for (int i = 0; i < dim; ++i) {
        const int num = factor(rng) * (rng() % 2 ? 1 : -1), den = factor(rng);
        sc.push_back(rational(num, den));
        st.push_back(fmt::format("\"{}/{}\"", num, den));
      }
      item = dim == 2 ? fmt::format("{{scale: [{}, {}]}}", st[0], st[1])
                      : fmt::format("{{scale: [{}, {}, {}]}}", st[0], st[1], st[2]);
      m = scale(sc);
    } else {
      MatX<Exact> h = MatX<Exact>::Zero(dim, dim);
      const int a = small(rng), b = small(rng);
      if (dim == 2) {
        item = fmt::format("{{shear: [{}, {}]}}", a, b);
        h(0, 1) = a;
        h(1, 0) = b;
      } else {
        item = fmt::format("{{shear: {{xy: {}, zx: {}}}}}", a, b);
        h(0, 1) = a;
        h(2, 0) = b;
      }
      m = shear(h);
    }
    g.yaml += (s ? ", " : "") + item;
    g.matrices.push_back(canonical(m));
  }
  g.yaml = "[" + g.yaml + "]";
  return g;
}

TEST(ViewingTransform, CompositeIsTheReversedProductAndTimesItsInverseIsIdentity) {
  std::mt19937 rng(4004);
  int inverted = 0, singular = 0;  // 2D shears with a·b = 1 are singular
  for (int i = 0; i < 40; ++i) {
    const int dim = i % 3 == 0 ? 2 : 3;
    const GeneratedSteps g = generate_steps(rng, dim, false, Axes::RationalLength);
    const std::string point = dim == 2 ? "[3, -2]" : "[3, -2, 5]";
    const ProblemResult r = solve_yaml(
        one("transform", fmt::format("{{dim: {}, steps: {}, points: [{}]}}", dim, g.yaml, point)),
        false);
    ASSERT_FALSE(r.error) << g.yaml << ": " << error_text(r);
    const MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
    ASSERT_EQ(m.rows(), dim + 1);
    // First step rightmost: M = A_k ··· A_2 · A_1.
    MatX<Exact> product = MatX<Exact>::Identity(dim + 1, dim + 1);
    for (const MatX<Exact>& a : g.matrices) product = canonical(MatX<Exact>(a * product));
    EXPECT_TRUE(same_matrix(m, product))
        << g.yaml << "\nkind: " << text_of(m) << "\nproduct: " << text_of(product);
    // The transformed point is M·p.
    std::vector<Exact> p = dim == 2 ? std::vector<Exact>{3, -2} : std::vector<Exact>{3, -2, 5};
    const std::vector<Exact> want = transform_point(product, p);
    const Value& pts = *r.answers.find("points");
    ASSERT_EQ(pts.exact.size(), static_cast<std::size_t>(dim));
    for (int k = 0; k < dim; ++k)
      EXPECT_TRUE(same(pts.exact[static_cast<std::size_t>(k)], want[static_cast<std::size_t>(k)]))
          << g.yaml;
    // M·M⁻¹ = M⁻¹·M = I exactly; no inverse exactly when det M = 0.
    const Value& inv = *r.answers.find("inverse");
    const bool det_zero = det(product).is_zero();
    if (det_zero) {
      EXPECT_EQ(inv.shape, Value::Shape::Null) << g.yaml;
      ++singular;
      continue;
    }
    ASSERT_EQ(inv.shape, Value::Shape::Matrix) << g.yaml;
    const MatX<Exact> mi = exact_matrix(inv);
    EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(m * mi))))
        << g.yaml << "\nM⁻¹: " << text_of(mi);
    EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(mi * m)))) << g.yaml;
    ++inverted;
  }
  EXPECT_GT(inverted, 30);
  EXPECT_LT(singular, 10);
}

TEST(ViewingTransform, RotationsPreserveLengthsExactly) {
  std::mt19937 rng(1729);
  std::uniform_int_distribution<int> c(-9, 9);
  for (int i = 0; i < 24; ++i) {
    const int dim = i % 4 == 0 ? 2 : 3;
    const GeneratedSteps g = generate_steps(rng, dim, true, Axes::RationalLength);
    std::vector<std::vector<int>> pts(3);
    std::string list;
    for (auto& p : pts) {
      for (int k = 0; k < dim; ++k) p.push_back(c(rng));
      list += (list.empty() ? "[" : ", [") + fmt::format("{}", fmt::join(p, ", ")) + "]";
    }
    const ProblemResult r = solve_yaml(
        one("transform", fmt::format("{{dim: {}, steps: {}, points: [{}]}}", dim, g.yaml, list)),
        false);
    ASSERT_FALSE(r.error) << g.yaml << ": " << error_text(r);
    const Value& moved = *r.answers.find("points");
    ASSERT_EQ(moved.exact.size(), pts.size() * static_cast<std::size_t>(dim));
    for (std::size_t j = 0; j < pts.size(); ++j) {
      Exact before = 0, after = 0;
      for (int k = 0; k < dim; ++k) {
        const Exact x =
            moved.exact[j * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)];
        before += pts[j][static_cast<std::size_t>(k)] * pts[j][static_cast<std::size_t>(k)];
        after += x * x;
      }
      EXPECT_TRUE(same(before, after)) << g.yaml << " point " << j;
    }
    // And the linear part is orthogonal with determinant 1.
    const MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
    const MatX<Exact> rot = m.topLeftCorner(dim, dim);
    EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(rot * rot.transpose())))) << g.yaml;
    EXPECT_TRUE(same(det(rot), 1)) << g.yaml;
  }
}

TEST(ViewingTransform, TemplateRotationsAboutSeveralAxesAreOrthogonal) {
  // Several general axes at once, with the templates only: R·Rᵀ = I and |R·p|² = |p|².
  std::mt19937 rng(2468);
  std::uniform_int_distribution<int> c(-9, 9);
  for (int i = 0; i < 12; ++i) {
    const GeneratedSteps g = generate_steps(rng, 3, true, Axes::Any);
    MatX<Exact> m = MatX<Exact>::Identity(4, 4);
    for (const MatX<Exact>& a : g.matrices) m = canonical(MatX<Exact>(a * m));
    const MatX<Exact> rot = m.topLeftCorner(3, 3);
    EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(rot * rot.transpose())))) << g.yaml;
    const Vec3<Exact> p(c(rng), c(rng), c(rng));
    const Vec3<Exact> q = apply(m, p);
    EXPECT_TRUE(same(q.dot(q), p.dot(p))) << g.yaml;
  }
}

TEST(ViewingTransform, InverseOfARotationPrintsAsItsTranspose) {
  const ProblemResult r = solve_yaml(
      one("transform", "{dim: 3, steps: [{rotate: {axis: [1, 2, 0], angle: 30}}]}"), false);
  ASSERT_FALSE(r.error) << error_text(r);
  const MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
  const MatX<Exact> inv = exact_matrix(*r.answers.find("inverse"));
  EXPECT_TRUE(same_matrix(inv, MatX<Exact>(m.transpose())));
  // Values that compare equal print equal (exact.hpp): the inverse reads as the transpose.
  EXPECT_EQ(text_of(inv), text_of(MatX<Exact>(m.transpose())));
  EXPECT_EQ(format_exact(inv(0, 0), MathStyle::Plain), "1/5 + 2*sqrt(3)/5");
}

TEST(ViewingTransform, InverseOfTwoGeneralRotationsIsTheTranspose) {
  const ProblemResult r = solve_yaml(one("transform",
                                         "{dim: 3, steps: [{rotate: {axis: [1, 2, 0], angle: 30}}, "
                                         "{rotate: {axis: [1, 1, 2], angle: 30}}]}"),
                                     false);
  ASSERT_FALSE(r.error) << error_text(r);
  const MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
  const MatX<Exact> inv = exact_matrix(*r.answers.find("inverse"));
  EXPECT_TRUE(same_matrix(inv, MatX<Exact>(m.transpose())));
  EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(m * inv))));
}

// ---------------------------------------------------------------------------------------
// 3, 4. Volumes to the NDC cube, and OpenGL against DirectX.

std::vector<Volume<Exact>> test_volumes() {
  std::vector<Volume<Exact>> v = {
      {-1, 1, -1, 1, 1, 100},
      {-2, 3, -1, 4, 2, 10},
      {rational(-1, 2), rational(3, 2), rational(-2, 3), rational(1, 3), rational(1, 10), 7},
      {GiNaC::sqrt(Exact(3)) * -1, GiNaC::sqrt(Exact(3)), -1, 1, 1, 1000},
  };
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> d(-9, 9), pos(1, 9);
  for (int i = 0; i < 8; ++i) {
    const int l = d(rng), b = d(rng), n = pos(rng);
    v.push_back({l, l + pos(rng), b, b + pos(rng), n, n + pos(rng)});
  }
  return v;
}

TEST(ViewingProjection, FrustumCornersMapToTheNdcCubeInEachConvention) {
  for (const Volume<Exact>& v : test_volumes()) {
    for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
      const MatX<Exact> m = canonical(frustum_matrix(v, api));
      const int look = api == Api::DirectX ? 1 : -1;  // eye space z of the volume's side
      for (const bool far : {false, true})
        for (const bool right : {false, true})
          for (const bool top : {false, true}) {
            // Far corners lie on the rays through the near corners, scaled by f/n. Processing's
            // negated y (−2n/(t−b), (t+b)/(t−b) kept) mirrors eye space: its volume spans
            // y ∈ [−t, −b], with y = −t → +1.
            const Exact k = far ? Exact(v.far / v.near) : Exact(1);
            const int mirror = api == Api::Processing ? -1 : 1;
            const Vec3<Exact> corner((right ? v.right : v.left) * k,
                                     mirror * (top ? v.top : v.bottom) * k,
                                     look * (far ? v.far : v.near));
            const Vec3<Exact> ndc = apply(m, corner);
            const int want_y = top ? 1 : -1;
            const Exact want_z = api == Api::DirectX ? Exact(far ? 1 : 0) : Exact(far ? 1 : -1);
            const std::string where =
                fmt::format("{} l={} far={} right={} top={}", to_string(api),
                            format_exact(v.left, MathStyle::Plain), far, right, top);
            EXPECT_TRUE(same(ndc(0), right ? 1 : -1)) << where;
            EXPECT_TRUE(same(ndc(1), want_y)) << where;
            EXPECT_TRUE(same(ndc(2), want_z)) << where;
          }
    }
  }
}

TEST(ViewingProjection, OrthoCornersMapToTheNdcCubeInEachConvention) {
  std::vector<Volume<Exact>> volumes = test_volumes();
  volumes.push_back({-4, 4, -3, 3, -5, 5});  // ortho allows a near plane behind the eye
  for (const Volume<Exact>& v : volumes) {
    for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
      const MatX<Exact> m = canonical(ortho_matrix(v, api));
      const int look = api == Api::DirectX ? 1 : -1;
      for (const bool far : {false, true})
        for (const bool right : {false, true})
          for (const bool top : {false, true}) {
            const int mirror = api == Api::Processing ? -1 : 1;
            const Vec3<Exact> corner(right ? v.right : v.left, mirror * (top ? v.top : v.bottom),
                                     look * (far ? v.far : v.near));
            const Vec3<Exact> ndc = apply(m, corner);
            const int want_y = top ? 1 : -1;
            const Exact want_z = api == Api::DirectX ? Exact(far ? 1 : 0) : Exact(far ? 1 : -1);
            const std::string where =
                fmt::format("{} far={} right={} top={}", to_string(api), far, right, top);
            EXPECT_TRUE(same(ndc(0), right ? 1 : -1)) << where;
            EXPECT_TRUE(same(ndc(1), want_y)) << where;
            EXPECT_TRUE(same(ndc(2), want_z)) << where;
          }
    }
  }
}

TEST(ViewingProjection, KindMatrixIsTheTemplateAndDirectXPrintsItsTranspose) {
  const std::string given = "{frustum: {left: -2, right: 3, bottom: -1, top: 4, near: 2, far: 10}}";
  const Volume<Exact> v{-2, 3, -1, 4, 2, 10};
  for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
    const ProblemResult r = solve_yaml(one("projection_matrix", given, api_conventions(api)));
    ASSERT_FALSE(r.error) << error_text(r);
    const MatX<Exact> printed = exact_matrix(*r.answers.find("matrix"));
    const MatX<Exact> column = canonical(frustum_matrix(v, api));
    EXPECT_TRUE(
        same_matrix(printed, api == Api::DirectX ? MatX<Exact>(column.transpose()) : column))
        << to_string(api);
  }
  // DirectX row vectors: the printed matrix has its 1 (w′ = z) in row 3, column 4.
  const ProblemResult dx = solve_yaml(one("projection_matrix", given, "{api: directx}"));
  EXPECT_EQ(dx.answers.find("matrix")->numbers[2 * 4 + 3], 1.0);
  EXPECT_EQ(dx.answers.find("matrix")->numbers[3 * 4 + 2], -2.5);  // nf/(n−f) = 20/−8
}

TEST(ViewingProjection, OpenGLAndDirectXAgreeAfterFlippingZ) {
  // With z_dx = −z_gl: x and y NDC are equal and z_dx = (z_gl + 1)/2, for frustum and ortho
  // (same l, r, b, t, n, f): (f+n)/(2(f−n)) + 1/2 = f/(f−n), and fn/((f−n)·z) matches.
  std::mt19937 rng(31337);
  std::uniform_int_distribution<int> c(-30, 30), depth(1, 60);
  int checked = 0;
  for (const Volume<Exact>& v : test_volumes()) {
    const MatX<Exact> gl_p = canonical(frustum_matrix(v, Api::OpenGL));
    const MatX<Exact> dx_p = canonical(frustum_matrix(v, Api::DirectX));
    const MatX<Exact> gl_o = canonical(ortho_matrix(v, Api::OpenGL));
    const MatX<Exact> dx_o = canonical(ortho_matrix(v, Api::DirectX));
    for (int i = 0; i < 12; ++i) {
      const Exact x = rational(c(rng), 3), y = rational(c(rng), 2), z = -rational(depth(rng), 4);
      for (const auto& [gl, dx] : {std::pair{&gl_p, &dx_p}, std::pair{&gl_o, &dx_o}}) {
        const Vec3<Exact> a = apply(*gl, Vec3<Exact>(x, y, z));
        const Vec3<Exact> b = apply(*dx, Vec3<Exact>(x, y, -z));
        EXPECT_TRUE(same(a(0), b(0))) << x << " " << y << " " << z;
        EXPECT_TRUE(same(a(1), b(1))) << x << " " << y << " " << z;
        EXPECT_TRUE(same((a(2) + 1) / 2, b(2)))
            << x << " " << y << " " << z << ": " << a(2) << " vs " << b(2);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 200);
}

// ---------------------------------------------------------------------------------------
// 5. project_point = projection matrix, divide, viewport (templates in double).

TEST(ViewingProjectPoint, AgreesWithTheTemplatesInDouble) {
  std::mt19937 rng(5150);
  std::uniform_int_distribution<int> coord(-40, 40), type(0, 2), fov_pick(0, 6), small(-6, 6),
      pos(1, 8);
  const int fovs[] = {30, 45, 60, 90, 120, 37, 71};
  const std::pair<int, int> aspects[] = {{1, 1}, {4, 3}, {16, 9}, {1, 2}};
  int with_ndc = 0, inside_count = 0, behind = 0;
  for (int i = 0; i < 120; ++i) {
    const Api api =
        std::array{Api::OpenGL, Api::Processing, Api::DirectX}[static_cast<std::size_t>(i % 3)];
    const int t = type(rng);
    std::string projection;
    Volume<double> vol{};
    const int n = pos(rng), f = n + pos(rng) * 10;
    if (t == 0) {
      const int fovy = fovs[fov_pick(rng)];
      const auto [an, ad] = aspects[static_cast<std::size_t>(rng() % 4)];
      projection = fmt::format("perspective: {{fovy: {}, aspect: \"{}/{}\", near: {}, far: {}}}",
                               fovy, an, ad, n, f);
      vol = perspective_volume<double>(fovy * std::numbers::pi / 180, double(an) / ad, n, f);
    } else {
      const int l = small(rng), b = small(rng), w = pos(rng), h = pos(rng);
      projection =
          fmt::format("{}: {{left: {}, right: {}, bottom: {}, top: {}, near: {}, far: {}}}",
                      t == 1 ? "frustum" : "ortho", l, l + w, b, b + h, n, f);
      vol = {double(l), double(l + w), double(b), double(b + h), double(n), double(f)};
    }
    const MatX<double> proj = t == 2 ? ortho_matrix(vol, api) : frustum_matrix(vol, api);
    const int px = coord(rng), py = coord(rng), pz = coord(rng);
    Eigen::Vector4d p(px, py, pz, 1);
    // Every fourth point (in view space, no camera) on the volume's centre line, halfway in
    // depth: inside.
    const double depth = (vol.near + vol.far) / 2, k = t == 2 ? 1.0 : depth / vol.near;
    const Eigen::Vector4d centre((vol.left + vol.right) / 2 * k, (vol.bottom + vol.top) / 2 * k,
                                 api == Api::DirectX ? depth : -depth, 1);
    if (i % 4 == 0) p = centre;
    std::string camera;
    if (i % 2 == 1) {  // a camera in world space
      Eigen::Vector3d eye, center, up;
      // Drawn one by one: the order of a call's arguments differs between compilers.
      const auto draw = [&] {
        const double x = small(rng), y = small(rng), z = small(rng);
        return Eigen::Vector3d(x, y, z);
      };
      do {
        eye = draw();
        center = draw();
        up = draw();
      } while ((center - eye).squaredNorm() == 0 || (center - eye).cross(up).squaredNorm() == 0);
      camera =
          fmt::format(", camera: {{eye: [{}, {}, {}], center: [{}, {}, {}], up: [{}, {}, {}]}}",
                      eye(0), eye(1), eye(2), center(0), center(1), center(2), up(0), up(1), up(2));
      const MatX<double> view = look_at<double>(eye, center, up, api);
      p = Eigen::Vector4d(view * p);
    }
    const int width = 100 + 20 * pos(rng), height = 80 + 10 * pos(rng);
    const Eigen::Vector4d written = i % 4 == 0 ? centre : Eigen::Vector4d(px, py, pz, 1);
    const std::string given = fmt::format(
        "{{point: [{:.17g}, {:.17g}, {:.17g}]{}, {}, viewport: {{width: {}, height: {}}}}}",
        written(0), written(1), written(2), camera, projection, width, height);
    const ProblemResult r = solve_yaml(one("project_point", given, api_conventions(api)), false);
    ASSERT_FALSE(r.error) << given << ": " << error_text(r);
    const Eigen::Vector4d clip = proj * p;
    const Value& kclip = *r.answers.find("clip");
    ASSERT_EQ(kclip.numbers.size(), 4u);
    for (int k = 0; k < 4; ++k)
      EXPECT_TRUE(near_rel(kclip.numbers[static_cast<std::size_t>(k)], clip(k)))
          << given << " clip " << k;
    const double w = clip(3);
    const Value& kndc = *r.answers.find("ndc");
    const Value& kwin = *r.answers.find("window");
    if (std::abs(w) < 1e-9) continue;  // the sign of w is the exact solver's to decide
    if (w < 0) {
      EXPECT_EQ(kndc.shape, Value::Shape::Null) << given;
      EXPECT_EQ(kwin.shape, Value::Shape::Null) << given;
      EXPECT_FALSE(r.answers.find("inside")->flag) << given;
      ++behind;
      continue;
    }
    const Vec3<double> ndc(clip(0) / w, clip(1) / w, clip(2) / w);
    const Vec3<double> win = viewport<double>(ndc, width, height, api);
    ASSERT_EQ(kndc.numbers.size(), 3u) << given;
    ASSERT_EQ(kwin.numbers.size(), 3u) << given;
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(near_rel(kndc.numbers[static_cast<std::size_t>(k)], ndc(k)))
          << given << " ndc " << k;
      EXPECT_TRUE(near_rel(kwin.numbers[static_cast<std::size_t>(k)], win(k)))
          << given << " window " << k;
    }
    ++with_ndc;
    // Inside: −w ≤ x, y ≤ w and −w ≤ z ≤ w (DirectX 0 ≤ z ≤ w); skip ties within rounding.
    const double z_low = api == Api::DirectX ? 0 : -w;
    const double slack = std::min(
        {clip(0) + w, w - clip(0), clip(1) + w, w - clip(1), clip(2) - z_low, w - clip(2)});
    if (std::abs(slack) > 1e-9 * std::max(1.0, w)) {
      EXPECT_EQ(r.answers.find("inside")->flag, slack > 0) << given;
      inside_count += slack > 0;
    }
  }
  EXPECT_GT(with_ndc, 30);
  EXPECT_GT(inside_count, 3);
  EXPECT_GT(behind, 3);
}

// ---------------------------------------------------------------------------------------
// 6. look_at.

TEST(ViewingLookAt, EyeToOriginCenterOnTheViewAxisAndOrthonormalRotation) {
  std::mt19937 rng(606);
  std::uniform_int_distribution<int> c(-5, 5);
  int cases = 0;
  for (int i = 0; i < 36; ++i) {
    const Api api =
        std::array{Api::OpenGL, Api::Processing, Api::DirectX}[static_cast<std::size_t>(i % 3)];
    Vec3<Exact> eye, center, up;
    int e[3], ce[3], u[3];
    do {
      for (int k = 0; k < 3; ++k) e[k] = c(rng), ce[k] = c(rng), u[k] = c(rng);
      eye = Vec3<Exact>(e[0], e[1], e[2]);
      center = Vec3<Exact>(ce[0], ce[1], ce[2]);
      up = Vec3<Exact>(u[0], u[1], u[2]);
    } while (
        canonical((center - eye).dot(center - eye)).is_zero() ||
        canonical(Vec3<Exact>((center - eye).cross(up)).dot((center - eye).cross(up))).is_zero());
    const std::string given = fmt::format(
        "{{eye: [{}, {}, {}], center: [{}, {}, {}], up: [{}, {}, {}], points: [[{}, {}, {}], [{}, "
        "{}, {}], [{}, {}, {}]]}}",
        e[0], e[1], e[2], ce[0], ce[1], ce[2], u[0], u[1], u[2], e[0], e[1], e[2], ce[0], ce[1],
        ce[2], e[0] + u[0], e[1] + u[1], e[2] + u[2]);
    const ProblemResult r = solve_yaml(one("look_at", given, api_conventions(api)), false);
    ASSERT_FALSE(r.error) << given << ": " << error_text(r);
    const Value& pts = *r.answers.find("points");
    ASSERT_EQ(pts.exact.size(), 9u);
    // The eye maps to the origin.
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(same(pts.exact[static_cast<std::size_t>(k)], 0)) << given;
    // The center lies on the view axis at distance |center − eye|: −z in OpenGL/Processing, +z in
    // DirectX.
    const Exact dist = GiNaC::sqrt(canonical((center - eye).dot(center - eye)));
    EXPECT_TRUE(same(pts.exact[3], 0)) << given;
    EXPECT_TRUE(same(pts.exact[4], 0)) << given;
    EXPECT_TRUE(same(pts.exact[5], api == Api::DirectX ? dist : Exact(-dist)))
        << to_string(api) << " " << given;
    // eye + up lands above the eye (view y > 0) and with no sideways part (x = 0).
    EXPECT_TRUE(same(pts.exact[6], 0)) << given;
    EXPECT_GT(exact_sign(pts.exact[7]), 0) << given;
    // The rotation part is orthonormal with determinant +1 (a rotation, no mirror), in column
    // form; DirectX prints the transpose, whose translation sits in the last row.
    MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
    if (api == Api::DirectX) m = MatX<Exact>(m.transpose());
    EXPECT_TRUE(same(m(3, 0), 0) && same(m(3, 1), 0) && same(m(3, 2), 0) && same(m(3, 3), 1))
        << given;
    const MatX<Exact> rot = m.topLeftCorner(3, 3);
    EXPECT_TRUE(is_exact_identity(canonical(MatX<Exact>(rot * rot.transpose()))))
        << to_string(api) << " " << text_of(rot);
    EXPECT_TRUE(same(det(rot), 1)) << to_string(api) << " " << text_of(rot);
    // Same matrix as the template.
    EXPECT_TRUE(same_matrix(m, canonical(look_at(eye, center, up, api)))) << given;
    ++cases;
  }
  EXPECT_EQ(cases, 36);
}

TEST(ViewingLookAt, OpenGLAndDirectXDifferByMirroringXAndZ) {
  // Looking from (0, 0, 5) at the origin with y up: OpenGL keeps x and y, z → −(5 − z);
  // DirectX's LookAtLH (x = up × z) sees x mirrored and z → 5 − z.
  const std::string given =
      "{eye: [0, 0, 5], center: [0, 0, 0], up: [0, 1, 0], points: [[1, 2, 3]]}";
  EXPECT_EQ(exact_text(solve_yaml(one("look_at", given)), "points"), "1, 2, -2");
  EXPECT_EQ(exact_text(solve_yaml(one("look_at", given, "{api: directx}")), "points"), "-1, 2, 2");
}

// ---------------------------------------------------------------------------------------
// 7. Bad cases: errors naming the field, and points that have no NDC.

void expect_error(const std::string& yaml, const std::string& field_suffix,
                  const std::string& word) {
  const ProblemResult r = solve_yaml(yaml, false);
  ASSERT_TRUE(r.error) << "no error for: " << yaml;
  const std::string& f = r.error->field;
  EXPECT_TRUE(f.size() >= field_suffix.size() &&
              f.compare(f.size() - field_suffix.size(), field_suffix.size(), field_suffix) == 0)
      << "field '" << f << "' should end with '" << field_suffix << "' for: " << yaml;
  EXPECT_NE(r.error->message.find(word), std::string::npos)
      << "message '" << r.error->message << "' should contain '" << word << "' for: " << yaml;
  EXPECT_GT(r.error->where.line, 0) << yaml;
}

TEST(ViewingErrors, ProjectionDomainErrorsNameTheField) {
  const auto persp = [](const std::string& inner) {
    return one("projection_matrix", "{perspective: {" + inner + "}}");
  };
  expect_error(persp("fovy: 60, aspect: 1, near: 0, far: 10"), ".perspective.near", "positive");
  expect_error(persp("fovy: 60, aspect: 1, near: -1, far: 10"), ".perspective.near", "positive");
  expect_error(persp("fovy: 60, aspect: 1, near: 10, far: 10"), ".perspective.far", "near = far");
  expect_error(persp("fovy: 0, aspect: 1, near: 1, far: 10"), ".perspective.fovy", "between");
  expect_error(persp("fovy: 180, aspect: 1, near: 1, far: 10"), ".perspective.fovy", "between");
  expect_error(persp("fovy: -30, aspect: 1, near: 1, far: 10"), ".perspective.fovy", "between");
  expect_error(persp("fovy: 60, aspect: 0, near: 1, far: 10"), ".perspective.aspect", "positive");
  expect_error(persp("fovy: 60, aspect: -1, near: 1, far: 10"), ".perspective.aspect", "positive");
  expect_error(one("projection_matrix",
                   "{frustum: {left: 2, right: 2, bottom: -1, top: 1, near: 1, far: 10}}"),
               ".frustum.right", "left = right");
  expect_error(one("projection_matrix",
                   "{frustum: {left: -1, right: 1, bottom: 3, top: 3, near: 1, far: 10}}"),
               ".frustum.top", "bottom = top");
  expect_error(one("projection_matrix",
                   "{frustum: {left: -1, right: 1, bottom: -1, top: 1, near: -1, far: 10}}"),
               ".frustum.near", "positive");
  expect_error(one("projection_matrix",
                   "{ortho: {left: -1, right: 1, bottom: -1, top: 1, near: 5, far: 5}}"),
               ".ortho.far", "near = far");
  // The same checks inside project_point.
  expect_error(one("project_point",
                   "{point: [0, 0, -5], perspective: {fovy: 60, aspect: 1, near: 0, far: 10}, "
                   "viewport: {width: 100, height: 100}}"),
               ".perspective.near", "positive");
}

TEST(ViewingErrors, DegenerateAxisAndCamera) {
  expect_error(one("transform", "{dim: 3, steps: [{rotate: {axis: [0, 0, 0], angle: 30}}]}"),
               ".axis", "zero");
  expect_error(one("look_at", "{eye: [0, 0, 5], center: [0, 0, 0], up: [0, 0, 1]}"), ".up",
               "parallel");
  expect_error(one("look_at", "{eye: [1, 1, 1], center: [3, 3, 3], up: [-2, -2, -2]}"), ".up",
               "parallel");
  expect_error(one("look_at", "{eye: [0, 0, 5], center: [0, 0, 0], up: [0, 0, 0]}"), ".up",
               "parallel");
  expect_error(one("look_at", "{eye: [1, 2, 3], center: [1, 2, 3], up: [0, 1, 0]}"), ".center",
               "center = eye");
  expect_error(one("project_point",
                   "{point: [0, 0, 0], camera: {eye: [1, 2, 3], center: [1, 2, 3], up: [0, 1, 0]}, "
                   "perspective: {fovy: 60, aspect: 1, near: 1, far: 10}, viewport: {width: 10, "
                   "height: 10}}"),
               "camera.center", "center = eye");
}

TEST(ViewingErrors, PointBehindOrBesideTheEyeHasNoNdcButIsNoError) {
  for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
    const int behind_z =
        api == Api::DirectX ? -5 : 5;  // behind: w = −z (OpenGL) or z (DirectX) < 0
    for (const int z : {behind_z, 0}) {
      const ProblemResult r = solve_yaml(
          one("project_point",
              fmt::format(
                  "{{point: [1, 2, {}], perspective: {{fovy: 90, aspect: 1, near: 1, far: 10}}, "
                  "viewport: {{width: 100, height: 50}}}}",
                  z),
              api_conventions(api)),
          false);
      ASSERT_FALSE(r.error) << error_text(r);
      const Value& clip = *r.answers.find("clip");
      EXPECT_EQ(exact_sign(clip.exact[3]), z == 0 ? 0 : -1) << to_string(api) << " z=" << z;
      EXPECT_EQ(r.answers.find("ndc")->shape, Value::Shape::Null) << to_string(api) << " z=" << z;
      EXPECT_EQ(r.answers.find("window")->shape, Value::Shape::Null)
          << to_string(api) << " z=" << z;
      EXPECT_FALSE(r.answers.find("inside")->flag) << to_string(api) << " z=" << z;
    }
  }
}

TEST(ViewingErrors, ProjectionPlanePointBehindOrBesideTheEyeIsAnError) {
  expect_error(one("projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, 300]}"),
               ".point", "behind");
  expect_error(one("projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, 0]}"),
               ".point", "eye's plane");
  expect_error(one("projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, -300]}",
                   "{api: directx}"),
               ".point", "behind");
  expect_error(one("projection_plane", "{window: [200, 200], fov: 180, point: [0, 100, -300]}"),
               ".fov", "between");
  // DirectX looks down +z: the plane is at +100√3.
  const ProblemResult dx = solve_yaml(one(
      "projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, 300]}", "{api: directx}"));
  ASSERT_FALSE(dx.error) << error_text(dx);
  EXPECT_EQ(exact_text(dx, "plane_z"), "100*sqrt(3)");
  EXPECT_EQ(exact_text(dx, "projected"), "0, 100*sqrt(3)/3, 100*sqrt(3)");
}

// ---------------------------------------------------------------------------------------
// 8. Processing's y flip and the window's y axis.

TEST(ViewingProcessing, ProjectionNegatesTheYRow) {
  for (const std::string given :
       {"{perspective: {fovy: 60, aspect: \"4/3\", near: 1, far: 100}}",
        "{frustum: {left: -2, right: 3, bottom: -1, top: 4, near: 2, far: 10}}",
        "{ortho: {left: -2, right: 3, bottom: -1, top: 4, near: 2, far: 10}}"}) {
    const ProblemResult gl = solve_yaml(one("projection_matrix", given));
    const ProblemResult pr = solve_yaml(one("projection_matrix", given, "{api: processing}"));
    ASSERT_FALSE(gl.error || pr.error) << given;
    const Value& a = *gl.answers.find("matrix");
    const Value& b = *pr.answers.find("matrix");
    for (int i = 0; i < 16; ++i) {
      const Exact want = i == 5 ? Exact(-a.exact[5]) : a.exact[static_cast<std::size_t>(i)];
      EXPECT_TRUE(same(b.exact[static_cast<std::size_t>(i)], want)) << given << " element " << i;
    }
    EXPECT_LT(b.numbers[5], 0) << given;
  }
}

TEST(ViewingProcessing, NdcIsOpenGLsOfTheYMirroredPoint) {
  // Processing's matrix is OpenGL's times diag(1, −1, 1, 1); for a volume symmetric in y
  // (perspective()) the same point's NDC y is simply negated.
  std::mt19937 rng(2718);
  std::uniform_int_distribution<int> c(-20, 20), depth(1, 40);
  for (const Volume<Exact>& v : test_volumes()) {
    for (const bool ortho : {false, true}) {
      const MatX<Exact> gl =
          canonical(ortho ? ortho_matrix(v, Api::OpenGL) : frustum_matrix(v, Api::OpenGL));
      const MatX<Exact> pr =
          canonical(ortho ? ortho_matrix(v, Api::Processing) : frustum_matrix(v, Api::Processing));
      for (int i = 0; i < 5; ++i) {
        const Exact x = c(rng), y = rational(c(rng), 3), z = -depth(rng);
        const Vec3<Exact> a = apply(pr, Vec3<Exact>(x, y, z));
        const Vec3<Exact> b = apply(gl, Vec3<Exact>(x, -y, z));
        EXPECT_TRUE(same(a(0), b(0)) && same(a(1), b(1)) && same(a(2), b(2)))
            << x << " " << y << " " << z;
      }
    }
  }
  const Volume<Exact> sym = perspective_volume<Exact>(degrees(60), rational(4, 3), 1, 50);
  const Vec3<Exact> p(3, 5, -7);
  const Vec3<Exact> a = apply(canonical(frustum_matrix(sym, Api::Processing)), p);
  const Vec3<Exact> b = apply(canonical(frustum_matrix(sym, Api::OpenGL)), p);
  EXPECT_TRUE(same(a(1), -b(1)));
  EXPECT_TRUE(same(a(0), b(0)) && same(a(2), b(2)));
  EXPECT_GT(exact_sign(b(1)), 0);
}

TEST(ViewingProcessing, DirectXAndOpenGLViewportsPutNdcYOneAtOppositeEdges) {
  const std::string top = "{ndc: [1, 1, 0], width: 640, height: 480}";
  EXPECT_EQ(exact_text(solve_yaml(one("viewport", top, "{api: directx}")), "window"), "640, 0, 0");
  EXPECT_EQ(exact_text(solve_yaml(one("viewport", top)), "window"), "640, 480, 1/2");
  EXPECT_EQ(exact_text(solve_yaml(one("viewport", "{ndc: [-1, -1, 1], width: 640, height: 480}",
                                      "{api: directx}")),
                       "window"),
            "0, 480, 1");
}

TEST(ViewingProcessing, DefaultCameraMapsWorldPixelsToTheSameWindowPixels) {
  // Processing's default camera: eye (w/2, h/2, (h/2)/tan(30°)) looking at (w/2, h/2, 0), up
  // (0, 1, 0), perspective(60°, w/h, …): a point (x, y, 0) appears at pixel (x, y), y down.
  const std::string camera =
      "camera: {eye: [320, 240, \"240*sqrt(3)\"], center: [320, 240, 0], up: [0, 1, 0]}";
  const std::string rest =
      "perspective: {fovy: 60, aspect: \"4/3\", near: 10, far: 10000}, viewport: {width: 640, "
      "height: 480}";
  const auto window_of = [&](int x, int y) {
    const ProblemResult r = solve_yaml(
        one("project_point", fmt::format("{{point: [{}, {}, 0], {}, {}}}", x, y, camera, rest),
            "{api: processing}"),
        false);
    EXPECT_FALSE(r.error) << error_text(r);
    return exact_text(r, "window");
  };
  const ProblemResult center =
      solve_yaml(one("project_point", fmt::format("{{point: [320, 240, 0], {}, {}}}", camera, rest),
                     "{api: processing}"),
                 false);
  const ProblemResult above =
      solve_yaml(one("project_point", fmt::format("{{point: [320, 100, 0], {}, {}}}", camera, rest),
                     "{api: processing}"),
                 false);
  ASSERT_FALSE(center.error || above.error);
  // Above the center in Processing's world (smaller y) is above it on screen (smaller window y).
  EXPECT_LT(above.answers.find("window")->numbers[1], center.answers.find("window")->numbers[1]);
  EXPECT_EQ(window_of(320, 240).substr(0, 8), "320, 240");
  EXPECT_EQ(window_of(0, 0).substr(0, 4), "0, 0");
  EXPECT_EQ(window_of(100, 400).substr(0, 8), "100, 400");
}

// ---------------------------------------------------------------------------------------
// 9. Degrees and radians.

TEST(ViewingAngles, RadiansGiveTheSameMatricesAsDegrees) {
  const ProblemResult deg =
      solve_yaml(one("projection_matrix", "{perspective: {fovy: 90, aspect: 2, near: 1, far: 3}}"));
  const ProblemResult rad = solve_yaml(
      one("projection_matrix", "{perspective: {fovy: \"pi/2\", aspect: 2, near: 1, far: 3}}",
          "{angles: radians}"));
  ASSERT_FALSE(deg.error || rad.error) << error_text(deg) << error_text(rad);
  EXPECT_EQ(exact_text(deg, "matrix"), exact_text(rad, "matrix"));
  EXPECT_EQ(exact_text(deg, "matrix"), "1/2, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -3, 0, 0, -1, 0");
  const ProblemResult deg60 =
      solve_yaml(one("projection_matrix", "{perspective: {fovy: 60, aspect: 1, near: 1, far: 3}}"));
  const ProblemResult rad60 = solve_yaml(
      one("projection_matrix", "{perspective: {fovy: \"pi/3\", aspect: 1, near: 1, far: 3}}",
          "{angles: radians}"));
  EXPECT_EQ(exact_text(deg60, "matrix"), exact_text(rad60, "matrix"));
  EXPECT_EQ(exact_text(deg60, "matrix").substr(0, 7), "sqrt(3)");
  // Transforms and the projection plane read their angles the same way.
  const ProblemResult td = solve_yaml(one(
      "transform", "{dim: 3, steps: [{rotate_z: 30}, {rotate: {axis: [1, 2, 2], angle: 150}}]}"));
  const ProblemResult tr = solve_yaml(
      one("transform",
          "{dim: 3, steps: [{rotate_z: \"pi/6\"}, {rotate: {axis: [1, 2, 2], angle: \"5*pi/6\"}}]}",
          "{angles: radians}"));
  EXPECT_EQ(exact_text(td, "matrix"), exact_text(tr, "matrix"));
  EXPECT_EQ(exact_text(solve_yaml(one("projection_plane",
                                      "{window: [200, 200], fov: \"pi/3\", point: [0, 100, -300]}",
                                      "{angles: radians}")),
                       "plane_z"),
            "-100*sqrt(3)");
  // pi/2 read as degrees is a small angle, not a right angle.
  const ProblemResult small = solve_yaml(
      one("projection_matrix", "{perspective: {fovy: \"pi/2\", aspect: 2, near: 1, far: 3}}"));
  EXPECT_NE(exact_text(small, "matrix"), exact_text(deg, "matrix"));
}

// ---- Every kind that prints a matrix or a volume, in each convention ----

// transform: column form (translation in the last column, P′ = M·P) for OpenGL and Processing;
// DirectX prints the transpose (translation in the bottom row, P′ = P·M), the inverse too, in
// the exact and every numeric backend; the moved points are the same.
TEST(ConventionsEveryKind, TransformPrintsRowFormUnderDirectX) {
  const std::string given =
      "{steps: [{translate: [1, 2, 3]}, {rotate_z: 90}, {scale: [2, 1, 1]}], points: [[1, 1, 1]]}";
  const ProblemResult gl = solve_yaml(one("transform", given, "{api: opengl}"));
  ASSERT_FALSE(gl.error) << error_text(gl);
  const MatX<Exact> m = exact_matrix(*gl.answers.find("matrix")),
                    inv = exact_matrix(*gl.answers.find("inverse"));
  EXPECT_TRUE(test::same(m(0, 3), -4))
      << text_of(m);  // translation (−2·2, 1, 3) in the last column
  EXPECT_TRUE(test::same(m(3, 0), 0));
  for (const Api api : {Api::Processing, Api::DirectX}) {
    const ProblemResult r = solve_yaml(one("transform", given, api_conventions(api)));
    ASSERT_FALSE(r.error) << error_text(r);
    const bool rows = api == Api::DirectX;
    EXPECT_TRUE(
        same_matrix(exact_matrix(*r.answers.find("matrix")), rows ? MatX<Exact>(m.transpose()) : m))
        << to_string(api);
    EXPECT_TRUE(same_matrix(exact_matrix(*r.answers.find("inverse")),
                            rows ? MatX<Exact>(inv.transpose()) : inv));
    EXPECT_EQ(exact_text(r, "points"), exact_text(gl, "points"));
    for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
      const ProblemResult n = solve_problem(
          load_problem_set_from_string(one("transform", given, api_conventions(api)), "t.yaml")
              .problems[0],
          "t.yaml", false, p);
      ASSERT_FALSE(n.error);
      const std::vector<double>& got = n.answers.find("matrix")->numbers;
      EXPECT_NEAR(got[rows ? 12 : 3], -4, 1e-6) << to_string(api) << " " << to_string(p);
    }
    if (rows) {
      bool said = false;
      for (const Step& st : r.derivation.steps())
        said = said || st.formula.unicode.find("P′ = P·M") != std::string::npos;
      EXPECT_TRUE(said);
    }
  }
}

// The transform's misconceptions are in the problem's own convention: under DirectX the
// "composition in the wrong order" matrix is the row form (the transpose of OpenGL's wrong
// order), so a DirectX student who multiplied in the wrong order is recognised.
TEST(ConventionsEveryKind, TransformMisconceptionsInTheProblemsConvention) {
  const std::string given =
      "{steps: [{translate: [1, 2, 3]}, {rotate_z: 90}, {scale: [2, 1, 1]}], points: [[1, 1, 1]]}";
  auto mistakes = [&](Api api) {
    const ProblemSet set =
        load_problem_set_from_string(one("transform", given, api_conventions(api)), "t.yaml");
    const ProblemSpec& spec = set.problems[0];
    std::map<std::string, MatX<Exact>> out;
    for (const Misconception& m : spec.info->misconceptions(spec.given))
      out[m.name.en()] = exact_matrix(*m.answers.find("matrix"));
    return out;
  };
  const auto gl = mistakes(Api::OpenGL), dx = mistakes(Api::DirectX);
  ASSERT_EQ(gl.size(), 2u);
  ASSERT_EQ(dx.size(), 2u);
  for (const auto& [name, m] : gl)
    EXPECT_TRUE(same_matrix(dx.at(name), MatX<Exact>(m.transpose()))) << name;
  // The wrong order under DirectX: translation (1, 2, 3) applied last, in the bottom row.
  const MatX<Exact>& wrong = dx.at("composition in the wrong order");
  EXPECT_TRUE(test::same(wrong(3, 0), 1) && test::same(wrong(3, 1), 2) &&
              test::same(wrong(3, 2), 3))
      << text_of(wrong);
  const ProblemResult key = solve_yaml(one("transform", given, api_conventions(Api::DirectX)));
  EXPECT_FALSE(same_matrix(wrong, exact_matrix(*key.answers.find("matrix"))));
}

// look_at: DirectX's view matrix has its translation in the bottom row; OpenGL's and
// Processing's in the last column.
TEST(ConventionsEveryKind, LookAtTranslationRowOrColumn) {
  const std::string given = "{eye: [1, 2, 5], center: [0, 0, 0], up: [0, 1, 0]}";
  for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
    const ProblemResult r = solve_yaml(one("look_at", given, api_conventions(api)));
    ASSERT_FALSE(r.error) << error_text(r);
    const MatX<Exact> m = exact_matrix(*r.answers.find("matrix"));
    const bool rows = api == Api::DirectX;
    for (int k = 0; k < 3; ++k)
      EXPECT_TRUE(test::same(rows ? m(k, 3) : m(3, k), 0)) << to_string(api) << text_of(m);
    EXPECT_FALSE(test::same(rows ? m(3, 2) : m(2, 3), 0)) << to_string(api);
  }
}

// projection_matrix: Processing's frustum differs from OpenGL's only in −2n/(t−b); DirectX
// prints the row form with w′ = z in row 3, column 4.
TEST(ConventionsEveryKind, ProjectionMatrixProcessingNegatesOnlyTheYScale) {
  const std::string given = "{frustum: {left: -2, right: 3, bottom: -1, top: 4, near: 2, far: 10}}";
  const MatX<Exact> gl = exact_matrix(
      *solve_yaml(one("projection_matrix", given, "{api: opengl}")).answers.find("matrix"));
  const MatX<Exact> pr = exact_matrix(
      *solve_yaml(one("projection_matrix", given, "{api: processing}")).answers.find("matrix"));
  const MatX<Exact> dx = exact_matrix(
      *solve_yaml(one("projection_matrix", given, "{api: directx}")).answers.find("matrix"));
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      EXPECT_TRUE(test::same(pr(i, j), i == 1 && j == 1 ? Exact(-gl(i, j)) : gl(i, j))) << i << j;
  EXPECT_TRUE(test::same(gl(1, 1), Exact(4) / 5));  // 2n/(t − b)
  EXPECT_TRUE(test::same(dx(2, 3), 1));
  EXPECT_TRUE(test::same(dx(3, 2), Exact(-5) / 2));
}

// view_volume (seed 002's S and P): column form, transposed under DirectX.
TEST(ConventionsEveryKind, ViewVolumeMatricesTransposeUnderDirectX) {
  const std::string given = "{d: 1, a: 1, b: 1, z_min: 1, z_max: 100}";
  const ProblemResult gl = solve_yaml(one("view_volume", given, "{api: opengl}"));
  for (const Api api : {Api::Processing, Api::DirectX}) {
    const ProblemResult r = solve_yaml(one("view_volume", given, api_conventions(api)));
    ASSERT_FALSE(r.error) << error_text(r);
    for (const char* name : {"scale_matrix", "perspective_matrix"}) {
      const MatX<Exact> m = exact_matrix(*gl.answers.find(name));
      EXPECT_TRUE(same_matrix(exact_matrix(*r.answers.find(name)),
                              api == Api::DirectX ? MatX<Exact>(m.transpose()) : m))
          << name;
    }
    EXPECT_EQ(exact_text(r, "point"), exact_text(gl, "point"));
  }
}

// clip_line and clip_polygon: the default volume is the API's NDC volume, so z = −1/2 is
// inside under OpenGL and Processing and outside (z < 0) under DirectX.
TEST(ConventionsEveryKind, ClippingDefaultVolumeFollowsTheNdcRange) {
  for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX}) {
    const bool dx = api == Api::DirectX;
    const ProblemResult line =
        solve_yaml(one("clip_line", "{p: [0, 0, -0.5], q: [0.5, 0, 0.5]}", api_conventions(api)));
    ASSERT_FALSE(line.error) << error_text(line);
    EXPECT_EQ(line.answers.find("accept")->flag, !dx) << to_string(api);
    EXPECT_EQ(exact_text(line, "clipped"),
              dx ? "1/4, 0, 0, 1/2, 0, 1/2" : "0, 0, -1/2, 1/2, 0, 1/2")
        << to_string(api);
    bool titled = false;
    for (const Step& st : line.derivation.steps())
      titled = titled ||
               st.title.en() == (dx ? "Clip volume (default: DirectX's NDC volume, z in [0, 1])"
                                    : "Clip volume (default: the NDC cube)");
    EXPECT_TRUE(titled) << to_string(api);
    const ProblemResult poly =
        solve_yaml(one("clip_polygon", "{points: [[0, 0, -0.5], [0.5, 0, 0.5], [0, 0.5, 0.5]]}",
                       api_conventions(api)));
    ASSERT_FALSE(poly.error) << error_text(poly);
    EXPECT_EQ(poly.answers.find("clipped")->rows, dx ? 4 : 3) << to_string(api);
  }
}

}  // namespace
}  // namespace frustum
