// Whole frames (`frustum render`) under the render kind's exact rule (certified_trace.hpp),
// kept at the speed of the float pipeline by filters that fall back where they cannot decide:
// - Geometry: the walk bounds each world vertex's error (WorldTriangle::error), the stage bounds
//   the clip coordinates' from it and from the ranged camera, and the certified trace's ranged
//   window polygon decides outside, clipping, facing and snapping on them; where a radius cannot,
//   the exact polygon from the scene's exact inputs decides (computed for that triangle alone).
// - Depth: each set-up triangle bounds its depths' error (at most kDepthTolerance, or all its
//   fragments are undecided), and the fill marks a pixel undecided where a fragment's 32-bit
//   depth is within that error and the floats' rounding of the stored one (Frame::ties).
// - Repair: the undecided pixels are traced again with the certified depth test (ranged, exact
//   where the ranges overlap) over the certified triangles; their colour and depth replaced.
// Every other pixel's fragments were each decided by the filter, so the frame is the exact rule's
// frame; the counts say how many pixels and triangles needed more than the doubles.
#pragma once

#include <map>
#include <mutex>
#include <utility>

#include "solver/raster/certified_trace.hpp"
#include "solver/raster/fill.hpp"

namespace frustum {

// What the repair did (the geometry's exact decisions are counted in GeometryStats::exact).
struct FrameCheck {
  long pixels = 0;        // pixels the fill's filter could not decide, traced again
  long exact_pixels = 0;  // of those, decided by exact depths
};

class FrameCertifier {
 public:
  // `clip_from_world`: the scene's exact projection · camera (as the double scene's: --size
  // applied). The scene must be read with its exact inputs.
  FrameCertifier(const Scene& scene, Mat4<Exact> clip_from_world);

  // The window polygon of world triangle t (a walk with track_error) with every decision the
  // exact inputs', its raster vertices (x, y on their grid points' doubles, z) and their depth
  // error; thread-safe.
  void window(const WorldTriangle& t, CertifiedWindow& out);

  // The sign of z_a − z_b at pixel (i, j), exactly: z of fan piece `fan` of world triangle
  // (object, face) on its snapped setup; b absent (object < 0) is the cleared buffer's 1.
  struct Piece {
    int object = -1, face = 0, fan = 0;
    TriangleSetup setup;
  };
  int exact_depth_sign(const Piece& a, const Piece& b, int i, int j);

  FrameCheck check;

  // A modelled scene (at most kBandedTriangles world triangles): the stages keep their certified
  // window triangles, and the repair reads them instead of walking the scene again.
  bool keeps() const { return keeps_; }
  // The kept triangles of a stage, appended in drawing order (the render's stages in order).
  void keep(std::vector<KeptWindow>&& part);
  const std::vector<KeptWindow>& kept() const { return kept_; }

 private:
  bool keeps_ = false;
  std::vector<KeptWindow> kept_;
  const Outcome<Exact>& exact_outcome(int object, int face);  // with mu_ held
  // Inside the view volume by the radii: the polygon is the triangle (no vectors but `out`'s).
  // `facing`: decide the facing too (else it is taken as front).
  bool inside_window(const std::array<Vec4<Ranged<double>>, 3>& clip, bool facing,
                     CertifiedWindow& out) const;
  const Scene& scene_;
  Mat4d clip_from_world_;  // the doubles the stage uses
  // Row i of a clip coordinate's error: alpha_[i]·(‖w‖∞ + e) + beta_[i]·e + gamma_[i], e the
  // world vertex's error.
  std::array<double, 4> alpha_{}, beta_{}, gamma_{};
  std::mutex mu_;  // exact arithmetic (GiNaC's counts are not atomic): one thread at a time
  Mat4<Exact> exact_clip_from_world_;
  std::map<int, std::pair<const SceneObject*, Mat4<Exact>>> clip_from_object_;
  std::map<std::pair<int, int>, Outcome<Exact>> outcomes_;
};

// The pixels the fill marked (frame.ties) decided again by the certified depth test over the
// scene's certified triangles; their colour and depth replaced, the marks cleared.
void repair_undecided(const Scene& scene, Frame& frame, FrameCertifier& certifier);

}  // namespace frustum
