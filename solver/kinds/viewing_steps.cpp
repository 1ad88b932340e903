#include "solver/kinds/viewing_steps.hpp"

#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/kind_steps.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

Exact read_angle(GivenReader& r, const std::string& key, AngleUnit unit) {
  const Exact a = r.number(key);
  return canonical(unit == AngleUnit::Degrees ? a * GiNaC::Pi / 180 : a);
}

MathText angle_text(const Exact& radians, AngleUnit unit) {
  if (unit == AngleUnit::Degrees) return exact(canonical(radians * 180 / GiNaC::Pi)) + math("°", "^\\circ");
  return exact(radians) + math(" rad", "\\,\\text{rad}");
}

bool has_projection(const GivenReader& r) {
  return r.has("perspective") || r.has("frustum") || r.has("ortho");
}

namespace {

void require_positive(GivenReader& r, const std::string& key, const Exact& v, const std::string& why) {
  if (exact_sign(v) <= 0) r.fail(key, "must be positive: " + why);
}

}  // namespace

ProjectionSpec read_projection(GivenReader& r, const Conventions& c) {
  const int count = r.has("perspective") + r.has("frustum") + r.has("ortho");
  if (count == 0) r.fail("perspective", "missing required field: give perspective, frustum or ortho");
  if (count > 1) r.fail(r.has("perspective") ? "perspective" : "frustum",
                        "give only one of perspective, frustum and ortho");
  ProjectionSpec p;
  p.unit = c.angles;
  if (r.has("perspective")) {
    GivenReader g = r.child("perspective", {"fovy", "aspect", "near", "far"});
    p.type = ProjectionSpec::Type::Perspective;
    p.fovy = read_angle(g, "fovy", c.angles);
    if (exact_sign(*p.fovy) <= 0 || exact_sign(*p.fovy - GiNaC::Pi) >= 0)
      g.fail("fovy", c.angles == AngleUnit::Degrees ? "must be between 0° and 180° (exclusive)"
                                                    : "must be between 0 and π (exclusive)");
    p.aspect = g.number("aspect");
    require_positive(g, "aspect", *p.aspect, "the aspect ratio is width / height");
    const Exact n = g.number("near"), f = g.number("far");
    require_positive(g, "near", n, "a perspective needs the near plane in front of the eye");
    if (canonical(f - n).is_zero()) g.fail("far", "near = far: the view volume has no depth");
    require_positive(g, "far", f, "the far plane is in front of the eye");
    g.finish();
    p.volume = perspective_volume(*p.fovy, *p.aspect, n, f);
    for (Exact* e : {&p.volume.left, &p.volume.right, &p.volume.bottom, &p.volume.top})
      *e = canonical(*e);
    return p;
  }
  const bool frustum = r.has("frustum");
  p.type = frustum ? ProjectionSpec::Type::Frustum : ProjectionSpec::Type::Ortho;
  GivenReader g = r.child(frustum ? "frustum" : "ortho", {"left", "right", "bottom", "top", "near", "far"});
  p.volume = {g.number("left"), g.number("right"), g.number("bottom"), g.number("top"),
              g.number("near"), g.number("far")};
  if (canonical(p.volume.right - p.volume.left).is_zero()) g.fail("right", "left = right: the view volume has no width");
  if (canonical(p.volume.top - p.volume.bottom).is_zero()) g.fail("top", "bottom = top: the view volume has no height");
  if (canonical(p.volume.far - p.volume.near).is_zero()) g.fail("far", "near = far: the view volume has no depth");
  if (frustum) {
    require_positive(g, "near", p.volume.near, "a perspective needs the near plane in front of the eye");
    require_positive(g, "far", p.volume.far, "the far plane is in front of the eye");
  }
  g.finish();
  return p;
}

MatX<Exact> canonical(const MatX<Exact>& m) {
  MatX<Exact> out(m.rows(), m.cols());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) out(i, j) = canonical(m(i, j));
  return out;
}

std::vector<std::vector<Exact>> rows_of(const MatX<Exact>& m) {
  std::vector<std::vector<Exact>> rows(static_cast<std::size_t>(m.rows()));
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) rows[static_cast<std::size_t>(i)].push_back(m(i, j));
  return rows;
}

Value transform_points_with_steps(const MatX<Exact>& m, const std::vector<std::vector<Exact>>& points,
                                  const std::string& title, const std::string& name,
                                  Derivation* steps, Api api) {
  if (points.empty()) return Value::null();
  std::vector<std::vector<Exact>> moved;
  for (const std::vector<Exact>& p : points) {
    moved.push_back(transform_point(m, p));
    for (Exact& x : moved.back()) x = canonical(x);
    if (steps)
      steps->add(title, math(api == Api::DirectX ? name + "′ = " + name + "·M" : name + "′ = M·" + name),
                 math(name + " = ") + vec(p),
                 math(name + "′ = ") + vec(moved.back(), true));
  }
  if (steps) steps->yields("points");
  return Value::matrix(moved);
}

Value matrix_value(const MatX<Exact>& m) { return Value::matrix(rows_of(canonical(m))); }

MathText matrix_text(const MatX<Exact>& m) { return matrix(rows_of(canonical(m))); }

std::string multiply_note(Api api) {
  return api == Api::DirectX
             ? "DirectX multiplies row vectors, p′ = p·M: the matrix is printed in that form "
               "(the transpose of the column-vector matrix)."
             : "Column vectors, p′ = M·p.";
}

MatX<Exact> look_at_with_steps(const Vec3<Exact>& eye, const Vec3<Exact>& center,
                               const Vec3<Exact>& up, Api api, const std::string& field,
                               Derivation* steps) {
  const Vec3<Exact> forward = center - eye;
  if (canonical(forward.dot(forward)).is_zero())
    throw DomainError(field + "center", "center = eye: the camera looks nowhere");
  const Vec3<Exact> side = forward.cross(up);
  if (canonical(side.dot(side)).is_zero())
    throw DomainError(field + "up", "up is parallel to the view direction (or zero): the camera's roll is undefined");
  const MatX<Exact> m = canonical(look_at(eye, center, up, api));
  if (steps) {
    if (api == Api::DirectX) {
      steps->add("Camera axes (left-handed, looking down +z)",
                 math("z = (center − eye)/‖center − eye‖,  x = (up × z)/‖up × z‖,  y = z × x"), {},
                 math("x = ") + vec(Vec3<Exact>(m(0, 0), m(0, 1), m(0, 2))) + math(",  y = ") +
                     vec(Vec3<Exact>(m(1, 0), m(1, 1), m(1, 2))) + math(",  z = ") +
                     vec(Vec3<Exact>(m(2, 0), m(2, 1), m(2, 2))));
    } else {
      steps->add("Camera axes (right-handed, looking down −z)",
                 math("f = (center − eye)/‖center − eye‖,  s = (f × up)/‖f × up‖,  u = s × f"),
                 math("f = ") + vec(unit(forward), true),
                 math("s = ") + vec(Vec3<Exact>(m(0, 0), m(0, 1), m(0, 2))) + math(",  u = ") +
                     vec(Vec3<Exact>(m(1, 0), m(1, 1), m(1, 2))) + math(",  −f = ") +
                     vec(Vec3<Exact>(m(2, 0), m(2, 1), m(2, 2))));
    }
    steps->add("View matrix", math("V = [s, −s·eye; u, −u·eye; −f, f·eye; 0 0 0 1]"), {},
               math("V = ") + matrix_text(paper_form(m, api)))
        .note = multiply_note(api);
  }
  return m;
}

MatX<Exact> projection_with_steps(const ProjectionSpec& p, Api api, Derivation* steps) {
  const Volume<Exact>& v = p.volume;
  if (steps && p.type == ProjectionSpec::Type::Perspective) {
    steps->add("The frustum of perspective(fovy, aspect, near, far)",
               math("t = n·tan(fovy/2),  b = −t,  r = t·aspect,  l = −r",
                    "t = n\\tan\\frac{\\text{fovy}}{2},\\; b = -t,\\; r = t\\cdot\\text{aspect},\\; l = -r"),
               math("fovy = ") + angle_text(*p.fovy, p.unit) + math(",  aspect = ", ",\\; \\text{aspect} = ") +
                   exact(*p.aspect) + math(",  n = ", ",\\; n = ") + exact(v.near),
               math("t = ") + exact(v.top, true) + math(",  r = ", ",\\; r = ") + exact(v.right, true))
        .note = "fovy is the vertical field of view. Seed 004 writes −b = t = n·(w/h)·tan(θ/2); "
                "the aspect ratio belongs on r (the horizontal extent), not on t.";
  }
  MatX<Exact> m = p.type == ProjectionSpec::Type::Ortho ? ortho_matrix(v, api) : frustum_matrix(v, api);
  m = canonical(m);
  if (steps) {
    const bool ortho = p.type == ProjectionSpec::Type::Ortho;
    std::string formula;
    if (api == Api::DirectX)
      formula = ortho ? "OrthoOffCenterLH: [2/(r−l) 0 0 0; 0 2/(t−b) 0 0; 0 0 1/(f−n) 0; (l+r)/(l−r) (t+b)/(b−t) n/(n−f) 1]"
                      : "PerspectiveOffCenterLH: [2n/(r−l) 0 0 0; 0 2n/(t−b) 0 0; (l+r)/(l−r) (t+b)/(b−t) f/(f−n) 1; 0 0 nf/(n−f) 0]";
    else if (ortho)
      formula = std::string("ortho: [2/(r−l) 0 0 −(r+l)/(r−l); 0 ") + (api == Api::Processing ? "−" : "") +
                "2/(t−b) 0 −(t+b)/(t−b); 0 0 −2/(f−n) −(f+n)/(f−n); 0 0 0 1]";
    else
      formula = std::string("frustum: [2n/(r−l) 0 (r+l)/(r−l) 0; 0 ") + (api == Api::Processing ? "−" : "") +
                "2n/(t−b) (t+b)/(t−b) 0; 0 0 −(f+n)/(f−n) −2fn/(f−n); 0 0 −1 0]";
    Step& s = steps->add(ortho ? "Orthographic projection matrix" : "Perspective projection matrix",
                         math(formula),
                         math("l = ") + exact(v.left) + math(", r = ") + exact(v.right) + math(", b = ") +
                             exact(v.bottom) + math(", t = ") + exact(v.top) + math(", n = ") +
                             exact(v.near) + math(", f = ") + exact(v.far),
                         math("M = ") + matrix_text(paper_form(m, api)));
    s.note = multiply_note(api);
    if (api == Api::Processing)
      s.note += " Processing negates the y row because its window's y axis points down.";
    if (api == Api::OpenGL && !ortho)
      s.note += " z = −n maps to z_ndc = −1 and z = −f to +1 (seed 000's prose says the "
                "opposite; its own matrix, like this one, maps near to −1).";
    if (api == Api::DirectX) s.note += " Looking down +z, z_ndc runs from 0 at near to 1 at far.";
    steps->yields("matrix");
  }
  return m;
}

}  // namespace frustum
