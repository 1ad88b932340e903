// The z-buffer fill of a whole frame band by band (tiles as wide as the frame), for a scene
// small enough that its triangles are all set up before any is drawn (`frustum render` of a
// modelled scene; a stream of millions goes through striped_render.hpp instead, or through
// fill.hpp's render_zbuffer_streamed on one thread).
//
// Each triangle is binned to the bands of rows its bounding box spans. A band is cleared and
// then drawn, the triangles of its bin in drawing order, while its rows (32 × the width × 8 B:
// 480 KB at 1920 pixels) are in the core's cache, so the frame goes through memory once instead
// of once to clear it and again for every triangle that covers a part of it. `threads` workers
// take the bands in turn as they finish one. A pixel belongs to one band, and a band's triangles
// are drawn in order, so the frame is the same bit for bit as clearing it and drawing every
// triangle in order with draw_triangle, whatever the number of threads. With a team
// (thread_team.hpp), its threads do the work instead of threads started for it.
#pragma once

#include <vector>

#include "solver/raster/fill.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {

inline constexpr int kBandRows = 32;

// `frame` is sized to width × height and every pixel written: the background and the far depth,
// then the triangles. Counts as draw_triangle would (every triangle, fragments, writes).
void fill_in_bands(const std::vector<RasterTriangle>& triangles, Frame& frame, int width,
                   int height, Rgb background, FillStats* stats = nullptr, int threads = 1,
                   ThreadTeam* team = nullptr);

// The whole z-buffer render of a scene (threaded_zbuffer.hpp's render_zbuffer with threads, for a
// scene of few enough triangles): the world triangles split into contiguous parts, each part
// through the geometry stage and set up on a thread of its own, joined in drawing order, then the
// frame filled band by band. The same frame and statistics as render_zbuffer on one thread.
void render_in_bands(const Scene& scene, Frame& frame, GeometryStats* geometry_stats = nullptr,
                     FillStats* stats = nullptr, int threads = 1, ThreadTeam* team = nullptr,
                     FrameCertifier* certifier = nullptr);

}  // namespace frustum
