#include "solver/geometry/polygon_normal.hpp"

#include <cmath>

namespace frustum {

PolygonAnalysis analyse_polygon(const Polygon3<Exact>& p) {
  PolygonAnalysis a;
  const std::size_t n = p.size();
  if (n < 3) {
    a.degenerate = true;
    return a;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3<Exact> e = edge(p, i);
    if (canonical(e.dot(e)).is_zero()) a.zero_edges.push_back(i);
  }
  // Sine of each consecutive edge pair, in doubles: only used to warn, never to decide.
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d e = to_double(edge(p, i));
    Eigen::Vector3d f = to_double(edge(p, i + 1));
    // Scale-free: each edge divided by its largest component (the sine is unchanged), so tiny or
    // huge edges neither underflow nor overflow in the products (no "inf digits" for short,
    // perpendicular edges).
    const double se = e.cwiseAbs().maxCoeff(), sf = f.cwiseAbs().maxCoeff();
    if (!(se > 0.0) || !(sf > 0.0) || !std::isfinite(se) || !std::isfinite(sf)) continue;
    e /= se;
    f /= sf;
    const double ef = e.norm() * f.norm();
    const double s = e.cross(f).norm() / ef;
    if (s < a.min_sine) {
      a.min_sine = s;
      a.worst_pair = i;
    }
  }
  a.condition = a.min_sine > 0 ? 1.0 / a.min_sine : INFINITY;
  const Vec3<Exact> normal = newell_normal(p);
  if (canonical(normal.dot(normal)).is_zero()) {
    a.degenerate = true;
    return a;
  }
  for (std::size_t i = 1; i < n; ++i) {
    if (!canonical(normal.dot(p[i] - p[0])).is_zero()) {
      a.planar = false;
      a.off_plane_vertex = i;
      break;
    }
  }
  return a;
}

}  // namespace frustum
