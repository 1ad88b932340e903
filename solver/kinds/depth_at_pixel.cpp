// seed 001: the z value of a pixel by the plane method. The triangle is in projection
// coordinates, which are left-handed (seed 001's warning), so its front normal is AC × AB:
// A(0,0,6), B(3,0,9), C(0,3,9) → n = (9, 9, −9), n̂ = (1/√3, 1/√3, −1/√3), x + y − z = −6,
// and the pixel (1, 1) has z = 8.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "solver/core/exact_vector.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/geometry/plane_depth.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/digits_said.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

constexpr Phrase kZAtThisPixel{"z at this pixel", "この画素の z", "z в этом пикселе"};

constexpr Phrase kByBarycentric{"z by barycentric interpolation (stable fallback).",
                                "z は重心座標による補間で求めた (安定な代替法).",
                                "z найдено барицентрической интерполяцией (устойчивая замена)."};
constexpr Phrase kByPlaneMethod{"z = (d − a·xₛ − b·yₛ)/c (the plane method).",
                                "z = (d − a·xₛ − b·yₛ)/c (平面の方程式による方法).",
                                "z = (d − a·xₛ − b·yₛ)/c (метод плоскости)."};
constexpr Phrase kBarycentricFallback{"Nearly edge-on triangle: barycentric fallback",
                                      "ほぼ真横から見た三角形: 重心座標による代替",
                                      "Треугольник почти с ребра: барицентрическая замена"};
constexpr Phrase kFallbackNote{
    "c ≈ 0 (κ_c ≈ {0}); the plane method would keep {1} digits of z, so z = Σ λᵢ zᵢ with λᵢ from "
    "the edge functions at the pixel is used: for a pixel inside the triangle it stays within the "
    "vertices' depths.",
    "c ≈ 0 (κ_c ≈ {0}). 平面の方程式では z が {1} 桁しか残らないので, 画素での辺関数から求めた λᵢ "
    "による z = Σ λᵢ zᵢ を使う. 三角形の内側の画素ではこの値は頂点の奥行きの範囲内にある.",
    "c ≈ 0 (κ_c ≈ {0}); метод плоскости сохранил бы {1} цифр z, поэтому используется z = Σ λᵢ zᵢ с "
    "λᵢ из рёберных функций в пикселе: для пикселя внутри треугольника оно остаётся в пределах "
    "глубин вершин."};
constexpr Phrase kProjectionLeftHanded{"Projection coordinates are left-handed",
                                       "投影座標系は左手系", "Координаты проекции — левая система"};
constexpr Phrase kMindOrderUses{
    "Mind the order of the cross product; this problem uses {0}.",
    "外積の順序に注意. この問題では {0} を使う.",
    "Следите за порядком векторного произведения; в этой задаче используется {0}."};
constexpr Phrase kMindOrderCourse{
    "Mind the order of the cross product: projection coordinates (x, y on the screen, z the depth "
    "away from the eye) are left-handed, as this course's eye space is, so the front normal of a "
    "triangle ABC is AC × AB (the order used by default).",
    "外積の順序に注意: 投影座標系 (画面上の x, y と視点から奥へ向かう奥行き z) "
    "はこのコースの視点座標系と同じく左手系なので, 三角形 ABC の表の法線は AC × AB (既定の順序) "
    "である.",
    "Следите за порядком векторного произведения: координаты проекции (x, y на экране, z — глубина "
    "от глаза) образуют левую систему, как и система координат вида в этом курсе, поэтому лицевая "
    "нормаль треугольника ABC — AC × AB (порядок по умолчанию)."};
constexpr Phrase kMindOrderLeftFrame{
    "Mind the order of the cross product: in a left-handed frame the front normal of a triangle "
    "ABC is AC × AB (the order used by default).",
    "外積の順序に注意: 左手系では三角形 ABC の表向きの法線は AC × AB (既定の順序).",
    "Следите за порядком векторного произведения: в левой системе лицевая нормаль треугольника ABC "
    "— AC × AB (порядок по умолчанию)."};
constexpr Phrase kPlaneThroughA{"Plane through A with normal n̂", "A を通り法線 n̂ の平面",
                                "Плоскость через A с нормалью n̂"};
constexpr Phrase kDepthAtPixel{"Depth at the pixel", "画素での奥行き (z 値)", "Глубина в пикселе"};
constexpr Phrase kNearlyEdgeOn{"Nearly edge-on triangle", "ほぼ真横から見た三角形",
                               "Треугольник почти с ребра"};
constexpr Phrase kCIsSmall{
    "c is small beside the terms it is computed from (κ_c ≈ {0}), so z = (d − a·xₛ − b·yₛ)/c is "
    "ill-conditioned ({1}).",
    "c はそれを計算する項に比べて小さい (κ_c ≈ {0}) ので, z = (d − a·xₛ − b·yₛ)/c は条件が悪い "
    "({1}).",
    "c мало по сравнению со слагаемыми, из которых вычисляется (κ_c ≈ {0}), поэтому z = (d − a·xₛ "
    "− b·yₛ)/c плохо обусловлено ({1})."};
constexpr Phrase kComputedInFloatingPoint{
    "Computed in floating point with fewer than half its digits left, z is better found by "
    "barycentric interpolation z = Σ λᵢ zᵢ.",
    "浮動小数点で計算すると桁が半分も残らないので, z は重心座標による補間 z = Σ λᵢ zᵢ "
    "で求める方がよい.",
    "При вычислении в плавающей точке остаётся меньше половины цифр, поэтому z лучше найти "
    "барицентрической интерполяцией z = Σ λᵢ zᵢ."};
constexpr Phrase kFrontNormalHereIs{
    "The projection coordinates are left-handed, so the front normal here is {0}.",
    "投影座標系は左手系なので, ここでの表向きの法線は {0} です.",
    "Координаты проекции — левая система, поэтому лицевая нормаль здесь {0}."};
constexpr Phrase kUnnormalisedNormal{"unnormalised normal", "法線を正規化していない",
                                     "ненормированная нормаль"};
constexpr Phrase kThatIsNItself{
    "That is n itself: a unit normal is n divided by its length ‖n‖.",
    "それは n そのものです. 単位法線は n をその長さ ‖n‖ で割ったものです.",
    "Это сама n: единичная нормаль — это n, делённая на свою длину ‖n‖."};
constexpr Phrase kPlaneThroughTheOrigin{"plane through the origin", "原点を通る平面",
                                        "плоскость через начало координат"};
constexpr Phrase kPlanePassesThroughOrigin{
    "Your plane passes through the origin: n·(p − A) = 0 gives d = n·A, not 0.",
    "あなたの平面は原点を通っています. n·(p − A) = 0 から d = n·A であり, 0 ではありません.",
    "Ваша плоскость проходит через начало координат: из n·(p − A) = 0 следует d = n·A, а не 0."};

// The decisions (edge-on, the pixel's edge signs) are geometry's edge_on_sign and pixel_sides,
// shared by the exact solve, the numeric path and the barycentric kind.

// The plane on which the exact solve evaluates plane_method_z: n̂·p = d itself or, when the
// normal n, the point A and the pixel are rational, the same plane scaled by ‖n‖ (n·p = n·A).
// z = (d − a·xₛ − b·yₛ)/c does not change with the plane's scale, so z is the same rational,
// found by dividing rationals instead of clearing the square roots of n̂ and d.
PlaneDepth<Exact> rational_plane(const PlaneDepth<Exact>& unit, const Vec3<Exact>& n,
                                 const Vec3<Exact>& a, const Vec2<Exact>& pixel) {
  for (int i = 0; i < 3; ++i)
    if (!is_rational(n(i)) || !is_rational(a(i)) || (i < 2 && !is_rational(pixel(i)))) return unit;
  PlaneDepth<Exact> scaled = unit;
  scaled.unit_normal = n;
  scaled.d = n.dot(a);
  return scaled;
}

std::unique_ptr<NumericSolver> depth_at_pixel_numeric(const std::array<Vec3<Exact>, 3>& triangle,
                                                      const Vec2<Exact>& pixel,
                                                      const CrossOrder& order, Precision p) {
  const DepthCondition cond = depth_condition(to_double(triangle[0]), to_double(triangle[1]),
                                              to_double(triangle[2]), to_double(pixel));
  // Fall back to the barycentric form when the plane method would keep fewer than half of the
  // backend's digits (the exact backend never needs to).
  const bool fallback =
      p != Precision::Exact && trusted_digits(cond.kappa_z, p) < decimal_digits(p) / 2;
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      std::array<Vec3<T>, 3> t;
      Vec2<T> pixel;
      std::array<int, 4> order;
      bool barycentric;
      std::array<Vec3<Exact>, 3> exact_t;  // for the exact fallback of `inside` and of c = 0
      Vec2<Exact> exact_pixel;
      InputRange range;
      CrossOrder cross;
    };
    struct Out {
      PlaneDepth<T> depth;
      bool inside = false;
      bool inside_exact = false;  // the exact fallback decided some edge sign
    };
    auto core = [](const In& in) {
      Out o;
      // Edge-on (c = 0) is a discrete answer too: c = ±E(A, B, C) over x and y, decided like the
      // edge signs; such a triangle is refused, as the exact solve refuses it (the same words).
      const SignDecision c = edge_on_sign(in.t, in.exact_t, in.range.relative());
      if (c.sign == 0) {
        cross_normal_with_steps(in.exact_t, in.cross, "triangle",
                                nullptr);  // refuses a collinear one
        refuse_edge_on_triangle("triangle");
      }
      const Vec3<T> first = in.t[in.order[1]] - in.t[in.order[0]];
      const Vec3<T> second = in.t[in.order[3]] - in.t[in.order[2]];
      o.depth = plane_depth(in.t, first, second, in.pixel, in.barycentric);
      const PixelSides sides =
          pixel_sides(in.t, in.pixel, in.exact_t, in.exact_pixel, in.range.relative());
      o.inside = sides.inside;
      o.inside_exact = sides.exact;
      return o;
    };
    auto report = [p, cond](const In& in, const Out& o) {
      const PlaneDepth<T>& r = o.depth;
      NumericOut<T> out(p);
      out.inputs(in.range);
      out.vector("normal", r.normal);
      out.vector("unit_normal", r.unit_normal);
      out.vector("plane",
                 std::vector<T>{r.unit_normal(0), r.unit_normal(1), r.unit_normal(2), r.d});
      out.scalar("z", r.z);
      out.boolean("inside", o.inside);
      out.note(say(r.barycentric ? kByBarycentric : kByPlaneMethod));
      if (o.inside_exact) out.exact_decision(Said(words::kInside));
      if (r.barycentric)
        out.warn(say(kBarycentricFallback),
                 say(kFallbackNote, fmt::format("{:.1e}", cond.kappa_c),
                     fmt::format("{:.1f}", trusted_digits(cond.kappa_z, p))));
      else
        warn_condition(out, p, cond.kappa_z, say(kNearlyEdgeOn), say(kZAtThisPixel));
      return out.take();
    };
    const std::array<int, 4> o = cross_indices(order);
    In in{{}, {}, o, fallback, triangle, pixel, {}, order};
    for (int k = 0; k < 3; ++k) in.t[k] = conv<T>(triangle[k], &in.range);
    in.pixel = conv<T>(pixel, &in.range);
    return prepare(std::move(in), core, report);
  });
}

struct DepthAtPixel {
  static constexpr const char* kName = "depth_at_pixel";
  static constexpr Phrase kSummary{
      "z of a pixel inside a projected triangle by the plane method",
      "平面の方程式による, 投影された三角形の内部の画素の z 値",
      "значение z пикселя внутри спроецированного треугольника методом уравнения плоскости"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    std::array<Vec3<Exact>, 3> triangle;
    Vec2<Exact> pixel;
    CrossOrder order;
    bool order_given = false;
    bool course_left_handed = false;  // the course's eye space (conventions: handedness)
  };
  static std::vector<std::string> given_fields() { return {"triangle", "pixel", "cross"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "normal", .kind = AnswerKind::Direction, .symbols = {"n"}},
            {.name = "unit_normal",
             .kind = AnswerKind::UnitVector,
             .depends_on = {"normal"},
             .symbols = {"n̂"}},
            {.name = "plane",
             .kind = AnswerKind::Plane,
             .depends_on = {"unit_normal"},
             .label = say(words::kPlane)},
            {.name = "z", .kind = AnswerKind::Scalar, .depends_on = {"plane"}, .symbols = {"z_S"}},
            {.name = "inside",
             .kind = AnswerKind::Bool,
             .words = {"inside", "outside"},
             .label = say(words::kInsideQuestion)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.course_left_handed = handedness_of(c) == Handedness::Left;
    const Polygon3<Exact> t = r.points("triangle", 3, 3);
    g.triangle = {t[0], t[1], t[2]};
    g.pixel = r.vector<2>("pixel");
    g.order_given = r.has("cross");
    g.order = read_cross(r, "cross", CrossOrder{"AC", "AB"});
    return g;
  }

  // (x − a, y − b, z − c) with zero offsets left out, as on paper: (x, y, z − 6).
  static MathText offset_point(const Vec3<Exact>& a) {
    MathText m = tex("\\left(");
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      m += (i ? math(", ") : MathText{}) + linear_expression({{1, names[i]}, {-a(i), ""}});
    return m + tex("\\right)");
  }

  // z at the pixel on a plane [a, b, c, d] (nullopt when the plane is edge-on).
  static std::optional<Exact> z_on(const Given& g, const std::vector<Exact>& plane) {
    if (canonical(plane[2]).is_zero()) return std::nullopt;
    return canonical((plane[3] - plane[0] * g.pixel(0) - plane[1] * g.pixel(1)) / plane[2]);
  }

  // Error carried forward: normal → unit normal → plane → z, from the student's own values.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    std::optional<Vec3<Exact>> n;
    if (const auto v = carried(student, "normal", 3)) n = Vec3<Exact>((*v)[0], (*v)[1], (*v)[2]);
    if (n) out.set("unit_normal", Value::vector(unit(*n)));
    if (const auto v = carried(student, "unit_normal", 3))
      n = Vec3<Exact>((*v)[0], (*v)[1], (*v)[2]);
    std::optional<std::vector<Exact>> plane;
    if (n) {
      const std::array<Exact, 4> p = carried_plane(
          *n, {g.triangle[0], g.triangle[1], g.triangle[2]}, carried(student, "plane", 4));
      out.set("plane", plane_answer(p));
      plane = std::vector<Exact>(p.begin(), p.end());
    }
    if (const auto v = carried(student, "plane", 4)) plane = v;
    if (plane)
      if (const auto z = z_on(g, *plane)) out.set("z", Value::scalar(*z));
    return out;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    std::vector<Misconception> out;
    const Vec3<Exact> n =
        named_edge(g.order.first, g.triangle).cross(named_edge(g.order.second, g.triangle));
    Answers reversed;
    reversed.set("normal", Value::vector(Vec3<Exact>(-n)));
    reversed.set("unit_normal", Value::vector(unit(Vec3<Exact>(-n))));
    out.push_back({say(kind_words::kReversedCrossProduct),
                   say(kind_words::kYouTook, g.order.second + " × " + g.order.first) +
                       say(kFrontNormalHereIs, g.order.first + " × " + g.order.second),
                   say(kind_words::kNormalTitle), reversed});
    Answers unnormalized;
    unnormalized.set("unit_normal", Value::vector(n));
    out.push_back({say(kUnnormalisedNormal), say(kThatIsNItself), say(kind_words::kUnitNormalTitle),
                   unnormalized});
    const Vec3<Exact> u = unit(n);
    Answers origin;
    const std::array<Exact, 4> p0 = paper_plane(u, 0);
    origin.set("plane", plane_answer(p0));
    if (const auto z = z_on(g, std::vector<Exact>(p0.begin(), p0.end())))
      origin.set("z", Value::scalar(*z));
    out.push_back(
        {say(kPlaneThroughTheOrigin), say(kPlanePassesThroughOrigin), say(kPlaneThroughA), origin});
    if (auto m =
            constant_sign_mistake(u, canonical_dot(u, g.triangle[0]), "A", say(kPlaneThroughA))) {
      const Value* plane = m->answers.find("plane");
      if (const auto z = z_on(g, plane->exact)) m->answers.set("z", Value::scalar(*z));
      out.push_back(std::move(*m));
    }
    return out;
  }

  // Grading scales (docs/grading.md §2): z = (d − a·x − b·y)/c has terms of size
  // max(|d|, |a·x|, |b·y|)/|c| on the key's plane.
  static AnswerScales scales(const Given& g, const Answers& key) {
    const Value* plane = key.find("plane");
    if (!plane || plane->numbers.size() != 4 || plane->numbers[2] == 0) return {};
    const std::vector<double>& p = plane->numbers;
    const double x = to_double(g.pixel(0)), y = to_double(g.pixel(1));
    const double terms = std::max({std::abs(p[3]), std::abs(p[0] * x), std::abs(p[1] * y)});
    return {{"z", uniform_scale(1, terms / std::abs(p[2]))}};
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return depth_at_pixel_numeric(g.triangle, g.pixel, g.order, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    if (steps)
      steps->note(say(kProjectionLeftHanded),
                  g.order_given ? say(kMindOrderUses, g.order.first + " × " + g.order.second)
                  : g.course_left_handed ? say(kMindOrderCourse)
                                         : say(kMindOrderLeftFrame));
    const Vec3<Exact> n = cross_normal_with_steps(g.triangle, g.order, "triangle", steps);
    if (steps) steps->yields("normal");
    Answers out;
    out.set("normal", Value::vector(n));
    // The plane method's values (plane_depth.hpp's n̂ = n/‖n‖, d = n̂·A and plane_method_z, the
    // template the numeric path uses); the steps show them.
    const Vec3<Exact>& A = g.triangle[0];
    PlaneDepth<Exact> r;
    r.normal = n;
    r.unit_normal = unit(n);  // plane_through's n/‖n‖, in canonical form
    r.d = canonical_dot(r.unit_normal, A);
    const Vec3<Exact>& u = r.unit_normal;
    record_unit_normal(n, u, steps);
    out.set("unit_normal", Value::vector(u));
    // Plane through A: n̂·(p − A) = 0, then cleared of its common factor.
    const std::array<Exact, 4> plane = paper_plane(u, r.d);
    const Value pv = plane_answer(plane);
    out.set("plane", pv);
    if (steps)
      steps
          ->add(say(kPlaneThroughA),
                tex("\\hat{\\mathbf{n}}\\cdot(\\mathbf{p} - \\overrightarrow{OA}) = 0"),
                vec(u) + tex("\\cdot") + offset_point(A) + math(" = 0"), pv.display)
          .yields("plane");
    const Exact& a = plane[0];
    const Exact& b = plane[1];
    const Exact& c = plane[2];
    if (edge_on_sign(g.triangle, g.triangle, true).sign == 0) refuse_edge_on_triangle("triangle");
    const Exact z = canonical(plane_method_z(rational_plane(r, n, A, g.pixel), g.pixel));
    out.set("z", Value::scalar(z));
    if (steps) {
      steps
          ->add(say(kDepthAtPixel), tex("z_S = \\frac{d - a\\,x_S - b\\,y_S}{c}"),
                linear_equation({{a * g.pixel(0), ""}, {b * g.pixel(1), ""}, {c, "z"}}, plane[3]),
                tex("z_S = ") + exact(z, true))
          .yields("z");
      const DepthCondition cond =
          depth_condition(to_double(g.triangle[0]), to_double(g.triangle[1]),
                          to_double(g.triangle[2]), to_double(g.pixel));
      if (cond.kappa_z > kIllConditioned)
        steps->warn(say(kNearlyEdgeOn),
                    say(kCIsSmall, format_approx(cond.kappa_c), digits_said(cond.kappa_z)) +
                        say(kComputedInFloatingPoint));
    }
    const bool inside = inside_triangle_with_steps(g.triangle, g.pixel, steps);
    out.set("inside", Value::boolean(inside));
    return out;
  }
  // Default generator: a triangle with x, y in [0, 8] and z in [1, 12] and a lattice pixel
  // strictly inside it (hard: on an edge); nice: an integer z, (n·A − nₓxₛ − n_y yₛ)/n_z.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node g;
    for (int attempt = 0; attempt < 2000; ++attempt) {
      std::array<IVec3, 3> t{};
      for (IVec3& v : t) v = {rng.integer(0, 8), rng.integer(0, 8), rng.integer(1, 12)};
      std::vector<std::vector<double>> xy;
      for (const IVec3& v : t) xy.push_back({double(v[0]), double(v[1])});
      const double shape = triangle_shape(xy);
      if (shape == 0 || (!o.hard && shape < kMinTriangleShape)) continue;
      auto orient = [](const IVec3& a, const IVec3& b, std::int64_t x, std::int64_t y) {
        const std::int64_t v = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
        return v > 0 ? 1 : v < 0 ? -1 : 0;
      };
      std::vector<std::pair<std::int64_t, std::int64_t>> pixels;
      // Only the bounding box can hold inside or edge pixels (same list, same order as the grid).
      const auto [x_lo, x_hi] = std::minmax({t[0][0], t[1][0], t[2][0]});
      const auto [y_lo, y_hi] = std::minmax({t[0][1], t[1][1], t[2][1]});
      for (std::int64_t x = x_lo; x <= x_hi; ++x)
        for (std::int64_t y = y_lo; y <= y_hi; ++y) {
          const int s0 = orient(t[0], t[1], x, y), s1 = orient(t[1], t[2], x, y),
                    s2 = orient(t[2], t[0], x, y);
          const bool strict = (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
          const bool edge =
              !strict && (s0 * s1 >= 0 && s1 * s2 >= 0 && s0 * s2 >= 0) && (s0 || s1 || s2);
          if (o.hard ? edge : strict) pixels.emplace_back(x, y);
        }
      if (pixels.empty()) continue;
      const auto [px, py] = rng.pick(pixels);
      const IVec3 n = icross(isub(t[2], t[0]), isub(t[1], t[0]));  // seed 001: AC × AB
      if (o.nice && (idot(n, t[0]) - n[0] * px - n[1] * py) % n[2] != 0) continue;
      g["triangle"] = gen_points({t[0], t[1], t[2]});
      g["pixel"] = gen_list({px, py});
      return g;
    }
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    std::vector<std::vector<double>> xy;
    for (const Vec3<Exact>& v : g.triangle) xy.push_back({to_double(v(0)), to_double(v(1))});
    if (triangle_shape(xy) < kMinTriangleShape) return "the triangle is nearly edge-on";
    for (const int s : pixel_sides(g.triangle, g.pixel, g.triangle, g.pixel, true).sign)
      if (s == 0) return "the pixel is on an edge";
    return "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  const accuracy::TriangleAndPixel d = accuracy::triangle_and_pixel(rng);
  const auto& t = d.triangle;
  if (depth_condition(t[0].d(), t[1].d(), t[2].d(), d.pixel).kappa_z < accuracy::kWellConditioned)
    return d.yaml();
  return std::nullopt;
}

}  // namespace

KindInfo depth_at_pixel_kind() {
  KindInfo k = make_kind<DepthAtPixel>();
  k.order = 40;
  k.doc_given =
      "`triangle` (projection coordinates), `pixel` [xs, ys], optional `cross` (default `[AC, "
      "AB]`, seed 001)";
  k.doc_answers = "`normal`, `unit_normal`, `plane`, `z`, `inside`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
