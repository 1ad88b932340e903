// Sutherland–Hodgman polygon clipping (Foley et al. §3.14): the polygon is clipped against one
// plane at a time, each stage feeding the next; a stage keeps the side where the plane's
// signed distance d(v) ≥ 0 (a vertex on the plane is kept). For an edge S → E:
//   E inside:  output the intersection I first when S is strictly outside (d(S) < 0) and E is
//              strictly inside (else I = E), then E;
//   E outside: output I when S is strictly inside (d(S) > 0).
// So no vertex is repeated. Three variants: a 2D window, a 3D box, and homogeneous clip
// space (−w ≤ x, y, z ≤ w and w ≥ ε, before any divide).
#pragma once

#include <string>
#include <vector>

#include "solver/clipping/clip_box.hpp"

namespace frustum {

template <typename V>
struct PolygonClipStage {
  std::string plane;        // "left: x ≥ xmin", "x ≥ −w"
  std::vector<V> vertices;  // the polygon after this stage
};

template <typename V>
struct PolygonClipResult {
  std::vector<PolygonClipStage<V>> stages;  // one per clip plane, in order
  std::vector<V> clipped;                   // the last stage's vertices; < 3 = nothing left
  bool empty() const { return clipped.size() < 3; }
};

// One stage: `dist(v)` is the signed distance (inside ≥ 0); `on_plane(v)` snaps an
// intersection onto the plane exactly (a coordinate set to the boundary).
template <typename V, typename Dist, typename OnPlane>
std::vector<V> clip_polygon_stage(const std::vector<V>& in, Dist dist, OnPlane on_plane) {
  using T = typename V::Scalar;
  std::vector<V> out;
  const std::size_t n = in.size();
  if (n == 0) return out;
  std::vector<T> d(n);
  std::vector<int> s(n);
  for (std::size_t i = 0; i < n; ++i) {
    d[i] = tidy(T(dist(in[i])));
    s[i] = scalar_sign(d[i]);
  }
  auto intersection = [&](std::size_t a, std::size_t b) {
    const T t = tidy(T(d[a] / (d[a] - d[b])));
    V v = in[a] + (in[b] - in[a]) * t;
    for (int k = 0; k < v.size(); ++k) v(k) = tidy(T(v(k)));
    on_plane(v);
    return v;
  };
  for (std::size_t e = 0; e < n; ++e) {
    const std::size_t sv = (e + n - 1) % n;  // S → E
    if (s[e] >= 0) {
      if (s[sv] < 0 && s[e] > 0) out.push_back(intersection(sv, e));
      out.push_back(in[e]);
    } else if (s[sv] > 0) {
      out.push_back(intersection(sv, e));
    }
  }
  return out;
}

// Against the box lo ≤ p ≤ hi: left, right, bottom, top (then z ≥ zmin, z ≤ zmax in 3D).
template <typename T, int N>
PolygonClipResult<Eigen::Matrix<T, N, 1>> clip_polygon_box(
    const std::vector<Eigen::Matrix<T, N, 1>>& polygon, const ClipBox<T, N>& box) {
  using V = Eigen::Matrix<T, N, 1>;
  static const char* names[3][2] = {{"left: x ≥ xmin", "right: x ≤ xmax"},
                                    {"bottom: y ≥ ymin", "top: y ≤ ymax"},
                                    {"z ≥ zmin", "z ≤ zmax"}};
  PolygonClipResult<V> r;
  std::vector<V> current = polygon;
  for (int a = 0; a < N; ++a)
    for (int high = 0; high < 2; ++high) {
      const T bound = high ? box.hi(a) : box.lo(a);
      current = clip_polygon_stage(
          current, [&](const V& v) { return high ? T(bound - v(a)) : T(v(a) - bound); },
          [&](V& v) { v(a) = bound; });
      r.stages.push_back({names[a][high], current});
    }
  r.clipped = current;
  return r;
}

// Homogeneous clip space, before the perspective divide: first w ≥ ε (so no later vertex has
// w ≤ 0: every later vertex is a convex combination of vertices with w ≥ ε), then
// x ≥ −w, x ≤ w, y ≥ −w, y ≤ w, z ≥ −w (0 ≤ z with `z_from_zero`, DirectX), z ≤ w.
// Without kStages only the clipped polygon is kept (the renderer's path: the same arithmetic,
// none of the stages' names and copies).
template <typename T, bool kStages = true>
PolygonClipResult<Vec4<T>> clip_polygon_homogeneous(const std::vector<Vec4<T>>& polygon,
                                                    const T& epsilon, bool z_from_zero = false) {
  PolygonClipResult<Vec4<T>> r;
  std::vector<Vec4<T>> current = clip_polygon_stage(
      polygon, [&](const Vec4<T>& v) { return T(v(3) - epsilon); },
      [&](Vec4<T>& v) { v(3) = epsilon; });
  if constexpr (kStages) r.stages.push_back({"w ≥ ε", current});
  static const char* names[3][2] = {{"x ≥ −w", "x ≤ w"}, {"y ≥ −w", "y ≤ w"}, {"z ≥ −w", "z ≤ w"}};
  for (int a = 0; a < 3; ++a)
    for (int high = 0; high < 2; ++high) {
      const bool zero = a == 2 && !high && z_from_zero;
      current = clip_polygon_stage(
          current,
          [&](const Vec4<T>& v) { return high   ? T(v(3) - v(a))
                                         : zero ? T(v(a))
                                                : T(v(a) + v(3)); },
          [&](Vec4<T>& v) { v(a) = high   ? v(3)
                                   : zero ? T(0)
                                          : T(-v(3)); });
      if constexpr (kStages)
        r.stages.push_back({zero ? std::string("z ≥ 0") : std::string(names[a][high]), current});
    }
  r.clipped = std::move(current);
  return r;
}

// Twice the signed area of a 2D polygon (shoelace; counter-clockwise positive).
template <typename T>
T twice_signed_area(const std::vector<Vec2<T>>& p) {
  T s = T(0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2<T>& a = p[i];
    const Vec2<T>& b = p[(i + 1) % p.size()];
    s += a(0) * b(1) - a(1) * b(0);
  }
  return s;
}

}  // namespace frustum
