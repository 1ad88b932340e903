// The plane through three or more points, or through a point with a normal (seed 001:
// n·(r − r₀) = 0 → ax + by + cz = d; the distance from the origin is |d| / ‖n‖).
#include "solver/core/exact_vector.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kIllConditionedPlane{"Ill-conditioned plane", "条件の悪い平面",
                                      "Плохо обусловленная плоскость"};
constexpr Phrase kThePlaneSNormal{"the plane's normal", "平面の法線", "нормаль плоскости"};

constexpr Phrase kPlaneNote{"plane = (n, n·p₀), not rescaled; distance = |n̂·p₀|.",
                            "平面 = (n, n·p₀) (係数は約さない), 距離 = |n̂·p₀|.",
                            "плоскость = (n, n·p₀) без масштабирования; расстояние = |n̂·p₀|."};
constexpr Phrase kPlaneThroughP0{"Plane through p₀ with normal n", "p₀ を通り法線 n の平面",
                                 "Плоскость через p₀ с нормалью n"};
constexpr Phrase kDistanceFromOrigin{"Distance from the origin", "原点からの距離",
                                     "Расстояние от начала координат"};

std::unique_ptr<NumericSolver> plane_numeric(const Polygon3<Exact>& points,
                                             const Vec3<Exact>& point, const Vec3<Exact>& normal,
                                             Precision p) {
  const double kappa = points.empty() ? 1.0 : normal_condition(double_points(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      Vec3<T> point, normal;
      InputRange range;
      Polygon3<Exact> exact_points;  // for the exact zero test and the refusal
    };
    struct Out {
      NormalPair<T> n;
      T d{}, distance{};
    };
    auto core = [](const In& in) {
      Out o;
      if (in.points.empty()) {
        o.n.n = in.normal;
        o.n.unit = in.normal / stable_norm(in.normal);
        o.d = in.normal.dot(in.point);
        o.distance = scalar_abs(T(o.n.unit.dot(in.point)));
        return o;
      }
      o.n = polygon_normal(in.points, in.exact_points, in.range.relative());
      // A degenerate polygon is refused, as the exact solve refuses it (the same words).
      if (o.n.zero) polygon_normal_with_steps(in.exact_points, "points", nullptr);
      o.d = o.n.n.dot(in.points[0]);
      // dist = |n̂·p₀|, the same as |d|/‖n‖ without squaring ‖n‖.
      if (!o.n.zero) o.distance = scalar_abs(T(o.n.unit.dot(in.points[0])));
      return o;
    };
    auto report = [p, kappa](const In& in, const Out& o) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      report_normal(out, o.n);
      out.vector("plane", std::vector<T>{o.n.n(0), o.n.n(1), o.n.n(2), o.d});
      if (o.n.zero)
        out.null("distance");
      else
        out.scalar("distance", o.distance);
      if (!o.n.exact_value)
        warn_condition(out, p, kappa, say(kIllConditionedPlane), say(kThePlaneSNormal));
      out.note(say(kPlaneNote));
      return out.take();
    };
    In in;
    in.exact_points = points;
    in.points = conv<T>(points, &in.range);
    in.point = conv<T>(point, &in.range);
    in.normal = conv<T>(normal, &in.range);
    return prepare(std::move(in), core, report);
  });
}

struct Plane {
  static constexpr const char* kName = "plane";
  static constexpr Phrase kSummary{"the plane through points, or through a point with a normal",
                                   "点を通る平面, または 1 点と法線ベクトルで決まる平面",
                                   "плоскость через точки или через точку с заданной нормалью"};
  static constexpr ConventionUse kUses{.api = false, .angles = false, .handedness = true};
  struct Given {
    Polygon3<Exact> points;  // empty when point + normal
    Vec3<Exact> point;
    Vec3<Exact> normal;
    bool left_handed = false;  // the course's coordinates: the front normal is e₁ × e₀
  };
  static std::vector<std::string> given_fields() { return {"points", "point", "normal"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "normal", .kind = AnswerKind::Direction, .symbols = {"n"}},
            {.name = "unit_normal",
             .kind = AnswerKind::UnitVector,
             .depends_on = {"normal"},
             .symbols = {"n̂"}},
            {.name = "plane",
             .kind = AnswerKind::Plane,
             .depends_on = {"normal"},
             .label = say(words::kPlane)},
            {.name = "distance",
             .kind = AnswerKind::Scalar,
             .depends_on = {"plane"},
             .symbols = {"dist"}}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.left_handed = left_handed_columns(c);  // DirectX: clockwise = front, e₀ × e₁ as it is
    if (r.has("points")) {
      if (r.has("point") || r.has("normal"))
        r.fail("points", "give either points or point + normal, not both");
      g.points = r.points("points", 3);
      return g;
    }
    if (!r.has("point") && !r.has("normal"))
      r.fail("points", "missing required field: give points, or point and normal");
    g.point = r.vector<3>("point");
    g.normal = r.vector<3>("normal");
    if (canonical(g.normal.dot(g.normal)).is_zero())
      r.fail("normal", "the zero vector is not a normal");
    return g;
  }

  // Error carried forward: the plane and distance from the student's own normal.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const Vec3<Exact> p0 = g.points.empty() ? g.point : g.points[0];
    std::optional<std::vector<Exact>> plane;
    if (const auto n = carried(student, "normal", 3)) {
      const Vec3<Exact> v((*n)[0], (*n)[1], (*n)[2]);
      out.set("unit_normal", Value::vector(unit(v)));
      const std::array<Exact, 4> p =
          carried_plane(v, g.points.empty() ? std::vector<Vec3<Exact>>{p0} : g.points,
                        carried(student, "plane", 4));
      out.set("plane", Value::vector(std::vector<Exact>(p.begin(), p.end())));
      plane = std::vector<Exact>(p.begin(), p.end());
    }
    if (const auto p = carried(student, "plane", 4)) plane = p;
    if (plane) {
      const Exact len = canonical(norm(Vec3<Exact>((*plane)[0], (*plane)[1], (*plane)[2])));
      if (!len.is_zero())
        out.set("distance",
                Value::scalar(canonical(
                    (exact_sign((*plane)[3]) < 0 ? Exact(-(*plane)[3]) : (*plane)[3]) / len)));
    }
    return out;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    const Vec3<Exact> p0 = g.points.empty() ? g.point : g.points[0];
    const Vec3<Exact> n =
        g.points.empty() ? g.normal
                         : polygon_normal_with_steps(g.points, "points", nullptr, g.left_handed);
    std::vector<Misconception> out;
    if (auto m = constant_sign_mistake(n, canonical_dot(n, p0), "p₀", say(kPlaneThroughP0)))
      out.push_back(std::move(*m));
    // The normal's side, when the problem has it computed by a cross product (not given).
    if (!g.points.empty())
      if (auto m = reversed_normal_mistake(n, g.points.size(), g.left_handed, std::nullopt))
        out.push_back(std::move(*m));
    return out;
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return plane_numeric(g.left_handed ? reversed_winding(g.points) : g.points, g.point, g.normal,
                         p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    Vec3<Exact> n = g.normal;
    Vec3<Exact> p0 = g.point;
    if (!g.points.empty()) {
      n = polygon_normal_with_steps(g.points, "points", steps, g.left_handed);
      p0 = g.points[0];
    }
    if (steps) steps->yields("normal");
    Answers out;
    out.set("normal", Value::vector(n));
    out.set("unit_normal", Value::vector(unit_normal_with_steps(n, steps)));
    const Exact len = canonical(norm(n));
    const Exact d = canonical_dot(n, p0);
    const Value pv = plane_answer(paper_plane(n, d));
    out.set("plane", pv);
    if (steps)
      steps
          ->add(say(kPlaneThroughP0),
                tex("\\mathbf{n}\\cdot(\\mathbf{p} - \\mathbf{p}_0) = 0 \\iff "
                    "\\mathbf{n}\\cdot\\mathbf{p} = \\mathbf{n}\\cdot\\mathbf{p}_0"),
                plane_equation(n(0), n(1), n(2), d), pv.display)
          .yields("plane");
    const Exact dist = canonical((exact_sign(d) < 0 ? Exact(-d) : d) / len);
    out.set("distance", Value::scalar(dist));
    if (steps)
      steps
          ->add(say(kDistanceFromOrigin),
                tex("\\text{dist} = \\frac{|d|}{\\lVert\\mathbf{n}\\rVert}"),
                tex("\\text{dist} = ") +
                    frac(tex("\\lvert ") + exact(d) + tex(" \\rvert"), exact(len)),
                tex("\\text{dist} = ") + exact(dist, true))
          .yields("distance");
    return out;
  }
  // Default generator: three integer points (three times in four) or a point and an integer
  // normal; nice: an integer ‖n‖, so the unit normal and the distance are rational.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node g;
    if (o.hard || rng.chance(3, 4)) {
      const std::array<IVec3, 3> t = gen_triangle(rng, o, -5, 5);
      g["points"] = gen_points({t[0], t[1], t[2]});
      return g;
    }
    IVec3 n{};
    for (int attempt = 0; attempt < 2000; ++attempt) {
      n = gen_ivec3(rng, -4, 4);
      if (idot(n, n) != 0 && (!o.nice || is_square(idot(n, n)))) break;
    }
    g["point"] = gen_list(to_list(gen_ivec3(rng, -5, 5)));
    g["normal"] = gen_list(to_list(n));
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    return !g.points.empty() && triangle_shape(doubles(g.points)) < kMinTriangleShape
               ? "the points are nearly collinear"
               : "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  const auto t = accuracy::well_conditioned_triangle(rng);
  if (!t) return std::nullopt;
  const Eigen::Vector3d p0 = (*t)[0].d(), p1 = (*t)[1].d(), p2 = (*t)[2].d();
  const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0);
  if (std::abs(n.normalized().dot(p0)) > 0.5)
    return "{points: " + accuracy::triangle_yaml(*t) + "}";
  return std::nullopt;
}

}  // namespace

KindInfo plane_kind() {
  KindInfo k = make_kind<Plane>();
  k.order = 30;
  k.doc_given = "`points` (3+), or `point` + `normal`";
  k.doc_answers = "`normal`, `unit_normal`, `plane` ([a, b, c, d] of ax + by + cz = d), `distance`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
