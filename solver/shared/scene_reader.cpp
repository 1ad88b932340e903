#include "solver/shared/scene_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/input/given_reader.hpp"
#include "solver/shared/transform_steps.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

const std::vector<std::string> kObjectFields = {
    "name", "triangle", "mesh", "box", "solid", "transform", "fill", "cull", "repeat", "children"};

template <typename M>
Mat4d to_mat4d(const M& m) {
  Mat4d out;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out(i, j) = to_double(m(i, j));
  return out;
}

Vec3d to_vec3d(const Vec3<Exact>& v) { return to_double(v); }

int read_int(GivenReader& r, const std::string& field, const Exact& e, long lo, long hi) {
  if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer() ||
      GiNaC::ex_to<GiNaC::numeric>(e) < GiNaC::numeric(lo) ||
      GiNaC::ex_to<GiNaC::numeric>(e) > GiNaC::numeric(hi))
    throw InputError(r.locate(field, fmt::format("expected an integer from {} to {}", lo, hi)));
  return static_cast<int>(GiNaC::ex_to<GiNaC::numeric>(e).to_long());
}

// [r, g, b] (0–255), "#rrggbb", or one grey level as in Processing's fill(255).
Rgb read_color(GivenReader& r, const std::string& key) {
  const YAML::Node n = r.node()[key];
  if (n.IsScalar() && !n.Scalar().empty() && n.Scalar()[0] == '#') {
    const std::string& s = n.Scalar();
    const bool hex = s.size() == 7 && std::all_of(s.begin() + 1, s.end(), [](char ch) {
                       return std::isxdigit(static_cast<unsigned char>(ch));
                     });
    if (!hex) r.fail(key, "expected a colour \"#rrggbb\", got '" + s + "'");
    auto byte = [&](int at) {
      return static_cast<std::uint8_t>(
          std::stoi(s.substr(static_cast<std::size_t>(at), 2), nullptr, 16));
    };
    return {byte(1), byte(3), byte(5)};
  }
  if (n.IsScalar()) {
    const auto g = static_cast<std::uint8_t>(read_int(r, key, r.number(key), 0, 255));
    return {g, g, g};
  }
  if (!n.IsSequence() || n.size() != 3)
    r.fail(key, "expected a colour [r, g, b] (0–255), \"#rrggbb\" or a grey level");
  const std::vector<Exact> v = r.numbers(key, 3);
  Rgb c;
  c.r = static_cast<std::uint8_t>(read_int(r, key + "[0]", v[0], 0, 255));
  c.g = static_cast<std::uint8_t>(read_int(r, key + "[1]", v[1], 0, 255));
  c.b = static_cast<std::uint8_t>(read_int(r, key + "[2]", v[2], 0, 255));
  return c;
}

// The composite of a list of transform steps, first applied first: M = Aₙ···A₁ (exact; the
// doubles are its entries rounded once).
Mat4<Exact> read_steps(GivenReader& r, const std::string& key, const Conventions& c) {
  Mat4<Exact> m = Mat4<Exact>::Identity();
  for (const TransformStep& t :
       read_transform_steps(r, key, 3, c, {.min_count = 0, .max_count = kMaxGivenListItems})) {
    m = Mat4<Exact>(t.matrix * m);
    for (Exact& e : m.reshaped()) e = canonical(e);
  }
  return m;
}

void add_vertex(SceneObject& o, const Vec3<Exact>& v, bool keep_exact) {
  o.vertices.push_back(to_vec3d(v));
  if (keep_exact) o.exact_vertices.push_back(v);
}

void add_polygons(SceneObject& o, const Mesh& mesh, bool keep_exact) {
  for (const Vec3<Exact>& v : mesh.vertices) add_vertex(o, v, keep_exact);
  for (const std::vector<int>& f : mesh.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) o.triangles.push_back({f[0], f[k], f[k + 1]});
}

SceneObject read_object(GivenReader& o, const Conventions& c, int depth, long multiplier,
                        long& triangles, bool keep_exact) {
  SceneObject obj;
  if (o.has("name")) {
    const YAML::Node name = o.node()["name"];
    if (!name.IsScalar()) o.fail("name", "expected a name");
    obj.name = name.Scalar();
  }
  const int shapes = o.has("triangle") + o.has("mesh") + o.has("box") + o.has("solid");
  if (shapes > 1)
    o.fail(o.has("triangle") ? "triangle" : "mesh",
           "give at most one of triangle, mesh, box and solid");
  if (o.has("triangle")) {
    for (const Vec3<Exact>& p : o.points("triangle", 3, 3)) add_vertex(obj, p, keep_exact);
    obj.triangles.push_back({0, 1, 2});
  } else if (o.has("mesh")) {
    GivenReader m = o.child("mesh", {"vertices", "faces"});
    add_polygons(obj, read_mesh(m, 3, 1), keep_exact);
  } else if (o.has("box")) {
    std::vector<Exact> size;
    if (o.is_list("box")) {
      size = o.numbers("box", 3);
    } else if (o.node()["box"].IsScalar()) {
      size.assign(3, o.number("box"));
    } else {
      GivenReader b = o.child("box", {"size", "w", "h", "d"});
      if (b.has("size") == (b.has("w") || b.has("h") || b.has("d")))
        b.fail("size", "give size (one number or [w, h, d]) or w, h and d");
      if (b.has("size"))
        size = b.is_list("size") ? b.numbers("size", 3) : std::vector<Exact>(3, b.number("size"));
      else
        size = {b.number("w"), b.number("h"), b.number("d")};
      b.finish();
    }
    for (const Exact& s : size)
      if (exact_sign(s) <= 0) o.fail("box", "the box's sizes must be positive");
    SceneObject box = box_object(to_double(size[0]), to_double(size[1]), to_double(size[2]));
    obj.vertices = box.vertices;
    obj.triangles = box.triangles;
    if (keep_exact) obj.exact_vertices = box_corners(size[0], size[1], size[2]);
  } else if (o.has("solid")) {
    add_polygons(obj, named_solid(o.word("solid", solid_names())), keep_exact);
  }
  if (o.has("transform")) {
    const Mat4<Exact> m = read_steps(o, "transform", c);
    obj.transform = to_mat4d(m);
    if (keep_exact) obj.exact_transform = m;
  }
  if (o.has("fill")) obj.fill = read_color(o, "fill");
  if (o.has("cull"))
    obj.cull = o.word("cull", {"none", "back"}) == "back" ? Cull::Back : Cull::None;
  long copies = 1;
  if (o.has("repeat")) {
    GivenReader r = o.child("repeat", {"from", "to", "step"});
    SceneObject::Repeat rep;
    const std::vector<Exact> from = r.numbers("from", 3), to = r.numbers("to", 3),
                             step = r.numbers("step", 3);
    for (int a = 0; a < 3; ++a) {
      rep.from[a] = read_int(r, fmt::format("from[{}]", a), from[a], -100000, 100000);
      rep.to[a] = read_int(r, fmt::format("to[{}]", a), to[a], rep.from[a], 100000);
      rep.step(a) = to_double(step[a]);
      if (keep_exact) obj.exact_step(a) = step[a];
    }
    r.finish();
    copies = rep.count();
    obj.repeat = rep;
  }
  // Every product checked for overflow before it is used: nested repeats of 100 001³ copies
  // each once overflowed `long` and the triangle limit let an unbounded scene through.
  long factor = 0, added = 0, total = 0;
  if (__builtin_mul_overflow(multiplier, copies, &factor) || factor > kMaxSceneTriangles)
    o.fail("repeat", fmt::format("more than {} copies (counting the repeats it is nested in)",
                                 kMaxSceneTriangles));
  if (__builtin_mul_overflow(factor, static_cast<long>(obj.triangles.size()), &added) ||
      __builtin_add_overflow(triangles, added, &total) || total > kMaxSceneTriangles)
    o.fail(o.has("repeat") ? "repeat" : "children",
           fmt::format("the scene has more than {} triangles", kMaxSceneTriangles));
  triangles = total;
  if (o.has("children")) {
    if (depth >= kMaxSceneDepth)
      o.fail("children", fmt::format("objects may nest at most {} levels deep", kMaxSceneDepth));
    const std::size_t n = o.list_size("children");
    for (std::size_t k = 0; k < n; ++k) {
      GivenReader ch = o.item("children", k, kObjectFields);
      obj.children.push_back(read_object(ch, c, depth + 1, factor, triangles, keep_exact));
    }
  }
  o.finish();
  return obj;
}

}  // namespace

std::vector<std::string> scene_fields() {
  return {"viewport",   "camera", "perspective", "frustum", "ortho",
          "background", "light",  "method",      "objects"};
}

Mesh read_mesh(GivenReader& m, std::size_t min_vertices, std::size_t min_faces) {
  Mesh mesh;
  mesh.vertices = m.points("vertices", min_vertices);
  const std::size_t count = m.list_size("faces", min_faces);
  const YAML::Node faces = m.node()["faces"];
  const auto n = static_cast<long>(mesh.vertices.size());
  for (std::size_t f = 0; f < count; ++f) {
    const std::string at = fmt::format("faces[{}]", f);
    const YAML::Node face = faces[f];
    if (!face.IsSequence() || face.size() < 3)
      throw InputError(m.locate(at, "expected a list of at least 3 vertex indices"));
    std::vector<int> idx;
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::string field = fmt::format("{}[{}]", at, k);
      const Exact v = read_number(face[k], m.file(), m.locate(field, "").field);
      // Compared exactly before any conversion: "2^64+1" once wrapped to vertex 1.
      if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_integer() ||
          GiNaC::ex_to<GiNaC::numeric>(v) < 0 ||
          GiNaC::ex_to<GiNaC::numeric>(v) >= GiNaC::numeric(n))
        throw InputError(
            m.locate(field, fmt::format("expected a vertex index from 0 to {}", n - 1)));
      const int i = static_cast<int>(GiNaC::ex_to<GiNaC::numeric>(v).to_long());
      if (std::find(idx.begin(), idx.end(), i) != idx.end())
        throw InputError(m.locate(field, fmt::format("vertex {} appears twice in this face", i)));
      idx.push_back(i);
    }
    mesh.faces.push_back(idx);
  }
  m.finish();
  return mesh;
}

Mat4<Exact> exact_clip_from_world(const SceneSpec& spec, Api api, Derivation* steps) {
  const MatX<Exact> view = look_at_with_steps(spec.eye, spec.center, spec.up, api, "scene.camera.",
                                              steps, spec.scene.left_handed);
  Mat4<Exact> m = projection_with_steps(spec.projection, api, steps) * view;
  for (Exact& e : m.reshaped()) e = canonical(e);
  return m;
}

SceneSpec read_scene(GivenReader& r, const Conventions& c, bool keep_exact) {
  SceneSpec spec;
  Scene& s = spec.scene;
  s.api = c.api;
  s.left_handed = left_handed_columns(c);
  {
    GivenReader v = r.child("viewport", {"width", "height"});
    s.width = read_int(v, "width", v.number("width"), 1, kMaxViewport);
    s.height = read_int(v, "height", v.number("height"), 1, kMaxViewport);
    if (static_cast<long>(s.width) * s.height > kMaxScenePixels)
      v.fail("height",
             fmt::format("{} × {} pixels: at most {} in all", s.width, s.height, kMaxScenePixels));
    v.finish();
  }
  {
    GivenReader cam = r.child("camera", {"eye", "center", "up"});
    spec.eye = cam.vector<3>("eye");
    spec.center = cam.vector<3>("center");
    spec.up = cam.vector<3>("up");
    cam.finish();
    try {
      check_camera(spec.eye, spec.center, spec.up, "camera.");
    } catch (const DomainError& e) {
      throw InputError(r.locate(e.field(), e.what()));
    }
    s.camera = {to_vec3d(spec.eye), to_vec3d(spec.center), to_vec3d(spec.up)};
  }
  spec.projection = read_projection(r, c);
  s.clip_from_eye = to_mat4d(projection_with_steps(spec.projection, c.api, nullptr));
  if (r.has("background")) s.background = read_color(r, "background");
  if (r.has("light")) {
    DirectionalLight light;
    if (!(r.node()["light"].IsScalar() && r.word("light", {"lights"}) == "lights")) {
      GivenReader l = r.child("light", {"direction", "transform", "ambient", "diffuse"});
      if (l.has("direction")) light.direction = to_vec3d(l.vector<3>("direction"));
      if (light.direction.norm() == 0) l.fail("direction", "the zero vector is not a direction");
      if (l.has("transform"))
        light.direction =
            to_mat4d(read_steps(l, "transform", c)).block<3, 3>(0, 0) * light.direction;
      if (l.has("ambient")) light.ambient = read_int(l, "ambient", l.number("ambient"), 0, 255);
      if (l.has("diffuse")) light.diffuse = read_int(l, "diffuse", l.number("diffuse"), 0, 255);
      l.finish();
    }
    s.light = light;
  }
  if (r.has("method")) s.scanline = r.word("method", {"zbuffer", "scanline"}) == "scanline";
  const std::size_t n = r.list_size("objects");
  for (std::size_t k = 0; k < n; ++k) {
    GivenReader o = r.item("objects", k, kObjectFields);
    s.objects.push_back(read_object(o, c, 1, 1, spec.triangles, keep_exact));
  }
  r.finish();
  return spec;
}

}  // namespace frustum
