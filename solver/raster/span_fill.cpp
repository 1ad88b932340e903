#include "solver/raster/span_fill.hpp"

#include "solver/raster/rasterizer.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define FRUSTUM_X86_VECTOR 1
#endif

namespace frustum {

namespace {

// Branch-free (both buffers read and written, a min for the depth and a mask for the colour),
// so that the compiler vectorises it where it can; the writes are counted only when asked.
template <bool kCount>
int portable(float* __restrict depth, std::uint32_t* __restrict color, int n, double row_z,
             double a, double dx0, std::uint32_t c) {
  int written = 0;
  for (int k = 0; k < n; ++k) {
    const float z = static_cast<float>(row_z + a * (dx0 + static_cast<double>(k) * kSubpixelScale));
    const float old = depth[k];
    const bool pass = z < old;
    if constexpr (kCount) written += pass;
    const std::uint32_t keep = pass ? 0u : ~0u;
    depth[k] = pass ? z : old;
    color[k] = (color[k] & keep) | (c & ~keep);
  }
  return written;
}

// The span's undecided pixels (depth_tie against the depths stored before the span is filled).
void log_ties(const float* depth, int n, double row_z, double a, double dx0, std::vector<int>& ties,
              int i0) {
  for (int k = 0; k < n; ++k) {
    const float z = static_cast<float>(row_z + a * (dx0 + static_cast<double>(k) * kSubpixelScale));
    if (depth_tie(z, depth[k])) ties.push_back(i0 + k);
  }
}

#if FRUSTUM_X86_VECTOR
// Eight depths of the span from dx (four columns) and dx + 4·2⁸ (the next four): the double
// products and sums, each rounded as the portable loop rounds them, then to float.
__attribute__((target("avx2"))) inline __m256 depths8(__m256d row_z, __m256d a, __m256d dx_lo,
                                                      __m256d dx_hi) {
  const __m128 lo = _mm256_cvtpd_ps(_mm256_add_pd(row_z, _mm256_mul_pd(a, dx_lo)));
  const __m128 hi = _mm256_cvtpd_ps(_mm256_add_pd(row_z, _mm256_mul_pd(a, dx_hi)));
  return _mm256_set_m128(hi, lo);
}

// Lanes of `mask` (bit k: pixel k of the eight) whose depth is undecided: depth_tie.
__attribute__((target("avx2"))) inline int tie_mask(__m256 z, __m256 old) {
  const __m256 magnitude = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
  const __m256 difference = _mm256_and_ps(_mm256_sub_ps(z, old), magnitude);
  const __m256 margin =
      _mm256_add_ps(_mm256_mul_ps(_mm256_and_ps(old, magnitude), _mm256_set1_ps(0x1p-22f)),
                    _mm256_set1_ps(0x1p-34f));
  return _mm256_movemask_ps(_mm256_cmp_ps(difference, margin, _CMP_LE_OQ));
}
inline void push_lanes(int mask, int at, std::vector<int>& ties) {
  for (; mask != 0; mask &= mask - 1)
    ties.push_back(at + __builtin_ctz(static_cast<unsigned>(mask)));
}

// The depth test of eight pixels: `pass` where z < the stored depth (false for a NaN, as `<`).
__attribute__((target("avx2"))) int avx2(float* depth, std::uint32_t* color, int n, double row_z,
                                         double a, double dx0, std::uint32_t c, bool count,
                                         std::vector<int>* ties, int i0) {
  constexpr double s = kSubpixelScale;
  const __m256d vz = _mm256_set1_pd(row_z), va = _mm256_set1_pd(a), step = _mm256_set1_pd(8 * s);
  // dx0 + k·2⁸ is an integer far below 2⁵³: the additions are exact, as the portable product.
  __m256d dx_lo = _mm256_setr_pd(dx0, dx0 + s, dx0 + 2 * s, dx0 + 3 * s);
  __m256d dx_hi = _mm256_setr_pd(dx0 + 4 * s, dx0 + 5 * s, dx0 + 6 * s, dx0 + 7 * s);
  const __m256 vc = _mm256_castsi256_ps(_mm256_set1_epi32(static_cast<int>(c)));
  int written = 0, k = 0;
  for (; k + 8 <= n; k += 8) {
    const __m256 z = depths8(vz, va, dx_lo, dx_hi);
    const __m256 old = _mm256_loadu_ps(depth + k);
    const __m256 pass = _mm256_cmp_ps(z, old, _CMP_LT_OQ);
    if (ties)
      if (const int tie = tie_mask(z, old)) push_lanes(tie, i0 + k, *ties);
    _mm256_storeu_ps(depth + k, _mm256_blendv_ps(old, z, pass));
    float* col = reinterpret_cast<float*>(color + k);
    _mm256_storeu_ps(col, _mm256_blendv_ps(_mm256_loadu_ps(col), vc, pass));
    if (count) written += __builtin_popcount(static_cast<unsigned>(_mm256_movemask_ps(pass)));
    dx_lo = _mm256_add_pd(dx_lo, step);
    dx_hi = _mm256_add_pd(dx_hi, step);
  }
  if (k < n) {
    // The last 1 … 7 pixels: lanes past the span are masked out of the loads and the stores.
    const __m256i in =
        _mm256_cmpgt_epi32(_mm256_set1_epi32(n - k), _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7));
    const __m256 z = depths8(vz, va, dx_lo, dx_hi);
    const __m256 old = _mm256_maskload_ps(depth + k, in);
    const __m256 pass = _mm256_and_ps(_mm256_cmp_ps(z, old, _CMP_LT_OQ), _mm256_castsi256_ps(in));
    if (ties)
      if (const int tie = tie_mask(z, old) & _mm256_movemask_ps(_mm256_castsi256_ps(in)))
        push_lanes(tie, i0 + k, *ties);
    _mm256_maskstore_ps(depth + k, in, _mm256_blendv_ps(old, z, pass));
    float* col = reinterpret_cast<float*>(color + k);
    _mm256_maskstore_ps(col, in, _mm256_blendv_ps(_mm256_maskload_ps(col, in), vc, pass));
    if (count) written += __builtin_popcount(static_cast<unsigned>(_mm256_movemask_ps(pass)));
  }
  _mm256_zeroupper();
  return written;
}

// Chosen once, by a static initializer: __builtin_cpu_init first, since it may run before
// libgcc's own detection.
bool cpu_has_avx2() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2");
}
const bool kAvx2 = cpu_has_avx2();
#endif

}  // namespace

int fill_span_portable(float* depth, std::uint32_t* color, int n, double row_z, double a,
                       double dx0, std::uint32_t c, bool count, std::vector<int>* ties, int i0) {
  if (ties) log_ties(depth, n, row_z, a, dx0, *ties, i0);
  return count ? portable<true>(depth, color, n, row_z, a, dx0, c)
               : portable<false>(depth, color, n, row_z, a, dx0, c);
}

int fill_span(float* depth, std::uint32_t* color, int n, double row_z, double a, double dx0,
              std::uint32_t c, bool count, std::vector<int>* ties, int i0) {
#if FRUSTUM_X86_VECTOR
  if (kAvx2) return avx2(depth, color, n, row_z, a, dx0, c, count, ties, i0);
#endif
  return fill_span_portable(depth, color, n, row_z, a, dx0, c, count, ties, i0);
}

bool fill_span_vectorised() {
#if FRUSTUM_X86_VECTOR
  return kAvx2;
#else
  return false;
#endif
}

#if FRUSTUM_X86_VECTOR
namespace {
__attribute__((target("avx"))) void vzeroupper() { _mm256_zeroupper(); }
}  // namespace
void clear_upper_vector_state() {
  if (__builtin_cpu_supports("avx")) vzeroupper();
}
#else
void clear_upper_vector_state() {}
#endif

}  // namespace frustum
