// A frame's colours as a palette, for the PNG writer (png_writer.hpp): flat-shaded frames hold a
// few colours in long runs of equal pixels, so each row is kept as its runs (a palette index and
// a length) and packed from them at the palette's bit depth, without a byte per pixel between.
#pragma once

#include <cstdint>
#include <vector>

#include "solver/raster/zbuffer.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {

// The palette (at most 256 opaque colours, in the order of their first appearance from the top
// row down) and every row's runs, top row first: runs[row_start[r]] … runs[row_start[r + 1] − 1],
// each (length << 8 | index).
struct FrameRuns {
  int width = 0, height = 0;
  std::vector<std::uint32_t> palette;  // packed colours (fill.hpp's pack)
  std::vector<std::uint32_t> runs;
  std::vector<std::size_t> row_start;
};

// The frame's runs (raster rows, y up: the top row is the last), or false when it has more than
// 256 colours or a colour that is not opaque. `threads` scan parts of the frame side by side; the
// result is the same whatever their number (with a team, on its threads).
bool frame_runs(const Image<std::uint32_t>& image, FrameRuns& out, int threads = 1,
                ThreadTeam* team = nullptr);

// The fewest bits a sample that hold every index of a palette of this size: 1, 2, 4 or 8.
int palette_bit_depth(std::size_t colours);

// Row r (top first) as PNG samples of `bits` bits: the leftmost pixel in the high bits of a
// byte, the last byte padded with zero bits; (width · bits + 7) / 8 bytes.
void pack_row(const FrameRuns& runs, int r, int bits, std::uint8_t* out);

// zlib's Adler-32 `adler` carried over row r as the image data holds it: the filter byte 0, then
// the bytes pack_row wrote to `packed`. The bytes inside one run are one repeated value, whose
// sums have closed forms (a + n·v, and b + n·a + v·n(n + 1)/2), so a row costs a few operations
// a run (each run's first and last byte, which may be shared, one by one) instead of one a byte.
std::uint32_t adler32_packed_row(std::uint32_t adler, const FrameRuns& runs, int r, int bits,
                                 const std::uint8_t* packed);

// Each pixel's index (top row first), as an image viewer would number the palette.
struct IndexedImage {
  std::vector<std::uint32_t> palette;  // packed colours
  std::vector<std::uint8_t> indices;   // width × height, top row first
};
bool index_colors(const Image<std::uint32_t>& image, IndexedImage& out);

}  // namespace frustum
