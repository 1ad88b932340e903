// Image-sized buffers on huge pages (solver/raster/large_buffer.hpp): a frame's buffers start on
// a 2 MiB boundary and, where the kernel offers transparent huge pages on request, are backed by
// them once touched; small images are allocated as usual. The pixels are the same either way.
#include "solver/raster/large_buffer.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>

#include "solver/raster/fill.hpp"
#include "solver/raster/zbuffer.hpp"

namespace frustum {
namespace {

// The kernel's transparent-huge-page mode ("always", "madvise" or "never").
std::string thp_mode() {
  std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string line;
  std::getline(f, line);
  const std::size_t open = line.find('['), close = line.find(']');
  return open == std::string::npos || close == std::string::npos
             ? "never"
             : line.substr(open + 1, close - open - 1);
}

// kB of this process's memory in huge pages, from /proc/self/smaps_rollup.
long anon_huge_kb() {
  std::ifstream f("/proc/self/smaps_rollup");
  std::string key;
  long kb = 0;
  while (f >> key) {
    if (key == "AnonHugePages:") {
      f >> kb;
      return kb;
    }
    f.ignore(1 << 12, '\n');
  }
  return -1;
}

TEST(LargeBuffer, AFrameStartsOnAHugePageBoundaryAndKeepsItsPixels) {
  const Frame frame(1920, 1080, Rgb{10, 20, 30});
  const auto at = [](const void* p) { return reinterpret_cast<std::uintptr_t>(p); };
  EXPECT_EQ(at(frame.color.data.data()) % LargeBufferAllocator<char>::kHugePage, 0u);
  EXPECT_EQ(at(frame.depth.data.data()) % LargeBufferAllocator<char>::kHugePage, 0u);
  ASSERT_EQ(frame.color.data.size(), 1920u * 1080u);
  for (const std::uint32_t c : frame.color.data) ASSERT_EQ(c, pack(Rgb{10, 20, 30}));
  for (const float z : frame.depth.data) ASSERT_EQ(z, kDepthClear);
  // A small image: an ordinary allocation, its values as asked.
  const Image<std::uint32_t> small(8, 8, 7u);
  ASSERT_EQ(small.data.size(), 64u);
  for (const std::uint32_t c : small.data) EXPECT_EQ(c, 7u);
}

// Where the kernel offers huge pages on request, a touched frame is backed by them.
TEST(LargeBuffer, ATouchedFrameIsOnHugePagesWhereTheKernelOffersThem) {
  const std::string mode = thp_mode();
  if (mode == "never") GTEST_SKIP() << "transparent huge pages are off on this machine";
  const long before = anon_huge_kb();
  ASSERT_GE(before, 0) << "no AnonHugePages in /proc/self/smaps_rollup";
  const Frame frame(1920, 1080, Rgb{0, 0, 0});
  const long after = anon_huge_kb();
  // 16 MB of colour and depth: at least half of it in 2 MiB pages (the kernel may fall back for
  // a page when memory is fragmented).
  EXPECT_GE(after - before, 8 * 1024) << "THP mode " << mode;
  EXPECT_EQ(frame.color.data.size(), 1920u * 1080u);
}

}  // namespace
}  // namespace frustum
