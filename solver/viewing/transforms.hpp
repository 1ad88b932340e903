// Homogeneous transforms in 2D (3×3) and 3D (4×4), column vectors: p′ = M·p, and a
// composite of steps A₁, A₂, A₃ (first applied first) is A₃·A₂·A₁ (seed 002).
#pragma once

#include <cmath>

#include "solver/core/matrix.hpp"

namespace frustum {

// T(t): translation by t (2 or 3 components) in homogeneous coordinates.
template <typename T>
MatX<T> translate(const std::vector<T>& t) {
  const int n = static_cast<int>(t.size());
  MatX<T> m = MatX<T>::Identity(n + 1, n + 1);
  for (int i = 0; i < n; ++i) m(i, n) = t[i];
  return m;
}

// S(s): scaling by s along the axes.
template <typename T>
MatX<T> scale(const std::vector<T>& s) {
  const int n = static_cast<int>(s.size());
  MatX<T> m = MatX<T>::Identity(n + 1, n + 1);
  for (int i = 0; i < n; ++i) m(i, i) = s[i];
  return m;
}

// R(θ) in 2D, counter-clockwise.
template <typename T>
MatX<T> rotate_2d(const T& radians) {
  const T c = scalar_cos(radians), s = scalar_sin(radians);
  MatX<T> m = MatX<T>::Identity(3, 3);
  m(0, 0) = c;
  m(0, 1) = -s;
  m(1, 0) = s;
  m(1, 1) = c;
  return m;
}

// R_x, R_y, R_z (axis 0, 1, 2): right-handed rotation about a coordinate axis (seed 002).
template <typename T>
MatX<T> rotate_axis_index(int axis, const T& radians) {
  const T c = scalar_cos(radians), s = scalar_sin(radians);
  MatX<T> m = MatX<T>::Identity(4, 4);
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  m(i, i) = c;
  m(i, j) = -s;
  m(j, i) = s;
  m(j, j) = c;
  return m;
}

// Rotation by θ about the unit axis (x, y, z) (seed 004's formula).
template <typename T>
MatX<T> rotate_about(const Vec3<T>& axis, const T& radians) {
  const T c = scalar_cos(radians), s = scalar_sin(radians), k = T(1) - c;
  const T x = axis(0), y = axis(1), z = axis(2);
  MatX<T> m = MatX<T>::Identity(4, 4);
  m(0, 0) = x * x * k + c;
  m(0, 1) = x * y * k - z * s;
  m(0, 2) = x * z * k + y * s;
  m(1, 0) = y * x * k + z * s;
  m(1, 1) = y * y * k + c;
  m(1, 2) = y * z * k - x * s;
  m(2, 0) = x * z * k - y * s;
  m(2, 1) = y * z * k + x * s;
  m(2, 2) = z * z * k + c;
  return m;
}

// Shear: h(i, j) is how much coordinate j adds to coordinate i (x′ = x + h_xy·y + …).
template <typename T>
MatX<T> shear(const MatX<T>& h) {
  const int n = static_cast<int>(h.rows());
  MatX<T> m = MatX<T>::Identity(n + 1, n + 1);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j) m(i, j) = h(i, j);
  return m;
}

// The point (affine, w = 1) after M, with the divide by w when M is projective.
template <typename T>
std::vector<T> transform_point(const MatX<T>& m, const std::vector<T>& p) {
  const int n = static_cast<int>(p.size());
  Eigen::Matrix<T, Eigen::Dynamic, 1> h(n + 1);
  for (int i = 0; i < n; ++i) h(i) = p[i];
  h(n) = T(1);
  const Eigen::Matrix<T, Eigen::Dynamic, 1> r = m * h;
  std::vector<T> out(n);
  for (int i = 0; i < n; ++i) out[i] = r(i) / r(n);
  return out;
}

}  // namespace frustum
