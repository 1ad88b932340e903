// The frame filled band by band (solver/raster_fast/banded_fill.hpp) is the frame of clearing it
// and drawing every triangle in order, bit for bit, whatever the number of threads and wherever the
// bands cut the triangles: random triangles of every size (slivers, ones larger than the frame,
// ones off it, degenerate ones), overlapping in depth, on frames whose height is and is not a
// multiple of the band.
#include "solver/raster_fast/banded_fill.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "solver/util/side_by_side.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {
namespace {

std::vector<WindowTriangle> random_triangles(std::mt19937& rng, int count, int width, int height) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<WindowTriangle> out;
  for (int k = 0; k < count; ++k) {
    WindowTriangle t;
    // A centre somewhere around the frame, a size from a pixel to twice the frame.
    const double cx = (unit(rng) * 1.4 - 0.2) * width, cy = (unit(rng) * 1.4 - 0.2) * height;
    const double size = std::pow(2.0, unit(rng) * std::log2(2.0 * std::max(width, height)));
    for (Vec3d& v : t.v)
      v = Vec3d(cx + (unit(rng) - 0.5) * size, cy + (unit(rng) - 0.5) * size, unit(rng));
    if (k % 17 == 0) t.v[2] = t.v[0];               // degenerate
    if (k % 13 == 0) t.v[1](1) = t.v[0](1);         // a horizontal edge on a row boundary or not
    if (k % 11 == 0) t.v[2](0) = t.v[0](0) + 0.25;  // a sliver
    t.color = Rgb{static_cast<std::uint8_t>(k * 37), static_cast<std::uint8_t>(k * 91),
                  static_cast<std::uint8_t>(k * 53)};
    out.push_back(t);
  }
  return out;
}

TEST(BandedFill, EqualsClearingAndDrawingInOrderForAnyThreadsAndBands) {
  std::mt19937 rng(20261202);
  const Rgb background{3, 5, 7};
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{
           {1, 1}, {40, 15}, {33, kBandRows}, {64, kBandRows + 1}, {97, 100}, {300, 161}}) {
    const std::vector<WindowTriangle> window = random_triangles(rng, 300, width, height);
    std::vector<RasterTriangle> setups;
    for (std::size_t k = 0; k < window.size(); ++k)
      setups.push_back(setup_raster(window[k], static_cast<int>(k)));
    Frame expected(width, height, background);
    FillStats drawn;
    for (const RasterTriangle& t : setups) draw_triangle(t, expected, &drawn);
    ASSERT_GT(drawn.written, 0);
    ThreadTeam team(3);  // kept from frame to frame, as a render keeps it for its rounds
    for (const int threads : {1, 2, 3, 8, -2, -3, -8}) {
      // A frame that held something else, larger, then smaller: every pixel is written again.
      Frame banded(width + 5, height + 40, Rgb{200, 0, 0});
      banded.depth.data.assign(banded.depth.data.size(), -1.0f);
      FillStats counted;
      // Negative: that many threads, on the team's (3) where there are enough of them.
      fill_in_bands(setups, banded, width, height, background, &counted, std::abs(threads),
                    threads < 0 ? &team : nullptr);
      SCOPED_TRACE(testing::Message() << width << " × " << height << ", " << threads << " threads");
      ASSERT_EQ(banded.color.width, width);
      ASSERT_EQ(banded.depth.height, height);
      EXPECT_EQ(banded.color.data, expected.color.data);
      EXPECT_EQ(banded.depth.data, expected.depth.data);
      EXPECT_EQ(counted.triangles, drawn.triangles);
      EXPECT_EQ(counted.fragments, drawn.fragments);
      EXPECT_EQ(counted.written, drawn.written);
    }
  }
}

// A triangle cut by a band boundary draws each row in the band that holds it, exactly once.
TEST(BandedFill, ARowRangeDrawsOnlyItsRowsAndTheRangesAddUp) {
  WindowTriangle w;
  w.v = {Vec3d(2.5, 1.0, 0.25), Vec3d(60.0, 20.0, 0.5), Vec3d(10.0, 45.0, 0.75)};
  w.color = Rgb{10, 200, 30};
  const RasterTriangle t = setup_raster(w);
  Frame whole(64, 48, Rgb{0, 0, 0}), parts(64, 48, Rgb{0, 0, 0});
  FillStats all, split;
  draw_triangle(t, whole, &all);
  for (int j0 = 0; j0 < 48; j0 += 7) {
    FillStats band;
    Frame alone(64, 48, Rgb{0, 0, 0});
    draw_triangle_rows(t, alone, j0, j0 + 6, &band);
    draw_triangle_rows(t, parts, j0, j0 + 6, &split);
    for (int j = 0; j < 48; ++j) {
      if (j >= j0 && j <= j0 + 6) continue;
      for (int i = 0; i < 64; ++i) ASSERT_EQ(alone.color.at(i, j), pack(Rgb{0, 0, 0}));
    }
  }
  EXPECT_GT(all.fragments, 500);
  EXPECT_EQ(split.fragments, all.fragments);
  EXPECT_EQ(split.written, all.written);
  EXPECT_EQ(parts.color.data, whole.color.data);
  EXPECT_EQ(parts.depth.data, whole.depth.data);
}

// Parts side by side: every part runs once whatever the threads, and an exception on a part's
// thread reaches the caller (the lowest part's) after every part has ended.
TEST(SideBySide, EveryPartRunsOnceAndAnErrorReachesTheCaller) {
  for (const int parts : {1, 2, 5}) {
    std::vector<int> ran(static_cast<std::size_t>(parts), 0);
    side_by_side(parts, [&](int k) { ++ran[static_cast<std::size_t>(k)]; });
    EXPECT_EQ(ran, std::vector<int>(static_cast<std::size_t>(parts), 1));
  }
  std::atomic<int> ended{0};
  try {
    side_by_side(4, [&](int k) {
      ++ended;
      if (k >= 2) throw std::runtime_error("part " + std::to_string(k));
    });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "part 2");
  }
  EXPECT_EQ(ended.load(), 4);
}

// A team's threads run round after round: every part once a round, on as many different threads
// as the team has (more parts than threads: the rest on the caller's), none after the round
// returns; an error reaches the caller and the team goes on; a team that is ended joins its
// threads.
TEST(ThreadTeam, EveryPartOfEveryRoundRunsOnceOnTheTeamsThreads) {
  for (const int size : {1, 2, 4}) {
    ThreadTeam team(size);
    ASSERT_EQ(team.threads(), size);
    for (int round = 0; round < 300; ++round) {
      const int parts = 1 + round % 6;
      std::vector<int> ran(static_cast<std::size_t>(parts), 0);
      std::vector<std::thread::id> on(static_cast<std::size_t>(parts));
      side_by_side(
          parts,
          [&](int k) {
            ++ran[static_cast<std::size_t>(k)];
            on[static_cast<std::size_t>(k)] = std::this_thread::get_id();
          },
          &team);
      ASSERT_EQ(ran, std::vector<int>(static_cast<std::size_t>(parts), 1)) << "round " << round;
      EXPECT_EQ(on[0], std::this_thread::get_id());
      const std::set<std::thread::id> threads(on.begin(), on.end());
      EXPECT_EQ(static_cast<int>(threads.size()), std::min(parts, size)) << "round " << round;
    }
    std::atomic<int> ended{0};
    try {
      side_by_side(
          std::max(size, 2),
          [&](int k) {
            ++ended;
            if (k == 1) throw std::runtime_error("part 1");
          },
          &team);
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "part 1");
    }
    EXPECT_EQ(ended.load(), std::max(size, 2));
    std::atomic<int> after{0};  // counted on every thread of the team
    side_by_side(
        size, [&](int) { ++after; }, &team);  // the team still works
    EXPECT_EQ(after.load(), size);
  }
}

}  // namespace
}  // namespace frustum
