// Each kind beyond the seeds: properties over generated cases, exact inputs, domain errors.
#include <fmt/format.h>

#include <random>

#include "solver/geometry/predicates.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::error_text;
using test::exact_text;
using test::solve_yaml;

std::string one(const std::string& kind, const std::string& given, const std::string& extra = "") {
  return test::one(kind, given, "", extra);
}

TEST(Kinds, RegistryHasTheFoundationKindsWithTheirAnswers) {
  const Registry& r = builtin_kinds();
  for (const char* k : {"vectors", "normal", "plane", "depth_at_pixel", "backface"})
    ASSERT_NE(r.find(k), nullptr) << k;
  EXPECT_NE(r.find("depth_at_pixel")->answer("inside"), nullptr);
  EXPECT_NE(r.find("backface")->answer("facing"), nullptr);
  EXPECT_EQ(r.find("nope"), nullptr);
}

TEST(Vectors, ParallelVectorsHaveNoUnitNormalButOtherAnswers) {
  const ProblemResult r = solve_yaml(one("vectors", "{a: [1, 2, 3], b: [2, 4, 6]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "area"), "0");
  EXPECT_EQ(exact_text(r, "cos"), "1");
  EXPECT_EQ(exact_text(r, "angle"), "0");
  EXPECT_EQ(r.answers.find("unit_normal")->shape, Value::Shape::Null);
  EXPECT_TRUE(r.derivation.has_warnings());
}

TEST(Vectors, AngleInDegreesAndRadians) {
  const ProblemResult deg = solve_yaml(one("vectors", "{a: [1, 0, 0], b: [1, 1, 0]}"));
  EXPECT_EQ(exact_text(deg, "angle"), "45");
  const ProblemResult rad = solve_yaml("conventions: {angles: radians}\n" +
                                       one("vectors", "{a: [1, 0, 0], b: [0, 0, 5]}"));
  EXPECT_EQ(exact_text(rad, "angle"), "pi/2");
}

TEST(Vectors, ZeroVectorIsADomainErrorNamingTheField) {
  const ProblemResult r = solve_yaml(one("vectors", "{a: [0, 0, 0], b: [1, 0, 0]}"));
  ASSERT_TRUE(r.error);
  EXPECT_EQ(r.error->field, "problems[0].given.a");
  EXPECT_GT(r.error->where.line, 0);
}

TEST(Vectors, ExactExpressionInputs) {
  const ProblemResult r =
      solve_yaml(one("vectors", "{a: [\"sqrt(3)\", 1, 0], b: [\"1/2\", \"sqrt(3)/2\", 0]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "dot"), "sqrt(3)");
  EXPECT_EQ(exact_text(r, "cross"), "0, 0, 1");
  EXPECT_EQ(exact_text(r, "angle"), "30");
}

TEST(Normal, QuadUsesNewellAndIsPlanar) {
  const ProblemResult r = solve_yaml(one("normal", "{points: [[0,0,0],[2,0,0],[2,2,0],[0,2,0]]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "normal"), "0, 0, 8");
  EXPECT_EQ(exact_text(r, "unit_normal"), "0, 0, 1");
}

TEST(Normal, CrossOrderFlipsTheNormal) {
  const ProblemResult ab =
      solve_yaml(one("normal", "{A: [0,0,6], B: [3,0,9], C: [0,3,9], cross: [AB, AC]}"));
  const ProblemResult ac =
      solve_yaml(one("normal", "{A: [0,0,6], B: [3,0,9], C: [0,3,9], cross: [AC, AB]}"));
  EXPECT_EQ(exact_text(ab, "normal"), "-9, -9, 9");
  EXPECT_EQ(exact_text(ac, "normal"), "9, 9, -9");
}

TEST(Normal, CollinearPointsAreADomainError) {
  const ProblemResult r = solve_yaml(one("normal", "{points: [[0,0,0],[1,1,1],[2,2,2]]}"));
  ASSERT_TRUE(r.error);
  EXPECT_NE(r.error->message.find("degenerate"), std::string::npos);
  EXPECT_EQ(r.error->field, "problems[0].given.points");
}

TEST(Normal, NearlyParallelEdgesWarnInTheDerivation) {
  const ProblemResult r =
      solve_yaml(one("normal", "{points: [[0,0,0],[1.0e8,0,0],[2.0e8, 1.0e-8, 0]]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_TRUE(r.derivation.has_warnings());
  EXPECT_EQ(exact_text(r, "unit_normal"), "0, 0, 1");
}

TEST(Plane, PointAndNormalWithDistance) {
  const ProblemResult r = solve_yaml(one("plane", "{point: [0, 0, 6], normal: [9, 9, -9]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "plane"), "1, 1, -1, -6");
  EXPECT_EQ(exact_text(r, "distance"), "2*sqrt(3)");
}

TEST(Plane, IrrationalNormalsStillGiveIntegerPlanes) {
  const ProblemResult r =
      solve_yaml(one("plane", "{point: [1, 1, 1], normal: [\"sqrt(2)\", \"sqrt(2)\", 0]}"));
  ASSERT_FALSE(r.error) << error_text(r);
  EXPECT_EQ(exact_text(r, "plane"), "1, 1, 0, 2");
}

TEST(DepthAtPixel, ZSatisfiesThePlaneOverManyTriangles) {
  std::mt19937 rng(2024);
  std::uniform_int_distribution<int> d(-20, 20);
  int solved = 0;
  for (int i = 0; i < 60; ++i) {
    const std::string tri = fmt::format("[[{},{},{}],[{},{},{}],[{},{},{}]]", d(rng), d(rng),
                                        d(rng), d(rng), d(rng), d(rng), d(rng), d(rng), d(rng));
    const int px = d(rng), py = d(rng);
    const ProblemResult r = solve_yaml(
        one("depth_at_pixel", fmt::format("{{triangle: {}, pixel: [{}, {}]}}", tri, px, py)));
    if (r.error) continue;  // edge-on or collinear: a domain error, tested elsewhere
    const Value& plane = *r.answers.find("plane");
    const Value& z = *r.answers.find("z");
    const Exact lhs = plane.exact[0] * px + plane.exact[1] * py + plane.exact[2] * z.exact[0];
    EXPECT_TRUE(canonical(lhs - plane.exact[3]).is_zero()) << tri;
    const Value& u = *r.answers.find("unit_normal");
    EXPECT_TRUE(
        canonical(u.exact[0] * u.exact[0] + u.exact[1] * u.exact[1] + u.exact[2] * u.exact[2] - 1)
            .is_zero());
    ++solved;
  }
  EXPECT_GT(solved, 50);
}

TEST(DepthAtPixel, OutsidePixelAndEdgeOnTriangle) {
  const ProblemResult out =
      solve_yaml(one("depth_at_pixel", "{triangle: [[0,0,6],[3,0,9],[0,3,9]], pixel: [5, 5]}"));
  ASSERT_FALSE(out.error);
  EXPECT_FALSE(out.answers.find("inside")->flag);
  EXPECT_EQ(exact_text(out, "z"), "16");
  const ProblemResult edge =
      solve_yaml(one("depth_at_pixel", "{triangle: [[0,0,0],[1,0,5],[0,0,9]], pixel: [0, 0]}"));
  ASSERT_TRUE(edge.error);
  EXPECT_NE(edge.error->message.find("edge-on"), std::string::npos);
  const ProblemResult on_edge =
      solve_yaml(one("depth_at_pixel", "{triangle: [[0,0,6],[3,0,9],[0,3,9]], pixel: [0, 0]}"));
  EXPECT_TRUE(on_edge.answers.find("inside")->flag) << "vertices and edges count as inside";
}

TEST(Backface, ExactEdgeOnAndFront) {
  const ProblemResult edge =
      solve_yaml(one("backface", "{points: [[0,0,0],[1,0,0],[0,1,0]], eye: [5, 7, 0]}"));
  EXPECT_EQ(edge.answers.find("facing")->word, "edge_on");
  const ProblemResult front =
      solve_yaml(one("backface", "{points: [[0,0,0],[1,0,0],[0,1,0]], eye: [0, 0, \"1/10^30\"]}"));
  EXPECT_EQ(front.answers.find("facing")->word, "front");
  const ProblemResult irr = solve_yaml(one(
      "backface",
      "{points: [[0,0,0],[1,0,0],[0,1,0]], eye: [0, 0, \"sqrt(2) - 1414213562373095/10^15\"]}"));
  EXPECT_EQ(irr.answers.find("facing")->word, "front");
}

TEST(Backface, AgreesWithTheDoublePredicateOnRandomTriangles) {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> d(-9, 9);
  for (int i = 0; i < 80; ++i) {
    int v[12];
    for (int& x : v) x = d(rng);
    const ProblemResult r = solve_yaml(
        one("backface",
            fmt::format("{{points: [[{},{},{}],[{},{},{}],[{},{},{}]], eye: [{},{},{}]}}", v[0],
                        v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11])));
    if (r.error) continue;
    const int s =
        orient3d_sign(Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(v[3], v[4], v[5]),
                      Eigen::Vector3d(v[6], v[7], v[8]), Eigen::Vector3d(v[9], v[10], v[11]));
    const std::string want = s > 0 ? "front" : s < 0 ? "back" : "edge_on";
    EXPECT_EQ(r.answers.find("facing")->word, want);
  }
}

}  // namespace
}  // namespace frustum
