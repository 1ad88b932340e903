// Reading and deriving the pieces of the viewing pipeline that several kinds share: angles
// in the set's unit, a projection (perspective, frustum or ortho) with its checks and steps,
// and matrices shown as on paper.
#pragma once

#include <optional>
#include <string>
#include <utility>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum {

// The step title of a projection's derivation by similar triangles.
inline constexpr Phrase kSimilarTriangles{"Similar triangles", "相似な三角形",
                                          "Подобные треугольники"};
// The titles of look_at_with_steps's axes step, where a reversed basis goes wrong.
inline constexpr Phrase kCameraAxesLeftHanded{"Camera axes (left-handed, looking down +z)",
                                              "カメラの軸 (左手系, +z 方向を見る)",
                                              "Оси камеры (левая система, взгляд вдоль +z)"};
inline constexpr Phrase kCameraAxesRightHanded{"Camera axes (right-handed, looking down −z)",
                                               "カメラの軸 (右手系, −z 方向を見る)",
                                               "Оси камеры (правая система, взгляд вдоль −z)"};
// The titles of projection_with_steps's matrix step, where a mistake that names no earlier step
// goes wrong.
inline constexpr Phrase kOrthographicProjectionMatrix{
    "Orthographic projection matrix", "平行投影の行列", "Матрица ортографической проекции"};
inline constexpr Phrase kPerspectiveProjectionMatrix{
    "Perspective projection matrix", "透視投影行列", "Матрица перспективной проекции"};

class GivenReader;

// An angle in the conventions' unit, returned in radians (exact: 60 → π/3).
Exact read_angle(GivenReader& r, const std::string& key, AngleUnit unit);
MathText angle_text(const Exact& radians, AngleUnit unit);

struct ProjectionSpec {
  enum class Type { Perspective, Frustum, Ortho } type = Type::Perspective;
  Volume<Exact> volume;
  std::optional<Exact> fovy;    // radians, perspective only
  std::optional<Exact> aspect;  // perspective only
  // The horizontal angle (radians) when the course gives one (`fovx`, or `fov` with
  // conventions fov: horizontal); fovy is then 2·atan(tan(fovx/2)/aspect).
  std::optional<Exact> fovx;
  AngleUnit unit = AngleUnit::Degrees;
  // perspective() with no arguments: Processing's defaults for a sketch of this width and
  // height (fovy = 60°, aspect = width/height, near = cameraZ/10, far = 10·cameraZ).
  std::optional<std::pair<Exact, Exact>> sketch;
  bool z_coordinates = false;  // ortho: near, far are z_min, z_max (Conventions::z_planes)
  // A left-handed course under OpenGL's or Processing's matrices: the eye looks down +z, w′ = z,
  // and the matrix is the right-handed one with its third column negated (left_handed_columns).
  bool left_handed = false;
};

// Reads whichever of perspective / frustum / ortho is given (exactly one), checking the
// domain: near > 0 for a perspective, near ≠ far, fovy in (0°, 180°), aspect > 0, l ≠ r, b ≠ t.
ProjectionSpec read_projection(GivenReader& r, const Conventions& c);
// A perspective from its four numbers (fovy in radians), its volume's bounds canonical.
ProjectionSpec perspective_projection(const Exact& fovy, const Exact& aspect, const Exact& near,
                                      const Exact& far);
// Processing's default camera distance for a sketch `height` pixels high: cameraZ =
// (height/2)/tan(fovy/2) with Processing's fovy = 60° (camera() and perspective() with no
// arguments; near = cameraZ/10, far = 10·cameraZ).
Exact processing_camera_z(const Exact& height);
bool has_projection(const GivenReader& r);

// The projection matrix (column form) with its derivation steps in the conventions, called
// `name` in them (P where a model or view matrix M, V stands beside it).
MatX<Exact> projection_with_steps(const ProjectionSpec& p, Api api, Derivation* steps,
                                  const std::string& name = "M");

// Throws DomainError naming field + "center" (center = eye) or field + "up" (up parallel to the
// view direction, or zero): a camera with no view matrix. Exact, and cheaper than the matrix.
void check_camera(const Vec3<Exact>& eye, const Vec3<Exact>& center, const Vec3<Exact>& up,
                  const std::string& field);

// The view matrix of a camera (column form) with its steps; throws DomainError naming
// field + "center" or field + "up" on a degenerate camera. `left_handed` (a left-handed course
// under OpenGL's or Processing's column vectors): LookAtLH's basis, looking down +z.
MatX<Exact> look_at_with_steps(const Vec3<Exact>& eye, const Vec3<Exact>& center,
                               const Vec3<Exact>& up, Api api, const std::string& field,
                               Derivation* steps, bool left_handed = false);

// Every point through M (with the divide by w), one step each, yielding "points" (written
// P′ = P·M under DirectX's row vectors; M is the column form either way); the
// answer value is the list of moved points (null when there are none).
Value transform_points_with_steps(const MatX<Exact>& m,
                                  const std::vector<std::vector<Exact>>& points, const Said& title,
                                  const std::string& name, Derivation* steps,
                                  Api api = Api::OpenGL);

MatX<Exact> canonical(const MatX<Exact>& m);
std::vector<std::vector<Exact>> rows_of(const MatX<Exact>& m);
Value matrix_value(const MatX<Exact>& m);
MathText matrix_text(const MatX<Exact>& m);

// The viewport step: window coordinates and depth from NDC in the conventions (y up or down,
// depth (z + 1)/2 or z), with `ndc` in the substitution when it is a given; yields "window".
void viewport_step(Derivation* steps, Api api, const Exact& width, const Exact& height,
                   const Vec3<Exact>& window, const Vec3<Exact>* ndc = nullptr);

// "M = " in the conventions: DirectX prints the row-vector matrix (p′ = p·M).
Said multiply_note(Api api);

// Common mistakes in setting up a projection, each as the projection it amounts to: degrees
// taken as radians, fovx for fovy, the planes' z coordinates for near and far. `step` is the
// derivation step where it goes wrong, said as that step's title (empty where the matrix itself
// is).
// A named mistake of the angle (projection_mistakes, and transform's rotations).
inline constexpr Phrase kDegreesTakenAsRadians{"degrees taken as radians", "度をラジアンとして計算",
                                               "градусы взяты как радианы"};

struct ProjectionMistake {
  Said name, feedback, step;
  ProjectionSpec projection;
};
std::vector<ProjectionMistake> projection_mistakes(const ProjectionSpec& p);

// Grading scales (docs/grading.md §2) of NDC — each coordinate of size 1, on the side of ±1
// that decides inside (DirectX's z of 0 and 1) — and of window coordinates: x and y of size
// width/2 and height/2 against the viewport's edges, the depth of size 1 against 0 and 1.
AnswerScale ndc_scale(Api api);
AnswerScale window_scale(const Exact& width, const Exact& height);
// Inside the NDC volume (a student's NDC, for error carried forward): |x|, |y| ≤ 1 and z in
// [−1, 1] ([0, 1] in DirectX), decided exactly.
bool ndc_inside(const Vec3<Exact>& ndc, Api api);

}  // namespace frustum
