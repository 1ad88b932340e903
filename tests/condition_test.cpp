// What a numeric solve says about its digits is checked against the digits it
// actually keeps, on generated ill-conditioned inputs of every kind with a numeric path (nearly
// parallel vectors, triangles far from the origin or nearly degenerate, nearly edge-on
// triangles, an eye nearly in a face's plane, points near the eye's plane, matrices with a
// condition of 10^L, pixels near an edge), at every level of difficulty from well-conditioned
// to hopeless, in float, double and long double. The exact backend of the same formulas is the
// reference. The properties (docs/accuracy.md):
//   - no warning: at most 5 of the format's digits are lost;
//   - "keeps about N digits": at least N − 1 are kept (never more claimed than kept), and the
//     claim is not needlessly gloomy: over a kind's warned cases the median of kept − N is at
//     most 3 digits;
//   - a value the exact fallback produced carries no ill-conditioning warning.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "solver/accuracy/accuracy.hpp"
#include "solver/problem/numeric_result.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_precision.hpp"

namespace frustum {
namespace {

// A double written so that the exact value read is that double to 17 digits.
std::string num(double v) { return fmt::format("{:.17g}", v); }
std::string vec(const Eigen::Vector3d& v) {
  return "[" + num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "]";
}
std::string tri(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return "[" + vec(a) + ", " + vec(b) + ", " + vec(c) + "]";
}

double uniform(Rng& rng, double lo, double hi) {
  return lo + (hi - lo) * static_cast<double>(rng.integer(0, 1 << 20)) / (1 << 20);
}
Eigen::Vector3d random_vector(Rng& rng, double lo, double hi) {
  return {uniform(rng, lo, hi), uniform(rng, lo, hi), uniform(rng, lo, hi)};
}
Eigen::Vector3d unit_vector(Rng& rng) {
  Eigen::Vector3d v;
  do v = random_vector(rng, -1, 1);
  while (v.norm() < 0.3);
  return v.normalized();
}

// One generated case: the kind and its given, at difficulty `level` (about 10^level).
using Draw = std::string (*)(Rng&, int level);

std::string vectors_draw(Rng& rng, int level) {
  const Eigen::Vector3d a = random_vector(rng, -9, 9), r = unit_vector(rng);
  const double eps = std::pow(10.0, -level) * a.norm();
  Eigen::Vector3d b;
  if (rng.chance(1, 2)) {
    b = uniform(rng, 0.5, 2) * a + eps * r;  // nearly parallel: a × b cancels
  } else {
    b = (r - r.dot(a) / a.squaredNorm() * a) * a.norm() + eps * a.normalized();  // a · b cancels
  }
  return "{a: " + vec(a) + ", b: " + vec(b) + "}";
}

// Three points: far from the origin with unit features, or nearly collinear.
std::string hard_triangle(Rng& rng, int level) {
  if (rng.chance(1, 2)) {
    const Eigen::Vector3d o = std::pow(10.0, level) * unit_vector(rng);
    return tri(o + random_vector(rng, -1, 1), o + random_vector(rng, -1, 1),
               o + random_vector(rng, -1, 1));
  }
  const Eigen::Vector3d a = random_vector(rng, -9, 9), b = random_vector(rng, -9, 9);
  const Eigen::Vector3d c = a + uniform(rng, 0.2, 0.8) * (b - a) +
                            std::pow(10.0, -level) * (b - a).norm() * unit_vector(rng);
  return tri(a, b, c);
}
std::string normal_draw(Rng& rng, int level) {
  return "{points: " + hard_triangle(rng, level) + "}";
}

// A triangle whose plane is nearly parallel to the z axis (nearly edge-on to the viewer), with
// a lattice pixel inside or near it.
std::string edge_on_triangle(Rng& rng, int level) {
  const Eigen::Vector2d a(uniform(rng, 2, 18), uniform(rng, 2, 18));
  const Eigen::Vector2d dir =
      Eigen::Vector2d(uniform(rng, -1, 1), uniform(rng, -1, 1)).normalized();
  const Eigen::Vector2d side(-dir.y(), dir.x());
  const double len = uniform(rng, 4, 8), width = 8 * std::pow(10.0, -level);
  const Eigen::Vector2d b = a + len * dir, c = a + 0.5 * len * dir + width * side;
  const Eigen::Vector2d pixel = (a + b + c) / 3;
  return fmt::format("{{triangle: {}, pixel: [{}, {}]}}",
                     tri({a.x(), a.y(), uniform(rng, 1, 20)}, {b.x(), b.y(), uniform(rng, 1, 20)},
                         {c.x(), c.y(), uniform(rng, 1, 20)}),
                     std::round(pixel.x()), std::round(pixel.y()));
}
std::string depth_draw(Rng& rng, int level) { return edge_on_triangle(rng, level); }

// A pixel 10^−level (relative) from an edge of a well-shaped triangle, or inside a thin one.
std::string barycentric_draw(Rng& rng, int level) {
  if (rng.chance(1, 2)) return edge_on_triangle(rng, level);
  const Eigen::Vector3d a(uniform(rng, 0, 8), uniform(rng, 0, 8), uniform(rng, 1, 20));
  const Eigen::Vector3d b(uniform(rng, 12, 20), uniform(rng, 0, 8), uniform(rng, 1, 20));
  const Eigen::Vector3d c(uniform(rng, 4, 16), uniform(rng, 12, 20), uniform(rng, 1, 20));
  // The pixel is a lattice point: move the edge AB so that it passes 10^−level from it.
  const Eigen::Vector2d pixel(std::round(uniform(rng, 8, 12)), std::round(uniform(rng, 6, 10)));
  const Eigen::Vector2d ab = (b - a).head<2>(), n(-ab.y(), ab.x());
  const double off = (pixel - a.head<2>()).dot(n.normalized()) -
                     std::pow(10.0, -level) * (rng.chance(1, 2) ? 1 : -1);
  Eigen::Vector3d a2 = a, b2 = b;
  a2.head<2>() += off * n.normalized();
  b2.head<2>() += off * n.normalized();
  return fmt::format("{{triangle: {}, pixel: [{}, {}]}}", tri(a2, b2, c), pixel.x(), pixel.y());
}

// The eye 10^−level (relative to the face's size and distance) off the face's plane.
std::string backface_draw(Rng& rng, int level) {
  const Eigen::Vector3d a = random_vector(rng, -9, 9), b = random_vector(rng, -9, 9),
                        c = random_vector(rng, -9, 9);
  const Eigen::Vector3d n = (b - a).cross(c - a);
  if (n.norm() < 10) return backface_draw(rng, level);
  const Eigen::Vector3d in_plane =
      a + uniform(rng, -3, 3) * (b - a) + uniform(rng, -3, 3) * (c - a);
  const double off = std::pow(10.0, -level) * in_plane.norm() * (rng.chance(1, 2) ? 1 : -1);
  return "{points: " + tri(a, b, c) + ", eye: " + vec(in_plane + off * n.normalized()) + "}";
}

// A point 10^−level (relative to its distance from the origin) from the eye's plane of a
// camera: w_c = −z_eye cancels in the view transform.
std::string project_draw(Rng& rng, int level) {
  const Eigen::Vector3d eye(uniform(rng, -5, 5), uniform(rng, -5, 5), uniform(rng, 10, 20));
  const Eigen::Vector3d forward = -eye.normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d(0, 1, 0)).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const double t =
      std::pow(10.0, -level) * eye.norm() * uniform(rng, 1, 9) * (rng.chance(4, 5) ? 1 : -1);
  const Eigen::Vector3d p =
      eye + uniform(rng, -3, 3) * right + uniform(rng, -3, 3) * up + t * forward;
  return fmt::format(
      "{{point: {}, camera: {{eye: {}, center: [0, 0, 0], up: [0, 1, 0]}}, perspective: {{fovy: "
      "{}, aspect: 1, near: 1, far: 100}}, viewport: {{width: 640, height: 480}}}}",
      vec(p), vec(eye), rng.integer(30, 90));
}

// A matrix whose condition is about 10^level: a scale by 10^−level between two rotations.
std::string transform_draw(Rng& rng, int level) {
  const Eigen::Vector3d axis = unit_vector(rng);
  return fmt::format(
      "{{dim: 3, steps: [{{rotate_z: {}}}, {{scale: [{}, 1, {}]}}, {{rotate: {{axis: {}, angle: "
      "{}}}}}], points: [{}]}}",
      rng.integer(5, 85), num(std::pow(10.0, -level)), num(uniform(rng, 1, 3)), vec(axis),
      rng.integer(5, 85), vec(random_vector(rng, -9, 9)));
}

// NDC coordinates 10^−level from the window's edges (x_w = (x + 1)·w/2 cancels near −1).
std::string viewport_draw(Rng& rng, int level) {
  const double e = std::pow(10.0, -level);
  return fmt::format("{{ndc: [{}, {}, {}], width: {}, height: {}}}",
                     num(-1 + e * uniform(rng, 1, 9)), num(1 - e * uniform(rng, 1, 9)),
                     num(uniform(rng, -1, 1)), rng.integer(100, 1920), rng.integer(100, 1080));
}

const std::map<std::string, Draw>& draws() {
  static const std::map<std::string, Draw> d = {{"vectors", vectors_draw},
                                                {"normal", normal_draw},
                                                {"plane", normal_draw},
                                                {"depth_at_pixel", depth_draw},
                                                {"barycentric", barycentric_draw},
                                                {"backface", backface_draw},
                                                {"project_point", project_draw},
                                                {"transform", transform_draw},
                                                {"viewport", viewport_draw}};
  return d;
}

NumericResult numeric(const ProblemSpec& spec, Precision p) {
  auto s = spec.info->solve_numeric(spec.given, p);
  s->run();
  return s->result();
}

bool exact_value_note(const NumericResult& r) {
  for (const Said& n : r.notes)
    if (n.en().find("computed exactly on the given numbers") != std::string::npos) return true;
  return false;
}

TEST(ConditioningProperty, EveryKindWithANumericPathIsDrawn) {
  for (const std::string& kind : bench::generated_kinds())
    EXPECT_TRUE(draws().count(kind)) << kind << " has a numeric path but no ill-conditioned draw";
}

TEST(ConditioningProperty, WarningsTellTheDigitsActuallyKept) {
  constexpr int kPerLevel = 3;
  std::map<std::string, int> claims;                 // kind → warned cases with a digit claim
  std::map<std::string, std::vector<double>> gloom;  // kind → kept − claimed
  int checked = 0;
  for (const auto& [kind, draw] : draws()) {
    Rng rng(0x42 ^ std::hash<std::string>{}(kind));
    std::string yaml = "title: ill-conditioned " + kind + "\nproblems:\n";
    int n = 0;
    for (int level = 0; level <= 17; ++level)
      for (int i = 0; i < kPerLevel; ++i)
        yaml += fmt::format("  - id: L{}-{}\n    kind: {}\n    given: {}\n", level, n++, kind,
                            draw(rng, level));
    const ProblemSet set = load_problem_set_from_string(yaml, "ill-conditioned-" + kind + ".yaml");
    for (const ProblemSpec& spec : set.problems) {
      NumericResult exact;
      try {
        exact = numeric(spec, Precision::Exact);
      } catch (const std::exception&) {
        continue;  // refused exactly (a degenerate triangle drawn at the last levels)
      }
      for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
        NumericResult r;
        try {
          r = numeric(spec, p);
        } catch (const std::exception& e) {
          ADD_FAILURE() << kind << " " << spec.id << " " << to_string(p)
                        << ": refused where the exact backend solves: " << e.what();
          continue;
        }
        const bench::CaseError e = bench::compare(r, exact);
        const std::string where = kind + " " + spec.id + " " + std::string(to_string(p));
        EXPECT_FALSE(e.wrong) << where << ": a discrete answer differs from the exact one";
        const double kept = e.error == 0 ? decimal_digits(p) : std::max(0.0, -std::log10(e.error));
        bool condition_warning = false;
        const std::string claim = std::string(to_string(p)) + " keeps about ";
        for (const NumericWarning& w : r.warnings) {
          const std::size_t at = w.text.en().find(claim);
          if (at == std::string::npos) continue;
          condition_warning = true;
          const double said = std::stod(w.text.en().substr(at + claim.size()));
          EXPECT_GE(kept, said - 1) << where << ": says " << said << " digits, keeps " << kept
                                    << " (" << w.title.en() << ": " << w.text.en() << ")";
          gloom[kind].push_back(kept - said);
          ++claims[kind];
        }
        if (r.warnings.empty()) {
          EXPECT_GE(kept, decimal_digits(p) - 5)
              << where << ": error " << e.error << " with no warning";
        }
        if (exact_value_note(r)) {
          EXPECT_FALSE(condition_warning)
              << where << ": warns about a value computed exactly on the given numbers";
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 400);
  for (const auto& [kind, g] : gloom) {
    std::vector<double> sorted = g;
    std::sort(sorted.begin(), sorted.end());
    std::cout << kind << ": " << sorted.size() << " digit claims, kept − claimed from "
              << sorted.front() << " to " << sorted.back() << ", median "
              << sorted[sorted.size() / 2] << "\n";
    EXPECT_LE(sorted[sorted.size() / 2], 3.0)
        << kind << ": the warnings' digit claims are needlessly gloomy (median kept − said "
        << sorted[sorted.size() / 2] << " over " << sorted.size() << ")";
  }
  // The draws reach the ill-conditioned range of each kind whose answers can lose digits.
  for (const char* kind :
       {"vectors", "normal", "plane", "depth_at_pixel", "backface", "project_point", "transform"})
    EXPECT_GT(claims[kind], 3) << kind << " never warned on its ill-conditioned draws";
}

}  // namespace
}  // namespace frustum
