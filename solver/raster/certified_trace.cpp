#include "solver/raster/certified_trace.hpp"

#include <cmath>
#include <map>
#include <stdexcept>

#include "solver/clipping/polygon_clip.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

// Clipping ranged polygons with clip_polygon_homogeneous itself (its dependent calls find
// these): a sign the radius does not prove stops the ranged attempt.
struct Unproven {};
static int scalar_sign(const Ranged<double>& x) {
  if (const int s = x.proven_sign()) return s;
  throw Unproven{};
}
static Ranged<double> tidy(const Ranged<double>& x) { return x; }

namespace {

using R = Ranged<double>;

// A sign the scalar proves: ranged values when |value| exceeds the radius, exact ones always.
std::optional<int> decided_sign(const R& x) {
  if (const int s = x.proven_sign()) return s;
  return std::nullopt;
}
std::optional<int> decided_sign(const Exact& x) { return exact_sign(x); }

}  // namespace

std::optional<std::int64_t> decided_snap(const Ranged<double>& x) {
  if (!std::isfinite(x.v) || !std::isfinite(x.r) || std::abs(x.v) > kMaxWindowCoordinate)
    return std::nullopt;
  const auto scale = static_cast<double>(kSubpixelScale);
  const std::int64_t k = to_fixed(x.v);
  // |x·2⁸ − k| < ½ for every x within the radius (x.v·2⁸ and its difference to k are exact).
  if ((std::abs(x.v * scale - static_cast<double>(k)) + x.r * scale) * (1 + 1e-12) < 0.5) return k;
  return std::nullopt;
}

namespace {

std::optional<std::int64_t> decided_snap(const Exact& x) {
  bool off_grid = false;
  return to_fixed(x, off_grid);
}

template <typename T>
T tidied(const T& x) {
  if constexpr (kIsExact<T>)
    return canonical(x);
  else
    return x;
}

// Signed distance of a clip-space vertex to plane k of the view volume (inside ≥ 0), in the
// order clip_polygon_homogeneous clips: w ≥ ε, x ≥ −w, x ≤ w, y ≥ −w, y ≤ w, z ≥ −w (z ≥ 0
// under DirectX), z ≤ w.
constexpr int kPlanes = 7;
template <typename T>
T plane_distance(const Vec4<T>& c, int k, bool z_from_zero, const T& eps) {
  switch (k) {
    case 0:
      return c(3) - eps;
    case 1:
      return c(0) + c(3);
    case 2:
      return c(3) - c(0);
    case 3:
      return c(1) + c(3);
    case 4:
      return c(3) - c(1);
    case 5:
      return z_from_zero ? c(2) : T(c(2) + c(3));
    default:
      return c(3) - c(2);
  }
}

}  // namespace

template <typename T>
std::optional<Outcome<T>> window_polygon(const std::array<Vec4<T>, 3>& clip, const Scene& s,
                                         const T& eps) {
  Outcome<T> out;
  if (!window_polygon_into(clip, s, eps, out)) return std::nullopt;
  return out;
}

template <typename T>
bool window_polygon_into(const std::array<Vec4<T>, 3>& clip, const Scene& s, const T& eps,
                         Outcome<T>& out, bool facing) {
  out.outside = out.clipped = out.front = false;
  out.snapped.clear();
  out.z.clear();
  const bool zero = s.api == Api::DirectX;
  // Trivially outside (all three beyond one plane) or inside (all within every plane).
  bool inside = true;
  for (int k = 0; k < kPlanes; ++k) {
    int beyond = 0;
    for (const Vec4<T>& c : clip) {
      const std::optional<int> d = decided_sign(tidied(plane_distance(c, k, zero, eps)));
      inside = inside && d && *d >= 0;
      beyond += d && *d < 0;
    }
    if (beyond == 3) {
      out.outside = true;
      return true;
    }
  }
  std::vector<Vec4<T>>& polygon = out.polygon;
  polygon.assign(clip.begin(), clip.end());
  if (!inside) {
    try {
      polygon = clip_polygon_homogeneous<T>(polygon, eps, zero).clipped;
    } catch (const Unproven&) {
      return false;  // a vertex within rounding of a plane: clipped exactly
    }
    out.clipped = true;
    if (polygon.size() < 3) {
      out.outside = true;
      return true;
    }
  }
  // Divide, viewport, y-up raster rows (pipeline.hpp's to_raster).
  std::vector<Vec2<T>>& xy = out.xy;
  xy.clear();
  for (const Vec4<T>& c : polygon) {
    const Vec3<T> ndc(tidied(T(c(0) / c(3))), tidied(T(c(1) / c(3))), tidied(T(c(2) / c(3))));
    Vec3<T> w = viewport<T>(ndc, T(s.width), T(s.height), s.api);
    if (window_y_down(s.api)) w(1) = T(s.height) - w(1);
    for (int a = 0; a < 3; ++a) w(a) = tidied(w(a));
    xy.emplace_back(w(0), w(1));
    out.z.push_back(w(2));
    const std::optional<std::int64_t> x = decided_snap(w(0)), y = decided_snap(w(1));
    if (!x || !y) return false;
    out.snapped.push_back({*x, *y});
  }
  // Facing (pipeline.hpp's front_facing): the sign of the unsnapped raster area; edge-on is not
  // front.
  if (!facing) {
    out.front = true;
    return true;
  }
  const std::optional<int> area = decided_sign(tidied(twice_signed_area(xy)));
  if (!area) return false;
  out.front = s.api == Api::OpenGL ? *area > 0 : *area < 0;
  return true;
}

template bool window_polygon_into(const std::array<Vec4<R>, 3>&, const Scene&, const R&,
                                  Outcome<R>&, bool);
template std::optional<Outcome<R>> window_polygon(const std::array<Vec4<R>, 3>&, const Scene&,
                                                  const R&);
template std::optional<Outcome<Exact>> window_polygon(const std::array<Vec4<Exact>, 3>&,
                                                      const Scene&, const Exact&);

template <typename T>
T depth_at_centre(const TriangleSetup& t, const std::array<T, 3>& z, int i, int j) {
  const FixedPoint2 p = pixel_centre(i, j);
  auto integer = [](std::int64_t n) {
    if constexpr (kIsExact<T>)
      return Exact(GiNaC::numeric(static_cast<long>(n)));
    else
      return R::input(static_cast<double>(n));
  };
  T sum = T(0);
  for (int k = 0; k < 3; ++k)
    sum += z[static_cast<std::size_t>(t.order[k])] * integer(t.edge[k].at(p.x, p.y));
  return tidied(T(sum / integer(t.area2)));
}
template R depth_at_centre(const TriangleSetup&, const std::array<R, 3>&, int, int);
template Exact depth_at_centre(const TriangleSetup&, const std::array<Exact, 3>&, int, int);

namespace {

Mat4<Exact> product(const Mat4<Exact>& a, const Mat4<Exact>& b) {
  Mat4<Exact> m = a * b;
  for (Exact& e : m.reshaped()) e = canonical(e);
  return m;
}

void place(const std::vector<SceneObject>& children, const Mat4<Exact>& world_from_parent,
           std::vector<ExactPlacement>& out);

void place_one(const SceneObject& o, const Mat4<Exact>& world_from_parent,
               std::vector<ExactPlacement>& out) {
  const Mat4<Exact> world_from_object = product(world_from_parent, o.exact_transform);
  out.push_back({&o, world_from_object});
  place(o.children, world_from_object, out);
}

// flatten()'s walk: children in order, the copies of a repeat in index order at
// world_from_parent · T(index · step).
void place(const std::vector<SceneObject>& children, const Mat4<Exact>& world_from_parent,
           std::vector<ExactPlacement>& out) {
  for (const SceneObject& child : children) {
    if (!child.repeat) {
      place_one(child, world_from_parent, out);
      continue;
    }
    const SceneObject::Repeat& r = *child.repeat;
    for (int i = r.from[0]; i <= r.to[0]; ++i)
      for (int j = r.from[1]; j <= r.to[1]; ++j)
        for (int l = r.from[2]; l <= r.to[2]; ++l) {
          Mat4<Exact> move = Mat4<Exact>::Identity();
          const int at[3] = {i, j, l};
          for (int a = 0; a < 3; ++a) move(a, 3) = canonical(at[a] * child.exact_step(a));
          place_one(child, product(world_from_parent, move), out);
        }
  }
}

// The clip coordinates of a flat triangle's vertices, exactly.
std::array<Vec4<Exact>, 3> exact_clip(const CertifiedScene& cs, const FlatScene& flat, int source) {
  const WorldTriangle& t = flat.triangles[static_cast<std::size_t>(source)];
  const auto o = static_cast<std::size_t>(t.object);
  const SceneObject& object = *cs.placements[o].object;
  std::array<Vec4<Exact>, 3> out;
  for (int v = 0; v < 3; ++v) {
    const Vec3<Exact>& p = object.exact_vertices[static_cast<std::size_t>(
        object.triangles[static_cast<std::size_t>(t.face)][v])];
    out[static_cast<std::size_t>(v)] = cs.clip_from_object[o] * Vec4<Exact>(p(0), p(1), p(2), 1);
    for (int a = 0; a < 4; ++a)
      out[static_cast<std::size_t>(v)](a) = canonical(out[static_cast<std::size_t>(v)](a));
  }
  return out;
}

// The same ranged, from the exact inputs rounded once (the vertices' doubles and
// clip_from_object's entries).
std::array<Vec4<R>, 3> ranged_clip(const Mat4<R>& clip_from_object, const SceneObject& object,
                                   int face) {
  std::array<Vec4<R>, 3> out;
  for (int v = 0; v < 3; ++v) {
    const Vec3d& p = object.vertices[static_cast<std::size_t>(
        object.triangles[static_cast<std::size_t>(face)][v])];
    out[static_cast<std::size_t>(v)] =
        clip_from_object * Vec4<R>(R::input(p(0)), R::input(p(1)), R::input(p(2)), R(1));
  }
  return out;
}

Exact exact_epsilon() { return exact_from_double(kClipEpsilon); }

Outcome<Exact> exact_outcome(const CertifiedScene& cs, const FlatScene& flat, const Scene& s,
                             int source) {
  return *window_polygon<Exact>(exact_clip(cs, flat, source), s, exact_epsilon());
}

}  // namespace

std::vector<ExactPlacement> exact_placements(const Scene& scene) {
  std::vector<ExactPlacement> out{
      {nullptr, Mat4<Exact>::Identity()}};  // the world (flatten's root)
  place(scene.objects, Mat4<Exact>::Identity(), out);
  return out;
}

CertifiedScene certified_geometry(const Scene& scene, const FlatScene& flat,
                                  const Mat4<Exact>& clip_from_world) {
  CertifiedScene cs;
  cs.placements = exact_placements(scene);
  if (cs.placements.size() != flat.objects.size())
    throw std::logic_error("certified_geometry: placements differ from flatten()");
  std::vector<Mat4<R>> ranged(cs.placements.size());
  for (std::size_t o = 0; o < cs.placements.size(); ++o) {
    cs.clip_from_object.push_back(product(clip_from_world, cs.placements[o].world_from_object));
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        ranged[o](i, j) = R::input(to_double(cs.clip_from_object[o](i, j)));
  }
  const R eps(kClipEpsilon, 0);
  GeometryStats& st = cs.stats;
  for (std::size_t k = 0; k < flat.triangles.size(); ++k) {
    const WorldTriangle& t = flat.triangles[k];
    const auto o = static_cast<std::size_t>(t.object);
    const SceneObject& object = *cs.placements[o].object;
    if (object.exact_vertices.size() != object.vertices.size())
      throw std::logic_error("certified_geometry: the scene was read without its exact inputs");
    ++st.triangles;
    // The ranged pipeline decides; the exact one where it cannot.
    std::optional<Outcome<R>> out =
        window_polygon<R>(ranged_clip(ranged[o], object, t.face), scene, eps);
    std::optional<Outcome<Exact>> exact;
    if (!out) {
      exact = exact_outcome(cs, flat, scene, static_cast<int>(k));
      ++cs.exact_geometry;
      out = Outcome<R>{exact->outside, exact->clipped, exact->front, exact->snapped, {}, {}, {}};
      for (const Exact& z : exact->z) out->z.push_back(R::input(to_double(z)));
    }
    if (out->outside) {
      ++st.outside;
      continue;
    }
    st.clipped += out->clipped;
    if (!out->front && t.cull == Cull::Back) {
      ++st.culled;
      continue;
    }
    const Rgb color = shade(t, out->front, scene.light, scene.left_handed);
    for (std::size_t v = 1; v + 1 < out->snapped.size(); ++v) {
      CertifiedPiece p;
      setup_fixed({out->snapped[0], out->snapped[v], out->snapped[v + 1]}, p.setup);
      p.fan = static_cast<int>(v) - 1;
      p.z = fan_depths(out->z, p.fan);
      if (exact) p.exact_z = fan_depths(exact->z, p.fan);
      p.color = color;
      p.source = static_cast<int>(k);
      p.front = out->front;
      cs.pieces.push_back(p);
      ++st.window;
    }
  }
  return cs;
}

PixelTrace certified_trace(CertifiedScene& cs, const Scene& s, const FlatScene& flat, int i, int j,
                           bool& exact_depths) {
  PixelTrace p;
  p.i = i;
  p.j = j;
  p.color = s.background;
  std::map<int, Outcome<Exact>> exact;  // per source triangle, computed when first needed
  auto exact_z = [&](CertifiedPiece& piece) -> const std::array<Exact, 3>& {
    if (!piece.exact_z) {
      auto it = exact.find(piece.source);
      if (it == exact.end())
        it = exact.emplace(piece.source, exact_outcome(cs, flat, s, piece.source)).first;
      piece.exact_z = fan_depths(it->second.z, piece.fan);
    }
    return *piece.exact_z;
  };
  R stored(1, 0);  // the cleared buffer: exactly 1
  int stored_piece = -1;
  for (std::size_t k = 0; k < cs.pieces.size(); ++k) {
    CertifiedPiece& piece = cs.pieces[k];
    const TriangleSetup& t = piece.setup;
    if (i < t.i_min || i > t.i_max || j < t.j_min || j > t.j_max || !covers(t, i, j)) continue;
    const R z = depth_at_centre(t, piece.z, i, j);
    // Written when z < stored: the ranged difference, else the exact depths.
    const SignDecision d = decide_sign(R(z - stored), [&] {
      const Exact zs =
          stored_piece < 0
              ? Exact(1)
              : depth_at_centre(cs.pieces[static_cast<std::size_t>(stored_piece)].setup,
                                exact_z(cs.pieces[static_cast<std::size_t>(stored_piece)]), i, j);
      return exact_sign(canonical(depth_at_centre(t, exact_z(piece), i, j) - zs));
    });
    exact_depths = exact_depths || d.exact;
    Competitor c{static_cast<int>(k), static_cast<float>(z.v), d.sign < 0};
    if (c.passed) {
      stored = z;
      stored_piece = static_cast<int>(k);
    }
    p.add(c, piece.color);
  }
  return p;
}

}  // namespace frustum
