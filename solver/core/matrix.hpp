// The vector and matrix vocabulary of the whole solver, templated on the scalar so float,
// double, long double and Exact run the same code; the double aliases of the pipeline.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "solver/core/scalar.hpp"

namespace frustum {

template <typename T>
using Vec2 = Eigen::Matrix<T, 2, 1>;
template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Vec4 = Eigen::Matrix<T, 4, 1>;
template <typename T>
using Mat4 = Eigen::Matrix<T, 4, 4>;

template <typename T>
using MatX = Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic>;

using Vec3d = Eigen::Vector3d;
using Vec4d = Eigen::Vector4d;
using Mat4d = Eigen::Matrix4d;

template <typename T>
using Polygon3 = std::vector<Vec3<T>>;

template <typename T>
T norm(const Vec3<T>& v) {
  return scalar_sqrt(T(v.dot(v)));
}

template <typename To, typename From, int N>
Eigen::Matrix<To, N, 1> cast_vec(const Eigen::Matrix<From, N, 1>& v) {
  Eigen::Matrix<To, N, 1> out;
  for (int i = 0; i < N; ++i) out(i) = static_cast<To>(v(i));
  return out;
}

// Exact vectors to doubles.
template <int N>
Eigen::Matrix<double, N, 1> to_double(const Eigen::Matrix<Exact, N, 1>& v) {
  Eigen::Matrix<double, N, 1> out;
  for (int i = 0; i < N; ++i) out(i) = to_double(v(i));
  return out;
}

}  // namespace frustum
