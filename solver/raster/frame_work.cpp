#include "solver/raster/frame_work.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

// ⌊v⌋ for v within a few pixels of the frame, without a library call: the price is taken for
// every triangle of a frame.
double floor_of(double v) {
  const auto t = static_cast<double>(static_cast<std::int64_t>(v));
  return t > v ? t - 1 : t;
}

}  // namespace

std::int64_t triangle_price(const WindowTriangle& t, int width, int height) {
  const Vec3d &a = t.v[0], &b = t.v[1], &c = t.v[2];
  const double x0 = std::min({a(0), b(0), c(0)}), x1 = std::max({a(0), b(0), c(0)}),
               y0 = std::min({a(1), b(1), c(1)}), y1 = std::max({a(1), b(1), c(1)});
  if (!(x0 <= x1) || !(y0 <= y1)) return 0;  // not numbers
  // Pixel i's centre is i + ½: the box's pixels, a pixel wider each way, within the frame; the
  // coordinates clamped to two pixels beyond it first, so that a huge or infinite one converts.
  const double w = width, h = height;
  const double i0 = std::max(0.0, floor_of(std::clamp(x0, -2.0, w + 2)) - 1),
               i1 = std::min(w - 1, floor_of(std::clamp(x1, -2.0, w + 2)) + 1),
               j0 = std::max(0.0, floor_of(std::clamp(y0, -2.0, h + 2)) - 1),
               j1 = std::min(h - 1, floor_of(std::clamp(y1, -2.0, h + 2)) + 1);
  if (i0 > i1 || j0 > j1) return 0;  // off the frame
  const double rows = j1 - j0 + 1, box = (i1 - i0 + 1) * rows;
  // A convex region of area A and perimeter P holds at most A + P/2 + 1 pixel centres; P is at
  // most the box's 2(x1 − x0 + y1 − y0), and the 2 % and the 1 more are room for the snapping.
  const double area = std::abs((b(0) - a(0)) * (c(1) - a(1)) - (b(1) - a(1)) * (c(0) - a(0))) / 2,
               cover = area + 1.02 * ((x1 - x0) + (y1 - y0)) + 2;
  // An infinite or NaN cover (a coordinate at infinity) is not below the box: the box counts.
  return static_cast<std::int64_t>(rows) +
         (cover < box ? static_cast<std::int64_t>(cover) + 1 : static_cast<std::int64_t>(box));
}

void FrameWork::add(const WindowTriangle& t) { add(triangle_price(t, width_, height_)); }

void FrameWork::add(std::int64_t pixels) {
  if (__builtin_add_overflow(total_, pixels, &total_) || total_ > limit_)
    throw DomainError(
        "scene.objects",
        fmt::format("the frame's triangles need more than {} pixel tests and row steps in all "
                    "(the limit is {} pixel tests a frame{}); draw fewer or smaller triangles, "
                    "or a smaller frame",
                    limit_, limit_,
                    limit_ == kMaxFrameWork ? ": 64 layers of a 4096 × 4096 frame" : ""));
}

std::int64_t price_frame(const Scene& scene) {
  GeometryStage stage(scene);
  FrameWork work(scene);
  std::vector<WindowTriangle> window;  // one world triangle's, reused
  int source = 0;
  for_each_world_triangle(scene, [&](const WorldTriangle& t) {
    window.clear();
    stage.add(t, source++, window);
    for (const WindowTriangle& w : window) work.add(w);
  });
  return work.total();
}

}  // namespace frustum
