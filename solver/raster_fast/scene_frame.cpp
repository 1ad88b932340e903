#include "solver/raster_fast/scene_frame.hpp"

#include <fmt/format.h>

#include "solver/raster/fill.hpp"
#include "solver/raster/scanline.hpp"
#include "solver/raster_fast/threaded_zbuffer.hpp"

namespace frustum {

void draw_scene_frame(const Scene& scene, const Mat4<Exact>& clip_from_world, bool keep_depth,
                      int threads, ThreadTeam* team, Frame& frame, SceneFrameReport* report) {
  SceneFrameReport own;
  SceneFrameReport& r = report ? *report : own;
  FrameCertifier certifier(scene, clip_from_world);
  if (scene.scanline) {
    // The world triangles are freed once in window space.
    const std::vector<WindowTriangle> tris =
        geometry(scene, flatten(scene, false, true), &r.geometry, &certifier);
    ScanlineStats st;
    frame.ties.assign(static_cast<std::size_t>(scene.height), {});
    frame.color = render_scanline(tris, scene.width, scene.height, scene.background, &st,
                                  keep_depth ? &frame.depth : nullptr, scene.max_work, &frame.ties);
    if (!keep_depth) frame.depth = {};
    r.method = fmt::format(
        "scan-line: one row of depth ({} bytes) instead of the z-buffer's {} bytes; at most {} "
        "triangles active on a row, {} spans",
        st.row_depth_bytes, st.zbuffer_depth_bytes, st.active_max, st.spans);
  } else {
    FillStats fs;
    render_zbuffer(scene, frame, &r.geometry, &fs, threads, team, &certifier);
    r.method = fmt::format("z-buffer: {} bytes of depth; {} fragments, {} written",
                           frame.depth.data.size() * sizeof(float), fs.fragments, fs.written);
  }
  repair_undecided(scene, frame, certifier);
  r.traced_pixels = certifier.check.pixels;
  r.exact_pixels = certifier.check.exact_pixels;
}

}  // namespace frustum
