#include "solver/raster_fast/frame_palette.hpp"

#include <algorithm>
#include <array>
#include <cstring>

#include "solver/util/side_by_side.hpp"

namespace frustum {

namespace {

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

// Where the run of `c` that starts before p ends: 16 pixels at a time (two vector compares with
// AVX2, chosen at load time where the CPU has it), then pixel by pixel.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && \
    !defined(__SANITIZE_ADDRESS__)
__attribute__((target_clones("avx2", "default")))
#endif
const std::uint32_t*
long_run_end(const std::uint32_t* p, const std::uint32_t* end, std::uint32_t c) {
  while (end - p >= 16) {
    std::uint32_t differ = 0;
    for (int m = 0; m < 16; ++m) differ |= p[m] ^ c;
    if (differ != 0) break;
    p += 16;
  }
  while (p < end && *p == c) ++p;
  return p;
}

const std::uint32_t* run_end(const std::uint32_t* p, const std::uint32_t* end, std::uint32_t c) {
  // A run of one or two pixels (an edge, a noisy image) without the call.
  if (p == end || *p != c) return p;
  ++p;
  if (p == end || *p != c) return p;
  return long_run_end(p + 1, end, c);
}

// Rows [r0, r1) of the file (top first) into `part`: its own palette, runs and row starts
// (relative to its own runs).
bool scan_rows(const Image<std::uint32_t>& image, int r0, int r1, FrameRuns& part) {
  ColorIndex index;
  const auto width = static_cast<std::size_t>(image.width);
  part.row_start.push_back(0);
  for (int r = r0; r < r1; ++r) {
    const std::uint32_t* p = &image.data[static_cast<std::size_t>(image.height - 1 - r) * width];
    const std::uint32_t* const end = p + width;
    while (p < end) {
      const std::uint32_t c = *p;
      if (c >> 24 != 0xff) return false;
      const int k = index.find_or_add(c, part.palette);
      if (k < 0) return false;
      const std::uint32_t* const q = run_end(p + 1, end, c);
      part.runs.push_back(static_cast<std::uint32_t>(q - p) << 8 | static_cast<std::uint32_t>(k));
      p = q;
    }
    part.row_start.push_back(part.runs.size());
  }
  return true;
}

}  // namespace

bool frame_runs(const Image<std::uint32_t>& image, FrameRuns& out, int threads, ThreadTeam* team) {
  out = FrameRuns{};
  out.width = image.width;
  out.height = image.height;
  if (image.width >= (1 << 24)) return false;  // a run's length must fit 24 bits
  // Parts of whole rows, each scanned with its own palette; with threads, four parts a thread,
  // taken in turn as the threads finish one (a frame's rows are not alike).
  const int parts = threads <= 1 ? 1 : std::max(1, std::min(image.height / 64, 4 * threads));
  std::vector<FrameRuns> part(static_cast<std::size_t>(parts));
  std::vector<char> fits(static_cast<std::size_t>(parts), 0);
  in_turn(
      std::min(threads, parts), parts,
      [&](int, const auto& next) {
        // Scanned into a part on this thread's stack and moved into place once: the parts side
        // by side in one array share cache lines, and a run's push writes its vector's end.
        for (int k; (k = next()) >= 0;) {
          FrameRuns scanned;
          fits[k] =
              scan_rows(image, image.height * k / parts, image.height * (k + 1) / parts, scanned);
          part[k] = std::move(scanned);
        }
      },
      team);
  if (std::find(fits.begin(), fits.end(), 0) != fits.end()) return false;
  // One palette in order of first appearance: part 0's, then each later part's new colours;
  // each part's indices mapped onto it.
  ColorIndex index;
  out.row_start.push_back(0);
  for (const FrameRuns& p : part) {
    std::array<std::uint32_t, 256> to{};
    for (std::size_t c = 0; c < p.palette.size(); ++c) {
      const int k = index.find_or_add(p.palette[c], out.palette);
      if (k < 0) return false;
      to[c] = static_cast<std::uint32_t>(k);
    }
    for (const std::uint32_t run : p.runs) out.runs.push_back((run & ~0xffu) | to[run & 0xff]);
    const std::size_t base = out.row_start.back();
    for (std::size_t r = 1; r < p.row_start.size(); ++r)
      out.row_start.push_back(base + p.row_start[r]);
  }
  return true;
}

int palette_bit_depth(std::size_t colours) {
  return colours <= 2 ? 1 : colours <= 4 ? 2 : colours <= 16 ? 4 : 8;
}

void pack_row(const FrameRuns& runs, int r, int bits, std::uint8_t* out) {
  const int per_byte = 8 / bits;
  const auto bytes = static_cast<std::size_t>((runs.width * bits + 7) / 8);
  std::memset(out, 0, bytes);
  std::size_t x = 0;  // the run's first pixel
  for (std::size_t k = runs.row_start[r]; k < runs.row_start[r + 1]; ++k) {
    const std::uint32_t index = runs.runs[k] & 0xff;
    std::size_t n = runs.runs[k] >> 8;
    // Pixel by pixel up to a byte boundary, whole bytes of the repeated index, then the rest.
    const auto put = [&](std::size_t at) {
      const int shift = 8 - bits * static_cast<int>(at % per_byte + 1);
      out[at / per_byte] |= static_cast<std::uint8_t>(index << shift);
    };
    for (; n > 0 && x % per_byte != 0; --n) put(x++);
    if (const std::size_t whole = n / per_byte; whole > 0) {
      std::uint32_t pattern = index;
      for (int b = bits; b < 8; b *= 2) pattern |= pattern << b;
      std::memset(out + x / per_byte, static_cast<int>(pattern & 0xff), whole);
      x += whole * per_byte;
      n -= whole * per_byte;
    }
    for (; n > 0; --n) put(x++);
  }
}

std::uint32_t adler32_packed_row(std::uint32_t adler, const FrameRuns& runs, int r, int bits,
                                 const std::uint8_t* packed) {
  constexpr std::uint64_t kBase = 65521;  // the largest prime below 2¹⁶
  // Reduced modulo kBase before each run and at the row's end only: a row has at most 2²⁴ bytes,
  // so between reductions a stays below 2³³ and b below 2⁵⁷.
  std::uint64_t a = adler & 0xffff, b = adler >> 16;
  const auto one = [&](std::uint64_t v) {
    a += v;
    b += a;
  };
  const auto repeated = [&](std::uint64_t v, std::uint64_t n) {  // n < 2²⁴
    a %= kBase;
    b %= kBase;
    b += n * a + v * ((n * (n + 1) / 2) % kBase);
    a += n * v;
  };
  const auto per_byte = static_cast<std::size_t>(8 / bits);
  const auto bytes = static_cast<std::size_t>((runs.width * bits + 7) / 8);
  one(0);                         // the filter byte
  std::size_t x = 0, summed = 0;  // the run's first pixel; the bytes summed so far
  for (std::size_t k = runs.row_start[r]; k < runs.row_start[r + 1]; ++k) {
    const std::size_t n = runs.runs[k] >> 8;
    const std::size_t first = (x + per_byte - 1) / per_byte, end = (x + n) / per_byte;
    if (end > first) {  // bytes first … end − 1 hold this run's pixels only
      for (; summed < first; ++summed) one(packed[summed]);
      repeated(packed[first], end - first);
      summed = end;
    }
    x += n;
  }
  for (; summed < bytes; ++summed) one(packed[summed]);
  return static_cast<std::uint32_t>((b % kBase) << 16 | (a % kBase));
}

bool index_colors(const Image<std::uint32_t>& image, IndexedImage& out) {
  FrameRuns runs;
  if (!frame_runs(image, runs)) return false;
  out.palette = runs.palette;
  out.indices.resize(image.data.size());
  for (int r = 0; r < image.height; ++r)
    pack_row(runs, r, 8, &out.indices[static_cast<std::size_t>(r) * image.width]);
  return true;
}

}  // namespace frustum
