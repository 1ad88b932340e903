#pragma once

#include <cstdint>

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
int fill_span(float* depth, std::uint32_t* color, int n, double row_z, double a, double dx0,
              std::uint32_t c, bool count);
// The portable loop alone (the tests compare the two).
int fill_span_portable(float* depth, std::uint32_t* color, int n, double row_z, double a,
                       double dx0, std::uint32_t c, bool count);
// Whether fill_span takes the vector path on this CPU.
bool fill_span_vectorised();

// vzeroupper where the CPU has AVX (nothing elsewhere). GCC 12 can return from the AVX2 clone
// of a vectorised loop (target_clones) with the upper halves of the vector registers still in
// use, and every SSE instruction after it then runs slower: zlib compressing the frame to PNG
// took 31 ms instead of 11 ms after a render. Vectorised loops call it before they return.
void clear_upper_vector_state();

}  // namespace frustum
