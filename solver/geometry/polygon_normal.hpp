// Normals of polygons. seed 003: n = e_i × e_{i+1} with e_i = p_{i+1} − p_i, counter-clockwise
// seen from the front; its error grows when the edges are near-parallel or near-zero, so
// polygons of more than three vertices use Newell's method (exact for planar polygons, the
// area-weighted normal) and the analysis below warns about the hard cases.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "solver/core/matrix.hpp"

namespace frustum {

// Edge vector e_i = p_{i+1} − p_i (indices wrap).
template <typename T>
Vec3<T> edge(const Polygon3<T>& p, std::size_t i) {
  return p[(i + 1) % p.size()] - p[i % p.size()];
}

// seed 003's formula: n = e_i × e_{i+1}.
template <typename T>
Vec3<T> edge_pair_normal(const Polygon3<T>& p, std::size_t i) {
  return edge(p, i).cross(edge(p, i + 1));
}

// Newell's method: n = Σ (p_i − p_0) × (p_{i+1} − p_0), twice the vector area. Taking the
// vertices relative to p_0 keeps large offsets (1e8) from swamping small features (1e-8).
// For a triangle it equals e_0 × e_1 exactly.
template <typename T>
Vec3<T> newell_normal(const Polygon3<T>& p) {
  Vec3<T> n = Vec3<T>::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) n += (p[i] - p[0]).cross(p[i + 1] - p[0]);
  return n;
}

// The polygon normal every path computes (the numeric backends, on offsets from p₀ scaled by a
// power of two; the exact backend; the exact solve): e₀ × e₁ for a triangle (seed 003),
// Newell's sum otherwise. The two agree for a triangle.
template <typename T>
Vec3<T> polygon_normal_formula(const Polygon3<T>& p) {
  return p.size() == 3 ? edge_pair_normal(p, 0) : newell_normal(p);
}

// The edge pair whose cross product is computed most accurately: the smallest estimated
// relative error (S·(‖e‖ + ‖f‖) + ‖e‖‖f‖) / ‖e × f‖, S the largest coordinate (rounding of the
// vertices and of the products, both relative to the product's size). A near-zero edge or a
// nearly parallel pair scores badly; for a triangle, where every pair has the same exact
// product, it picks the two shortest edges (the largest angle). Floating-point scalars only
// (the exact backend has no rounding to avoid).
template <typename T>
Vec3<T> best_edge_pair_normal(const Polygon3<T>& p) {
  T scale = T(0);
  for (const Vec3<T>& v : p) scale = std::max(scale, v.cwiseAbs().maxCoeff());
  Vec3<T> best = Vec3<T>::Zero();
  T best_error = T(-1);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3<T> e = edge(p, i), f = edge(p, i + 1);
    const Vec3<T> n = e.cross(f);
    const T size = n.norm();
    if (!(size > T(0))) continue;
    const T error = (scale * (e.norm() + f.norm()) + e.norm() * f.norm()) / size;
    if (best_error < T(0) || error < best_error) {
      best_error = error;
      best = n;
    }
  }
  return best;
}

// What can go wrong with a polygon's normal, found on the exact input.
struct PolygonAnalysis {
  bool degenerate = false;              // zero normal: all vertices collinear or coincident
  std::vector<std::size_t> zero_edges;  // e_i = 0 (repeated vertex)
  std::size_t worst_pair = 0;           // edge pair with the smallest sine
  double min_sine = 1.0;                // smallest |e_i × e_{i+1}| / (|e_i| |e_{i+1}|)
  bool planar = true;
  std::size_t off_plane_vertex = 0;  // first vertex off the plane of the normal
  double condition = 1.0;            // ≈ 1 / min_sine: digits lost in e_i × e_{i+1}
};

// Below this sine the edge pair is nearly parallel and a float normal loses its digits.
inline constexpr double kNearParallelSine = 1e-6;

PolygonAnalysis analyse_polygon(const Polygon3<Exact>& p);

}  // namespace frustum
