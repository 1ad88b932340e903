// A frame's total work, bounded before it is done. Each window triangle is priced by what the
// fill spends on it: a step for each row of its bounding box within the frame, and the pixels it
// can cover: at most its box (widened by a pixel each way), and at most A + P/2 + 1 for area A
// and perimeter P (a convex region's pixel centres), with P at most the box's perimeter and a
// little room for the snapping to 1/256 pixel. The frame is refused, naming the bound, at the
// triangle whose price takes the total past Scene::max_work (kMaxFrameWork). Every renderer
// prices the same triangles in the same order, so a scene is refused or drawn alike by one
// thread or many, z-buffer or scan line.
#pragma once

#include <cstdint>

#include "solver/raster/pipeline.hpp"

namespace frustum {

// The triangle's price in a width × height frame: rows + min(box, A + 1.02·(w + h) + 3) for its
// extents w and h, as above; 0 off the frame or for coordinates that are not numbers.
std::int64_t triangle_price(const WindowTriangle& t, int width, int height);

class FrameWork {
 public:
  FrameWork(int width, int height, std::int64_t limit)
      : width_(width), height_(height), limit_(limit) {}
  explicit FrameWork(const Scene& scene) : FrameWork(scene.width, scene.height, scene.max_work) {}
  // Adds the triangle's price; past the limit throws DomainError("scene.objects") naming it.
  void add(const WindowTriangle& t);
  // Adds a price counted elsewhere (a part of the triangles, priced on another thread).
  void add(std::int64_t pixels);
  std::int64_t total() const { return total_; }

 private:
  int width_, height_;
  std::int64_t limit_;
  std::int64_t total_ = 0;
};

// The price of the scene's frame, its world triangles walked through the geometry stage as
// render_zbuffer_streamed walks them and none kept; throws as FrameWork::add past Scene::max_work
// (so at most a geometry pass is spent on a scene that would be refused).
std::int64_t price_frame(const Scene& scene);

}  // namespace frustum
