// The PNG files `frustum render` writes (libpng, zlib). bench/render_race.cpp writes llvmpipe's
// frame with the same writer, so that the race compares the pipelines, not two encoders.
#pragma once

#include <png.h>

#include <cstdint>
#include <string>
#include <vector>

#include "solver/raster/zbuffer.hpp"
#include "solver/raster_fast/frame_palette.hpp"

namespace frustum {

// One PNG, 8 bits a sample, from rows given top first; color_type is libpng's
// (PNG_COLOR_TYPE_GRAY, _RGBA, …). False when the file cannot be written.
bool write_png_rows(const std::string& path, int width, int height, int color_type,
                    const png_byte* const* rows);

// A frame (raster rows, y up; packed as fill.hpp's pack()) as a PNG, top row first. A frame of
// at most 256 colours, all opaque — every flat-shaded frame of a scene with few fills — is
// written as a palette image of 1, 2, 4 or 8 bits a pixel (at most 2, 4, 16 or 256 colours):
// the same pixels in a quarter to a thirty-second of the bytes to compress. Any other frame is
// written as 8-bit RGBA (frame_palette.hpp finds the palette; `threads` scan parts of the frame
// side by side — with a team, on its threads — and the file is the same whatever their number).
bool write_color_png(const std::string& path, const Image<std::uint32_t>& image, int threads = 1,
                     ThreadTeam* team = nullptr);

// Depth as grey: the covered depths' range [min, max] stretched to white (near) … dark grey
// (far); the background (depth 1, nothing drawn) black.
bool write_depth_png(const std::string& path, const Image<float>& depth);

}  // namespace frustum
