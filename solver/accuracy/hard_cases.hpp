// The hard-case studies beside the table (`frustum bench accuracy`, docs/accuracy.md): normals
// of near-degenerate polygons by three methods, back-face signs with the eye nearly in the
// face's plane, and depth-buffer precision (standard, DirectX [0, 1], reversed-Z).
#pragma once

#include <string>
#include <vector>

#include "solver/numeric/precision.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum::bench {

// Angle (radians) between a method's normal and the exact one; π/2 stands for a zero vector.
struct NormalMethods {
  std::string id;
  Precision precision;
  double naive = 0;      // seed 003's e₀ × e₁
  double best_pair = 0;  // the consecutive edge pair with the largest sine
  double newell = 0;     // Σ (pᵢ − p₀) × (pᵢ₊₁ − p₀)
};
// Every `normal` problem given by `points` in the set, in float, double and long double.
std::vector<NormalMethods> normal_methods(const ProblemSet& set);

// Signs of D_f with the eye within a few units in the last place of the face's plane.
struct FacingStudy {
  Precision precision;
  int cases = 0;
  int naive_wrong = 0;     // computed sign ≠ exact sign of the same inputs
  int adaptive_wrong = 0;  // the filtered predicate with exact fallback (must be 0)
  int exact_fallbacks = 0;
  double naive_ns = 0, adaptive_ns = 0;                  // per test, on these near-plane cases
  double naive_ns_generic = 0, adaptive_ns_generic = 0;  // per test, eye well off the plane
};
FacingStudy facing_study(Precision p, int cases, std::uint64_t seed);

// Depth precision: two parallel planes facing the camera at eye distances D and D·(1 + gap),
// one pixel per D (geometric from 2·near to far/2), projected and stored in a float depth
// buffer. A pixel flips when the farther plane's stored depth is not strictly behind the
// nearer's (the farther plane is drawn first, so a tie shows it).
enum class DepthMapping { OpenGL, DirectX, ReversedZ };
std::string to_string(DepthMapping m);
int depth_flips(DepthMapping m, double far_over_near, double relative_gap, int pixels = 1000);
// The smallest relative gap (on a ladder 10^(−k/8)) from which no pixel flips.
double smallest_separable_gap(DepthMapping m, double far_over_near, int pixels = 1000);

// The studies as Markdown sections.
std::string hard_case_report(const ProblemSet& hard, int facing_cases, std::uint64_t seed);

}  // namespace frustum::bench
