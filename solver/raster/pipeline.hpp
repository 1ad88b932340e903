// The geometry half of the pipeline (seed 004), each stage a plain function:
// model → world (the object hierarchy) → view → clip (double precision), Sutherland–Hodgman
// in homogeneous clip space (so w ≤ 0 never reaches the divide), the perspective divide, the
// viewport, face orientation (culling) and flat shading. Its output, window triangles in
// drawing order, feeds the raster half (fill.hpp, scanline.hpp).
//
// Raster coordinates: x right, y UP, pixel (i, j) centred at (i + ½, j + ½), as in
// rasterizer.hpp, whatever the API. OpenGL's window is already y-up; Processing's and
// DirectX's windows are y-down (top-left origin), so y_raster = height − y_window and window
// pixel row j is raster row height − 1 − j.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "solver/raster/scene.hpp"

namespace frustum {

// A triangle in world coordinates, in drawing order, with what it inherited.
struct WorldTriangle {
  std::array<Vec3d, 3> v;
  Rgb fill;
  Cull cull = Cull::None;
  int object = 0;  // index into FlatScene::objects
  int face = 0;    // triangle index within its object
  // A bound on |v − v_exact| (each coordinate of each vertex) against the world vertices of the
  // scene's exact inputs, when the walk tracks it (certified frames, certified_frame.hpp).
  double error = 0;
};

struct FlatScene {
  std::vector<WorldTriangle> triangles;
  std::vector<std::string> objects;  // names, "boxes[3]" for a repeated copy
};

// The hierarchy walked depth first (objects in file order, children after their parent,
// copies of a repeat in index order): world_from_object = world_from_parent · M_object.
// Without `names`, FlatScene::objects stays empty (WorldTriangle::object still counts the
// objects): a million copies' names would take more memory than their triangles.
FlatScene flatten(const Scene& scene, bool names = true, bool track_error = false);
// How many world triangles the walk yields (every copy of a repeat counted), without walking.
std::size_t world_triangle_count(const Scene& scene);
// The same walk, each world triangle handed to `visit` in order and none kept. The walk only
// reads the scene (it copies no object, and so none of the exact coordinates an object may keep,
// whose reference counts are not atomic): threads may walk one scene side by side.
// `track_error`: each WorldTriangle::error bounds its vertices' distance from the exact ones
// (the inputs rounded once, the products' roundings).
void for_each_world_triangle(const Scene& scene,
                             const std::function<void(const WorldTriangle&)>& visit,
                             bool track_error = false);

Mat4d eye_from_world(const Scene& scene);   // the camera (look_at in the API)
Mat4d clip_from_world(const Scene& scene);  // projection · camera

// Stage: a world point to clip coordinates.
inline Vec4d to_clip(const Mat4d& clip_from_world, const Vec3d& p) {
  return clip_from_world * Vec4d(p(0), p(1), p(2), 1.0);
}

// Stage: Sutherland–Hodgman against w ≥ ε and the six planes −w ≤ x, y ≤ w, −w ≤ z ≤ w
// (DirectX 0 ≤ z ≤ w). Fewer than 3 vertices: nothing is visible.
constexpr double kClipEpsilon = 1e-9;
// Trivially inside: all three vertices within every plane (nothing to clip).
bool inside_volume(const std::array<Vec4d, 3>& clip, Api api);
std::vector<Vec4d> clip_to_volume(const std::array<Vec4d, 3>& clip, Api api);

// Stage: (x, y, z, w) → (x/w, y/w, z/w); w > 0 after clipping.
inline Vec3d perspective_divide(const Vec4d& c) {
  return Vec3d(c(0) / c(3), c(1) / c(3), c(2) / c(3));
}

// Whether the API's window has its origin top-left with y down.
inline bool window_y_down(Api api) { return api != Api::OpenGL; }

// Stage: NDC → raster (x, y-up, window depth in [0, 1]) through viewport() of the API.
Vec3d to_raster(const Vec3d& ndc, int width, int height, Api api);

// Twice the signed area of a raster-space polygon (counter-clockwise positive).
double raster_area2(const std::vector<Vec3d>& polygon);

// Stage: orientation. Counter-clockwise in raster (y-up) space is the front in OpenGL;
// Processing (y-down world seen through a y-negating projection) and DirectX (left-handed)
// show a face whose n = (v1 − v0) × (v2 − v0) points at the viewer clockwise. In all three
// the front is the side n points to, n computed in world coordinates.
bool front_facing(double raster_area2, Api api);

class FrameCertifier;

// A world triangle's window polygon decided under the exact rule (FrameCertifier::window): its
// raster vertices (x, y on their grid points, z) and a bound on their depths' error.
struct CertifiedWindow {
  bool outside = false, clipped = false, front = false;
  bool exact = false;             // exact arithmetic decided (the ranged values could not)
  std::shared_ptr<void> scratch;  // the certifier's, reused from one triangle to the next
  std::vector<Vec3d> raster;
  double depth_error = 0;
};

// Stage: flat two-sided shading (scene.hpp's DirectionalLight). Without a light, the fill.
// `left_handed` (Scene::left_handed): counter-clockwise = front in a left-handed frame, so the
// front normal is e₁ × e₀.
Rgb shade(const WorldTriangle& t, bool front, const std::optional<DirectionalLight>& light,
          bool left_handed = false);

// A raster-space triangle ready to rasterize.
struct WindowTriangle {
  std::array<Vec3d, 3> v;  // raster x, y (y up), window depth z
  Rgb color;
  int source = 0;  // index into FlatScene::triangles
  bool front = true;
  // Certified (a FrameCertifier's stage): x and y snap where the exact inputs' do, and each z
  // is within depth_error of the exact window depth. Negative: not certified.
  double depth_error = -1;
};

struct GeometryStats {
  long triangles = 0;  // world triangles in
  long outside = 0;    // clipped away entirely
  long clipped = 0;    // cut by some plane of the view volume
  long culled = 0;     // back faces removed
  long window = 0;     // window triangles out (clipped polygons are fans)
  long exact = 0;      // certified stages: triangles whose decisions exact arithmetic took
  GeometryStats& operator+=(const GeometryStats& o) {
    exact += o.exact;
    triangles += o.triangles;
    outside += o.outside;
    clipped += o.clipped;
    culled += o.culled;
    window += o.window;
    return *this;
  }
};

// Every stage above for one world triangle at a time: its window triangles (a fan when it was
// clipped) appended to `out`, `source` their index of the world triangle.
// A certified window triangle kept for the repair of a modelled scene's undecided pixels, with
// what its exact depths are found from: world triangle (object, face), piece `fan` of its fan.
struct KeptWindow {
  WindowTriangle w;
  int object = 0, face = 0, fan = 0;
};

// With a certifier (certified_frame.hpp), every decision — outside, clipped, facing, the grid
// point each vertex snaps to — is the exact inputs' (the doubles when their error bound proves
// it, else ranged and exact arithmetic), and each window triangle carries its depth error.
class GeometryStage {
 public:
  explicit GeometryStage(const Scene& scene, FrameCertifier* certifier = nullptr);
  void add(const WorldTriangle& t, int source, std::vector<WindowTriangle>& out);
  GeometryStats stats;
  // Certified stages of a modelled scene (FrameCertifier::keeps()): every window triangle out,
  // in order, for the repair.
  std::vector<KeptWindow> kept;

 private:
  const Scene& scene_;
  FrameCertifier* certifier_;
  Mat4d clip_from_world_;
  std::vector<Vec4d> polygon_;  // reused: no allocation per triangle
  std::vector<Vec3d> raster_;
  void add_certified(const WorldTriangle& t, int source, std::vector<WindowTriangle>& out);
  CertifiedWindow certified_;
  bool keep_ = false;
};

// Every stage above for every triangle, in drawing order.
std::vector<WindowTriangle> geometry(const Scene& scene, const FlatScene& flat,
                                     GeometryStats* stats = nullptr,
                                     FrameCertifier* certifier = nullptr);

// Raster row j ↔ the API's window row (y-down APIs count rows from the top).
inline int raster_row(int window_row, int height, Api api) {
  return window_y_down(api) ? height - 1 - window_row : window_row;
}

}  // namespace frustum
