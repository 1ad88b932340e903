// The scanline kind (solver/kinds/scanline.cpp): the lecture exercise's two triangles, a
// cross-check against the Z-buffer kind along the same line on drawn scenes, and the givens it
// refuses.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "solver/problem/problem_set.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

TEST(Scanline, TheLectureExercisesTwoTrianglesCrossAtSixteenThirds) {
  const SetResult set = solve_set(
      load_problem_set(test::source_path("problems/examples/lecture_exercises.yaml")), true, {});
  const ProblemResult* p = nullptr;
  for (const ProblemResult& r : set.problems)
    if (r.id == "scanline-two-triangles") p = &r;
  ASSERT_TRUE(p);
  ASSERT_FALSE(p->error) << test::error_text(*p);
  EXPECT_EQ(test::exact_text(*p, "spans"), "2, 5/2, 6, 11/2, 21/5, 5, 49/5, 5");
  EXPECT_EQ(p->answers.find("visible")->shown().unicode, "A, B");
  EXPECT_EQ(test::exact_text(*p, "breaks"), "2, 16/3, 49/5");
}

// Drawn scenes of two or three triangles on a 12 × 12 grid: along the line through row j's
// pixel centres (y = j + ½) the section seen at each centre x = i + ½ is the Z-buffer's frame
// at (i, j) — smaller z nearer, the polygon listed first kept on a tie — except where a centre
// lies exactly on a breakpoint, which the Z-buffer settles by its top-left rule.
TEST(Scanline, EqualsTheZBufferFrameAlongTheLine) {
  Rng rng(1206);
  int compared = 0;
  for (int scene = 0; scene < 120; ++scene) {
    const int j = static_cast<int>(rng.integer(2, 9));
    std::string polygons;
    const int count = static_cast<int>(rng.integer(2, 3));
    for (int k = 0; k < count; ++k) {
      const std::int64_t x0 = rng.integer(0, 7);
      polygons +=
          fmt::format("      - {{label: {}, points: [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]}}\n",
                      static_cast<char>('A' + k), x0, rng.integer(0, j), rng.integer(1, 9),
                      x0 + rng.integer(2, 5), rng.integer(0, j), rng.integer(1, 9),
                      x0 + rng.integer(0, 5), rng.integer(j + 1, 12), rng.integer(1, 9));
    }
    const ProblemResult line = test::solve_yaml(
        fmt::format("problems:\n  - id: p\n    kind: scanline\n    given:\n      y: \"{}/2\"\n"
                    "      polygons:\n{}",
                    2 * j + 1, polygons));
    if (line.error) continue;  // a flat triangle, refused: drawn again
    const ProblemResult grid = test::solve_yaml(
        fmt::format("problems:\n  - id: p\n    kind: zbuffer\n    given:\n      size: [12, 12]\n"
                    "      polygons:\n{}",
                    polygons));
    ASSERT_FALSE(grid.error) << test::error_text(grid);
    const std::vector<std::string>& visible = line.answers.find("visible")->words;
    const std::vector<Exact>& breaks = line.answers.find("breaks")->exact;
    ASSERT_EQ(breaks.size(), visible.size() + 1);
    const std::vector<std::string>& rows = grid.answers.find("frame")->words;
    ASSERT_EQ(rows.size(), 12u);
    const std::string& row = rows[static_cast<std::size_t>(11 - j)];  // top row first
    for (int i = 0; i < 12; ++i) {
      const Exact x = Exact(GiNaC::numeric(2 * i + 1, 2));
      bool on_break = false;
      std::string seen = ".";
      for (std::size_t k = 0; k < breaks.size(); ++k) on_break |= test::same(breaks[k], x);
      for (std::size_t k = 0; k < visible.size(); ++k)
        if (exact_sign(breaks[k] - x) < 0 && exact_sign(x - breaks[k + 1]) < 0) seen = visible[k];
      if (on_break) continue;
      EXPECT_EQ(seen, std::string(1, row[static_cast<std::size_t>(i)]))
          << "scene " << scene << ", pixel (" << i << ", " << j << ")\n"
          << polygons;
      ++compared;
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(Scanline, GivensItCannotCutAreRefusedNamingTheField) {
  for (const auto& [polygons, y, field] :
       {std::tuple{"[{label: A, points: [[0, 0, 1], [4, 0, 1], [1, 1, 1], [0, 4, 1]]}]", "1/2",
                   "points"},  // concave
        std::tuple{"[{label: A, points: [[0, 0, 1], [4, 0, 1], [4, 4, 9], [0, 4, 1]]}]", "1/2",
                   "points"},  // not planar
        std::tuple{"[{label: A, points: [[0, 0, 1], [4, 0, 1], [8, 0, 1]]}]", "0",
                   "points"},  // no area
        std::tuple{"[{label: \".\", points: [[0, 0, 1], [4, 0, 1], [2, 4, 1]]}]", "1", "label"},
        std::tuple{"[{label: \"A}\", points: [[0, 0, 1], [4, 0, 1], [2, 4, 1]]}]", "1", "label"},
        std::tuple{"[{label: A, points: [[0, 0, 1], [4, 0, 1], [2, 4, 1]]}, {label: A, points: "
                   "[[0, 0, 2], [4, 0, 2], [2, 4, 2]]}]",
                   "1", "label"},
        std::tuple{"[{label: A, points: [[0, 0, 1], [4, 0, 1], [2, 4, 1]]}]", "9", "y"}}) {
    const ProblemResult r = test::solve_yaml(
        test::one("scanline", fmt::format("{{y: \"{}\", polygons: {}}}", y, polygons)));
    ASSERT_TRUE(r.error) << polygons << " y = " << y;
    EXPECT_NE(test::error_text(r).find(field), std::string::npos)
        << polygons << ": " << test::error_text(r);
  }
}

}  // namespace
}  // namespace frustum
