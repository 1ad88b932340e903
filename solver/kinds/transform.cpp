// Composite transforms in 2D and 3D homogeneous coordinates (seeds 002, 004): steps applied
// in the listed order, so the composite of A₁, A₂, A₃ is M = A₃·A₂·A₁ and P′ = M·P.
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/kind_steps.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/kinds/viewing_steps.hpp"
#include "solver/util/diagnostic.hpp"

#include <fmt/format.h>

namespace frustum {

namespace {

struct TransformStep {
  std::string title;  // "translate (2, 3)"
  MatX<Exact> matrix;
  std::string note;
};

struct Transform {
  static constexpr const char* kName = "transform";
  static constexpr const char* kSummary = "the composite of translations, scalings, rotations and shears";
  struct Given {
    int dim = 3;
    std::vector<TransformStep> steps;
    std::vector<std::vector<Exact>> points;
  };
  static std::vector<std::string> given_fields() { return {"dim", "steps", "points"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"matrix", AnswerKind::Matrix, {}, {}},
            {"points", AnswerKind::Matrix, {"matrix"}, {}},
            {"inverse", AnswerKind::Matrix, {"matrix"}, {}}};
  }

  static std::string list_text(const std::vector<Exact>& v) {
    return vec(v).unicode;
  }

  static TransformStep read_step(GivenReader& s, int dim, const Conventions& c) {
    const std::vector<std::string> keys = s.keys();
    if (keys.size() != 1)
      s.fail(keys.empty() ? "translate" : keys[1],
             "each step is one of translate, scale, rotate_x, rotate_y, rotate_z, rotate, shear");
    const std::string& k = keys[0];
    TransformStep t;
    const std::size_t n = static_cast<std::size_t>(dim);
    if (k == "translate") {
      const std::vector<Exact> v = s.numbers(k, n);
      t = {"translate " + list_text(v), translate(v), ""};
    } else if (k == "scale") {
      std::vector<Exact> v = s.is_list(k) ? s.numbers(k, n) : std::vector<Exact>(n, s.number(k));
      t = {"scale " + list_text(v), scale(v), ""};
      for (const Exact& x : v)
        if (x.is_zero()) t.note = "a zero scale factor flattens space: the composite has no inverse";
    } else if (k == "rotate_x" || k == "rotate_y" || k == "rotate_z") {
      if (dim != 3) s.fail(k, "rotations about x, y, z are 3D; in 2D use rotate");
      const Exact a = read_angle(s, k, c.angles);
      t = {k + " " + angle_text(a, c.angles).unicode, rotate_axis_index(k[7] - 'x', a), ""};
    } else if (k == "rotate") {
      if (dim == 2) {
        const Exact a = read_angle(s, k, c.angles);
        t = {"rotate " + angle_text(a, c.angles).unicode, rotate_2d(a), ""};
      } else {
        GivenReader r = s.child(k, {"axis", "angle"});
        const Vec3<Exact> axis = r.vector<3>("axis");
        if (canonical(axis.dot(axis)).is_zero()) r.fail("axis", "the zero vector is not an axis");
        const Exact a = read_angle(r, "angle", c.angles);
        r.finish();
        const Vec3<Exact> u = unit(axis);
        t = {"rotate " + angle_text(a, c.angles).unicode + " about " + vec(axis).unicode,
             rotate_about(u, a), ""};
        if (!canonical(axis.dot(axis) - 1).is_zero())
          t.note = "the axis is normalised first: (x, y, z) = " + vec(u).unicode;
      }
    } else if (k == "shear") {
      MatX<Exact> h = MatX<Exact>::Zero(dim, dim);
      if (dim == 2) {
        const std::vector<Exact> v = s.numbers(k, 2);
        h(0, 1) = v[0];
        h(1, 0) = v[1];
        t.title = "shear x′ = x + " + exact(v[0]).unicode + "·y, y′ = y + " + exact(v[1]).unicode + "·x";
      } else {
        GivenReader r = s.child(k, {"xy", "xz", "yx", "yz", "zx", "zy"});
        const std::string names = "xyz";
        for (const std::string f : {"xy", "xz", "yx", "yz", "zx", "zy"})
          if (r.has(f)) h(static_cast<int>(names.find(f[0])), static_cast<int>(names.find(f[1]))) = r.number(f);
        r.finish();
        t.title = "shear (h_ij adds coordinate j to coordinate i)";
      }
      t.matrix = shear(h);
    } else {
      s.fail(k, "unknown step: use translate, scale, rotate_x, rotate_y, rotate_z, rotate or shear");
    }
    s.finish();
    t.matrix = canonical(t.matrix);
    return t;
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.dim = r.has("dim") ? static_cast<int>(to_double(r.number("dim"))) : 3;
    if (g.dim != 2 && g.dim != 3) r.fail("dim", "must be 2 or 3");
    const std::size_t n = r.list_size("steps");
    for (std::size_t i = 0; i < n; ++i) {
      GivenReader s = r.item("steps", i, {"translate", "scale", "rotate_x", "rotate_y", "rotate_z", "rotate", "shear"});
      g.steps.push_back(read_step(s, g.dim, c));
    }
    if (r.has("points")) {
      const std::size_t count = r.list_size("points");
      for (std::size_t i = 0; i < count; ++i) {
        // Each point is a list of dim numbers; reuse the reader on a one-field view.
        g.points.push_back(r.numbers_at("points", i, static_cast<std::size_t>(g.dim)));
      }
    }
    return g;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    if (g.steps.size() < 2) return {};
    const int size = g.dim + 1;
    MatX<Exact> m = MatX<Exact>::Identity(size, size);
    for (const TransformStep& s : g.steps) m = canonical(MatX<Exact>(m * s.matrix));
    Answers reversed;
    reversed.set("matrix", matrix_value(m));
    if (!g.points.empty()) reversed.set("points", transform_points_with_steps(m, g.points, "", "P", nullptr));
    return {{"composition in the wrong order",
             "You multiplied the steps in the order they are applied (A₁·A₂·…): with column vectors the "
             "step applied first stands rightmost, M = …·A₂·A₁ (seed 002: P′ = A₃A₂A₁P).",
             "Composite (first step applied first)", reversed}};
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const int size = g.dim + 1;
    MatX<Exact> m = MatX<Exact>::Identity(size, size);
    for (std::size_t i = 0; i < g.steps.size(); ++i) {
      const TransformStep& s = g.steps[i];
      m = canonical(MatX<Exact>(s.matrix * m));
      if (steps) {
        Step& st = steps->add(fmt::format("A{}: {}", i + 1, s.title), {}, {},
                              math(fmt::format("A{} = ", i + 1)) + matrix_text(s.matrix));
        st.note = s.note;
      }
    }
    Answers out;
    out.set("matrix", matrix_value(m));
    if (steps) {
      std::string order;
      for (std::size_t i = g.steps.size(); i >= 1; --i) order += fmt::format("{}A{}", i == g.steps.size() ? "" : "·", i);
      steps->add("Composite (first step applied first)", math("M = " + order),
                 {}, math("M = ") + matrix_text(m))
          .note = "Column vectors: P′ = M·P, so the step applied first stands rightmost (seed 002: P′ = A₃A₂A₁P).";
      steps->yields("matrix");
    }
    out.set("points", transform_points_with_steps(m, g.points, "Transform a point", "P", steps));
    const Exact det = canonical(m.determinant());
    if (det.is_zero()) {
      out.set("inverse", Value::null());
      if (steps) steps->warn("No inverse", "det M = 0: the transform flattens space and cannot be undone.");
    } else {
      const MatX<Exact> inv = canonical(MatX<Exact>(m.inverse()));
      out.set("inverse", matrix_value(inv));
      if (steps) {
        steps->add("Inverse", math("M⁻¹ (M·M⁻¹ = I)", "M^{-1}\\;(M M^{-1} = I)"), {},
                   math("M⁻¹ = ", "M^{-1} = ") + matrix_text(inv));
        steps->yields("inverse");
      }
    }
    return out;
  }
};

}  // namespace

KindInfo transform_kind() { return make_kind<Transform>(); }

}  // namespace frustum
