// The conventions a problem is solved in. Every one is a value in the data, stated in every
// derivation; none is a hidden global.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace frustum {

enum class Api {
  OpenGL,  // right-handed eye space looking down −z, NDC [−1,1]³, near → −1, window origin
           // bottom-left
  Processing,  // OpenGL math, window origin top-left with y down, Processing's default camera
  DirectX      // left-handed, looking down +z, NDC z in [0,1], row vectors, window y down
};

enum class AngleUnit { Degrees, Radians };

// How a course reads ortho()'s near and far: distances in front of the eye (OpenGL's glOrtho:
// the planes z = −near, −far) or the z coordinates z_min, z_max of the planes on an axis
// pointing into the scene (as some lectures write the orthographic matrix).
enum class ZPlanes { Distances, Coordinates };

// Which extent a perspective's `fov` spans: the height (OpenGL's and Processing's fovy) or the
// width (as some lectures read θ); `fovy` and `fovx` always name their own axis.
enum class FovAxis { Vertical, Horizontal };

// The handedness of world and eye space. OpenGL and Processing are right-handed (the eye looks
// down −z); DirectX is left-handed (the eye looks down +z). A course may declare `left` with
// OpenGL's or Processing's column vectors and NDC cube: the eye then looks down +z (as a
// lecture's projection coordinates, where z is the depth), look_at's basis is LookAtLH's and
// the projection puts w′ = +z (the right-handed matrices with their third column negated), and
// a polygon's front normal (counter-clockwise = front) is e₁ × e₀ (AC × AB).
enum class Handedness { Right, Left };

struct Conventions {
  Api api = Api::OpenGL;
  AngleUnit angles = AngleUnit::Degrees;
  ZPlanes z_planes = ZPlanes::Distances;
  FovAxis fov = FovAxis::Vertical;
  std::optional<Handedness> handedness;  // unset: the API's own (handedness_of)
};

// The declared handedness, or the API's own (left for DirectX, right otherwise).
Handedness handedness_of(const Conventions& c);
// A left-handed course under OpenGL's or Processing's matrices (DirectX is left-handed anyway,
// with its own matrices).
bool left_handed_columns(const Conventions& c);

std::string_view to_string(Api api);
std::string_view to_string(AngleUnit unit);
std::optional<Api> parse_api(std::string_view text);
std::optional<AngleUnit> parse_angle_unit(std::string_view text);

// Which conventions can change a kind's answers (a derivation states a convention only where it
// matters; a 2D clipping problem has no eye space to describe).
struct ConventionUse {
  bool api = true;  // handedness, viewing direction, NDC range, row/column vectors, window origin
  bool angles = true;  // degrees or radians
  // The handedness alone (for kinds with no API: a polygon's front normal), stated when left.
  bool handedness = false;
};

}  // namespace frustum
