// seeds 001, 003: the painter's (depth-sort) result against the z-buffer's, both rasterized
// with the same rasterizer at a small resolution. The painter draws whole polygons in the
// centroid order, back to front, each over what is there; the z-buffer draws them in the
// listed order and keeps the nearest per pixel. Where the centroid order is wrong (三すくみ,
// 貫通, concave) the two frames differ.
//
// View: draw_view (perspective from the eye toward the mean centroid, or orthographic along
// the view direction); the scene's projection is fitted into the size × size window.
// Depth per vertex: d (orthographic) or −1/d (perspective), d the distance along the line of
// sight; both are affine in window coordinates over a planar polygon, so the rasterizer's
// linear interpolation is exact, and smaller is nearer.
#pragma once

#include <utility>
#include <vector>

#include "solver/raster/zbuffer.hpp"
#include "solver/visibility/draw_view.hpp"

namespace frustum {

inline constexpr int kPainterRasterDefault = 48;

struct PainterVsZBuffer {
  DepthSortResult sort;  // centroids, order, conflicts
  DrawView view;
  std::vector<std::vector<Eigen::Vector2d>>
      window;                                  // each polygon's vertices in window coordinates
  FrameBuffer painter, zbuffer;                // labels "0", "1", …; "." background
  std::vector<std::pair<int, int>> differing;  // pixels (i, j) whose labels differ
};

// Throws DomainError as depth_sort does; size is clamped to [4, 512].
PainterVsZBuffer painter_vs_zbuffer(const std::vector<Polygon3<Exact>>& polygons,
                                    const DepthViewer& viewer, Api api,
                                    int size = kPainterRasterDefault);

}  // namespace frustum
