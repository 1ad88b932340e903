#include "solver/raster/pipeline.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "solver/clipping/polygon_clip.hpp"
#include "solver/raster/certified_frame.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

namespace {

Mat4d to_mat4(const MatX<double>& m) { return Mat4d(m); }

Mat4d translation(const Vec3d& t) {
  Mat4d m = Mat4d::Identity();
  m.block<3, 1>(0, 3) = t;
  return m;
}

std::string copy_name(const std::string& name, const SceneObject::Repeat& r,
                      const std::array<int, 3>& at) {
  std::string s;
  for (int a = 0; a < 3; ++a)
    if (r.from[a] != r.to[a]) s += (s.empty() ? "" : ",") + std::to_string(at[a]);
  return name + "[" + s + "]";
}

// A factor that an identity leaves unchanged bit for bit: finite, with no −0 entry. Each entry
// of I·B (or A·I) is then one entry of B plus ±0 terms, which is that entry exactly.
bool identity_keeps(const Mat4d& m) {
  for (int k = 0; k < 16; ++k) {
    const double v = m.data()[k];
    if (!std::isfinite(v) || (v == 0 && std::signbit(v))) return false;
  }
  return true;
}

bool finite_without_negative_zero(const Vec3d& v) {
  for (int k = 0; k < 3; ++k)
    if (!std::isfinite(v(k)) || (v(k) == 0 && std::signbit(v(k)))) return false;
  return true;
}

// a · b, without the 64 products when a factor is exactly the identity (a repeat of a million
// copies composes two matrices per copy): the same matrix as the product, bit for bit.
bool is_identity(const Mat4d& m) { return m == Mat4d::Identity(); }  // ±0 off the diagonal
Mat4d compose(const Mat4d& a, const Mat4d& b) {
  if (is_identity(b) && identity_keeps(a)) return a;
  if (is_identity(a) && identity_keeps(b)) return b;
  return a * b;
}

// World triangles and objects under `children` (each child included), copies of repeats
// counted.
std::pair<std::size_t, std::size_t> flat_size(const std::vector<SceneObject>& children) {
  std::pair<std::size_t, std::size_t> n{0, 0};
  for (const SceneObject& child : children) {
    const auto [t, objects] = flat_size(child.children);
    const auto copies = static_cast<std::size_t>(child.repeat ? child.repeat->count() : 1);
    n.first += copies * (child.triangles.size() + t);
    n.second += copies * (1 + objects);
  }
  return n;
}

// The walk's output: every world triangle to `visit`, and the objects' names when `names`.
struct FlatSink {
  const std::function<void(const WorldTriangle&)>& visit;
  std::vector<std::string>* names = nullptr;
  int objects = 0;
  bool track_error = false;
};

// Error bounds of the walk (WorldTriangle::error), in the ∞-norm: u = 2⁻⁵³, an input rounded
// once within 2u of its exact value (numeric/ranged.hpp's rule), a dot product of 4 terms within
// γ₄ = 4u/(1 − 4u) of the sum of its terms' magnitudes, η for subnormal results.
constexpr double kU = std::numeric_limits<double>::epsilon() / 2;
constexpr double kGamma4 = 4 * kU * (1 + 8 * kU);
constexpr double kEta = std::numeric_limits<double>::denorm_min();
double norm_inf(const Mat4d& m) { return m.cwiseAbs().rowwise().sum().maxCoeff(); }
double norm_inf(const Vec3d& v) { return v.cwiseAbs().maxCoeff(); }
// ‖fl(a·b) − a_exact·b_exact‖ from the factors' bounds ea, eb (widened for the bound's own
// roundings).
double product_error(const Mat4d& a, double ea, const Mat4d& b, double eb) {
  const double na = norm_inf(a), nb = norm_inf(b);
  return (kGamma4 * na * nb + ea * nb + (na + ea) * eb) * (1 + 8 * kU) + kEta;
}
// An object's matrix, its entries rounded once from the exact composite.
double rounded_error(const Mat4d& m) { return 2 * kU * norm_inf(m) + kEta; }
// T(i·step): each offset fl(i·fl(step)) within 3u of i·step.
double offset_error(const Vec3d& offset) { return 3 * kU * norm_inf(offset) + kEta; }

Vec3d transformed(const Mat4d& m, const Vec3d& p) {
  return (m * Vec4d(p(0), p(1), p(2), 1.0)).head<3>();
}

// Object o's own triangles in the world, each vertex placed by `place`; o counts as an object.
// `error(p, w)`: the bound on |w − w_exact| for the vertex p placed at w (when tracked).
template <typename Place, typename Error>
void emit_triangles(const SceneObject& o, Rgb f, Cull c, const std::string* name, FlatSink& out,
                    const Place& place, const Error& error) {
  const int index = out.objects++;
  if (name) out.names->push_back(*name);
  for (std::size_t k = 0; k < o.triangles.size(); ++k) {
    WorldTriangle t;
    for (int v = 0; v < 3; ++v) {
      const Vec3d& p = o.vertices[static_cast<std::size_t>(o.triangles[k][v])];
      t.v[v] = place(p);
      if (out.track_error) t.error = std::max(t.error, error(p, t.v[v]));
    }
    t.fill = f;
    t.cull = c;
    t.object = index;
    t.face = static_cast<int>(k);
    out.visit(t);
  }
}

// p moved by the translation T(offset), offset finite without −0: the same doubles as T·p.
// T·p's row is 1·x + 0·y + 0·z + t, in whatever order: the ±0 terms leave a sum that is not
// zero as it is, so it is x + t rounded once; and a zero sum includes t (+0 or not zero), so it
// is +0, as x + t is.
Vec3d translated(const Vec3d& offset, const Vec3d& p) { return p + offset; }

void flatten_children(const std::vector<SceneObject>& children, const Mat4d& world_from_object,
                      double error, Rgb f, Cull c, const std::string* name, bool top,
                      FlatSink& out);

// `name` is null when names are not kept; world_from_object = world_from_parent · M_object.
// The walk reads the scene and copies none of it: the exact coordinates a scene object keeps
// (GiNaC's, whose reference counts are not atomic) are never touched, so threads may walk one
// scene side by side.
// `error`: the bound on ‖world_from_object − its exact value‖ (tracked walks only).
void flatten_into(const SceneObject& o, const Mat4d& world_from_object, double error, Rgb fill,
                  Cull cull, const std::string* name, FlatSink& out) {
  const Rgb f = o.fill.value_or(fill);
  const Cull c = o.cull.value_or(cull);
  const double norm = out.track_error ? norm_inf(world_from_object) : 0;
  emit_triangles(
      o, f, c, name, out, [&](const Vec3d& p) { return transformed(world_from_object, p); },
      [&](const Vec3d& p, const Vec3d&) {
        // fl(W·p̃) against W_exact·p_exact, p̃ = (p, 1), p within 2u of its exact value.
        const double np = std::max(1.0, norm_inf(p));
        return ((kGamma4 * norm + error) * np + (norm + error) * 2 * kU * norm_inf(p)) *
                   (1 + 8 * kU) +
               kEta;
      });
  flatten_children(o.children, world_from_object, error, f, c, name, false, out);
}

// The children of an object (`top`: the scene's objects, children of the world, whose unnamed
// ones are "objects[k]"); a repeated child once per copy (its own repeat is not read below it).
void flatten_children(const std::vector<SceneObject>& children, const Mat4d& world_from_object,
                      double error, Rgb f, Cull c, const std::string* name, bool top,
                      FlatSink& out) {
  const bool track = out.track_error;
  std::string child_name;
  for (std::size_t k = 0; k < children.size(); ++k) {
    const SceneObject& child = children[k];
    if (name)
      child_name = !child.name.empty() ? child.name
                   : top               ? "objects[" + std::to_string(k) + "]"
                                       : *name + ".children[" + std::to_string(k) + "]";
    const std::string* child_name_or_null = name ? &child_name : nullptr;
    if (!child.repeat) {
      flatten_into(child, compose(world_from_object, child.transform),
                   track ? product_error(world_from_object, error, child.transform,
                                         rounded_error(child.transform))
                         : 0,
                   f, c, child_name_or_null, out);
      continue;
    }
    // Copies: world_from_object · T(index · step) · M_child.
    const SceneObject::Repeat& r = *child.repeat;
    std::string copy;
    // Neither the parent nor the copy moves anything: each copy's matrix is T(offset) itself
    // (compose's rule, decided once for the repeat instead of twice per copy).
    const bool translation_only = is_identity(world_from_object) && is_identity(child.transform);
    const Rgb own_fill = child.fill.value_or(f);
    const Cull own_cull = child.cull.value_or(c);
    for (int i = r.from[0]; i <= r.to[0]; ++i)
      for (int j = r.from[1]; j <= r.to[1]; ++j)
        for (int l = r.from[2]; l <= r.to[2]; ++l) {
          const Vec3d offset(i * r.step(0), j * r.step(1), l * r.step(2));
          if (name) copy = copy_name(child_name, r, {i, j, l});
          if (translation_only && child.children.empty() && finite_without_negative_zero(offset)) {
            // A copy that only moves (most repeats; identity_keeps(T(offset)) holds): each vertex
            // plus the offset.
            emit_triangles(
                child, own_fill, own_cull, name ? &copy : nullptr, out,
                [&](const Vec3d& p) { return translated(offset, p); },
                [&](const Vec3d& p, const Vec3d& w) {
                  // fl(p + offset): its rounding, p's and the offset's.
                  return (kU * norm_inf(w) + 2 * kU * norm_inf(p) + 3 * kU * norm_inf(offset)) *
                             (1 + 8 * kU) +
                         3 * kEta;
                });
            continue;
          }
          const Mat4d t = translation(offset);
          const bool only_t = translation_only && identity_keeps(t);
          const Mat4d moved = only_t ? t : compose(world_from_object, t);
          double moved_error = 0;
          if (track)
            moved_error = only_t ? offset_error(offset)
                                 : product_error(world_from_object, error, t, offset_error(offset));
          flatten_into(child, only_t ? t : compose(moved, child.transform),
                       track && !only_t ? product_error(moved, moved_error, child.transform,
                                                        rounded_error(child.transform))
                                        : moved_error,
                       f, c, name ? &copy : nullptr, out);
        }
  }
}

// The world: an object of no triangles whose children are the scene's objects.
void flatten_scene(const Scene& scene, const std::string* name, FlatSink& out) {
  ++out.objects;
  if (name) out.names->push_back(*name);
  flatten_children(scene.objects, Mat4d::Identity(), 0, scene.default_fill, Cull::None, name, true,
                   out);
}

}  // namespace

std::size_t world_triangle_count(const Scene& scene) { return flat_size(scene.objects).first; }

void for_each_world_triangle(const Scene& scene,
                             const std::function<void(const WorldTriangle&)>& visit,
                             bool track_error) {
  FlatSink sink{visit};
  sink.track_error = track_error;
  flatten_scene(scene, nullptr, sink);
}

FlatScene flatten(const Scene& scene, bool names, bool track_error) {
  FlatScene out;
  // Sized once: a million triangles are 88 MB, which doubling would copy and fault in again.
  const auto [triangles, objects] = flat_size(scene.objects);
  out.triangles.reserve(triangles);
  if (names) out.objects.reserve(objects + 1);  // the world counts as an object
  const std::function<void(const WorldTriangle&)> keep = [&](const WorldTriangle& t) {
    out.triangles.push_back(t);
  };
  FlatSink sink{keep, names ? &out.objects : nullptr};
  sink.track_error = track_error;
  const std::string world = "world";
  flatten_scene(scene, names ? &world : nullptr, sink);
  return out;
}

Mat4d eye_from_world(const Scene& scene) {
  return to_mat4(look_at<double>(scene.camera.eye, scene.camera.center, scene.camera.up,
                                 scene.left_handed ? Api::DirectX : scene.api));
}

Mat4d clip_from_world(const Scene& scene) { return scene.clip_from_eye * eye_from_world(scene); }

bool inside_volume(const std::array<Vec4d, 3>& clip, Api api) {
  const bool zero = api == Api::DirectX;
  bool inside = true;
  for (const Vec4d& c : clip) {
    const double w = c(3);
    inside = inside && w >= kClipEpsilon && std::abs(c(0)) <= w && std::abs(c(1)) <= w &&
             c(2) <= w && (zero ? c(2) >= 0 : c(2) >= -w);
  }
  return inside;
}

std::vector<Vec4d> clip_to_volume(const std::array<Vec4d, 3>& clip, Api api) {
  if (inside_volume(clip, api)) return {clip[0], clip[1], clip[2]};
  return clip_polygon_homogeneous<double, false>({clip[0], clip[1], clip[2]}, kClipEpsilon,
                                                 api == Api::DirectX)
      .clipped;
}

Vec3d to_raster(const Vec3d& ndc, int width, int height, Api api) {
  Vec3d w = viewport<double>(ndc, width, height, api);
  if (window_y_down(api)) w(1) = height - w(1);
  return w;
}

double raster_area2(const std::vector<Vec3d>& p) {
  double s = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3d& a = p[i];
    const Vec3d& b = p[(i + 1) % p.size()];
    s += a(0) * b(1) - a(1) * b(0);
  }
  return s;
}

bool front_facing(double area2, Api api) { return api == Api::OpenGL ? area2 > 0 : area2 < 0; }

Rgb shade(const WorldTriangle& t, bool front, const std::optional<DirectionalLight>& light,
          bool left_handed) {
  if (!light) return t.fill;
  Vec3d n = (t.v[1] - t.v[0]).cross(t.v[2] - t.v[0]);
  const double len = n.norm();
  double ndotl = 0;
  if (len > 0 && light->direction.norm() > 0) {
    n /= len;
    if (!front != left_handed) n = -n;  // two-sided: the side the viewer sees
    ndotl = std::max(0.0, n.dot(-light->direction.normalized()));
  }
  const double k = (light->ambient + light->diffuse * ndotl) / 255.0;
  auto channel = [&](std::uint8_t c) {
    return static_cast<std::uint8_t>(std::clamp(std::lround(c * k), 0L, 255L));
  };
  return {channel(t.fill.r), channel(t.fill.g), channel(t.fill.b)};
}

GeometryStage::GeometryStage(const Scene& scene, FrameCertifier* certifier)
    : scene_(scene),
      certifier_(certifier),
      clip_from_world_(clip_from_world(scene)),
      keep_(certifier && certifier->keeps()) {}

void GeometryStage::add(const WorldTriangle& t, int source, std::vector<WindowTriangle>& out) {
  if (certifier_) {
    add_certified(t, source, out);
    return;
  }
  GeometryStats& s = stats;
  ++s.triangles;
  const Mat4d& m = clip_from_world_;
  const std::array<Vec4d, 3> clip{to_clip(m, t.v[0]), to_clip(m, t.v[1]), to_clip(m, t.v[2])};
  // Inside (the common case): the triangle itself, with no allocation.
  if (inside_volume(clip, scene_.api)) {
    polygon_.assign(clip.begin(), clip.end());
  } else {
    polygon_ = clip_to_volume(clip, scene_.api);
    if (polygon_.size() < 3) {
      ++s.outside;
      return;
    }
    if (polygon_.size() != 3 || polygon_[0] != clip[0] || polygon_[1] != clip[1] ||
        polygon_[2] != clip[2])
      ++s.clipped;
  }
  raster_.clear();
  for (const Vec4d& c : polygon_)
    raster_.push_back(to_raster(perspective_divide(c), scene_.width, scene_.height, scene_.api));
  const bool front = front_facing(raster_area2(raster_), scene_.api);
  if (!front && t.cull == Cull::Back) {
    ++s.culled;
    return;
  }
  const Rgb color = shade(t, front, scene_.light, scene_.left_handed);
  // A clipped polygon is convex: a fan from its first vertex.
  for (std::size_t v = 1; v + 1 < raster_.size(); ++v) {
    out.push_back({{raster_[0], raster_[v], raster_[v + 1]}, color, source, front});
    ++s.window;
  }
}

void GeometryStage::add_certified(const WorldTriangle& t, int source,
                                  std::vector<WindowTriangle>& out) {
  GeometryStats& s = stats;
  ++s.triangles;
  certifier_->window(t, certified_);
  s.exact += certified_.exact;
  if (certified_.outside) {
    ++s.outside;
    return;
  }
  s.clipped += certified_.clipped;
  if (!certified_.front && t.cull == Cull::Back) {
    ++s.culled;
    return;
  }
  const Rgb color = shade(t, certified_.front, scene_.light, scene_.left_handed);
  const std::vector<Vec3d>& r = certified_.raster;
  for (std::size_t v = 1; v + 1 < r.size(); ++v) {
    out.push_back(
        {{r[0], r[v], r[v + 1]}, color, source, certified_.front, certified_.depth_error});
    if (keep_) {
      if (kept.empty()) kept.reserve(kBandedTriangles / 8);
      kept.push_back({out.back(), t.object, t.face, static_cast<int>(v) - 1});
    }
    ++s.window;
  }
}

std::vector<WindowTriangle> geometry(const Scene& scene, const FlatScene& flat,
                                     GeometryStats* stats, FrameCertifier* certifier) {
  std::vector<WindowTriangle> out;
  out.reserve(flat.triangles.size());
  GeometryStage stage(scene, certifier);
  for (std::size_t k = 0; k < flat.triangles.size(); ++k)
    stage.add(flat.triangles[k], static_cast<int>(k), out);
  if (stats) *stats = stage.stats;
  if (certifier) certifier->keep(std::move(stage.kept));
  return out;
}

}  // namespace frustum
