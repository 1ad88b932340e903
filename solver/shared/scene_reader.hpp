// Reads a `scene` mapping (render kind, `frustum render`) into the plain Scene of
// solver/raster/scene.hpp, keeping the exact camera and projection for the derivation.
//
//   scene:
//     viewport: {width: 640, height: 480}
//     camera: {eye: [-150, -500, 1500], center: [0, 0, 0], up: [0, 1, 0]}
//     perspective: {fovy: 60, aspect: 4/3, near: 10, far: 10000}   # or frustum / ortho
//     background: [50, 50, 100]            # [r, g, b] 0–255, "#rrggbb" or one grey level
//     light: {direction: [0, 0, -1], transform: [{rotate_x: 90}]}   # Processing's lights()
//     method: zbuffer                      # or scanline
//     objects:
//       - name: plane                      # optional
//         mesh: {vertices: [...], faces: [[0, 1, 2], ...]}   # or triangle, box, solid
//         transform: [{translate: [0, -300, 1200]}]          # the transform kind's steps
//         fill: [255, 255, 255]
//         cull: none                       # or back
//         repeat: {from: [-10, 0, -10], to: [10, 0, 10], step: [200, 0, 200]}
//         children: [...]                  # M_child_world = M_world · M_child
#pragma once

#include <string>
#include <vector>

#include "solver/raster/scene.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/visibility/mesh.hpp"

namespace frustum {

class GivenReader;

// The scene plus the exact data its derivation shows.
struct SceneSpec {
  Scene scene;
  Vec3<Exact> eye, center, up;
  ProjectionSpec projection;
  long triangles = 0;  // world triangles, repeats counted
};

// Limits that keep any input bounded.
inline constexpr int kMaxViewport = 16384;
// Width × height: a render's memory grows with its pixels, so a 16384² frame would take
// gigabytes; 4096² (16.8 M pixels) is a poster, and any proportion within it is allowed.
inline constexpr long kMaxScenePixels = 4096L * 4096L;
inline constexpr long kMaxSceneTriangles = 10'000'000;
inline constexpr int kMaxSceneDepth = 32;

std::vector<std::string> scene_fields();

// `r` is the scene mapping itself. Throws InputError naming file, line, column and field.
// `keep_exact`: keep the exact vertices, transforms and steps beside their doubles
// (SceneObject::exact_*), for decisions that fall back on them (the render kind).
SceneSpec read_scene(GivenReader& r, const Conventions& c, bool keep_exact = false);

// The exact projection · camera of a scene (column form), with the camera's and the
// projection's derivation steps when `steps` is given.
Mat4<Exact> exact_clip_from_world(const SceneSpec& spec, Api api, Derivation* steps = nullptr);

// A mesh {vertices, faces}: faces are lists of ≥ 3 distinct vertex indices.
Mesh read_mesh(GivenReader& m, std::size_t min_vertices, std::size_t min_faces);

}  // namespace frustum
