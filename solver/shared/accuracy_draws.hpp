// What the kinds' accuracy generators (KindInfo::accuracy_given, `frustum bench accuracy`)
// share: exact two-decimal numbers, points and triangles written as YAML, and the condition
// bound a generated problem must meet.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <optional>
#include <string>

#include "solver/problem/rng.hpp"

namespace frustum::accuracy {

// A generated problem is redrawn until its condition estimate is below this.
constexpr double kWellConditioned = 50;

// A decimal in [lo, hi] with two decimals, written exactly ("-3.25"): most are not binary
// fractions, so rounding the inputs is part of what is measured.
std::string decimal(Rng& rng, int lo, int hi);

struct Point3 {
  std::string x, y, z;
  Eigen::Vector3d d() const;
  std::string yaml() const;
};
Point3 point(Rng& rng, int lo, int hi);

std::string triangle_yaml(const std::array<Point3, 3>& t);

// Three points in [-9, 9]³ whose normal is well conditioned (normal, plane, backface), or
// nullopt to draw again.
std::optional<std::array<Point3, 3>> well_conditioned_triangle(Rng& rng);

// A triangle with x, y in [0, 20] and z in [1, 20] (two decimals) and a lattice pixel in
// [0, 20]², drawn in that order (depth_at_pixel, barycentric).
struct TriangleAndPixel {
  std::array<Point3, 3> triangle;
  Eigen::Vector2d pixel;
  std::string yaml() const;  // {triangle: …, pixel: […]}
};
TriangleAndPixel triangle_and_pixel(Rng& rng);

}  // namespace frustum::accuracy
