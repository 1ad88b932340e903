// The axis-aligned region that clipping keeps: a 2D window {xmin, xmax, ymin, ymax} or a 3D
// box {xmin, …, zmax} (the NDC cube [−1, 1]³ by default), and `tidy`, which keeps exact
// intermediate values small, so double and Exact share one implementation.
#pragma once

#include <string>

#include "solver/core/matrix.hpp"
#include "solver/core/scalar.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

// Keeps exact intermediate values small (canonical form); the identity for doubles.
inline double tidy(double v) { return v; }
inline Exact tidy(const Exact& v) { return canonical(v); }

// lo ≤ p ≤ hi componentwise; N = 2 (window) or 3 (volume).
template <typename T, int N>
struct ClipBox {
  Eigen::Matrix<T, N, 1> lo, hi;
};

// The NDC cube [−1, 1]³ of OpenGL, the default `volume` of clip_line and clip_polygon.
template <typename T>
ClipBox<T, 3> ndc_cube() {
  return {Vec3<T>(T(-1), T(-1), T(-1)), Vec3<T>(T(1), T(1), T(1))};
}

// The API's NDC volume: the cube [−1, 1]³ (OpenGL, Processing), or z ∈ [0, 1] (DirectX).
template <typename T>
ClipBox<T, 3> ndc_volume(Api api) {
  ClipBox<T, 3> box = ndc_cube<T>();
  if (api == Api::DirectX) box.lo(2) = T(0);
  return box;
}

// Axis names for messages and steps: "x", "y", "z".
inline std::string axis_name(int axis) { return std::string(1, static_cast<char>('x' + axis)); }

}  // namespace frustum
