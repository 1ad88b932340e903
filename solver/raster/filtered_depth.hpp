// The z-buffer's exact depth test, filtered: each stored exact depth has a ranged double beside
// it (numeric/ranged.hpp: a double and a proven bound on its distance from the exact value),
// and a fragment's depth is compared exactly only when the two ranges overlap (equal depths,
// depths within rounding). An exact depth is built only for a fragment that is written.
// Interpolating and comparing every fragment in GiNaC would take seconds on a 256 × 256 buffer
// with √2 among its depths; the answers (frame, exact depths) are the same either way.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/numeric/ranged.hpp"
#include "solver/raster/zbuffer.hpp"

namespace frustum {

struct FilteredDepthBuffer {
  DepthBuffer<Exact> exact;          // the answer: nullopt is +∞
  Image<Ranged<double>> approx;      // beside each stored exact depth
  std::vector<std::size_t> written;  // cells written since the caller last cleared it
  long exact_comparisons = 0;        // depth tests the ranges could not decide

  FilteredDepthBuffer(int width, int height)
      : exact(width, height, std::nullopt), approx(width, height, Ranged<double>{}) {}
};

// draw_triangle (zbuffer.hpp) with the exact test z < Z(i, j), decided by the ranges first.
DrawCount draw_triangle_filtered(const TriangleSetup& t, const std::array<Exact, 3>& z,
                                 const std::string& label, FilteredDepthBuffer& depth,
                                 FrameBuffer& frame);

}  // namespace frustum
