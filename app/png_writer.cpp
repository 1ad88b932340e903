#include "app/png_writer.hpp"

#include <zlib.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

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

// Colour → palette index: open addressing in a table four times the palette's size. 0 is no
// opaque colour, so it marks an empty slot.
class ColorIndex {
 public:
  // The colour's index, a new one if it is new; −1 when the palette is full.
  int find_or_add(std::uint32_t c, std::vector<std::uint32_t>& palette) {
    for (std::uint32_t slot = (c * 0x9E3779B1u) >> (32 - kBits);; slot = (slot + 1) & kMask) {
      if (keys_[slot] == c) return values_[slot];
      if (keys_[slot] != 0) continue;
      if (palette.size() == 256) return -1;
      keys_[slot] = c;
      values_[slot] = static_cast<std::uint8_t>(palette.size());
      palette.push_back(c);
      return values_[slot];
    }
  }

 private:
  static constexpr int kBits = 10;
  static constexpr std::uint32_t kMask = (1u << kBits) - 1;
  std::array<std::uint32_t, 1u << kBits> keys_{};
  std::array<std::uint8_t, 1u << kBits> values_{};
};

// Row of 8-bit indices → kBits-bit samples, the leftmost pixel in the high bits of a byte and
// the last byte padded with zero bits, as PNG packs them.
template <int kBits>
void pack_row(const std::uint8_t* in, int width, std::uint8_t* out) {
  constexpr int kPerByte = 8 / kBits;
  const int whole = width / kPerByte;
  for (int b = 0; b < whole; ++b, in += kPerByte) {
    unsigned v = 0;
    for (int k = 0; k < kPerByte; ++k) v = v << kBits | in[k];
    out[b] = static_cast<std::uint8_t>(v);
  }
  if (const int rest = width - whole * kPerByte; rest > 0) {
    unsigned v = 0;
    for (int k = 0; k < kPerByte; ++k) v = v << kBits | (k < rest ? in[k] : 0u);
    out[whole] = static_cast<std::uint8_t>(v);
  }
}

// The fewest bits a sample that hold every index of the palette: 1, 2, 4 or 8.
int palette_bit_depth(std::size_t colors) {
  return colors <= 2 ? 1 : colors <= 4 ? 2 : colors <= 16 ? 4 : 8;
}

}  // namespace

bool write_png_rows(const std::string& path, int width, int height, int color_type,
                    const png_byte* const* rows) {
  return write_png(path, width, height, color_type, 8, rows, nullptr);
}

bool index_colors(const Image<std::uint32_t>& image, IndexedImage& out) {
  out.palette.clear();
  out.indices.resize(image.data.size());
  ColorIndex index;
  const auto width = static_cast<std::size_t>(image.width);
  std::uint8_t* to = out.indices.data();
  for (int r = 0; r < image.height; ++r) {
    const std::uint32_t* p = &image.data[static_cast<std::size_t>(image.height - 1 - r) * width];
    const std::uint32_t* const end = p + width;
    while (p < end) {  // one run of equal pixels at a time
      const std::uint32_t c = *p;
      if (c >> 24 != 0xff) return false;
      const int k = index.find_or_add(c, out.palette);
      if (k < 0) return false;
      // The run's end, 8 pixels at a time (one vector compare), then pixel by pixel.
      const std::uint32_t* q = p + 1;
      while (end - q >= 8) {
        std::uint32_t differ = 0;
        for (int m = 0; m < 8; ++m) differ |= q[m] ^ c;
        if (differ != 0) break;
        q += 8;
      }
      while (q < end && *q == c) ++q;
      std::memset(to, k, static_cast<std::size_t>(q - p));
      to += q - p;
      p = q;
    }
  }
  return true;
}

bool write_color_png(const std::string& path, const Image<std::uint32_t>& img) {
  const auto height = static_cast<std::size_t>(img.height);
  std::vector<const png_byte*> rows(height);
  IndexedImage indexed;
  if (index_colors(img, indexed)) {
    // A palette of at most 16 colours packs 2, 4 or 8 pixels into a byte: fewer bytes to
    // compress. The indices are packed row by row in place, each row at the start of its own.
    const int bits = palette_bit_depth(indexed.palette.size());
    const auto width = static_cast<std::size_t>(img.width);
    for (std::size_t r = 0; r < height; ++r) {
      std::uint8_t* row = indexed.indices.data() + r * width;
      if (bits == 4) pack_row<4>(row, img.width, row);
      if (bits == 2) pack_row<2>(row, img.width, row);
      if (bits == 1) pack_row<1>(row, img.width, row);
      rows[r] = row;
    }
    return write_png(path, img.width, img.height, PNG_COLOR_TYPE_PALETTE, bits, rows.data(),
                     &indexed.palette);
  }
  // Raster rows (y up) to PNG rows (top first), in place: rows handed to the writer bottom first.
  for (std::size_t r = 0; r < height; ++r)
    rows[r] = reinterpret_cast<const png_byte*>(&img.at(0, img.height - 1 - static_cast<int>(r)));
  return write_png(path, img.width, img.height, PNG_COLOR_TYPE_RGBA, 8, rows.data(), nullptr);
}

}  // namespace frustum::app
