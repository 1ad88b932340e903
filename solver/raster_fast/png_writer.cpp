#include "solver/raster_fast/png_writer.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "solver/raster/fill.hpp"
#include "solver/raster_fast/frame_palette.hpp"
#include "solver/util/side_by_side.hpp"

namespace frustum {

namespace {

// Flat-shaded frames are long runs of equal pixels. RGBA rows go through the Sub filter, which
// turns a run into zeros; palette rows need no filter (a run is already one repeated byte), as
// the PNG specification recommends for them. zlib's run-length strategy then finds the runs in
// one pass, at a tenth of the time of a full deflate search. Plain data only between setjmp and
// png_write_end: libpng reports an error by longjmp.
// `rows` are compressed by libpng; or, with `idat`, the image data is that zlib stream, already
// compressed, written as the one IDAT chunk (libpng still writes the signature, IHDR, PLTE, the
// chunks' CRCs and IEND).
// The file is written over from its start and then cut to the new length, not emptied first:
// emptying a file gives its blocks back to the disk at once (on a file system mounted with
// `discard`, a synchronous trim of each block, longer than writing the whole image).
bool write_png(const std::string& path, int width, int height, int color_type, int bit_depth,
               const png_byte* const* rows, const std::vector<std::uint32_t>* palette,
               const std::vector<unsigned char>* idat = nullptr) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  std::FILE* file = ::fdopen(fd, "wb");  // no O_TRUNC: fdopen keeps the file as it is
  if (!file) {
    ::close(fd);
    return false;
  }
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
    // The indices come from the palette (frame_runs): libpng's check of every one of them
    // against its size would be a third of the writing.
    png_set_check_for_invalid_index(png, 0);
  }
  png_set_filter(png, PNG_FILTER_TYPE_BASE, palette ? PNG_FILTER_NONE : PNG_FILTER_SUB);
  png_set_compression_strategy(png, Z_RLE);
  png_set_compression_level(png, 1);
  png_write_info(png, info);
  if (idat) {
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IDAT"), idat->data(), idat->size());
    png_write_chunk(png, reinterpret_cast<png_const_bytep>("IEND"), nullptr, 0);
  } else {
    png_write_rows(png, const_cast<png_bytepp>(rows), static_cast<png_uint_32>(height));
    png_write_end(png, nullptr);
  }
  png_destroy_write_struct(&png, &info);
  // Cut to the image's length: what was left of a longer file that was there before goes.
  const bool ok = std::fflush(file) == 0 && ::ftruncate(fd, ::ftello(file)) == 0;
  return std::fclose(file) == 0 && ok;
}

// A palette frame's image data as one zlib stream, made of pieces of kRowsPerPiece rows that
// are packed and compressed independently — side by side with `threads` — and joined: the zlib
// header, each piece's raw deflate data (every piece but the last ends on a byte boundary with a
// sync flush), and the Adler-32 of all the rows, combined from the pieces'. The run-length
// strategy only ever refers back one byte, so a piece loses nothing by not seeing the rows
// before it, and the stream is the same whatever the number of threads. Empty on a zlib error.
constexpr int kRowsPerPiece = 64;

std::vector<unsigned char> compress_rows(const FrameRuns& runs, int bits, int threads,
                                         ThreadTeam* team) {
  const auto stride = static_cast<std::size_t>((runs.width * bits + 7) / 8) + 1;  // + filter byte
  const int pieces = std::max(1, (runs.height + kRowsPerPiece - 1) / kRowsPerPiece);
  const int workers = std::max(1, std::min(threads, pieces));
  // Each piece compressed on its own into its own buffer. The workers take the pieces in turn as
  // they finish one (a frame's rows are not alike: one part of a picture can take far longer to
  // compress than another), each with one deflate state (reset for each piece) and one row
  // buffer.
  struct Piece {
    std::vector<unsigned char> out;
    uLong adler = 0, length = 0;
    bool ok = false;
  };
  std::vector<Piece> piece(static_cast<std::size_t>(pieces));
  in_turn(
      workers, pieces,
      [&](int, const auto& next) {
        z_stream z{};
        if (deflateInit2(&z, 1, Z_DEFLATED, -15, 8, Z_RLE) != Z_OK) return;
        std::vector<unsigned char> raw(stride * kRowsPerPiece);
        for (int k; (k = next()) >= 0;) {
          Piece& p = piece[static_cast<std::size_t>(k)];
          const int r0 = k * kRowsPerPiece, r1 = std::min(runs.height, r0 + kRowsPerPiece);
          const std::size_t size = stride * static_cast<std::size_t>(r1 - r0);
          std::uint32_t adler = 1;  // of no bytes
          for (int r = r0; r < r1; ++r) {
            unsigned char* row = raw.data() + stride * static_cast<std::size_t>(r - r0);
            row[0] = 0;  // filter type None: a palette row's runs are already repeated bytes
            pack_row(runs, r, bits, row + 1);
            adler = adler32_packed_row(adler, runs, r, bits, row + 1);
          }
          p.adler = adler;
          p.length = static_cast<uLong>(size);
          p.out.resize(deflateBound(&z, static_cast<uLong>(size)) + 16);  // + a sync flush
          z.next_in = raw.data();
          z.avail_in = static_cast<uInt>(size);
          z.next_out = p.out.data();
          z.avail_out = static_cast<uInt>(p.out.size());
          const bool end = k == pieces - 1;
          const int rc = deflate(&z, end ? Z_FINISH : Z_SYNC_FLUSH);
          p.ok = (end ? rc == Z_STREAM_END : rc == Z_OK && z.avail_out > 0) && z.avail_in == 0;
          p.out.resize(p.out.size() - z.avail_out);
          if (deflateReset(&z) != Z_OK) p.ok = false;
        }
        deflateEnd(&z);
      },
      team);
  // CMF 0x78: deflate with a 32 KB window; FLG 0x01: the fastest level, 0x7801 divisible by 31.
  std::vector<unsigned char> stream = {0x78, 0x01};
  uLong adler = adler32(0L, Z_NULL, 0);
  for (const Piece& p : piece) {
    if (!p.ok) return {};
    stream.insert(stream.end(), p.out.begin(), p.out.end());
    adler = adler32_combine(adler, p.adler, static_cast<z_off_t>(p.length));
  }
  for (int shift = 24; shift >= 0; shift -= 8)
    stream.push_back(static_cast<unsigned char>((adler >> shift) & 0xff));
  return stream;
}

}  // namespace

bool write_png_rows(const std::string& path, int width, int height, int color_type,
                    const png_byte* const* rows) {
  return write_png(path, width, height, color_type, 8, rows, nullptr);
}

bool write_color_png(const std::string& path, const Image<std::uint32_t>& img, int threads,
                     ThreadTeam* team) {
  FrameRuns runs;
  if (frame_runs(img, runs, threads, team)) {
    // A palette of at most 16 colours packs 2, 4 or 8 pixels into a byte: fewer bytes to
    // compress. Each row is packed from its runs, and the rows compressed in pieces.
    const int bits = palette_bit_depth(runs.palette.size());
    const std::vector<unsigned char> idat = compress_rows(runs, bits, threads, team);
    if (!idat.empty())
      return write_png(path, img.width, img.height, PNG_COLOR_TYPE_PALETTE, bits, nullptr,
                       &runs.palette, &idat);
  }
  // Raster rows (y up) to PNG rows (top first), in place: rows handed to the writer bottom first.
  const auto height = static_cast<std::size_t>(img.height);
  std::vector<const png_byte*> rows(height);
  for (std::size_t r = 0; r < height; ++r)
    rows[r] = reinterpret_cast<const png_byte*>(&img.at(0, img.height - 1 - static_cast<int>(r)));
  return write_png(path, img.width, img.height, PNG_COLOR_TYPE_RGBA, 8, rows.data(), nullptr);
}

bool write_depth_png(const std::string& path, const Image<float>& depth) {
  float lo = kDepthClear, hi = 0;
  for (float z : depth.data)
    if (z < kDepthClear) {
      lo = std::min(lo, z);
      hi = std::max(hi, z);
    }
  std::vector<std::uint8_t> grey(depth.data.size(), 0);
  for (int r = 0; r < depth.height; ++r)
    for (int i = 0; i < depth.width; ++i) {
      const float z = depth.at(i, depth.height - 1 - r);
      if (z >= kDepthClear) continue;
      const double t = hi > lo ? (z - lo) / (hi - lo) : 0.0;
      grey[static_cast<std::size_t>(r) * depth.width + i] =
          static_cast<std::uint8_t>(255 - std::lround(t * 215));
    }
  std::vector<const png_byte*> rows(static_cast<std::size_t>(depth.height));
  for (int r = 0; r < depth.height; ++r)
    rows[static_cast<std::size_t>(r)] = grey.data() + static_cast<std::size_t>(r) * depth.width;
  return write_png_rows(path, depth.width, depth.height, PNG_COLOR_TYPE_GRAY, rows.data());
}

}  // namespace frustum
