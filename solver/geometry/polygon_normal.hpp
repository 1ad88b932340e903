// Normals of polygons. seed 003: n = e_i × e_{i+1} with e_i = p_{i+1} − p_i, counter-clockwise
// seen from the front; its error grows when the edges are near-parallel or near-zero, so
// polygons of more than three vertices use Newell's method (exact for planar polygons, the
// area-weighted normal) and the analysis below warns about the hard cases.
#pragma once

#include "solver/geometry/vec.hpp"

#include <cstddef>
#include <string>
#include <vector>

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

// What can go wrong with a polygon's normal, found on the exact input.
struct PolygonAnalysis {
  bool degenerate = false;             // zero normal: all vertices collinear or coincident
  std::vector<std::size_t> zero_edges; // e_i = 0 (repeated vertex)
  std::size_t worst_pair = 0;          // edge pair with the smallest sine
  double min_sine = 1.0;               // smallest |e_i × e_{i+1}| / (|e_i| |e_{i+1}|)
  bool planar = true;
  std::size_t off_plane_vertex = 0;    // first vertex off the plane of the normal
  double condition = 1.0;              // ≈ 1 / min_sine: digits lost in e_i × e_{i+1}
};

// Below this sine the edge pair is nearly parallel and a float normal loses its digits.
inline constexpr double kNearParallelSine = 1e-6;

PolygonAnalysis analyse_polygon(const Polygon3<Exact>& p);

}  // namespace frustum
