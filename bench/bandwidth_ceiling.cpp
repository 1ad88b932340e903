#include "bench/bandwidth_ceiling.hpp"

#include <cstddef>

#include "solver/raster/fill.hpp"
#include "solver/raster/span_fill.hpp"

namespace frustum {

__attribute__((target_clones("avx2", "default"))) void depth_pass(float* depth,
                                                                  std::uint32_t* color, float z0,
                                                                  float dz, std::uint32_t id) {
  for (int y = 0; y < kCeilingHeight; ++y) {
    float* d = depth + static_cast<std::size_t>(y) * kCeilingWidth;
    std::uint32_t* c = color + static_cast<std::size_t>(y) * kCeilingWidth;
    // kCeilingWidth is a multiple of every vector width: no epilogue.
    for (int x = 0; x < kCeilingWidth; ++x) {
      const float z = z0 + dz * static_cast<float>(x);
      const bool pass = z < d[x];
      d[x] = pass ? z : d[x];
      c[x] = pass ? id : c[x];
    }
  }
  clear_upper_vector_state();  // the AVX2 clone's registers (span_fill.hpp)
}

}  // namespace frustum
