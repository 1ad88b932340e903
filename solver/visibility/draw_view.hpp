// The camera of `frustum draw`: what the problem's viewer sees. With an eye, a perspective
// view from the eye toward a centre (the scene's centroid); with a view direction, an
// orthographic view along it. Up is +y, or ∓z when looking straight down/up the y axis. The
// camera is look_at in the problem's api (DirectX: left-handed; `left_handed`: a left-handed
// course under another api, LookAtLH's basis), so the picture is the one that frame shows;
// Processing's window y points down, so its pictures are flipped vertically.
// Screen coordinates: x right, y up, unscaled (perspective: x_view/depth, y_view/depth).
#pragma once

#include <Eigen/Core>
#include <string>

#include "solver/util/said.hpp"
#include "solver/viewing/conventions.hpp"
#include "solver/visibility/depth_order.hpp"

namespace frustum {

struct DrawView {
  bool perspective = true;
  Api api = Api::OpenGL;
  bool left_handed = false;  // looking down +z (DirectX, or a left-handed course)
  Eigen::Matrix4d view_from_world = Eigen::Matrix4d::Identity();
  Said description;  // one sentence for the picture's caption, in every language

  // Distance in front of the viewer along the line of sight (> 0 in front).
  double depth(const Eigen::Vector3d& world) const;
  // Screen position (x right, y up).
  Eigen::Vector2d project(const Eigen::Vector3d& world) const;
};

// Throws DomainError("eye") when the eye is at the centre, or "view_direction" when it is zero.
DrawView draw_view(const DepthViewer& viewer, const Eigen::Vector3d& center, Api api,
                   bool left_handed = false);

// Fits screen points into a w × h canvas with a margin, keeping the aspect ratio; maps to SVG
// coordinates (y down).
struct ScreenFit {
  double scale = 1, ox = 0, oy = 0;
  Eigen::Vector2d operator()(const Eigen::Vector2d& s) const {
    return {ox + scale * s.x(), oy - scale * s.y()};
  }
};
ScreenFit fit_screen(const std::vector<Eigen::Vector2d>& points, double x0, double y0, double w,
                     double h, double margin);

}  // namespace frustum
