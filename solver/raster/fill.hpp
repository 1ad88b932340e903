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

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>

#include "solver/raster/pipeline.hpp"
#include "solver/raster/rasterizer.hpp"
#include "solver/raster/span_fill.hpp"
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
  // A certified window triangle (WindowTriangle::depth_error ≥ 0) whose depth at every pixel
  // centre it covers is within kDepthTolerance of the exact one: the fill's tie test decides
  // its fragments. False for one whose bound is larger: each of its fragments is undecided.
  bool depth_decided = true;
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

// An edge covers a centre when E ≥ fill_bias: E > 0, or E = 0 on a top or left edge.
inline std::int64_t fill_bias(const EdgeFunction& e) { return e.top_left() ? 0 : 1; }

// The spans of rows j, j + 1, … of one triangle in turn, each what span_on_row gives. An edge
// function is linear in y, so each edge's bound on a row is the one before plus a fixed
// quotient with the remainder carried: after the first row, a row costs a few additions instead
// of three divisions (a thin triangle has many rows and few pixels on each). For the rows
// j_min … j_max of a triangle that is not degenerate.
class RowSpans {
 public:
  RowSpans(const TriangleSetup& t, int j)
      : lo_(t.i_min), hi_(t.i_max), e0_(t.edge[0], j), e1_(t.edge[1], j), e2_(t.edge[2], j) {}
  // The current row's span (within the triangle's box, like span_on_row's); then the next row.
  Span next() {
    std::int64_t lo = lo_, hi = hi_;
    e0_.bound(lo, hi);
    e1_.bound(lo, hi);
    e2_.bound(lo, hi);
    return {static_cast<int>(lo), static_cast<int>(std::max(hi, lo - 1))};
  }

 private:
  // One edge. N = b·y_c + c − bias: the edge's value at x = 0 on the current row's centre line,
  // less the fill rule's bias, kept as ⌊N/|a|⌋ = f with remainder r (|a| = 1 for a horizontal
  // edge: f = N); N grows by b·2⁸ a row, which is step_f·|a| + step_r.
  struct Edge {
    std::int64_t f, r, divisor, step_f, step_r;
    int side;  // +1: a > 0, a lower bound on i; −1: a < 0, an upper bound; 0: a = 0
    Edge(const EdgeFunction& e, int j) {
      side = e.a > 0 ? 1 : (e.a < 0 ? -1 : 0);
      divisor = e.a == 0 ? 1 : (e.a > 0 ? e.a : -e.a);
      const std::int64_t n = e.b * pixel_centre(0, j).y + e.c - fill_bias(e);
      f = floor_div(n, divisor);
      r = n - f * divisor;
      const std::int64_t step = e.b * kSubpixelScale;
      step_f = floor_div(step, divisor);
      step_r = step - step_f * divisor;
    }
    // The centre x = i·2⁸ + 2⁷ is inside the edge when a·x + N ≥ 0: for a > 0 when
    // i ≥ ⌈(−⌊N/a⌋ − 2⁷)/2⁸⌉ = −⌊(f + 2⁷)/2⁸⌋; for a < 0 when i ≤ ⌊(⌊N/|a|⌋ − 2⁷)/2⁸⌋ =
    // ⌊(f − 2⁷)/2⁸⌋; for a = 0 on the whole row when N ≥ 0, else nowhere (⌊x/2⁸⌋ = x >> 8).
    // Then one row down.
    void bound(std::int64_t& lo, std::int64_t& hi) {
      constexpr std::int64_t half = kSubpixelScale / 2;
      if (side > 0)
        lo = std::max(lo, -((f + half) >> kSubpixelBits));
      else if (side < 0)
        hi = std::min(hi, (f - half) >> kSubpixelBits);
      else if (f < 0)
        hi = std::numeric_limits<int>::min();
      // Branch-free: whether the remainder carries is as good as random from row to row.
      r += step_r;
      const bool carry = r >= divisor;
      r = carry ? r - divisor : r;
      f += step_f + carry;
    }
  };
  std::int64_t lo_, hi_;
  Edge e0_, e1_, e2_;
};

struct Frame {
  Image<std::uint32_t> color;  // raster rows, j = 0 the bottom
  Image<float> depth;
  // A certified render's undecided pixels (certified_frame.hpp): per raster row, the columns
  // where a fragment's depth test was a tie for the floats (span_fill.hpp's depth_tie) or its
  // triangle's depth was not decided (in any order, possibly repeated). Empty when not certified.
  std::vector<std::vector<int>> ties;
  Frame() = default;
  Frame(int width, int height, Rgb background)
      : color(width, height, pack(background)), depth(width, height, kDepthClear) {}
  // Cleared to the background and the far depth. A frame kept from one render to the next (a
  // render target, as a GL context keeps its framebuffer) reuses its buffers when the size is
  // the same: a fresh 1920 × 1080 frame costs the kernel 16 MB of zeroed pages first.
  void reset(int width, int height, Rgb background) {
    resize(width, height);
    clear_rows(0, height - 1, background);
  }
  // Sized without clearing: the caller writes every pixel (fill_in_bands clears band by band).
  void resize(int width, int height) {
    color.resize(width, height);
    depth.resize(width, height);
  }
  // Rows j0 … j1 cleared to the background and the far depth: the first row pixel by pixel, the
  // others copied from it (memcpy moves a vector at a time; GCC's -O2 stores a fill of a
  // non-zero 32-bit value one pixel at a time, four times as many stores).
  void clear_rows(int j0, int j1, Rgb background) {
    fill_rows(color, j0, j1, pack(background));
    fill_rows(depth, j0, j1, kDepthClear);
  }

 private:
  template <typename P>
  static void fill_rows(Image<P>& image, int j0, int j1, P value) {
    if (j0 > j1) return;
    const auto width = static_cast<std::size_t>(image.width);
    P* const first = image.data.data() + static_cast<std::size_t>(j0) * width;
    std::fill(first, first + width, value);
    for (int j = j0 + 1; j <= j1; ++j)
      std::memcpy(first + static_cast<std::size_t>(j - j0) * width, first, width * sizeof(P));
  }
};

struct FillStats {
  long triangles = 0;
  long fragments = 0;  // covered pixels inside the frame
  long written = 0;    // passed the depth test
  FillStats& operator+=(const FillStats& o) {
    triangles += o.triangles;
    fragments += o.fragments;
    written += o.written;
    return *this;
  }
};

// The z-buffer's inner loop for one triangle.
void draw_triangle(const RasterTriangle& t, Frame& frame, FillStats* stats = nullptr);
// Only its pixels on rows j_lo … j_hi (a band of the frame), each exactly as draw_triangle
// gives it; counts the band's fragments and writes, not the triangle.
void draw_triangle_rows(const RasterTriangle& t, Frame& frame, int j_lo, int j_hi,
                        FillStats* stats = nullptr);

// Setup + draw for every triangle, in order; refused before any is drawn when their price passes
// `max_work` (frame_work.hpp). The scene's renders below price each triangle as it comes, with
// Scene::max_work, and stop at the one past it (DomainError naming the bound).
Frame render_zbuffer(const std::vector<WindowTriangle>& triangles, int width, int height,
                     Rgb background, FillStats* stats = nullptr,
                     std::int64_t max_work = kMaxFrameWork);
// The whole pipeline streamed on one thread (`frustum render`'s z-buffer; with threads, and
// choosing between them, solver/raster_fast/threaded_zbuffer.hpp's render_zbuffer): each world
// triangle, as the hierarchy walk yields it, through the geometry stage and into the frame;
// neither the world nor the window triangles are kept. The same frame as
// render_zbuffer(geometry(scene, flatten(scene)), …), drawn into a render target the caller
// keeps (reset to the scene's size and background). With a certifier (certified_frame.hpp) the
// geometry is certified and the fill notes its ties in frame.ties (the caller repairs them:
// repair_undecided).
void render_zbuffer_streamed(const Scene& scene, Frame& target,
                             GeometryStats* geometry_stats = nullptr, FillStats* stats = nullptr,
                             FrameCertifier* certifier = nullptr);
// A modelled scene: at most this many world triangles. With threads, render_zbuffer sets it up
// whole and fills it band by band (solver/raster_fast/banded_fill.hpp, 320 B a triangle set up)
// rather than streaming it; a certifier keeps its certified window triangles.
inline constexpr std::size_t kBandedTriangles = std::size_t(1) << 15;

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
