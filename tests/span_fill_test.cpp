// The z-buffer's span loop: the vector path (AVX2, eight pixels a step and a masked last step)
// against the portable loop, and both against the formula, pixel for pixel and bit for bit.
#include "solver/raster/span_fill.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "solver/raster/rasterizer.hpp"

namespace frustum {
namespace {

struct Row {
  std::vector<float> depth;
  std::vector<std::uint32_t> color;
};

// A row of 80 pixels of stored depths: random, equal to the span's own depths, NaN, ±∞, 0.
Row random_row(std::mt19937& rng, double row_z, double a, double dx0, int first) {
  Row r{std::vector<float>(80), std::vector<std::uint32_t>(80)};
  std::uniform_real_distribution<float> uniform(-1.5f, 1.5f);
  std::uniform_int_distribution<int> pick(0, 9);
  for (int k = 0; k < 80; ++k) {
    r.color[k] = static_cast<std::uint32_t>(rng());
    const float own =
        static_cast<float>(row_z + a * (dx0 + static_cast<double>(k - first) * kSubpixelScale));
    switch (pick(rng)) {
      case 0:
        r.depth[k] = own;
        break;  // a tie: not written
      case 1:
        r.depth[k] = std::nextafter(own, 2.0f);
        break;
      case 2:
        r.depth[k] = std::numeric_limits<float>::quiet_NaN();
        break;
      case 3:
        r.depth[k] = std::numeric_limits<float>::infinity();
        break;
      case 4:
        r.depth[k] = -std::numeric_limits<float>::infinity();
        break;
      default:
        r.depth[k] = uniform(rng);
    }
  }
  return r;
}

bool same_bits(const std::vector<float>& x, const std::vector<float>& y) {
  for (std::size_t k = 0; k < x.size(); ++k)
    if (std::bit_cast<std::uint32_t>(x[k]) != std::bit_cast<std::uint32_t>(y[k])) return false;
  return true;
}

TEST(SpanFill, TheVectorPathEqualsThePortableLoopAndTheFormulaForEveryLength) {
  if (!fill_span_vectorised()) GTEST_SKIP() << "this CPU takes the portable loop only";
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> first_of(0, 7);
  for (int n = 0; n <= 70; ++n) {
    for (int trial = 0; trial < 40; ++trial) {
      const int first = first_of(rng);  // the span starts anywhere in a vector's width
      const double row_z = unit(rng), a = unit(rng) * 1e-4;
      const double dx0 = std::floor(unit(rng) * 1e5);
      const std::uint32_t c = static_cast<std::uint32_t>(rng());
      const Row before = random_row(rng, row_z, a, dx0, first);
      for (const bool count : {false, true}) {
        Row vector = before, portable = before;
        const int wv = fill_span(vector.depth.data() + first, vector.color.data() + first, n, row_z,
                                 a, dx0, c, count);
        const int wp =
            fill_span_portable(portable.depth.data() + first, portable.color.data() + first, n,
                               row_z, a, dx0, c, count);
        ASSERT_EQ(wv, wp) << "n " << n;
        ASSERT_TRUE(same_bits(vector.depth, portable.depth)) << "n " << n;
        ASSERT_EQ(vector.color, portable.color) << "n " << n;
        // The formula, pixel by pixel: written exactly where the span's depth is nearer.
        int expected_written = 0;
        for (int k = 0; k < 80; ++k) {
          const bool in_span = k >= first && k < first + n;
          const float z = static_cast<float>(
              row_z + a * (dx0 + static_cast<double>(k - first) * kSubpixelScale));
          const bool pass = in_span && z < before.depth[k];
          expected_written += pass;
          ASSERT_EQ(std::bit_cast<std::uint32_t>(vector.depth[k]),
                    std::bit_cast<std::uint32_t>(pass ? z : before.depth[k]))
              << "n " << n << " pixel " << k;
          ASSERT_EQ(vector.color[k], pass ? c : before.color[k]) << "n " << n << " pixel " << k;
        }
        ASSERT_EQ(wv, count ? expected_written : 0);
      }
    }
  }
}

}  // namespace
}  // namespace frustum
