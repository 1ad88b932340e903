// The depth-sort (painter's) algorithm of seeds 001 and 003 and where it fails. Polygons are
// sorted by the depth of their centroids g = (p₀ + … + p_{n−1})/n and drawn back to front;
// a pair of polygons is a conflict when their projections overlap and that order is wrong:
// the true order over the overlap disagrees (the centroid order fails), the polygons
// interpenetrate (貫通), a concave polygon wraps around the other (no whole-polygon order
// exists), or the pair lies on a cycle of "must be drawn before" (三すくみ).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/core/matrix.hpp"

namespace frustum {

// The viewer: an eye point (perspective) or a view direction (orthographic; the direction
// the viewer looks, from the eye into the scene).
struct DepthViewer {
  std::optional<Vec3<Exact>> eye;
  std::optional<Vec3<Exact>> view_direction;
};

// How two polygons i < j relate where their projections overlap.
enum class PairOrder {
  FirstBehind,       // i is farther over the whole overlap: draw i before j
  SecondBehind,      // j is farther: draw j before i
  Interpenetrating,  // the depth order changes inside one convex piece: they intersect
  WrapsAround,       // different pieces disagree (a concave polygon): split to draw them
  Coplanar           // equal depth over the overlap: any order
};

struct PlaneTests {
  // Newell's tests, each "all vertices of A on the far (near) side of B's plane, seen from
  // the eye" (vertices in the plane allowed).
  bool i_behind_plane_j = false;  // i entirely on the far side of j's plane
  bool i_front_plane_j = false;   // i entirely on the near side of j's plane
  bool j_behind_plane_i = false;
  bool j_front_plane_i = false;
};

struct PairReport {
  int i = 0, j = 0;  // i < j
  PairOrder order = PairOrder::Coplanar;
  PlaneTests planes;
  bool cyclic = false;
  bool conflict = false;
  bool centroid_tie = false;  // a conflict of a nearer polygon whose centroid is as far
  std::string reason;         // why the pair conflicts (empty when it does not)
  std::string name() const;   // "i-j"
};

struct DepthSortResult {
  std::vector<Vec3<Exact>> centroids;
  std::vector<Exact> depths;            // larger = farther
  std::vector<int> order;               // back to front (stable for equal depths)
  std::vector<PairReport> overlapping;  // every pair whose projections overlap (positive area)
  std::vector<int> edge_on;             // polygons seen edge-on (no area on screen)
  std::vector<std::string> conflicts;   // "i-j", sorted
  std::string projection;               // how overlap was decided, in a sentence
};

// Throws DomainError naming "view_direction" (zero vector), "eye" (a vertex not in front of
// the eye) or "polygons[k]" (a degenerate polygon).
DepthSortResult depth_sort(const std::vector<Polygon3<Exact>>& polygons, const DepthViewer& viewer);

}  // namespace frustum
