#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

namespace frustum {

// One row's span of a triangle through the depth test: pixels k = 0 … n − 1 of the row from
// `depth` and `color` on, at depth z_k = float(row_z + a·(dx0 + k·2⁸)) in double (the plane
// method's depth_at, bit for bit), each written (depth and colour c) where z_k < the stored
// depth. Returns how many were written when `count`, else 0. Pixels outside the span are neither
// read nor written (another thread may own them).
//
// On x86-64 with AVX2 (chosen at run time) eight pixels go through at a time, the span's last
// few under a mask, so a short span costs one masked step instead of a scalar loop; elsewhere
// the portable loop below. Both compute the same floats: no fused multiply-add, the same
// rounding of the same double operations.
//
// `ties` (certified frames, certified_frame.hpp): the pixels whose test the floats cannot decide
// are appended as i0 + k — those where z_k is within depth_tie's margin of the stored depth.
int fill_span(float* depth, std::uint32_t* color, int n, double row_z, double a, double dx0,
              std::uint32_t c, bool count, std::vector<int>* ties = nullptr, int i0 = 0);
// The portable loop alone (the tests compare the two).
int fill_span_portable(float* depth, std::uint32_t* color, int n, double row_z, double a,
                       double dx0, std::uint32_t c, bool count, std::vector<int>* ties = nullptr,
                       int i0 = 0);

// A depth within this of the exact one (each set-up triangle's bound, fill.hpp) leaves the
// depth test to the floats where depth_tie is false.
inline constexpr double kDepthTolerance = 0x1p-36;
// Whether the test z < stored of two 32-bit depths may differ from the test of the exact depths
// they were rounded from, each computed within kDepthTolerance and then rounded to float
// (relative 2⁻²⁴, or 2⁻¹⁴⁹ below the normal range): |z − stored| ≤ |stored|·2⁻²² + 2⁻³⁴. Beyond
// it, |z − stored|·(1 − 2⁻²⁴) exceeds 2⁻²³·|stored| + 2⁻³⁵ + 2⁻¹⁴⁹, which bounds what the two
// roundings (2⁻²⁴·(|z| + |stored|), |z| ≤ |stored| + |z − stored|) and the two tolerances can
// move the difference, even with the margin itself rounded in float.
inline bool depth_tie(float z, float stored) {
  return std::abs(z - stored) <= std::abs(stored) * 0x1p-22f + 0x1p-34f;
}
// Whether fill_span takes the vector path on this CPU.
bool fill_span_vectorised();

// vzeroupper where the CPU has AVX (nothing elsewhere). GCC 12 can return from the AVX2 clone
// of a vectorised loop (target_clones) with the upper halves of the vector registers still in
// use, and every SSE instruction after it then runs slower (zlib compressing the frame to PNG
// after a render among them). Vectorised loops call it before they return.
void clear_upper_vector_state();

}  // namespace frustum
