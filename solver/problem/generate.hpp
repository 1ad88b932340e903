// What a kind's default generator needs: the options of a draw, builders for the `given` YAML
// it returns, small integer vector maths for drawing, and the shared conditioning measures.
// A generator returns YAML (never a typed Given) so that every variant is read and validated
// by the kind's `parse`, exactly like a hand-written problem.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/core/matrix.hpp"
#include "solver/problem/rng.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

struct GenerateOptions {
  bool nice = false;  // integer or simple exact answers (integer z, integer D_f, fov 60°/90°)
  bool hard = false;  // near-degenerate cases on purpose
  Conventions conventions;
};

// A well-conditioned triangle has area ≥ kMinTriangleShape · (longest edge)²; an equilateral
// one has √3/4 ≈ 0.43, a 1 × 10 right triangle 0.05.
inline constexpr double kMinTriangleShape = 0.05;
// Angles whose sine is below this (about 5.7°) count as near-parallel or near-grazing.
inline constexpr double kMinSine = 0.1;

// ---- building `given` nodes (sequences of numbers are written in flow style) ----
YAML::Node gen_number(std::int64_t v);
// An exact number: an integer as is, otherwise its plain exact text ("1/2", "sqrt(3)").
YAML::Node gen_number(const Exact& v);
YAML::Node gen_list(const std::vector<std::int64_t>& v);
inline YAML::Node gen_list(std::initializer_list<std::int64_t> v) {
  return gen_list(std::vector<std::int64_t>(v));
}
YAML::Node gen_list(const std::vector<Exact>& v);
YAML::Node gen_rows(const std::vector<std::vector<std::int64_t>>& rows);
YAML::Node gen_word(const std::string& w);
// A 2D clipping window {xmin, xmax, ymin, ymax}.
YAML::Node gen_window(std::int64_t xmin, std::int64_t xmax, std::int64_t ymin, std::int64_t ymax);
YAML::Node gen_fraction(std::int64_t num, std::int64_t den);
// An angle given in degrees, written in the set's unit (60 or pi/3).
YAML::Node gen_angle(std::int64_t degrees, const Conventions& c);

// ---- keeping an exercise's structure ----
// The shape of a given: its keys, list lengths and words, with every number written "#". Two
// givens of the same exercise with other values have the same shape ({rotate: 90} and
// {rotate: 45} do; {rotate: 90} and {scale: 2} do not).
std::string given_shape(const YAML::Node& given);
// The given with its values drawn again and its shape kept: a non-zero integer moves within
// about half its size keeping its sign, an angle (fovy, fov, angle, rotate…) becomes another
// common angle of the same sign; zeros, fractions, words, sizes and indices (dim, width, height,
// faces, pixels) stay. A mesh's integer `vertices` move together (one axis-aligned scale by 1 or 2
// and one shift), so its faces stay planar and the solid keeps its shape class.
YAML::Node redraw_values(const YAML::Node& given, Rng& rng);

// ---- integer vectors for drawing ----
using IVec3 = std::array<std::int64_t, 3>;
IVec3 gen_ivec3(Rng& rng, std::int64_t lo, std::int64_t hi);
IVec3 isub(const IVec3& a, const IVec3& b);
IVec3 iadd(const IVec3& a, const IVec3& b);
IVec3 iscale(std::int64_t k, const IVec3& a);
IVec3 icross(const IVec3& a, const IVec3& b);
std::int64_t idot(const IVec3& a, const IVec3& b);
bool is_square(std::int64_t v);
std::vector<std::int64_t> to_list(const IVec3& v);
// Three integer points in [lo, hi]³: well shaped (kMinTriangleShape), with an integer ‖n‖ when
// nice (a rational unit normal), nearly collinear when hard.
std::array<IVec3, 3> gen_triangle(Rng& rng, const GenerateOptions& o, std::int64_t lo,
                                  std::int64_t hi);
YAML::Node gen_points(const std::vector<IVec3>& points);

// ---- conditioning measures on doubles ----
// Triangle area / (longest edge)² of the first three points (2 or 3 coordinates each).
double triangle_shape(const std::vector<std::vector<double>>& points);
// |sin| of the angle between two vectors (0 when either is zero).
double sine_between(const std::vector<double>& a, const std::vector<double>& b);
// The doubles of exact values.
std::vector<double> doubles(const std::vector<Exact>& v);
template <int N>
std::vector<double> doubles(const Eigen::Matrix<Exact, N, 1>& v) {
  return doubles(std::vector<Exact>(v.data(), v.data() + N));
}
std::vector<std::vector<double>> doubles(const std::vector<Vec3<Exact>>& points);

}  // namespace frustum
