// seed 001: the z value of a pixel by the plane method. The triangle is in projection
// coordinates, which are left-handed (seed 001's warning), so its front normal is AC × AB:
// A(0,0,6), B(3,0,9), C(0,3,9) → n = (9, 9, −9), n̂ = (1/√3, 1/√3, −1/√3), x + y − z = −6,
// and the pixel (1, 1) has z = 8.
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/kind_steps.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

struct DepthAtPixel {
  static constexpr const char* kName = "depth_at_pixel";
  static constexpr const char* kSummary = "z of a pixel inside a projected triangle by the plane method";
  struct Given {
    std::array<Vec3<Exact>, 3> triangle;
    Vec2<Exact> pixel;
    CrossOrder order;
    bool order_given = false;
  };
  static std::vector<std::string> given_fields() { return {"triangle", "pixel", "cross"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"normal", AnswerKind::Direction, {}, {}},
            {"unit_normal", AnswerKind::UnitVector, {"normal"}, {}},
            {"plane", AnswerKind::Plane, {"unit_normal"}, {}},
            {"z", AnswerKind::Scalar, {"plane"}, {}},
            {"inside", AnswerKind::Bool, {}, {}}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const Polygon3<Exact> t = r.points("triangle", 3, 3);
    g.triangle = {t[0], t[1], t[2]};
    g.pixel = r.vector<2>("pixel");
    g.order_given = r.has("cross");
    g.order = read_cross(r, "cross", CrossOrder{"AC", "AB"});
    return g;
  }

  // (x − a, y − b, z − c) with zero offsets left out, as on paper: (x, y, z − 6).
  static MathText offset_point(const Vec3<Exact>& a) {
    MathText m = math("(", "\\left(");
    const char* names[3] = {"x", "y", "z"};
    for (int i = 0; i < 3; ++i)
      m += (i ? math(", ") : MathText{}) + linear_expression({{1, names[i]}, {-a(i), ""}});
    return m + math(")", "\\right)");
  }

  static int orient2d(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec2<Exact>& p) {
    return exact_sign((b(0) - a(0)) * (p(1) - a(1)) - (b(1) - a(1)) * (p(0) - a(0)));
  }

  static Answers solve(const Given& g, Derivation* steps) {
    if (steps)
      steps->note("Projection coordinates are left-handed",
                  g.order_given
                      ? "seed 001: mind the order of the cross product; this problem uses " +
                            g.order.first + " × " + g.order.second + "."
                      : "seed 001: mind the order of the cross product; the front normal of a "
                        "triangle ABC here is AC × AB (the order used by default).");
    const Vec3<Exact> n = cross_normal_with_steps(g.triangle, g.order, "triangle", steps);
    if (steps) steps->yields("normal");
    Answers out;
    out.set("normal", Value::vector(n));
    const Vec3<Exact> u = unit_normal_with_steps(n, steps);
    out.set("unit_normal", Value::vector(u));
    // Plane through A: n̂·(p − A) = 0, then cleared of its common factor.
    const Vec3<Exact>& A = g.triangle[0];
    const Exact d = canonical(u.dot(A));
    const std::array<Exact, 4> plane = paper_plane(u, d);
    Value pv = Value::vector(std::vector<Exact>(plane.begin(), plane.end()));
    pv.display = plane_equation(plane[0], plane[1], plane[2], plane[3]);
    out.set("plane", pv);
    if (steps) {
      steps->add("Plane through A with normal n̂",
                 math("n̂·(p − A) = 0", "\\hat{\\mathbf{n}}\\cdot(\\mathbf{p} - \\overrightarrow{OA}) = 0"),
                 vec(u) + math("·", "\\cdot") + offset_point(A) + math(" = 0"),
                 pv.display);
      steps->yields("plane");
    }
    const Exact& a = plane[0];
    const Exact& b = plane[1];
    const Exact& c = plane[2];
    if (c.is_zero())
      throw DomainError("triangle", "the triangle is edge-on (c = 0 in ax + by + cz = d): its "
                                    "plane has no single z above a pixel");
    const Exact z = canonical((plane[3] - a * g.pixel(0) - b * g.pixel(1)) / c);
    out.set("z", Value::scalar(z));
    if (steps) {
      steps->add("Depth at the pixel", math("z = (d − a·xₛ − b·yₛ) / c", "z_S = \\frac{d - a x_S - b y_S}{c}"),
                 linear_equation({{a * g.pixel(0), ""}, {b * g.pixel(1), ""}, {c, "z"}}, plane[3]),
                 math("z = ", "z_S = ") + exact(z, true));
      steps->yields("z");
    }
    // Inside the closed triangle: the three edge orientations agree (zero = on an edge).
    const int s0 = orient2d(g.triangle[0], g.triangle[1], g.pixel);
    const int s1 = orient2d(g.triangle[1], g.triangle[2], g.pixel);
    const int s2 = orient2d(g.triangle[2], g.triangle[0], g.pixel);
    const bool inside = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
    out.set("inside", Value::boolean(inside));
    if (steps) {
      steps->add("Is the pixel inside the projected triangle?")
          .note = "Signs of the edge functions AB, BC, CA at the pixel: " + std::to_string(s0) +
                  ", " + std::to_string(s1) + ", " + std::to_string(s2) +
                  (inside ? " — all agree (0 = on an edge), so the pixel is inside the closed "
                            "triangle."
                          : " — they differ, so the pixel is outside; the plane still gives its z.");
      steps->yields("inside");
    }
    return out;
  }
};

}  // namespace

KindInfo depth_at_pixel_kind() { return make_kind<DepthAtPixel>(); }

}  // namespace frustum
