// Exact geometric predicates. A front/back decision is the sign of a determinant, never a
// comparison with a float epsilon: doubles decide when an error bound proves the sign, and
// exact rational arithmetic (every double is a dyadic rational) decides the rest.
#pragma once

#include "solver/geometry/vec.hpp"

namespace frustum {

// Sign of det[b − a, c − a, d − a] = ((b − a) × (c − a)) · (d − a): +1 when d lies on the
// side the normal of triangle abc (counter-clockwise) points to, −1 behind it, 0 in its plane.
int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d);

// The same on exact values.
int orient3d_sign(const Vec3<Exact>& a, const Vec3<Exact>& b, const Vec3<Exact>& c,
                  const Vec3<Exact>& d);

// How many orient3d_sign calls on doubles needed the exact fallback (for benchmarks).
struct PredicateStats {
  long filtered = 0;
  long exact = 0;
};
int orient3d_sign(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                  const Eigen::Vector3d& d, PredicateStats* stats);

}  // namespace frustum
