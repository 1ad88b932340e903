// `frustum render`'s z-buffer of a whole scene, on as many threads as asked for: on one, the
// stream of the teaching pipeline (solver/raster/fill.hpp's render_zbuffer_streamed); with
// threads, a modelled scene (at most kBandedTriangles world triangles) goes through the geometry
// in parts side by side and is filled band by band by every thread (banded_fill.hpp), and a
// larger one streams on every thread, each walking the scene and drawing its own strips of rows
// (striped_render.hpp). Whichever is chosen, the frame is the same bit for bit.
#pragma once

#include "solver/raster/fill.hpp"
#include "solver/raster/pipeline.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {

// The scene's frame, as render_zbuffer_streamed draws it, on `threads` threads. With a
// certifier (certified_frame.hpp) the geometry is certified and the fill notes its ties in
// frame.ties (the caller repairs them: repair_undecided).
Frame render_zbuffer(const Scene& scene, GeometryStats* geometry_stats = nullptr,
                     FillStats* stats = nullptr, int threads = 1);
// The same into a render target the caller keeps (reset to the scene's size and background).
// With a team (thread_team.hpp), the threaded render's parts run on its threads.
void render_zbuffer(const Scene& scene, Frame& target, GeometryStats* geometry_stats = nullptr,
                    FillStats* stats = nullptr, int threads = 1, ThreadTeam* team = nullptr,
                    FrameCertifier* certifier = nullptr);
// Whether render_zbuffer with `threads` sets a modelled scene up whole and fills it band by band
// (at least two threads, at most kBandedTriangles world triangles) rather than streaming it.
bool zbuffer_banded(const Scene& scene, int threads);

}  // namespace frustum
