// A scene as plain data (seed 004: scene → objects → primitives → vertices): a camera, a
// projection, a viewport, objects with flat fill colours in a parent–child hierarchy, and at
// most one directional light as in Processing's lights(). No textures, no materials. Read
// from YAML only in solver/shared/scene_reader.*.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "solver/core/matrix.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

struct Rgb {
  std::uint8_t r = 0, g = 0, b = 0;
  bool operator==(const Rgb&) const = default;
};

enum class Cull { None, Back };

// Processing's lights(): ambientLight(128, 128, 128) and directionalLight(128, 128, 128,
// 0, 0, −1). `direction` is where the light travels, in world coordinates (Processing takes
// (0, 0, −1) through the model part of the matrix current at the call: the light's own
// transform). Lighting is two-sided and flat: one face normal per triangle, turned towards
// the viewer, colour = fill·(ambient + diffuse·max(0, n̂·(−d̂)))/255.
struct DirectionalLight {
  Vec3d direction{0, 0, -1};
  double ambient = 128;
  double diffuse = 128;
};

// One object: its geometry in its own coordinates (triangles; polygons are split into fans
// from their first vertex), its transform M_object, and children placed by
// M_child_world = M_world · M_child. Fill and cull are inherited when unset.
struct SceneObject {
  std::string name;                     // "plane", "objects[2]"
  Mat4d transform = Mat4d::Identity();  // parent_from_object, the composite of its steps
  std::vector<Vec3d> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from the front
  std::optional<Rgb> fill;
  std::optional<Cull> cull;
  // Copies at translate(i·step) for every index from..to (inclusive, per axis), applied in
  // the parent's space before the object's own transform: Processing's
  // `for (i…) { pushMatrix(); translate(i*200, 0, j*200); box(…); popMatrix(); }`.
  struct Repeat {
    std::array<int, 3> from{0, 0, 0}, to{0, 0, 0};
    Vec3d step{0, 0, 0};
    long count() const {
      long n = 1;
      for (int a = 0; a < 3; ++a) n *= to[a] - from[a] + 1;
      return n;
    }
  };
  std::optional<Repeat> repeat;
  std::vector<SceneObject> children;
  // The exact inputs the doubles above were rounded from (decimals as rationals), kept when
  // the scene was read for the render kind, whose discrete decisions fall back on them
  // (raster/certified_trace.hpp); empty otherwise.
  std::vector<Vec3<Exact>> exact_vertices;
  Mat4<Exact> exact_transform = Mat4<Exact>::Identity();
  Vec3<Exact> exact_step = Vec3<Exact>::Zero();  // the repeat's step
};

struct Camera {
  Vec3d eye{0, 0, 0}, center{0, 0, -1}, up{0, 1, 0};
};

// A frame's total rasterization work: the sum over its window triangles of the rows of their
// boxes and the pixels they can cover (frame_work.hpp), which bounds both the pixels a fill
// tests and the rows a scan line walks. 2³⁰ is 64 layers of the largest frame (4096²), 512 of a
// 1920 × 1080 one: each triangle within its limits, 10⁷ full-frame triangles at 4096² would ask
// for about 44 hours; at 2³⁰ the fill of the worst frame takes about a second.
inline constexpr std::int64_t kMaxFrameWork = std::int64_t{1} << 30;

struct Scene {
  Api api = Api::OpenGL;
  // A left-handed course under OpenGL's or Processing's matrices: the camera takes LookAtLH's
  // basis (looking down +z) and clip_from_eye is the projection with its third column negated;
  // NDC, window and culling (counter-clockwise = front) stay the api's.
  bool left_handed = false;
  Camera camera;
  Mat4d clip_from_eye = Mat4d::Identity();  // the projection, column form
  int width = 0, height = 0;                // viewport in pixels
  Rgb background{0, 0, 0};
  Rgb default_fill{255, 255, 255};  // Processing's default fill
  std::optional<DirectionalLight> light;
  std::vector<SceneObject> objects;
  bool scanline = false;                  // render with the scan-line method
  std::int64_t max_work = kMaxFrameWork;  // lower for a bounded test or fuzz run
};

// Processing's box(w, h, d): centred at the origin, 12 triangles counter-clockwise seen from
// outside (right-handed).
SceneObject box_object(double w, double h, double d);
// Its eight corners in any scalar (the same numbering).
template <typename T>
std::vector<Vec3<T>> box_corners(const T& w, const T& h, const T& d) {
  // seed 003's cube numbering: 0..3 the top (y = +h/2), 4..7 the bottom; z = +d/2 the front.
  static const int xyz[8][3] = {{-1, 1, 1},  {1, 1, 1},  {1, 1, -1},  {-1, 1, -1},
                                {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}};
  std::vector<Vec3<T>> out;
  for (const auto& v : xyz) out.emplace_back(T(v[0] * w / 2), T(v[1] * h / 2), T(v[2] * d / 2));
  return out;
}

}  // namespace frustum
