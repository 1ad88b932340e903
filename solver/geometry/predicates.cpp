#include "solver/geometry/predicates.hpp"

#include <cmath>
#include <limits>

namespace frustum {

namespace {

// Forward error bound of the 3×3 determinant of differences evaluated in doubles
// (Shewchuk's o3derrboundA = (7 + 56ε)ε).
constexpr double kEps = std::numeric_limits<double>::epsilon() / 2;
constexpr double kOrient3dBound = (7.0 + 56.0 * kEps) * kEps;

}  // namespace

int orient3d_sign(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec3<Exact>& c,
                  const Vec3<Exact>& d) {
  return exact_sign((b - a).cross(c - a).dot(d - a));
}

int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d, PredicateStats* stats) {
  const Eigen::Vector3d u = b - a, v = c - a, w = d - a;
  const double det = u.cross(v).dot(w);
  // Permanent: the same products with absolute values bound the rounding error.
  const Eigen::Vector3d ua = u.cwiseAbs(), va = v.cwiseAbs(), wa = w.cwiseAbs();
  const double permanent = ua.x() * (va.y() * wa.z() + va.z() * wa.y()) +
                           ua.y() * (va.x() * wa.z() + va.z() * wa.x()) +
                           ua.z() * (va.x() * wa.y() + va.y() * wa.x());
  // Products in the subnormal range are off by up to η/2 absolutely; the cross product's meet w.
  const double eta = std::numeric_limits<double>::denorm_min();
  const double bound = kOrient3dBound * permanent + eta * (2 * wa.sum() + 4);
  if (std::isfinite(det) && std::isfinite(bound) && std::abs(det) > bound) {
    if (stats) ++stats->filtered;
    return det > 0 ? 1 : -1;
  }
  if (stats) ++stats->exact;
  auto exact = [](const Eigen::Vector3d& p) {
    return Vec3<Exact>(exact_from_double(p.x()), exact_from_double(p.y()),
                       exact_from_double(p.z()));
  };
  return orient3d_sign(exact(a), exact(b), exact(c), exact(d));
}

int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d) {
  return orient3d_sign(a, b, c, d, nullptr);
}

}  // namespace frustum
