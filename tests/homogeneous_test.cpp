// The homogeneous kind (solver/kinds/homogeneous.cpp) on the lecture's own example and on many
// drawn points; transform's `array` answer (OpenGL's m0–m15); the concave polygon that depth
// sort cannot order.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

SetResult solve_file(const std::string& relative) {
  return solve_set(load_problem_set(test::source_path(relative)), true, {});
}

// The solved problem `id` of `set` (the test fails at .at() when it is missing).
const ProblemResult& find(const SetResult& set, const std::string& id) {
  const auto it = std::find_if(set.problems.begin(), set.problems.end(),
                               [&](const ProblemResult& p) { return p.id == id; });
  return set.problems.at(static_cast<std::size_t>(it - set.problems.begin()));
}

// Seed 002: "(5, 7) is (5, 7, 1), (10, 15, 2), …" — with w = 2 the point is (10, 14, 2), and
// (10, 15, 2) is the point (5, 15/2): the derivation says so, in each language.
TEST(Homogeneous, TheLecturesPointFiveSevenWithWeightTwo) {
  const SetResult set = solve_file("problems/seeds/002_transforms_and_view_volume.yaml");
  const ProblemResult& p = find(set, "seed002-homogeneous-2d");
  ASSERT_FALSE(p.error) << test::error_text(p);
  EXPECT_EQ(test::exact_text(p, "homogeneous"), "10, 14, 2");
  EXPECT_EQ(test::exact_text(p, "cartesian"), "5, 15/2");
  ASSERT_TRUE(p.answers.find("same_point"));
  EXPECT_FALSE(p.answers.find("same_point")->flag);
  // The first problem of the set, as the example comes first in the lecture.
  EXPECT_EQ(set.problems.front().id, "seed002-homogeneous-2d");
  const std::string en = render_text(set, TextStyle{});
  EXPECT_NE(en.find("With W = 2 the point (5, 7) is written (10, 14, 2)."), std::string::npos);
  const std::string text = render_text(set, TextStyle{.lang = Lang::Ja});
  EXPECT_NE(text.find("W = 2 とすると, 点 (5, 7) は (10, 14, 2) と表される."), std::string::npos);
  EXPECT_NE(text.find("商が等しい ⇔ 同じ点"), std::string::npos);
}

// Writing a point with a weight and reading it back is the identity, and a tuple off by one in
// a coordinate is another point, for drawn points, weights (whole and fractional, negative) and
// dimensions.
TEST(Homogeneous, WritingAPointAndReadingItBackIsTheIdentity) {
  Rng rng(20261205);
  for (int i = 0; i < 200; ++i) {
    const int dim = rng.integer(2, 3);
    std::vector<std::int64_t> point;
    for (int k = 0; k < dim; ++k) point.push_back(rng.integer(-50, 50));
    const std::int64_t num = rng.nonzero(-9, 9), den = rng.integer(1, 4);
    std::string point_text, w_text = fmt::format("\"{}/{}\"", num, den);
    for (int k = 0; k < dim; ++k) point_text += fmt::format("{}{}", k ? ", " : "", point[k]);
    const ProblemResult written = test::solve_yaml(
        test::one("homogeneous", fmt::format("{{point: [{}], w: {}}}", point_text, w_text)));
    ASSERT_FALSE(written.error) << test::error_text(written);
    const Value* h = written.answers.find("homogeneous");
    ASSERT_TRUE(h && h->exact.size() == static_cast<std::size_t>(dim + 1));
    EXPECT_TRUE(test::same(h->exact.back(), Exact(GiNaC::numeric(num, den))));
    std::string tuple, off;
    for (std::size_t k = 0; k < h->exact.size(); ++k) {
      const std::string e = format_exact(h->exact[k], MathStyle::Plain);
      tuple += fmt::format("{}\"{}\"", k ? ", " : "", e);
      off += fmt::format("{}\"{}\"", k ? ", " : "", k == 0 ? "(" + e + ") + 1" : e);
    }
    for (const auto& [candidate, same] : {std::pair{tuple, true}, std::pair{off, false}}) {
      const ProblemResult read = test::solve_yaml(test::one(
          "homogeneous", fmt::format("{{point: [{}], candidate: [{}]}}", point_text, candidate)));
      ASSERT_FALSE(read.error) << test::error_text(read);
      const Value* c = read.answers.find("cartesian");
      ASSERT_TRUE(c && c->exact.size() == static_cast<std::size_t>(dim));
      if (same) {
        for (int k = 0; k < dim; ++k) EXPECT_TRUE(test::same(c->exact[k], Exact(point[k])));
      }
      EXPECT_EQ(read.answers.find("same_point")->flag, same) << candidate;
    }
  }
}

TEST(Homogeneous, GivensThatAreNoPointAreRefusedNamingTheField) {
  for (const auto& [given, field] :
       {std::pair{"{point: [5, 7], w: 0}", "w"},
        std::pair{"{point: [5, 7], candidate: [1, 2, 0]}", "candidate"},
        std::pair{"{point: [1, 2, 3, 4], w: 2}", "point"}, std::pair{"{point: [5, 7]}", "w"},
        std::pair{"{point: [5, 7], candidate: [1, 2]}", "candidate"}}) {
    const ProblemResult r = test::solve_yaml(test::one("homogeneous", given));
    ASSERT_TRUE(r.error) << given;
    EXPECT_NE(test::error_text(r).find("given." + std::string(field) + ":"), std::string::npos)
        << given << ": " << test::error_text(r);
  }
}

// Seed 004: OpenGL keeps M column by column, so m0–m2 is the image of x, m4–m6 of y, m8–m10 of
// z and m12–m14 the translation.
TEST(TransformArray, TheLecturesColumnsAreTheNewAxesAndOrigin) {
  const SetResult set = solve_file("problems/seeds/004_placing_and_projecting.yaml");
  const ProblemResult& p = find(set, "seed004-matrix-layout");
  ASSERT_FALSE(p.error) << test::error_text(p);
  EXPECT_EQ(set.problems.front().id, "seed004-matrix-layout");
  EXPECT_EQ(test::exact_text(p, "array"), "0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1");
  const std::string text = render_text(set, TextStyle{.lang = Lang::Ru});
  EXPECT_NE(text.find("Матрица как массив: по столбцам"), std::string::npos);
  EXPECT_NE(text.find("m12–m14 — перенос"), std::string::npos);
}

// For drawn transforms, in 2-D and 3-D: entry k of the column-major array is M(k mod n, k div
// n); and the column-major array of OpenGL's M holds the same numbers as the row-major array of
// DirectX's printed (transposed) matrix, the one memory layout both APIs load.
TEST(TransformArray, ColumnMajorOfOpenGLIsRowMajorOfDirectX) {
  Rng rng(7);
  for (int i = 0; i < 40; ++i) {
    const int dim = rng.integer(2, 3);
    const std::string steps =
        dim == 2
            ? fmt::format("[{{rotate: {}}}, {{translate: [{}, {}]}}, {{scale: [{}, 2]}}]",
                          rng.integer(-180, 180), rng.integer(-9, 9), rng.integer(-9, 9),
                          rng.nonzero(-3, 3))
            : fmt::format("[{{rotate_x: {}}}, {{translate: [{}, {}, {}]}}, {{shear: {{xy: {}}}}}]",
                          rng.integer(-180, 180), rng.integer(-9, 9), rng.integer(-9, 9),
                          rng.integer(-9, 9), rng.nonzero(-2, 2));
    const auto solved = [&](const std::string& api, const std::string& order) {
      return test::solve_yaml(test::one(
          "transform", fmt::format("{{dim: {}, steps: {}, array: {}}}", dim, steps, order),
          "{api: " + api + "}", "    ask: [matrix, array]\n"));
    };
    const ProblemResult gl = solved("opengl", "column_major");
    const ProblemResult dx = solved("directx", "row_major");
    ASSERT_FALSE(gl.error) << test::error_text(gl);
    ASSERT_FALSE(dx.error) << test::error_text(dx);
    EXPECT_EQ(test::exact_text(gl, "array"), test::exact_text(dx, "array")) << steps;
    const Value* m = gl.answers.find("matrix");
    const Value* a = gl.answers.find("array");
    const std::size_t n = static_cast<std::size_t>(dim + 1);
    ASSERT_TRUE(m && a && a->exact.size() == n * n && m->exact.size() == n * n);
    for (std::size_t k = 0; k < n * n; ++k)  // the matrix's values are row by row
      EXPECT_TRUE(test::same(a->exact[k], m->exact[(k % n) * n + k / n])) << k;
  }
}

// The lectures' third failure of depth sort: a concave polygon and a strip through its notch.
// Over one arm the strip is behind, over the other in front: the pair conflicts whatever the
// order, and the centroid order (the strip first) is wrong.
TEST(LectureDepthSort, AConcavePolygonConflictsWithAStripThroughItsNotch) {
  const SetResult set = solve_file("problems/examples/visibility.yaml");
  const ProblemResult& p = find(set, "depth-sort-concave");
  ASSERT_FALSE(p.error) << test::error_text(p);
  EXPECT_EQ(p.answers.find("order")->shown().unicode, "1, 0");
  EXPECT_EQ(p.answers.find("conflicts")->shown().unicode, "0-1");
  const std::string text = render_text(set, TextStyle{});
  EXPECT_NE(text.find("one wraps around the other (a concave polygon)"), std::string::npos);
}

// The tie rule of the drawing order is said where two centroids are equally deep (the
// interpenetrating pair) and nowhere else (the concave pair: 6 and 13/2).
TEST(LectureDepthSort, TheTieRuleIsSaidOnlyWhereDepthsTie) {
  const SetResult set = solve_file("problems/examples/visibility.yaml");
  const auto said = [&](const std::string& id) {
    for (const Step& s : find(set, id).derivation.steps())
      if (s.note.en() == "Equal depths keep the listed order.") return true;
    return false;
  };
  EXPECT_TRUE(said("depth-sort-interpenetrating"));
  EXPECT_FALSE(said("depth-sort-concave"));
}

}  // namespace
}  // namespace frustum
