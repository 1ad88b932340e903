// The raster half of the pipeline: triangle setup in fixed point (rasterizer.hpp: 1/256
// pixel, exact edge functions, top-left rule), the depth plane, per-row spans, and the
// z-buffer test and write into a colour buffer.
//
// Depth: window z is affine in raster x and y (z_ndc = z_clip/w_clip is, after the divide),
// so it is interpolated as the plane through the three snapped vertices,
//   z(x, y) = z₀ + A·(x − x₀) + B·(y − y₀)   (the plane method of depth_at_pixel),
// evaluated in double at the pixel centre and stored as a 32-bit float (like a D32F buffer).
// Every renderer here evaluates it through depth_at(), so they agree bit for bit.
// The test is `less`: a fragment is written when its depth is smaller than the stored one;
// the buffer is cleared to 1 (the far plane), so a fragment exactly on the far plane is not.
#pragma once

#include <cstdint>

#include "solver/raster/pipeline.hpp"
#include "solver/raster/rasterizer.hpp"
#include "solver/raster/zbuffer.hpp"

namespace frustum {

inline constexpr float kDepthClear = 1.0f;

// Colours packed as 0xAABBGGRR (bytes R, G, B, A in memory: what PNG writers take).
inline std::uint32_t pack(Rgb c) {
  return 0xff000000u | (std::uint32_t{c.b} << 16) | (std::uint32_t{c.g} << 8) | c.r;
}
inline Rgb unpack(std::uint32_t c) {
  return {static_cast<std::uint8_t>(c & 0xff), static_cast<std::uint8_t>((c >> 8) & 0xff),
          static_cast<std::uint8_t>((c >> 16) & 0xff)};
}

struct RasterTriangle {
  TriangleSetup setup;
  double z0 = 0, a = 0, b = 0;  // the depth plane, per 1/256 pixel, about vertex v[0]
  std::uint32_t color = 0;
  int source = 0;  // index of the WindowTriangle
};

// Setup: snap, edge functions, bounding box, depth plane.
RasterTriangle setup_raster(const WindowTriangle& t, int source = 0);

// Depth at the centre of pixel (i, j) (raster rows, y up).
inline double depth_offset(const RasterTriangle& t, std::int64_t dx, std::int64_t dy) {
  return (t.z0 + t.b * static_cast<double>(dy)) + t.a * static_cast<double>(dx);
}
inline float depth_at(const RasterTriangle& t, int i, int j) {
  const FixedPoint2 p = pixel_centre(i, j);
  return static_cast<float>(depth_offset(t, p.x - t.setup.v[0].x, p.y - t.setup.v[0].y));
}

// The covered pixels of row j: i0 … i1 (empty when i0 > i1), exactly the centres that
// covers() accepts, found from the three edge functions without testing pixels one by one.
struct Span {
  int i0 = 0, i1 = -1;
};
Span span_on_row(const TriangleSetup& t, int j);

struct Frame {
  Image<std::uint32_t> color;  // raster rows, j = 0 the bottom
  Image<float> depth;
  Frame(int width, int height, Rgb background)
      : color(width, height, pack(background)), depth(width, height, kDepthClear) {}
};

struct FillStats {
  long triangles = 0;
  long fragments = 0;  // covered pixels inside the frame
  long written = 0;    // passed the depth test
};

// vzeroupper where the CPU has AVX (nothing elsewhere). GCC 12 can return from the AVX2 clone
// of a vectorised loop (target_clones) with the upper halves of the vector registers still in
// use, and every SSE instruction after it then runs slower: zlib compressing the frame to PNG
// took 31 ms instead of 11 ms after a render. draw_triangle() calls it before it returns.
void clear_upper_vector_state();

// The z-buffer's inner loop for one triangle.
void draw_triangle(const RasterTriangle& t, Frame& frame, FillStats* stats = nullptr);

// Setup + draw for every triangle, in order.
Frame render_zbuffer(const std::vector<WindowTriangle>& triangles, int width, int height,
                     Rgb background, FillStats* stats = nullptr);
// The whole pipeline streamed (`frustum render`): each world triangle, as the hierarchy walk
// yields it, through the geometry stage and into the frame; neither the world nor the window
// triangles are kept. The same frame as render_zbuffer(geometry(scene, flatten(scene)), …).
// threads ≥ 2: the walk and the geometry run on a thread of their own, handing window
// triangles to the fill (on the caller's thread, in drawing order) in small chunks; the frame
// is the same bit for bit.
Frame render_zbuffer(const Scene& scene, GeometryStats* geometry_stats = nullptr,
                     FillStats* stats = nullptr, int threads = 1);

// Only what one pixel needs (the render kind): the triangles whose bounds hold the pixel
// centre compete, in drawing order; no frame is allocated.
struct Competitor {
  int triangle = 0;  // index into the window triangles
  float depth = 0;
  bool passed = false;  // nearer than the stored depth: written
};
struct PixelTrace {
  int i = 0, j = 0;  // raster pixel
  std::vector<Competitor> competitors;
  int winner = -1;  // −1: the background
  float depth = kDepthClear;
  Rgb color;
  // Records a competitor in drawing order; one that passed is the new winner.
  void add(const Competitor& c, Rgb colour) {
    if (c.passed) {
      depth = c.depth;
      winner = c.triangle;
      color = colour;
    }
    competitors.push_back(c);
  }
};
PixelTrace trace_pixel(const std::vector<WindowTriangle>& triangles, int i, int j, Rgb background);

}  // namespace frustum
