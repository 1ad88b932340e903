// The PNG files `frustum render` writes (libpng, zlib). bench/render_race.cpp writes llvmpipe's
// frame with the same writer, so that the race compares the pipelines, not two encoders.
#pragma once

#include <png.h>

#include <cstdint>
#include <string>
#include <vector>

#include "solver/raster/zbuffer.hpp"

namespace frustum::app {

// One PNG, 8 bits a sample, from rows given top first; color_type is libpng's
// (PNG_COLOR_TYPE_GRAY, _RGBA, …). False when the file cannot be written.
bool write_png_rows(const std::string& path, int width, int height, int color_type,
                    const png_byte* const* rows);

// A frame (raster rows, y up; packed as fill.hpp's pack()) as a PNG, top row first. A frame of
// at most 256 colours, all opaque — every flat-shaded frame of a scene with few fills — is
// written as a palette image of 1, 2, 4 or 8 bits a pixel (at most 2, 4, 16 or 256 colours):
// the same pixels in a quarter to a thirty-second of the bytes to compress. Any other frame is
// written as 8-bit RGBA.
bool write_color_png(const std::string& path, const Image<std::uint32_t>& image);

// What write_color_png chooses: the palette (at most 256 opaque colours, in the order of their
// first appearance from the top row down) and each pixel's index into it, top row first; or
// false when the frame has more colours or a colour that is not opaque.
struct IndexedImage {
  std::vector<std::uint32_t> palette;  // packed colours
  std::vector<std::uint8_t> indices;   // width × height, top row first
};
bool index_colors(const Image<std::uint32_t>& image, IndexedImage& out);

}  // namespace frustum::app
