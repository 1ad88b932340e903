// Barycentric coordinates of a pixel in a projected triangle, the other way to z-buffer depth
// than the plane method: the three edge functions at the pixel are twice the signed areas of
// the triangles PBC, PCA, PAB, their sum is twice the signed area of ABC, λᵢ is each one's
// share, and z = λ₀z_A + λ₁z_B + λ₂z_C. The triangle is in projection coordinates like
// depth_at_pixel's (x, y on the screen, z the depth): λ uses x and y only.
// A(0,0,6), B(3,0,9), C(0,3,9), pixel (1, 1): E = (3, 3, 3), total 9, λ = (1/3, 1/3, 1/3),
// z = 8 (the plane method's z).
#include <cmath>

#include "solver/derivation/vocabulary.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kTotal{"total", "合計", "сумма"};

constexpr Phrase kNearlyDegenerateTriangle{"Nearly degenerate triangle", "ほぼ退化した三角形",
                                           "Почти вырожденный треугольник"};
constexpr Phrase kTheTotalTwiceTheProjectedArea{
    "the total (twice the projected area), and λ and z with it",
    "合計 (投影した面積の 2 倍) と, それに従う λ と z",
    "сумма (удвоенная площадь проекции), а с ней λ и z"};

constexpr Phrase kEdgeFunctions{"Edge functions at the pixel", "画素での辺関数",
                                "Рёберные функции в пикселе"};
constexpr Phrase kTwiceSignedArea{"Twice the signed area of the triangle",
                                  "三角形の符号付き面積の 2 倍",
                                  "Удвоенная ориентированная площадь треугольника"};
constexpr Phrase kBarycentricCoordinates{"Barycentric coordinates", "重心座標",
                                         "Барицентрические координаты"};
constexpr Phrase kDepthByInterpolation{"Depth by barycentric interpolation",
                                       "重心座標による奥行きの補間",
                                       "Глубина барицентрической интерполяцией"};

struct Barycentric {
  static constexpr const char* kName = "barycentric";
  static constexpr Phrase kSummary{
      "barycentric coordinates of a pixel in a projected triangle, and its interpolated z",
      "投影された三角形での画素の重心座標と, 補間した z 値",
      "барицентрические координаты пикселя в спроецированном треугольнике и интерполированное "
      "значение z"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    std::array<Vec3<Exact>, 3> triangle;
    Vec2<Exact> pixel;
  };
  static std::vector<std::string> given_fields() { return {"triangle", "pixel"}; }
  static std::vector<AnswerSpec> answers() {
    return {
        {.name = "edges", .kind = AnswerKind::Vector, .label = say(words::kEdges)},
        {.name = "total", .kind = AnswerKind::Scalar, .label = say(kTotal)},
        {.name = "lambda",
         .kind = AnswerKind::Vector,
         .depends_on = {"edges", "total"},
         .symbols = {"λ"}},
        {.name = "inside",
         .kind = AnswerKind::Bool,
         .depends_on = {"edges"},
         .words = {"inside", "outside"},
         .label = say(words::kInsideQuestion)},
        {.name = "z", .kind = AnswerKind::Scalar, .depends_on = {"lambda"}, .symbols = {"z_S"}}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const Polygon3<Exact> t = r.points("triangle", 3, 3);
    g.triangle = {t[0], t[1], t[2]};
    g.pixel = r.vector<2>("pixel");
    return g;
  }

  // The formulas, once for the exact solve and every numeric backend. E_BC(P), E_CA(P), E_AB(P):
  // the edge opposite each vertex, so that λᵢ belongs to vertex i; the total E_AB(C) is twice
  // the signed area; λᵢ = Eᵢ / total; z = Σ λᵢ zᵢ.
  template <typename T>
  static Vec3<T> edges_of(const std::array<Vec3<T>, 3>& t, const Vec2<T>& pixel) {
    return {edge_function<T>(t[1], t[2], pixel), edge_function<T>(t[2], t[0], pixel),
            edge_function<T>(t[0], t[1], pixel)};
  }
  template <typename T>
  static T total_of(const std::array<Vec3<T>, 3>& t) {
    return edge_function<T>(t[0], t[1], Vec2<T>(t[2](0), t[2](1)));
  }
  template <typename T>
  static Vec3<T> lambda_of(const Vec3<T>& e, const T& total) {
    return {T(e(0) / total), T(e(1) / total), T(e(2) / total)};
  }
  template <typename T>
  static T z_of(const std::array<Vec3<T>, 3>& t, const Vec3<T>& lambda) {
    return lambda(0) * t[0](2) + lambda(1) * t[1](2) + lambda(2) * t[2](2);
  }
  // Their exact values in canonical form.
  static Vec3<Exact> canonical_vec(const Vec3<Exact>& v) {
    return {canonical(v(0)), canonical(v(1)), canonical(v(2))};
  }
  static Vec3<Exact> edges(const Given& g) { return canonical_vec(edges_of(g.triangle, g.pixel)); }
  static Exact total(const Given& g) { return canonical(total_of(g.triangle)); }
  static Exact interpolated_z(const Given& g, const Vec3<Exact>& lambda) {
    return canonical(z_of(g.triangle, lambda));
  }

  // Error carried forward: λ from the student's edge values and total, z from their λ.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    std::optional<Vec3<Exact>> e;
    if (const auto v = carried(student, "edges", 3)) e = Vec3<Exact>((*v)[0], (*v)[1], (*v)[2]);
    Exact t = total(g);
    if (const Value* s = student.find("total"); s && s->exact.size() == 1) t = s->exact[0];
    std::optional<Vec3<Exact>> lambda;
    if (e && !canonical(t).is_zero()) lambda = canonical_vec(lambda_of(*e, t));
    if (lambda) out.set("lambda", Value::vector(*lambda));
    // Inside the closed triangle: every edge value on the side of the total (or 0).
    if (e) {
      const int side = exact_sign(canonical(t));
      bool inside = side != 0;
      for (int i = 0; i < 3; ++i) inside = inside && exact_sign(canonical((*e)(i))) * side >= 0;
      out.set("inside", Value::boolean(inside));
    }
    if (const auto v = carried(student, "lambda", 3))
      lambda = Vec3<Exact>((*v)[0], (*v)[1], (*v)[2]);
    if (lambda) out.set("z", Value::scalar(interpolated_z(g, *lambda)));
    return out;
  }

  [[noreturn]] static void refuse_flat() {
    throw DomainError("triangle",
                      "the triangle's projection has no area (its x, y are on one line): no "
                      "barycentric coordinates");
  }

  // The numeric path (`solve --precision`, `bench accuracy`): the same formulas in the
  // backend's scalar; the signs of the edge functions (inside, and a flat triangle) by the
  // filtered predicate with its exact fallback, as depth_at_pixel's numeric path decides them.
  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    const DepthCondition cond = depth_condition(to_double(g.triangle[0]), to_double(g.triangle[1]),
                                                to_double(g.triangle[2]), to_double(g.pixel));
    return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
      struct In {
        std::array<Vec3<T>, 3> t;
        Vec2<T> pixel;
        Given exact;
        InputRange range;
      };
      struct Out {
        Vec3<T> edges, lambda;
        T total{}, z{};
        bool inside = false, inside_exact = false;
      };
      auto core = [](const In& in) {
        Out o;
        const auto& t = in.t;
        const auto& et = in.exact.triangle;
        const bool relative = in.range.relative();
        if (edge_on_sign(t, et, relative).sign == 0) refuse_flat();
        o.total = total_of(t);
        o.edges = edges_of(t, in.pixel);
        o.lambda = lambda_of(o.edges, o.total);
        o.z = z_of(t, o.lambda);
        const PixelSides sides = pixel_sides(t, in.pixel, et, in.exact.pixel, relative);
        o.inside = sides.inside;
        o.inside_exact = sides.exact;
        return o;
      };
      auto report = [p, cond](const In& in, const Out& o) {
        NumericOut<T> out(p);
        out.inputs(in.range);
        out.vector("edges", o.edges);
        out.scalar("total", o.total);
        out.vector("lambda", o.lambda);
        out.boolean("inside", o.inside);
        out.scalar("z", o.z);
        if (o.inside_exact) out.exact_decision(Said(words::kInside));
        // A thin triangle's total (twice its projected area) cancels, and λ and z with it.
        warn_condition(out, p, std::max(cond.kappa_c, cond.kappa_z), say(kNearlyDegenerateTriangle),
                       say(kTheTotalTwiceTheProjectedArea));
        return out.take();
      };
      In in{{}, {}, g, {}};
      for (int k = 0; k < 3; ++k) in.t[k] = conv<T>(g.triangle[k], &in.range);
      in.pixel = conv<T>(g.pixel, &in.range);
      return prepare(std::move(in), core, report);
    });
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const Vec3<Exact> e = edges(g);
    const Exact t = total(g);
    Answers out;
    out.set("edges", Value::vector(e));
    if (steps)
      steps
          ->add(say(kEdgeFunctions),
                tex("E_{BC}(x_S, y_S),\\; E_{CA}(x_S, y_S),\\; E_{AB}(x_S, y_S);\\quad "
                    "E_{PQ}(x, y) = (x_Q - x_P)(y - y_P) - (y_Q - y_P)(x - x_P)"),
                {}, vec(e))
          .yields("edges");
    out.set("total", Value::scalar(t));
    if (steps)
      steps
          ->add(say(kTwiceSignedArea), tex("E_{AB}(x_C, y_C) = E_{BC} + E_{CA} + E_{AB}"), {},
                exact(t))
          .yields("total");
    if (t.is_zero()) refuse_flat();
    const Vec3<Exact> lambda = canonical_vec(lambda_of(e, t));
    out.set("lambda", Value::vector(lambda));
    if (steps)
      steps
          ->add(say(kBarycentricCoordinates),
                tex("\\lambda_0 = \\frac{E_{BC}}{E_{AB}(C)},\\; \\lambda_1 = "
                    "\\frac{E_{CA}}{E_{AB}(C)},\\; \\lambda_2 = \\frac{E_{AB}}{E_{AB}(C)}"),
                {}, vec(lambda, true))
          .yields("lambda");
    // Inside the closed triangle, decided (and written) as depth_at_pixel decides it.
    const bool inside =
        inside_triangle_with_steps(g.triangle, g.pixel, steps, ZFrom::Interpolation);
    out.set("inside", Value::boolean(inside));
    const Exact z = interpolated_z(g, lambda);
    out.set("z", Value::scalar(z));
    if (steps)
      steps
          ->add(say(kDepthByInterpolation),
                tex("z_S = \\lambda_0\\,z_A + \\lambda_1\\,z_B + "
                    "\\lambda_2\\,z_C"),
                {}, tex("z_S = ") + exact(z, true))
          .yields("z");
    return out;
  }

  // Default generator: depth_at_pixel's, the same exercise (a triangle with x, y in [0, 8] and
  // z in [1, 12] and a lattice pixel strictly inside it; hard: on an edge).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    return builtin_kinds().find("depth_at_pixel")->generate(rng, o);
  }

  static std::string ill_conditioned(const Given& g) {
    std::vector<std::vector<double>> xy;
    for (const Vec3<Exact>& v : g.triangle) xy.push_back({to_double(v(0)), to_double(v(1))});
    if (triangle_shape(xy) < kMinTriangleShape) return "the triangle is nearly edge-on";
    return "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given): a well-shaped triangle with two-decimal
// vertices and a lattice pixel well inside it (every λᵢ ≥ 0.05), so that λ and z are well
// conditioned.
std::optional<std::string> accuracy_given(Rng& rng) {
  const accuracy::TriangleAndPixel d = accuracy::triangle_and_pixel(rng);
  std::vector<Eigen::Vector2d> v;
  for (const accuracy::Point3& q : d.triangle) v.push_back(q.d().head<2>());
  if (triangle_shape({{v[0].x(), v[0].y()}, {v[1].x(), v[1].y()}, {v[2].x(), v[2].y()}}) <
      kMinTriangleShape)
    return std::nullopt;
  const std::array<Vec3<double>, 3> t = {d.triangle[0].d(), d.triangle[1].d(), d.triangle[2].d()};
  const Vec3<double> lambda =
      Barycentric::lambda_of(Barycentric::edges_of(t, d.pixel), Barycentric::total_of(t));
  if (lambda.minCoeff() < 0.05) return std::nullopt;
  return d.yaml();
}

}  // namespace

KindInfo barycentric_kind() {
  KindInfo k = make_kind<Barycentric>();
  k.order = 45;
  k.doc_given = "`triangle` (projection coordinates; λ from x, y), `pixel` [xs, ys]";
  k.doc_answers =
      "`edges` (E_BC, E_CA, E_AB at the pixel), `total` (E_AB(C), twice the signed area), "
      "`lambda` (λ₀, λ₁, λ₂), `inside`, `z` (Σλᵢzᵢ, the plane method's z)";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
