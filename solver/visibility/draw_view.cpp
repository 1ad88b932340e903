#include "solver/visibility/draw_view.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/util/diagnostic.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

namespace {

// Looking within about 8° of the y axis, +y cannot be the up vector.
constexpr double kUpParallel = 0.99;

// The caption's sentence about the camera; points, vectors and the api's name as written.
constexpr Phrase kPerspectiveView{"perspective from the eye {0} toward {1}, up {2}",
                                  "視点 {0} から {1} を見る透視投影, 上方向 {2}",
                                  "перспектива из глаза {0} на {1}, вверх {2}"};
constexpr Phrase kOrthographicView{"orthographic along {0}, up {1}",
                                   "{0} 方向の平行投影, 上方向 {1}",
                                   "ортографическая проекция вдоль {0}, вверх {1}"};
// "… (opengl, left-handed, window y down)": the view, the api, then what of these applies.
constexpr Phrase kViewInApi{"{0} ({1}{2}{3})", "{0} ({1}{2}{3})", "{0} ({1}{2}{3})"};
constexpr Phrase kLeftHanded{", left-handed", ", 左手系", ", левая система"};
constexpr Phrase kWindowYDown{", window y down", ", 画面の y は下向き", ", ось y окна вниз"};

// As a student reads a point of a scene of size `scale`: what rounding left of a zero
// (−1.85e−17 where a rotation by 30° meets the axis) is 0, and six significant digits at most.
std::string point_text(const Eigen::Vector3d& p, double scale) {
  const auto shown = [&](double x) { return std::abs(x) < 1e-9 * scale ? 0.0 : x; };
  return fmt::format("({:.6g}, {:.6g}, {:.6g})", shown(p.x()), shown(p.y()), shown(p.z()));
}

}  // namespace

double DrawView::depth(const Eigen::Vector3d& world) const {
  const Eigen::Vector4d v = view_from_world * world.homogeneous();
  return left_handed ? v.z() : -v.z();  // left-handed views look down +z, the others down −z
}

Eigen::Vector2d DrawView::project(const Eigen::Vector3d& world) const {
  const Eigen::Vector4d v = view_from_world * world.homogeneous();
  Eigen::Vector2d s(v.x(), v.y());
  if (perspective) s /= depth(world);
  if (api == Api::Processing) s.y() = -s.y();
  return s;
}

DrawView draw_view(const DepthViewer& viewer, const Eigen::Vector3d& center, Api api,
                   bool left_handed) {
  DrawView d;
  d.api = api;
  d.left_handed = left_handed || api == Api::DirectX;
  d.perspective = viewer.eye.has_value();
  Eigen::Vector3d eye, forward;
  if (d.perspective) {
    eye = to_double(*viewer.eye);
    forward = center - eye;
    if (forward.norm() == 0)
      throw DomainError("eye",
                        "the eye is at the centre of the scene: there is no direction to look in");
  } else {
    forward = to_double(*viewer.view_direction);
    if (forward.norm() == 0)
      throw DomainError("view_direction", "the zero vector is not a direction");
    eye = center - forward;
  }
  Eigen::Vector3d up(0, 1, 0);
  const double along_y = forward.normalized().y();
  if (std::abs(along_y) > kUpParallel) up = Eigen::Vector3d(0, 0, along_y < 0 ? -1 : 1);
  const MatX<double> m = look_at<double>(eye, center, up, d.left_handed ? Api::DirectX : api);
  d.view_from_world = m;
  const double scale = std::max({1.0, eye.cwiseAbs().maxCoeff(), center.cwiseAbs().maxCoeff()});
  const Said view = d.perspective
                        ? say(kPerspectiveView, point_text(eye, scale), point_text(center, scale),
                              point_text(up, 1))
                        : say(kOrthographicView, point_text(forward, scale), point_text(up, 1));
  d.description = say(kViewInApi, view, to_string(api),
                      left_handed && api != Api::DirectX ? Said(kLeftHanded) : Said(),
                      api == Api::Processing ? Said(kWindowYDown) : Said());
  return d;
}

ScreenFit fit_screen(const std::vector<Eigen::Vector2d>& points, double x0, double y0, double w,
                     double h, double margin) {
  ScreenFit f;
  if (points.empty()) return f;
  Eigen::Vector2d lo = points[0], hi = points[0];
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector2d size = (hi - lo).cwiseMax(Eigen::Vector2d(1e-12, 1e-12));
  f.scale = std::min((w - 2 * margin) / size.x(), (h - 2 * margin) / size.y());
  const Eigen::Vector2d mid = (lo + hi) / 2;
  f.ox = x0 + w / 2 - f.scale * mid.x();
  f.oy = y0 + h / 2 + f.scale * mid.y();
  return f;
}

}  // namespace frustum
