// Exact-structure hidden-line removal per segment (seed 003, 隠線消去): every edge of a mesh is
// split where other faces cover it as seen from the eye. A point X on edge a → b is covered by
// a face triangle pqr when the ray from X to the eye passes through the triangle's interior:
//   X inside the three wedges (eye, p, q), (eye, q, r), (eye, r, p), and
//   X and the eye strictly on opposite sides of the triangle's plane.
// Each condition is the sign of orient3d(…, X), which is affine along the edge, so each is a
// half-line in t (X = a + t(b − a)) and a triangle covers one interval of t. The side of each
// end point is decided by the exact predicate orient3d_sign (on the double coordinates); only
// the cut positions t* = g(a)/(g(a) − g(b)) are rounded. Touching (a zero orient3d) never
// covers, so an edge meeting a face at a shared vertex is not hidden by it. Covered intervals
// shorter than kMinSpan are dropped as rounding slivers.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "solver/visibility/edge_classes.hpp"

namespace frustum {

inline constexpr double kMinSpan = 1e-9;
// Edge–triangle pairs tested in one picture: every edge that is not back–back against every face
// triangle is quadratic in the mesh (a few thousand faces would take tens of seconds, and a mesh
// may have 100 000).
inline constexpr std::int64_t kMaxHiddenLinePairs = 2'000'000;

using Interval = std::pair<double, double>;  // [t0, t1] ⊂ [0, 1]

// A face cut into triangles (ear clipping in the face's plane), in doubles.
struct Occluder {
  std::array<Eigen::Vector3d, 3> v;
  int face = 0;
};
std::vector<Occluder> face_triangles(const Mesh& m);

// The part of segment a → b that triangle `o` covers from `eye` (empty when none).
std::vector<Interval> covered_by(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                 const Eigen::Vector3d& eye, const Occluder& o);
// Sorted union of intervals, merging those that touch or overlap; slivers dropped.
std::vector<Interval> merge_intervals(std::vector<Interval> spans);

struct EdgeSpan {
  double t0 = 0, t1 = 1;
  bool visible = true;
};

struct EdgeLines {
  MeshEdge edge;
  EdgeClass cls = EdgeClass::Visible;
  std::vector<EdgeSpan>
      spans;  // in order from vertex i (t = 0) to vertex j (t = 1), covering [0, 1]
  bool split() const { return spans.size() > 1; }
};

struct HiddenLines {
  std::vector<FaceTest> faces;
  std::vector<EdgeLines> edges;
  int split_edges = 0;  // edges partly visible, partly covered
};

// Every edge of a closed, consistently oriented mesh (check_mesh passed): its class from the
// two faces it joins, and its visible and covered spans against every face that does not
// contain it. A back–back (hidden) edge is one covered span. More than kMaxHiddenLinePairs pairs
// (`max_pairs`, lower for a bounded test or fuzz run) to test: DomainError("mesh.faces") naming
// the limit, before any is tested.
HiddenLines hidden_lines(const Mesh& m, const Vec3<Exact>& eye,
                         std::int64_t max_pairs = kMaxHiddenLinePairs);

}  // namespace frustum
