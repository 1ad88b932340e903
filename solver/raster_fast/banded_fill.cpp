#include "solver/raster_fast/banded_fill.hpp"

#include <algorithm>
#include <span>

#include "solver/raster/certified_frame.hpp"
#include "solver/raster/frame_work.hpp"
#include "solver/util/side_by_side.hpp"

namespace frustum {

namespace {

// Fewer world triangles than this to a thread are not worth its start.
constexpr std::size_t kMinTrianglesPerPart = 512;

// Bins as one array (a counting sort by band): band b's triangles are
// index[start[b]] … index[start[b + 1] − 1], in drawing order.
struct Bins {
  std::vector<int> start;
  std::vector<const RasterTriangle*> index;
};

// A thread's part of the geometry: its stage and its set-up triangles, on cache lines of their
// own. The stage's counts and the vector's end change at every triangle, and two threads that
// write one cache line pass it back and forth between their cores at every write.
struct alignas(128) Part {
  Part(const Scene& scene, FrameCertifier* certifier) : stage(scene, certifier) {}
  GeometryStage stage;
  std::vector<RasterTriangle> triangles;
  std::int64_t work = 0;  // the part's price (frame_work.hpp), summed in order before the fill
};

// Triangles in drawing order: one part after another (render_in_bands's, set up side by side).
using Parts = std::vector<std::span<const RasterTriangle>>;

Bins bin_by_band(const Parts& parts, int width, int height, int bands) {
  Bins bins;
  bins.start.assign(static_cast<std::size_t>(bands) + 1, 0);
  // The bands a triangle's box spans inside the frame, or none (degenerate, off the frame).
  const auto span = [&](const RasterTriangle& t, int& b0, int& b1) {
    const TriangleSetup& s = t.setup;
    if (s.degenerate || s.i_max < 0 || s.i_min >= width || s.i_min > s.i_max) return false;
    const int j0 = std::max(s.j_min, 0), j1 = std::min(s.j_max, height - 1);
    if (j0 > j1) return false;
    b0 = j0 / kBandRows;
    b1 = j1 / kBandRows;
    return true;
  };
  int b0 = 0, b1 = 0;
  for (const std::span<const RasterTriangle> part : parts)
    for (const RasterTriangle& t : part)
      if (span(t, b0, b1))
        for (int b = b0; b <= b1; ++b) ++bins.start[static_cast<std::size_t>(b) + 1];
  for (int b = 0; b < bands; ++b) bins.start[b + 1] += bins.start[b];
  bins.index.resize(static_cast<std::size_t>(bins.start[bands]));
  std::vector<int> next(bins.start.begin(), bins.start.end() - 1);
  for (const std::span<const RasterTriangle> part : parts)
    for (const RasterTriangle& t : part)
      if (span(t, b0, b1))
        for (int b = b0; b <= b1; ++b) bins.index[next[b]++] = &t;
  return bins;
}

void fill_parts_in_bands(const Parts& parts, Frame& frame, int width, int height, Rgb background,
                         FillStats* stats, int threads, ThreadTeam* team) {
  frame.resize(width, height);
  const int bands = (height + kBandRows - 1) / kBandRows;
  const Bins bins = bin_by_band(parts, width, height, bands);
  const int workers = std::max(1, std::min(threads, bands));
  std::vector<FillStats> counts(static_cast<std::size_t>(workers));
  in_turn(
      workers, bands,
      [&](int w, const auto& next) {
        // Counted on this thread's stack and stored once: the workers' counts side by side in
        // one array share a cache line, which the cores would pass back and forth at every
        // triangle.
        FillStats mine;
        FillStats* counted = stats ? &mine : nullptr;  // counting costs the span loop a reduction
        for (int b; (b = next()) >= 0;) {
          const int j0 = b * kBandRows, j1 = std::min(height, j0 + kBandRows) - 1;
          frame.clear_rows(j0, j1, background);
          for (int k = bins.start[b]; k < bins.start[b + 1]; ++k)
            draw_triangle_rows(*bins.index[k], frame, j0, j1, counted);
        }
        counts[static_cast<std::size_t>(w)] = mine;
      },
      team);
  if (stats) {
    for (const std::span<const RasterTriangle> part : parts)
      stats->triangles += static_cast<long>(part.size());
    for (const FillStats& c : counts) *stats += c;
  }
}

}  // namespace

void fill_in_bands(const std::vector<RasterTriangle>& triangles, Frame& frame, int width,
                   int height, Rgb background, FillStats* stats, int threads, ThreadTeam* team) {
  fill_parts_in_bands(Parts{triangles}, frame, width, height, background, stats, threads, team);
}

void render_in_bands(const Scene& scene, Frame& frame, GeometryStats* geometry_stats,
                     FillStats* stats, int threads, ThreadTeam* team, FrameCertifier* certifier) {
  // The world triangles walked here (the walk copies the scene's objects, exact coordinates
  // included, whose reference counts are not atomic: not a walk per thread), then in `parts`
  // contiguous ranges, each through a geometry stage and set up on a thread of its own, and
  // joined in drawing order.
  const FlatScene flat = flatten(scene, false, certifier != nullptr);
  const std::size_t count = flat.triangles.size();
  // Contiguous parts, one a thread: no more than the team has (a team's extra parts would run
  // one after another on the caller's thread).
  const int usable = team ? std::min(threads, team->threads()) : threads;
  const int parts = static_cast<int>(
      std::clamp<std::size_t>(count / kMinTrianglesPerPart, 1, static_cast<std::size_t>(usable)));
  std::vector<Part> setups;  // made here: each stage reads the scene only once made
  setups.reserve(static_cast<std::size_t>(parts));
  for (int k = 0; k < parts; ++k) setups.emplace_back(scene, certifier);
  side_by_side(
      parts,
      [&](int k) {
        const std::size_t lo =
                              count * static_cast<std::size_t>(k) / static_cast<std::size_t>(parts),
                          hi = count * static_cast<std::size_t>(k + 1) /
                               static_cast<std::size_t>(parts);
        GeometryStage& stage = setups[static_cast<std::size_t>(k)].stage;
        std::vector<WindowTriangle> window;  // one world triangle's, reused
        std::vector<RasterTriangle>& out = setups[static_cast<std::size_t>(k)].triangles;
        out.reserve(hi - lo);
        for (std::size_t source = lo; source < hi; ++source) {
          window.clear();
          stage.add(flat.triangles[source], static_cast<int>(source), window);
          for (const WindowTriangle& w : window) {
            setups[static_cast<std::size_t>(k)].work +=
                triangle_price(w, scene.width, scene.height);
            out.push_back(setup_raster(w));
          }
        }
      },
      team);
  // Numbered in drawing order across the parts, then filled from the parts as they are (no
  // copy into one array: a megabyte of fresh memory for the paper plane's 3,520).
  FrameWork work(scene);
  for (const Part& part : setups) work.add(part.work);
  int source = 0;
  Parts filled;
  for (Part& part : setups) {
    for (RasterTriangle& t : part.triangles) t.source = source++;
    filled.emplace_back(part.triangles);
  }
  fill_parts_in_bands(filled, frame, scene.width, scene.height, scene.background, stats, threads,
                      team);
  if (geometry_stats) {
    *geometry_stats = GeometryStats{};
    for (const Part& part : setups) *geometry_stats += part.stage.stats;
  }
  if (certifier)
    for (Part& part : setups) certifier->keep(std::move(part.stage.kept));
}

}  // namespace frustum
