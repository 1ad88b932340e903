// The render kind's pixels with every discrete decision exact: whether a triangle
// leaves the view volume or is clipped, which way it faces (culling), where each vertex snaps
// on the 1/256-pixel grid (and with it coverage under the top-left rule, exact integers from
// there on), and which fragment wins the depth test. Each decision is first taken on the
// doubles the pipeline computes, carried as ranged values (numeric/ranged.hpp: value and a
// proven error radius) from the exact inputs rounded once; when the radius cannot prove it
// (a vertex within rounding of a half-grid point, a face within rounding of edge-on, two
// depths within rounding of each other, a vertex within rounding of a clip plane), the same
// formula is evaluated exactly on the scene's exact inputs (SceneObject::exact_*), and the
// trace says so. The model is the one the render kind states: clip in homogeneous space
// (w ≥ ε), divide, viewport, snap, top-left coverage, depth the plane through the snapped
// vertices; a fragment is written when its depth is less than the stored one (the buffer
// cleared to 1), equal keeping the earlier, the depths compared exactly and shown as 32-bit
// floats. The full-frame renderer (fill.hpp) keeps its float buffer and is not changed.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "solver/numeric/ranged.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster/pipeline.hpp"

namespace frustum {

// A window triangle (a piece of a clipped polygon's fan) with its snapped setup and its
// window depths per input vertex: ranged always, exact once a decision needed them.
struct CertifiedPiece {
  TriangleSetup setup;
  std::array<Ranged<double>, 3> z;
  std::optional<std::array<Exact, 3>> exact_z;
  Rgb color;
  int source = 0;  // index into FlatScene::triangles
  int fan = 0;     // which piece of the source's fan
  bool front = true;
};

// A triangle's window polygon with every decision taken: outside, clipped, facing, the
// snapped vertices and their window depths, from its clip coordinates: ranged (nullopt when a
// radius cannot prove a decision) or exact. `eps`: the clip plane w ≥ ε.
template <typename T>
struct Outcome {
  bool outside = false, clipped = false, front = false;
  std::vector<FixedPoint2> snapped;
  std::vector<T> z;
  std::vector<Vec4<T>> polygon;  // scratch: the clipped polygon
  std::vector<Vec2<T>> xy;       // scratch: its raster x, y
};
template <typename T>
std::optional<Outcome<T>> window_polygon(const std::array<Vec4<T>, 3>& clip, const Scene& s,
                                         const T& eps);
// The same into `out`, its vectors reused (false: a radius could not prove a decision). Without
// `facing` the facing is not decided (front is set), for an image it cannot change.
template <typename T>
bool window_polygon_into(const std::array<Vec4<T>, 3>& clip, const Scene& s, const T& eps,
                         Outcome<T>& out, bool facing = true);

// The 1/256-pixel grid point a window coordinate snaps to (rasterizer.hpp's to_fixed, halves
// away from zero), for a ranged value when its whole interval rounds to one grid point.
std::optional<std::int64_t> decided_snap(const Ranged<double>& x);

// Depth at the centre of pixel (i, j): the plane through the snapped vertices, Σ λₖ zₖ with
// λₖ = Eₖ / (2·area) exact ratios of integers (rasterizer.hpp's interpolate); z per input
// vertex. Ranged (Ranged<double>) or exact.
template <typename T>
T depth_at_centre(const TriangleSetup& t, const std::array<T, 3>& z, int i, int j);

// The window depths of piece `fan` of a fan from a polygon's first vertex.
template <typename T>
std::array<T, 3> fan_depths(const std::vector<T>& z, int fan) {
  const auto v = static_cast<std::size_t>(fan) + 1;
  return {z[0], z[v], z[v + 1]};
}

// Placement of every flattened object (flatten()'s order, index = FlatScene object index):
// its exact world_from_object and the object whose exact vertices it places (null for the
// root).
struct ExactPlacement {
  const SceneObject* object = nullptr;
  Mat4<Exact> world_from_object;
};
std::vector<ExactPlacement> exact_placements(const Scene& scene);

struct CertifiedScene {
  std::vector<CertifiedPiece> pieces;  // drawing order
  GeometryStats stats;
  long exact_geometry =
      0;  // triangles whose clipping, facing or snapping the exact fallback decided
  // For the exact fallback: per flattened object, clip_from_object = clip_from_world ·
  // world_from_object, exactly.
  std::vector<ExactPlacement> placements;
  std::vector<Mat4<Exact>> clip_from_object;
};

// The geometry half with exact decisions. `clip_from_world`: the exact projection · camera.
// Needs the scene read with its exact inputs (read_scene(…, keep_exact = true)).
CertifiedScene certified_geometry(const Scene& scene, const FlatScene& flat,
                                  const Mat4<Exact>& clip_from_world);

// One pixel's z-buffer trace (raster row j, y up): the pieces covering its centre in drawing
// order, the depth test decided exactly. Competitor::triangle indexes scene.pieces;
// `exact_depths` is set when some comparison needed the exact depths.
PixelTrace certified_trace(CertifiedScene& scene, const Scene& s, const FlatScene& flat, int i,
                           int j, bool& exact_depths);

}  // namespace frustum
