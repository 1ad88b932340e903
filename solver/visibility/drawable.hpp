// What a problem kind hands to `frustum draw`: its geometry in world coordinates, the viewer,
// and which picture to make. A kind that can be drawn fills one (KindInfo::drawable).
#pragma once

#include <vector>

#include "solver/visibility/depth_order.hpp"
#include "solver/visibility/mesh.hpp"

namespace frustum {

struct Drawable {
  enum class Picture {
    HiddenLines,      // a closed mesh: visible edges solid, silhouette bold, covered parts dashed
    PainterVsZBuffer  // polygons: the painter's result next to the z-buffer's
  };
  Picture picture = Picture::HiddenLines;
  Mesh mesh;                              // HiddenLines (already transformed)
  std::vector<Polygon3<Exact>> polygons;  // PainterVsZBuffer
  DepthViewer viewer;                     // HiddenLines: always an eye
  // The course's frame is left-handed under OpenGL's or Processing's matrices: the camera is
  // the left-handed look-at (LookAtLH's basis), so the picture is what that frame shows.
  bool left_handed = false;
};

}  // namespace frustum
