// The normal of a polygon (counter-clockwise = front, seed 003) or of a triangle ABC with an
// explicit cross-product order (seed 001: AC × AB in left-handed projection coordinates).
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/steps/accuracy_draws.hpp"
#include "solver/steps/kind_steps.hpp"
#include "solver/steps/numeric_paths.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

struct Normal {
  static constexpr const char* kName = "normal";
  static constexpr const char* kSummary = "the normal and unit normal of a polygon";
  static constexpr ConventionUse kUses{.api = false, .angles = false, .handedness = true};
  struct Given {
    Polygon3<Exact> points;           // when given as a polygon
    std::optional<CrossOrder> order;  // when given as A, B, C
    bool left_handed = false;         // the course's coordinates (conventions: handedness)
  };
  // Error carried forward: the unit normal of the student's own normal.
  static Answers carry_forward(const Given&, const Answers& student) {
    Answers out;
    if (const auto n = carried(student, "normal", 3))
      out.set("unit_normal", Value::vector(unit(Vec3<Exact>((*n)[0], (*n)[1], (*n)[2]))));
    return out;
  }

  static std::vector<std::string> given_fields() { return {"points", "A", "B", "C", "cross"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"normal", AnswerKind::Direction, {}, {}},
            {"unit_normal", AnswerKind::UnitVector, {"normal"}, {}}};
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
        steps->note(
            "Orientation",
            g.left_handed
                ? "These coordinates are left-handed: AC × AB points to the side from which "
                  "A, B, C run counter-clockwise (the front). Read in a right-handed frame, "
                  "the same numbers describe the mirror image, whose front normal is "
                  "AB × AC = −(AC × AB)."
                : "In a right-handed frame AB × AC points to the side from which A, B, C run "
                  "counter-clockwise; in a left-handed frame (such as projection coordinates) "
                  "that side's normal is AC × AB.");
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

  static std::string ill_conditioned(const Given& g, const Answers&) {
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
