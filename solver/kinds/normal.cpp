// The normal of a polygon (counter-clockwise = front, seed 003) or of a triangle ABC with an
// explicit cross-product order (seed 001: AC × AB in left-handed projection coordinates).
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kTheNormalSDirection{"the normal's direction", "法線の向き",
                                      "направление нормали"};

constexpr Phrase kOrientation{"Orientation", "向き", "Ориентация"};
constexpr Phrase kLeftHandedCross{
    "These coordinates are left-handed: AC × AB points to the side from which A, B, C run "
    "counter-clockwise (the front).",
    "この座標は左手系である: AC × AB は A, B, C が反時計回りに見える側 (表) を向く.",
    "Эти координаты — левая система: AC × AB направлен в ту сторону, откуда A, B, C идут против "
    "часовой стрелки (лицевая сторона)."};
constexpr Phrase kMirrorFrontNormal{
    "Read in a right-handed frame, the same numbers describe the mirror image, whose front normal "
    "is AB × AC = −(AC × AB).",
    "右手系で読むと同じ数値は鏡像を表し, その表の法線は AB × AC = −(AC × AB) である.",
    "Прочитанные в правой системе, те же числа описывают зеркальный образ, лицевая нормаль "
    "которого AB × AC = −(AC × AB)."};
constexpr Phrase kRightHandedCross{
    "In a right-handed frame AB × AC points to the side from which A, B, C run counter-clockwise; "
    "in a left-handed frame (such as projection coordinates) that side's normal is AC × AB.",
    "右手系では AB × AC は A, B, C が反時計回りに見える側を向く. 左手系 (投影座標系など) "
    "ではその側の法線は AC × AB.",
    "В правой системе AB × AC направлен в ту сторону, откуда A, B, C идут против часовой стрелки; "
    "в левой системе (например, в координатах проекции) нормаль этой стороны — AC × AB."};

std::unique_ptr<NumericSolver> normal_numeric(const Polygon3<Exact>& points,
                                              const std::optional<CrossOrder>& order, Precision p) {
  const double kappa = normal_condition(double_points(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      std::optional<std::array<int, 4>> order;  // first = X₀→Y₀, second = X₁→Y₁ (vertex indices)
      InputRange range;
      Polygon3<Exact> exact_points;  // for the exact zero test and the refusal
      std::optional<CrossOrder> cross;
    };
    auto core = [](const In& in) {
      NormalPair<T> r;
      if (!in.order) {
        r = polygon_normal(in.points, in.exact_points, in.range.relative());
        // A degenerate polygon is refused, as the exact solve refuses it (the same words).
        if (r.zero) polygon_normal_with_steps(in.exact_points, "points", nullptr);
        return r;
      }
      const auto& o = *in.order;
      r.n = cross_order_normal<T>(in.points, o);
      Vec3<T> bound = Vec3<T>::Zero();
      if constexpr (!kIsExact<T>) {
        auto magnitude = [&](int i, int j) {
          return Vec3<T>(in.points[i].cwiseAbs() + in.points[j].cwiseAbs());
        };
        bound = cross_error_bound(magnitude(o[1], o[0]), magnitude(o[3], o[2]), 2);
      }
      const std::array<Vec3<Exact>, 3> abc{in.exact_points[0], in.exact_points[1],
                                           in.exact_points[2]};
      decide_normal_zero(r, r.n, bound, in.range.relative(), 0,
                         [&] { return cross_order_normal<Exact>(abc, o); });
      if (r.zero) cross_normal_with_steps(abc, *in.cross, "A", nullptr);
      return r;
    };
    auto report = [p, kappa](const In& in, const NormalPair<T>& n) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      report_normal(out, n);
      if (!n.exact_value)
        warn_condition(out, p, kappa, say(kIllConditionedNormal), say(kTheNormalSDirection));
      return out.take();
    };
    In in{{}, std::nullopt, {}, points, order};
    in.points = conv<T>(points, &in.range);
    if (order) in.order = cross_indices(*order);
    return prepare(std::move(in), core, report);
  });
}

struct Normal {
  static constexpr const char* kName = "normal";
  static constexpr Phrase kSummary{"the normal and unit normal of a polygon",
                                   "多角形の法線ベクトルと単位法線ベクトル",
                                   "нормаль и единичная нормаль многоугольника"};
  static constexpr ConventionUse kUses{.api = false, .angles = false, .handedness = true};
  struct Given {
    Polygon3<Exact> points;           // when given as a polygon
    std::optional<CrossOrder> order;  // when given as A, B, C
    bool left_handed = false;         // the course's coordinates (conventions: handedness)
  };
  // The normal with the cross product's factors swapped (its side decides the front).
  static std::vector<Misconception> misconceptions(const Given& g) {
    const Vec3<Exact> n =
        g.order ? cross_normal_with_steps({g.points[0], g.points[1], g.points[2]}, *g.order, "A",
                                          nullptr)
                : polygon_normal_with_steps(g.points, "points", nullptr, g.left_handed);
    const auto m = reversed_normal_mistake(n, g.points.size(), g.left_handed, g.order);
    return m ? std::vector<Misconception>{*m} : std::vector<Misconception>{};
  }

  // Error carried forward: the unit normal of the student's own normal.
  static Answers carry_forward(const Given&, const Answers& student) {
    Answers out;
    if (const auto n = carried(student, "normal", 3))
      out.set("unit_normal", Value::vector(unit(Vec3<Exact>((*n)[0], (*n)[1], (*n)[2]))));
    return out;
  }

  static std::vector<std::string> given_fields() { return {"points", "A", "B", "C", "cross"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "normal", .kind = AnswerKind::Direction, .symbols = {"n"}},
            {.name = "unit_normal",
             .kind = AnswerKind::UnitVector,
             .depends_on = {"normal"},
             .symbols = {"n̂"}}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.left_handed = left_handed_columns(c);  // DirectX: clockwise = front, e₀ × e₁ as it is
    if (r.has("points")) {
      if (r.has("A") || r.has("cross"))
        r.fail("points", "give either points or A, B, C (with cross), not both");
      g.points = r.points("points", 3);
      return g;
    }
    if (!r.has("A") && !r.has("B") && !r.has("C"))
      r.fail("points", "missing required field: give points (a polygon) or A, B, C");
    g.points = {r.vector<3>("A"), r.vector<3>("B"), r.vector<3>("C")};
    // The front normal by default: AB × AC in right-handed coordinates, AC × AB in left-handed.
    g.order = read_cross(r, "cross", g.left_handed ? CrossOrder{"AC", "AB"} : CrossOrder{});
    return g;
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    // The numeric paths take the polygon's right-handed normal: a left-handed one is that of
    // the polygon listed the other way round.
    if (g.left_handed && !g.order) return normal_numeric(reversed_winding(g.points), g.order, p);
    return normal_numeric(g.points, g.order, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    Vec3<Exact> n;
    if (g.order) {
      // Which side the normal points to depends on the frame's handedness: said here, as
      // depth_at_pixel says it for its left-handed projection coordinates.
      if (steps)
        steps->note(say(kOrientation), g.left_handed
                                           ? say(kLeftHandedCross) + say(kMirrorFrontNormal)
                                           : say(kRightHandedCross));
      n = cross_normal_with_steps({g.points[0], g.points[1], g.points[2]}, *g.order, "A", steps);
    } else {
      n = polygon_normal_with_steps(g.points, "points", steps, g.left_handed);
    }
    if (steps) steps->yields("normal");
    Answers out;
    out.set("normal", Value::vector(n));
    out.set("unit_normal", Value::vector(unit_normal_with_steps(n, steps)));
    return out;
  }
  // Default generator: an integer triangle (gen_triangle: nice gives an integer ‖n‖, hard a
  // nearly collinear one).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::array<IVec3, 3> t = gen_triangle(rng, o, -5, 5);
    YAML::Node g;
    g["points"] = gen_points({t[0], t[1], t[2]});
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    return triangle_shape(doubles(g.points)) < kMinTriangleShape
               ? "the polygon is nearly degenerate"
               : "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  const auto t = accuracy::well_conditioned_triangle(rng);
  if (!t) return std::nullopt;
  return "{points: " + accuracy::triangle_yaml(*t) + "}";
}

}  // namespace

KindInfo normal_kind() {
  KindInfo k = make_kind<Normal>();
  k.order = 20;
  k.doc_given =
      "`points` (counter-clockwise = front), or `A`, `B`, `C` with optional `cross: [AC, AB]` "
      "(default `[AB, AC]`)";
  k.doc_answers = "`normal`, `unit_normal`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
