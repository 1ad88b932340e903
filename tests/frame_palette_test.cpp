// A frame's palette and runs (solver/raster_fast/frame_palette.hpp): the palette in order of first
// appearance from the top row down, and each row's runs, the same whether one thread scans the
// frame or several scan a part each (each part meets the colours in its own order).
#include "solver/raster_fast/frame_palette.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "solver/raster/fill.hpp"

namespace frustum::app {
namespace {

TEST(FramePalette, PartsScannedSideBySideGiveTheOnePaletteAndTheSameRuns) {
  // Raster rows go up: the file's top rows are the frame's last. The top third uses colours
  // 0 and 1, the middle third meets 4, 3, 0 in that order, the bottom third 2, 4, 1, 5.
  const std::vector<std::vector<int>> thirds = {{0, 1}, {4, 3, 0}, {2, 4, 1, 5}};
  const int width = 157, height = 3 * 70;
  Image<std::uint32_t> img(width, height, 0);
  std::mt19937 rng(5);
  const auto colour = [](int k) {
    return pack(Rgb{static_cast<std::uint8_t>(40 * k), static_cast<std::uint8_t>(255 - k), 9});
  };
  for (int r = 0; r < height; ++r) {
    const std::vector<int>& use = thirds[static_cast<std::size_t>(r / 70)];
    int x = 0;
    for (std::size_t k = 0; x < width; ++k) {
      // The colours in their order first, then runs of random lengths and colours.
      const int c = k < use.size() ? use[k] : use[rng() % use.size()];
      const int n = std::min(width - x, 1 + static_cast<int>(rng() % 40));
      for (int m = 0; m < n; ++m, ++x) img.at(x, height - 1 - r) = colour(c);
    }
  }
  FrameRuns one;
  ASSERT_TRUE(frame_runs(img, one, 1));
  const std::vector<std::uint32_t> order = {colour(0), colour(1), colour(4),
                                            colour(3), colour(2), colour(5)};
  EXPECT_EQ(one.palette, order);
  ThreadTeam team(3);
  for (const int threads : {2, 3, 8, -2, -3, -8}) {  // negative: on the team's threads
    FrameRuns parts;
    ASSERT_TRUE(frame_runs(img, parts, std::abs(threads), threads < 0 ? &team : nullptr));
    EXPECT_EQ(parts.palette, one.palette) << threads;
    EXPECT_EQ(parts.runs, one.runs) << threads;
    EXPECT_EQ(parts.row_start, one.row_start) << threads;
  }
  // The runs hold the pixels: packed at 8 bits, each byte is the pixel's palette index.
  std::vector<std::uint8_t> row(width);
  for (int r = 0; r < height; ++r) {
    pack_row(one, r, 8, row.data());
    for (int x = 0; x < width; ++x)
      ASSERT_EQ(one.palette[row[static_cast<std::size_t>(x)]], img.at(x, height - 1 - r))
          << r << " " << x;
  }
}

// Packed at 1, 2 and 4 bits: the leftmost pixel in the high bits, the last byte padded with
// zeros; runs that start and end inside a byte and ones that span many.
TEST(FramePalette, RowsPackAtEveryBitDepth) {
  for (const int bits : {1, 2, 4}) {
    const int colours = 1 << bits, width = 67;
    Image<std::uint32_t> img(width, 1, 0);
    std::mt19937 rng(static_cast<unsigned>(bits));
    for (int x = 0; x < width;) {
      const int k = static_cast<int>(rng() % colours);
      for (int n = 1 + static_cast<int>(rng() % 19); n > 0 && x < width; --n, ++x)
        img.at(x, 0) = pack(Rgb{static_cast<std::uint8_t>(k), 0, 0});
    }
    FrameRuns runs;
    ASSERT_TRUE(frame_runs(img, runs));
    ASSERT_LE(runs.palette.size(), static_cast<std::size_t>(colours));
    std::vector<std::uint8_t> packed((width * bits + 7) / 8, 0xAA);
    pack_row(runs, 0, bits, packed.data());
    const int per_byte = 8 / bits;
    for (int x = 0; x < width; ++x) {
      const int shift = 8 - bits * (x % per_byte + 1);
      const int index = (packed[static_cast<std::size_t>(x / per_byte)] >> shift) & (colours - 1);
      ASSERT_EQ(runs.palette[static_cast<std::size_t>(index)], img.at(x, 0)) << bits << " " << x;
    }
    const int used = width % per_byte;  // pixels in the last byte
    if (used != 0) {
      EXPECT_EQ(packed.back() & ((1 << (8 - bits * used)) - 1), 0) << bits;
    }
  }
}

}  // namespace
}  // namespace frustum::app
