// The z-buffer render of a large scene (millions of world triangles, streamed: none kept) with
// several threads, each owning strips of the frame's rows.
//
// Strips of strip_rows() rows are dealt to the threads in turn.
//
// Each thread walks the whole scene itself (the walk copies nothing of the scene, so threads may
// walk it side by side: pipeline.hpp) and takes every world triangle through its own geometry
// stage, then sets up and draws only the window triangles whose rows reach a strip it owns, and
// only those rows. Nothing a thread writes is read by another. The price is the walk and the
// geometry (about a third of a small triangle's work) done by every thread.
//
// Why not the geometry split between the threads and the set-up triangles handed over (a sort
// in the middle, as banded_fill.hpp does for a modelled scene, or a thread for the geometry
// feeding one for the fill)? For a stream of small triangles each set-up triangle is ~300 bytes
// made on one core and read on another, and the frame's rows move from core to core as bands
// change hands, which costs more than the second core gains: on two cores, two threads that way
// are slower than one on a million small triangles, and strips faster
// (docs/performance-notes.md has the figures).
//
// A pixel belongs to one strip and a strip's triangles are drawn in order, so the frame is the
// same bit for bit as one thread's, and so are the counts.
#pragma once

#include "solver/raster/fill.hpp"
#include "solver/raster/pipeline.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {

// Rows a strip: about four strips a thread, so that a scene drawn on part of the frame still
// gives every thread a share, and at least kMinStripRows, so that few small triangles straddle
// two strips (such a triangle is set up by both threads).
inline constexpr int kMinStripRows = 8, kMaxStripRows = 64;
int strip_rows(int height, int threads);

// `frame` reset to the scene's size and background, then every world triangle drawn, with
// `threads` threads (the team's, when given).
void render_in_strips(const Scene& scene, Frame& frame, GeometryStats* geometry_stats,
                      FillStats* stats, int threads, ThreadTeam* team = nullptr,
                      FrameCertifier* certifier = nullptr);

}  // namespace frustum
