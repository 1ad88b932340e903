#include "solver/raster_fast/striped_render.hpp"

#include <algorithm>
#include <cmath>

#include "solver/raster/frame_work.hpp"
#include "solver/util/side_by_side.hpp"

namespace frustum {

namespace {

// One thread's state, on cache lines of its own: its stage's counts and its vectors change at
// every triangle, and two threads writing one cache line pass it back and forth between cores.
struct alignas(128) Worker {
  Worker(const Scene& scene, FrameCertifier* certifier) : stage(scene, certifier), work(scene) {}
  GeometryStage stage;
  FrameWork work;  // every thread prices every triangle: each stops at the same one
  std::vector<WindowTriangle> window;  // one world triangle's, reused
  FillStats fill;
};

}  // namespace

int strip_rows(int height, int threads) {
  return std::clamp(height / (4 * std::max(1, threads)), kMinStripRows, kMaxStripRows);
}

void render_in_strips(const Scene& scene, Frame& frame, GeometryStats* geometry_stats,
                      FillStats* stats, int threads, ThreadTeam* team, FrameCertifier* certifier) {
  frame.reset(scene.width, scene.height, scene.background);
  const int height = scene.height;
  const int rows = strip_rows(height, threads);
  const int strips = (height + rows - 1) / rows;
  // No more parts than the team has threads (a team's extra parts would run one after another
  // on the caller's thread).
  const int workers = std::max(1, std::min({threads, strips, team ? team->threads() : threads}));
  std::vector<Worker> state;
  state.reserve(static_cast<std::size_t>(workers));
  for (int k = 0; k < workers; ++k) state.emplace_back(scene, certifier);
  side_by_side(
      workers,
      [&](int k) {
        Worker& w = state[static_cast<std::size_t>(k)];
        FillStats* counted = stats ? &w.fill : nullptr;
        int source = 0;
        for_each_world_triangle(
            scene,
            [&](const WorldTriangle& world) {
              w.window.clear();
              w.stage.add(world, source++, w.window);
              for (const WindowTriangle& t : w.window) {
                w.work.add(t);
                // The rows the triangle may cover, widened by a row each way for the snapping to
                // 1/256 pixel: none of this thread's strips among them, no set-up. A coordinate the
                // set-up refuses goes to it on every thread, so that its error reaches the caller
                // as on one thread.
                const double y0 = std::min({t.v[0](1), t.v[1](1), t.v[2](1)}),
                             y1 = std::max({t.v[0](1), t.v[1](1), t.v[2](1)});
                const bool usual = std::abs(y0) <= kMaxWindowCoordinate &&
                                   std::abs(y1) <= kMaxWindowCoordinate &&
                                   std::abs(t.v[0](0)) <= kMaxWindowCoordinate &&
                                   std::abs(t.v[1](0)) <= kMaxWindowCoordinate &&
                                   std::abs(t.v[2](0)) <= kMaxWindowCoordinate;
                if (usual && (y1 < -1.0 || y0 > height + 1.0)) continue;
                const int s0 = usual ? std::max(0, static_cast<int>(std::floor(y0)) - 1) / rows : 0,
                          s1 = usual ? std::min(height - 1, static_cast<int>(std::ceil(y1)) + 1) /
                                           rows
                                     : strips - 1;
                const int mine = s0 + ((k - s0 % workers) + workers) % workers;  // first strip ≥ s0
                if (usual && mine > s1) continue;
                const RasterTriangle r = setup_raster(t);
                const TriangleSetup& s = r.setup;
                const int j0 = std::max(s.j_min, 0), j1 = std::min(s.j_max, height - 1);
                for (int strip = mine; strip <= s1; strip += workers) {
                  const int lo = std::max(j0, strip * rows),
                            hi = std::min(j1, strip * rows + rows - 1);
                  if (lo <= hi) draw_triangle_rows(r, frame, lo, hi, counted);
                }
              }
            },
            certifier != nullptr);
      },
      team);
  // Every thread ran every world triangle through the geometry: one thread's counts are the
  // scene's. The fill's are each thread's rows'.
  if (geometry_stats) *geometry_stats = state[0].stage.stats;
  if (stats) {
    stats->triangles += state[0].stage.stats.window;
    for (const Worker& w : state) {
      stats->fragments += w.fill.fragments;
      stats->written += w.fill.written;
    }
  }
}

}  // namespace frustum
