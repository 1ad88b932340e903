#include "solver/raster_fast/threaded_zbuffer.hpp"

#include "solver/raster_fast/banded_fill.hpp"
#include "solver/raster_fast/striped_render.hpp"

namespace frustum {

Frame render_zbuffer(const Scene& scene, GeometryStats* geometry_stats, FillStats* stats,
                     int threads) {
  Frame frame;
  render_zbuffer(scene, frame, geometry_stats, stats, threads);
  return frame;
}

// With threads, a scene of at most kBandedTriangles world triangles is set up whole and filled
// band by band (banded_fill.hpp); a larger one streams, every thread drawing its strips of rows
// (striped_render.hpp).
bool zbuffer_banded(const Scene& scene, int threads) {
  return threads >= 2 && world_triangle_count(scene) <= kBandedTriangles;
}

void render_zbuffer(const Scene& scene, Frame& frame, GeometryStats* geometry_stats,
                    FillStats* stats, int threads, ThreadTeam* team, FrameCertifier* certifier) {
  if (threads < 2) {
    render_zbuffer_streamed(scene, frame, geometry_stats, stats, certifier);
    return;
  }
  // Sized before the fill: threads note ties on their own rows' lists.
  frame.ties.assign(certifier ? static_cast<std::size_t>(scene.height) : 0, {});
  if (zbuffer_banded(scene, threads)) {
    // A modelled scene with threads to share: the geometry in parts side by side, then the
    // frame filled band by band (on one thread this is no faster than the stream: where a
    // 1920 × 1080 frame fits in the last-level cache, one thread streaming over it is as fast
    // as bands).
    render_in_bands(scene, frame, geometry_stats, stats, threads, team, certifier);
    return;
  }
  render_in_strips(scene, frame, geometry_stats, stats, threads, team, certifier);
}

}  // namespace frustum
