// A scene's frame as `frustum render` draws it, for the command and for the authoring page's
// preview alike: the z-buffer (or the scan-line method, when the scene asks for it), every
// decision the exact inputs' (the floats decide where their error bounds prove it, ranged and
// exact arithmetic elsewhere: certified_frame.hpp).
#pragma once

#include <string>

#include "solver/raster/certified_frame.hpp"
#include "solver/raster/pipeline.hpp"
#include "solver/raster/zbuffer.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {

struct SceneFrameReport {
  GeometryStats geometry;
  std::string method;                        // which method drew it, and what it kept (one line)
  long traced_pixels = 0, exact_pixels = 0;  // pixels the floats could not decide; by exact depths
};

// Draws `scene` into `frame` (its depth kept when `keep_depth`), on `threads` threads (with
// `team`'s, when given). Throws DomainError when the frame's work passes its bound, a coordinate
// is beyond the rasterizer's range, or a sign exact arithmetic could not prove.
void draw_scene_frame(const Scene& scene, const Mat4<Exact>& clip_from_world, bool keep_depth,
                      int threads, ThreadTeam* team, Frame& frame, SceneFrameReport* report);

}  // namespace frustum
