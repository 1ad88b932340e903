// The bandwidth ceiling fill is measured against (raster_bench's BM_BandwidthCeiling and the
// end-to-end race, render_race.cpp): every pixel of a 1920 × 1080 frame depth-tested against
// a plane and written (read depth, write depth and colour: 12 bytes per fragment), a loop the
// compiler vectorises with nothing else in it. Fill's pixels/s over this one's is the fraction
// of the ceiling it reaches.
#pragma once

#include <cstdint>

namespace frustum {

inline constexpr int kCeilingWidth = 1920, kCeilingHeight = 1080;

// One pass over buffers of kCeilingWidth × kCeilingHeight: depth z0 + dz·x, `id` written
// where it is nearer.
void depth_pass(float* depth, std::uint32_t* color, float z0, float dz, std::uint32_t id);

}  // namespace frustum
