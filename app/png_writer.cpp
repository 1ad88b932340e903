#include "app/png_writer.hpp"

#include <zlib.h>

#include <array>
#include <cstdio>
#include <vector>

#include "app/frame_palette.hpp"

namespace frustum::app {

namespace {

// Flat-shaded frames are long runs of equal pixels. RGBA rows go through the Sub filter, which
// turns a run into zeros; palette rows need no filter (a run is already one repeated byte), as
// the PNG specification recommends for them. zlib's run-length strategy then finds the runs in
// one pass, at a tenth of the time of a full deflate search. Plain data only between setjmp and
// png_write_end: libpng reports an error by longjmp.
bool write_png(const std::string& path, int width, int height, int color_type, int bit_depth,
               const png_byte* const* rows, const std::vector<std::uint32_t>* palette) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    std::fclose(file);
    return false;
  }
  std::array<png_color, 256> colors{};
  if (palette)
    for (std::size_t k = 0; k < palette->size(); ++k) {
      const std::uint32_t c = (*palette)[k];
      colors[k] = {static_cast<png_byte>(c & 0xff), static_cast<png_byte>((c >> 8) & 0xff),
                   static_cast<png_byte>((c >> 16) & 0xff)};
    }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    return false;
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height),
               bit_depth, color_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  if (palette) {
    png_set_PLTE(png, info, colors.data(), static_cast<int>(palette->size()));
    // The indices come from the palette (index_colors): libpng's check of every one of them
    // against its size would be a third of the writing.
    png_set_check_for_invalid_index(png, 0);
  }
  png_set_filter(png, PNG_FILTER_TYPE_BASE, palette ? PNG_FILTER_NONE : PNG_FILTER_SUB);
  png_set_compression_strategy(png, Z_RLE);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  png_write_rows(png, const_cast<png_bytepp>(rows), static_cast<png_uint_32>(height));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return std::fclose(file) == 0;
}

}  // namespace

bool write_png_rows(const std::string& path, int width, int height, int color_type,
                    const png_byte* const* rows) {
  return write_png(path, width, height, color_type, 8, rows, nullptr);
}

bool write_color_png(const std::string& path, const Image<std::uint32_t>& img, int threads) {
  const auto height = static_cast<std::size_t>(img.height);
  std::vector<const png_byte*> rows(height);
  FrameRuns runs;
  if (frame_runs(img, runs, threads)) {
    // A palette of at most 16 colours packs 2, 4 or 8 pixels into a byte: fewer bytes to
    // compress. Each row is packed from its runs.
    const int bits = palette_bit_depth(runs.palette.size());
    const auto stride = static_cast<std::size_t>((img.width * bits + 7) / 8);
    std::vector<std::uint8_t> packed(stride * height);
    for (std::size_t r = 0; r < height; ++r) {
      pack_row(runs, static_cast<int>(r), bits, packed.data() + r * stride);
      rows[r] = packed.data() + r * stride;
    }
    return write_png(path, img.width, img.height, PNG_COLOR_TYPE_PALETTE, bits, rows.data(),
                     &runs.palette);
  }
  // Raster rows (y up) to PNG rows (top first), in place: rows handed to the writer bottom first.
  for (std::size_t r = 0; r < height; ++r)
    rows[r] = reinterpret_cast<const png_byte*>(&img.at(0, img.height - 1 - static_cast<int>(r)));
  return write_png(path, img.width, img.height, PNG_COLOR_TYPE_RGBA, 8, rows.data(), nullptr);
}

}  // namespace frustum::app
