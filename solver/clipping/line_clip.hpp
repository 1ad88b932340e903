// Cohen–Sutherland line clipping (Foley et al. §3.12; seed 000: "コーエン・サザランド法",
// "z座標を加えた6ビットコード") against a 2D window or a 3D box.
//
// Outcode bits, written most significant first:
//   2D (4 bits)  1000 top    (y > ymax)   0100 bottom (y < ymin)
//                0010 right  (x > xmax)   0001 left   (x < xmin)
//   3D (6 bits)  100000 z > zmax   010000 z < zmin   then the 2D bits for y and x.
// A point on a boundary is inside (its bit is 0). Each iteration takes an endpoint whose
// code is non-zero (p first), the highest set bit of its code, and moves the endpoint to the
// intersection of the segment with that boundary.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "solver/clipping/clip_box.hpp"

namespace frustum {

// Bit of the boundary `axis` (0 = x, 1 = y, 2 = z) on its `high` side (x > xmax) or low side.
constexpr unsigned outcode_bit(int axis, bool high) { return 1u << (2 * axis + (high ? 1 : 0)); }

// "0101": the code's 2N bits, most significant first.
std::string outcode_string(unsigned code, int dims);
// "top (y > ymax)", "z < zmin": what one bit means.
std::string outcode_bit_meaning(unsigned bit);
// "above and left" style summary: the meanings of every set bit, "inside" for 0.
std::string outcode_meaning(unsigned code);

template <typename T, int N>
unsigned outcode(const Eigen::Matrix<T, N, 1>& p, const ClipBox<T, N>& box) {
  unsigned code = 0;
  for (int a = 0; a < N; ++a) {
    if (scalar_sign(T(p(a) - box.lo(a))) < 0) code |= outcode_bit(a, false);
    if (scalar_sign(T(p(a) - box.hi(a))) > 0) code |= outcode_bit(a, true);
  }
  return code;
}

// One pass of the loop: `endpoint` (0 = p, 1 = q) moved from `before` to `after`, the
// intersection with the boundary of `bit`.
template <typename T, int N>
struct LineClipIteration {
  int endpoint;
  unsigned code_before;
  unsigned bit;
  Eigen::Matrix<T, N, 1> before, after;
  unsigned code_after;
};

template <typename T, int N>
struct LineClipResult {
  unsigned code_p = 0, code_q = 0;  // the endpoints' codes before any clipping
  bool trivial_accept = false;      // code_p | code_q == 0
  bool trivial_reject = false;      // code_p & code_q != 0
  // The visible part, or nothing when the segment misses the box (also after iterations).
  std::optional<std::array<Eigen::Matrix<T, N, 1>, 2>> clipped;
  std::vector<LineClipIteration<T, N>> iterations;
};

template <typename T, int N>
LineClipResult<T, N> cohen_sutherland(const Eigen::Matrix<T, N, 1>& p,
                                      const Eigen::Matrix<T, N, 1>& q, const ClipBox<T, N>& box) {
  using V = Eigen::Matrix<T, N, 1>;
  LineClipResult<T, N> r;
  std::array<V, 2> e{p, q};
  std::array<unsigned, 2> c{outcode(p, box), outcode(q, box)};
  r.code_p = c[0];
  r.code_q = c[1];
  r.trivial_accept = (c[0] | c[1]) == 0;
  r.trivial_reject = (c[0] & c[1]) != 0;
  // Each iteration clears a bit for good with exact values; the cap guards doubles.
  for (int guard = 0; guard < 8 * N; ++guard) {
    if ((c[0] | c[1]) == 0) {
      r.clipped = e;
      return r;
    }
    if ((c[0] & c[1]) != 0) return r;
    const int k = c[0] != 0 ? 0 : 1;
    unsigned bit = 1u << (2 * N - 1);
    while (!(c[k] & bit)) bit >>= 1;
    int axis = 0;
    while (outcode_bit(axis, false) != bit && outcode_bit(axis, true) != bit) ++axis;
    const T bound = (bit == outcode_bit(axis, true)) ? box.hi(axis) : box.lo(axis);
    // Parametric intersection from the other endpoint: x = a + t (b − a) with x_axis = bound;
    // the other endpoint is on the inside of this boundary, so b_axis ≠ a_axis.
    const V& a = e[k];
    const V& b = e[1 - k];
    const T t = tidy(T((bound - a(axis)) / (b(axis) - a(axis))));
    V hit;
    for (int i = 0; i < N; ++i) hit(i) = i == axis ? bound : tidy(T(a(i) + t * (b(i) - a(i))));
    LineClipIteration<T, N> it{k, c[k], bit, a, hit, 0};
    e[k] = hit;
    c[k] = outcode(hit, box);
    it.code_after = c[k];
    r.iterations.push_back(it);
  }
  return r;
}

}  // namespace frustum
