// Cameras and projections in the three conventions. Every matrix here is in column-vector
// form (clip = M·p); DirectX's row-vector matrix as printed on paper is its transpose
// (paper_form). NDC: OpenGL and Processing [−1, 1]³ with near → −1; DirectX z in [0, 1].
#pragma once

#include "solver/viewing/conventions.hpp"
#include "solver/viewing/transforms.hpp"

namespace frustum {

// The view volume of frustum()/ortho(): l, r, b, t at the near plane; near and far as
// positive distances in front of the eye.
template <typename T>
struct Volume {
  T left, right, bottom, top, near, far;
};

// gluLookAt / Processing camera() (right-handed, looking down −z), or DirectX's
// LookAtLH (left-handed, looking down +z). Rows are the camera's axes.
template <typename T>
MatX<T> look_at(const Vec3<T>& eye, const Vec3<T>& center, const Vec3<T>& up, Api api) {
  const Vec3<T> forward = (center - eye) / norm(Vec3<T>(center - eye));
  MatX<T> m = MatX<T>::Identity(4, 4);
  Vec3<T> x, y, z;
  if (api == Api::DirectX) {
    z = forward;
    const Vec3<T> s = up.cross(z);
    x = s / norm(s);
    y = z.cross(x);
  } else {
    const Vec3<T> s = forward.cross(up);
    x = s / norm(s);
    y = x.cross(forward);
    z = -forward;
  }
  for (int j = 0; j < 3; ++j) {
    m(0, j) = x(j);
    m(1, j) = y(j);
    m(2, j) = z(j);
  }
  m(0, 3) = -x.dot(eye);
  m(1, 3) = -y.dot(eye);
  m(2, 3) = -z.dot(eye);
  return m;
}

// glFrustum; Processing negates the y row (−2n/(t−b)) because its window y points down;
// DirectX's PerspectiveOffCenterLH maps z to [0, 1] looking down +z.
template <typename T>
MatX<T> frustum_matrix(const Volume<T>& v, Api api) {
  const T &l = v.left, &r = v.right, &b = v.bottom, &t = v.top, &n = v.near, &f = v.far;
  MatX<T> m = MatX<T>::Zero(4, 4);
  m(0, 0) = T(2) * n / (r - l);
  m(1, 1) = T(2) * n / (t - b);
  if (api == Api::DirectX) {
    m(0, 2) = (l + r) / (l - r);
    m(1, 2) = (t + b) / (b - t);
    m(2, 2) = f / (f - n);
    m(2, 3) = n * f / (n - f);
    m(3, 2) = T(1);
    return m;
  }
  if (api == Api::Processing) m(1, 1) = -m(1, 1);
  m(0, 2) = (r + l) / (r - l);
  m(1, 2) = (t + b) / (t - b);
  m(2, 2) = -(f + n) / (f - n);
  m(2, 3) = -T(2) * f * n / (f - n);
  m(3, 2) = T(-1);
  return m;
}

// glOrtho (Processing: y row negated; DirectX: OrthoOffCenterLH, z to [0, 1]).
template <typename T>
MatX<T> ortho_matrix(const Volume<T>& v, Api api) {
  const T &l = v.left, &r = v.right, &b = v.bottom, &t = v.top, &n = v.near, &f = v.far;
  MatX<T> m = MatX<T>::Identity(4, 4);
  m(0, 0) = T(2) / (r - l);
  m(1, 1) = T(2) / (t - b);
  m(0, 3) = -(r + l) / (r - l);
  m(1, 3) = -(t + b) / (t - b);
  if (api == Api::DirectX) {
    m(2, 2) = T(1) / (f - n);
    m(2, 3) = n / (n - f);
    return m;
  }
  if (api == Api::Processing) m(1, 1) = -m(1, 1);
  m(2, 2) = -T(2) / (f - n);
  m(2, 3) = -(f + n) / (f - n);
  return m;
}

// The symmetric frustum of perspective(fovy, aspect, near, far): t = n·tan(fovy/2),
// r = t·aspect (seed 004 puts the aspect on t instead: a slip).
template <typename T>
Volume<T> perspective_volume(const T& fovy_radians, const T& aspect, const T& near, const T& far) {
  const T t = near * scalar_sin(fovy_radians / T(2)) / scalar_cos(fovy_radians / T(2));
  const T r = t * aspect;
  return Volume<T>{-r, r, -t, t, near, far};
}

// The matrix as printed on paper: DirectX multiplies row vectors, p′ = p·M, so its printed
// matrix is the transpose of the column form.
template <typename T>
MatX<T> paper_form(const MatX<T>& column_form, Api api) {
  return api == Api::DirectX ? MatX<T>(column_form.transpose()) : column_form;
}

// Viewport: NDC to window coordinates and depth in [0, 1]. OpenGL's window origin is
// bottom-left; DirectX's and Processing's are top-left with y down, so y_w = (1 − y)/2·h.
// Processing: its projection negated y because its world y points down (world y = 0, the
// top, ends at y_ndc = +1), and its screenY() then takes h − (1 + y_ndc)/2·h, so world y
// and window y both point down.
template <typename T>
Vec3<T> viewport(const Vec3<T>& ndc, const T& width, const T& height, Api api) {
  Vec3<T> w;
  w(0) = (ndc(0) + T(1)) / T(2) * width;
  w(1) = api == Api::OpenGL ? (ndc(1) + T(1)) / T(2) * height : (T(1) - ndc(1)) / T(2) * height;
  w(2) = api == Api::DirectX ? ndc(2) : (ndc(2) + T(1)) / T(2);
  return w;
}

}  // namespace frustum
