// Triangle rasterization as plain pipeline stages: setup (snap to fixed point, edge
// functions, bounding box), coverage of pixel centres under the top-left fill rule, and
// depth interpolation.
//
// Conventions (stated in every derivation that uses them):
// - Window coordinates are y-up; pixel (i, j) is the unit square [i, i+1] × [j, j+1] and its
//   centre is (i + ½, j + ½).
// - Vertices are snapped to a grid of 1/2⁸ pixel (kSubpixelBits) and all coverage arithmetic
//   is exact int64 on that grid, so a pixel's coverage never depends on rounding.
// - Edge function of the edge a → b: E(p) = (b − a) × (p − a) = (bx − ax)(py − ay) − (by − ay)(px −
// ax).
//   The triangle is taken counter-clockwise (a clockwise one is reordered: scan conversion does
//   no culling), so its interior has E > 0 on all three edges.
// - Top-left fill rule: a centre with E = 0 on an edge is covered only when that edge is a top
//   edge (horizontal with the interior below it: dy = 0, dx < 0 counter-clockwise) or a left
//   edge (the interior to its right: dy < 0 counter-clockwise). Triangles sharing an edge thus
//   cover each pixel centre on it exactly once.
// - A degenerate triangle (zero area after snapping) covers no pixels.
// - Depth: z in window coordinates is affine in x and y, so it is interpolated linearly with
//   the barycentric coordinates λₖ = Eₖ / (2·area) at the pixel centre (Eₖ the edge opposite
//   vertex k). λₖ are exact ratios of integers.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "solver/core/matrix.hpp"

namespace frustum {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kSubpixelScale = std::int64_t{1} << kSubpixelBits;
// Largest |coordinate| in pixels that setup accepts: keeps every product within int64.
constexpr double kMaxWindowCoordinate = 1 << 20;

// ⌊a / b⌋ and ⌈a / b⌉ for b > 0 (C++ division truncates towards zero).
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
  return a / b - ((a % b != 0) && (a < 0));
}
inline std::int64_t ceil_div(std::int64_t a, std::int64_t b) { return -floor_div(-a, b); }

// v rounded to the nearest 1/2⁸ pixel, in units of 1/2⁸ pixel (halves away from zero).
std::int64_t to_fixed(double v);
// The same from an exact value, decided exactly (a coordinate within rounding of a half-grid
// point snaps the way its exact value says, not its nearest double). Sets `off_grid` when v is
// not a multiple of 1/2⁸. Throws DomainError("triangle") beyond kMaxWindowCoordinate.
std::int64_t to_fixed(const Exact& v, bool& off_grid);

struct FixedPoint2 {
  std::int64_t x, y;  // 1/2⁸ pixel units
};

// E(x, y) = a·x + b·y + c over fixed-point coordinates, for the edge from → to.
struct EdgeFunction {
  FixedPoint2 from, to;
  std::int64_t a, b, c;
  bool top = false, left = false;  // fill-rule class (counter-clockwise orientation)
  std::int64_t at(std::int64_t x, std::int64_t y) const { return a * x + b * y + c; }
  bool top_left() const { return top || left; }
};

struct TriangleSetup {
  std::array<FixedPoint2, 3> v;      // counter-clockwise
  std::array<int, 3> order;          // input index of v[k] (reordered when clockwise)
  std::array<EdgeFunction, 3> edge;  // edge[k] = v[k+1] → v[k+2], the edge opposite v[k]
  std::int64_t area2 = 0;            // twice the area, in (1/2⁸ pixel)² units, ≥ 0
  bool reordered = false;            // the input was clockwise
  bool degenerate = false;           // area2 = 0: covers nothing
  bool snapped = false;              // some vertex was not on the 1/2⁸ grid
  int i_min = 0, i_max = -1, j_min = 0, j_max = -1;  // pixels whose centres lie in the bounding box
};

// Setup of a triangle in window coordinates (x, y). Throws DomainError("triangle") when a
// coordinate is not finite or exceeds kMaxWindowCoordinate.
TriangleSetup setup_triangle(const std::array<Vec2<double>, 3>& window);
// The same into t, overwriting every field (no temporary: the z-buffer's hot path).
void setup_triangle(const std::array<Vec2<double>, 3>& window, TriangleSetup& t);
// From exact window coordinates (the kinds' inputs), snapped exactly.
TriangleSetup setup_triangle_exact(const std::array<Vec2<Exact>, 3>& window);
// The setup from snapped vertices (orientation, edges, fill-rule classes, bounding box).
void setup_fixed(const std::array<FixedPoint2, 3>& snapped, TriangleSetup& t);

// Fixed-point centre of pixel (i, j): ((i + ½)·2⁸, (j + ½)·2⁸).
inline FixedPoint2 pixel_centre(int i, int j) {
  const std::int64_t half = kSubpixelScale / 2;
  return {std::int64_t{i} * kSubpixelScale + half, std::int64_t{j} * kSubpixelScale + half};
}

// Whether the centre of pixel (i, j) is covered (top-left rule).
bool covers(const TriangleSetup& t, int i, int j);

struct Fragment {
  int i, j;
  std::array<std::int64_t, 3> e;  // edge functions at the centre; λₖ = e[k] / area2
};

// Every covered pixel, row by row (j ascending, then i ascending), limited to the pixels
// 0 ≤ i < width, 0 ≤ j < height when width, height > 0.
std::vector<Fragment> rasterize(const TriangleSetup& t, int width = 0, int height = 0);

// z at a fragment: Σ λₖ zₖ with z given per input vertex (the setup's `order` maps them).
template <typename T>
T interpolate(const TriangleSetup& t, const Fragment& f, const std::array<T, 3>& z_input) {
  T sum = T(0);
  for (int k = 0; k < 3; ++k) sum += z_input[t.order[k]] * T(f.e[k]);
  return sum / T(t.area2);
}

}  // namespace frustum
