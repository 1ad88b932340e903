// seed 001's plane method in any scalar: the triangle's front normal (AC × AB by default, in
// left-handed projection coordinates), the plane n̂·(p − A) = 0 written ax + by + cz = d, and
// z = (d − a·xₛ − b·yₛ)/c at the pixel. When the triangle is nearly edge-on (c ≈ 0) that formula
// divides a cancelled numerator by a tiny c; the barycentric form z = Σ λᵢ zᵢ with λᵢ from the
// 2D edge functions (predicates.hpp) at the pixel is then used instead: for a pixel inside the
// triangle it is a convex combination, so z stays within the vertices' depths whatever the
// rounding.
#pragma once

#include <array>

#include "solver/core/matrix.hpp"
#include "solver/core/scalar.hpp"
#include "solver/geometry/predicates.hpp"

namespace frustum {

template <typename T>
struct PlaneDepth {
  Vec3<T> normal;       // first × second (the cross order of the problem)
  Vec3<T> unit_normal;  // n̂ = n/‖n‖
  T d{};                // n̂·A
  T z{};                // the plane method's z (or the barycentric one, see `barycentric`)
  bool barycentric = false;
};

// z at the pixel by barycentric interpolation: λ_A ∝ E(B, C, p), λ_B ∝ E(C, A, p), λ_C ∝ E(A, B,
// p).
template <typename T>
T barycentric_depth(const std::array<Vec3<T>, 3>& t, const Vec2<T>& p) {
  const T wa = edge_function<T>(t[1], t[2], p), wb = edge_function<T>(t[2], t[0], p),
          wc = edge_function<T>(t[0], t[1], p);
  return (wa * t[0](2) + wb * t[1](2) + wc * t[2](2)) / (wa + wb + wc);
}

// The plane through A with normal n: n, n̂ = n/‖n‖ and d = n̂·A (z is left unset).
template <typename T>
PlaneDepth<T> plane_through(const Vec3<T>& normal, const Vec3<T>& a) {
  PlaneDepth<T> out;
  out.normal = normal;
  out.unit_normal = out.normal / stable_norm(out.normal);
  out.d = out.unit_normal.dot(a);
  return out;
}

// The plane method's z = (d − a·xₛ − b·yₛ)/c on the plane n̂·p = d (c = n̂_z must not be 0).
template <typename T>
T plane_method_z(const PlaneDepth<T>& plane, const Vec2<T>& pixel) {
  const Vec3<T>& u = plane.unit_normal;
  return (plane.d - u(0) * pixel(0) - u(1) * pixel(1)) / u(2);
}

// `first` and `second` are the edge vectors of the cross order (AC, AB for seed 001).
// use_barycentric chooses the stable form for z; the caller decides it from the condition.
template <typename T>
PlaneDepth<T> plane_depth(const std::array<Vec3<T>, 3>& t, const Vec3<T>& first,
                          const Vec3<T>& second, const Vec2<T>& pixel, bool use_barycentric) {
  PlaneDepth<T> out = plane_through<T>(first.cross(second), t[0]);
  out.barycentric = use_barycentric;
  out.z = use_barycentric ? barycentric_depth(t, pixel) : plane_method_z(out, pixel);
  return out;
}

}  // namespace frustum
