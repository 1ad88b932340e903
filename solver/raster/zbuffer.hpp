// The Z-buffer algorithm (seed 001, p.133): a depth buffer Z(i, j) initialised to the far
// value (+∞) and a frame buffer F(i, j) initialised to the background; for each polygon, for
// each covered pixel, when the polygon's z is smaller than Z(i, j) (seed 001: "ポリゴンのZ値が
// Z(i,j) より小さいならば") its label is stored in F and its z in Z. Smaller z is nearer;
// equal z keeps what was drawn first. Pixel (i, j) follows rasterizer.hpp: y-up, centre
// (i + ½, j + ½).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/raster/large_buffer.hpp"
#include "solver/raster/rasterizer.hpp"

namespace frustum {

// A width × height grid of pixels, (i, j) with j = 0 the bottom row (a large grid on huge
// pages where the kernel offers them: large_buffer.hpp).
template <typename P>
struct Image {
  int width = 0, height = 0;
  std::vector<P, LargeBufferAllocator<P>> data;
  Image() = default;
  Image(int w, int h, const P& fill)
      : width(w),
        height(h),
        data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}
  // w × h pixels; those the buffer did not hold are left to the caller to write (numbers are
  // not initialised).
  void resize(int w, int h) {
    width = w;
    height = h;
    data.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  }
  P& at(int i, int j) { return data[static_cast<std::size_t>(j) * width + i]; }
  const P& at(int i, int j) const { return data[static_cast<std::size_t>(j) * width + i]; }
};

// Depth of scalar T; nullopt is +∞ (the cleared value).
template <typename T>
using DepthBuffer = Image<std::optional<T>>;
// One label per pixel ("1", "①"); the background is ".".
using FrameBuffer = Image<std::string>;

inline constexpr const char* kBackground = ".";

struct DrawCount {
  int covered = 0;  // fragments inside the frame
  int written = 0;  // fragments that passed the depth test
};

// Z-buffer's inner loop for one triangle; z per input vertex.
template <typename T, typename Less>
DrawCount draw_triangle(const TriangleSetup& t, const std::array<T, 3>& z, const std::string& label,
                        DepthBuffer<T>& depth, FrameBuffer& frame, Less less) {
  DrawCount n;
  for (const Fragment& f : rasterize(t, frame.width, frame.height)) {
    ++n.covered;
    const T zf = interpolate(t, f, z);
    std::optional<T>& stored = depth.at(f.i, f.j);
    if (stored && !less(zf, *stored)) continue;
    stored = zf;
    frame.at(f.i, f.j) = label;
    ++n.written;
  }
  return n;
}

template <typename T>
DrawCount draw_triangle(const TriangleSetup& t, const std::array<T, 3>& z, const std::string& label,
                        DepthBuffer<T>& depth, FrameBuffer& frame) {
  return draw_triangle(t, z, label, depth, frame, [](const T& a, const T& b) { return a < b; });
}

// The frame's rows as text, top row (j = height − 1) first, as the grid is drawn on paper.
std::vector<std::string> frame_rows(const FrameBuffer& frame);

}  // namespace frustum
