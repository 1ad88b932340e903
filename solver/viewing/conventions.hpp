// The conventions a problem is solved in. Every one is a value in the data, stated in every
// derivation; none is a hidden global.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace frustum {

enum class Api {
  OpenGL,      // right-handed eye space looking down −z, NDC [−1,1]³, near → −1, window origin bottom-left
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

struct Conventions {
  Api api = Api::OpenGL;
  AngleUnit angles = AngleUnit::Degrees;
  ZPlanes z_planes = ZPlanes::Distances;
  FovAxis fov = FovAxis::Vertical;
};

std::string_view to_string(Api api);
std::string_view to_string(AngleUnit unit);
std::optional<Api> parse_api(std::string_view text);
std::optional<AngleUnit> parse_angle_unit(std::string_view text);

// Which conventions can change a kind's answers (issue 16: a derivation states a convention only
// where it matters; a 2D clipping problem has no eye space to describe).
struct ConventionUse {
  bool api = true;     // handedness, viewing direction, NDC range, row/column vectors, window origin
  bool angles = true;  // degrees or radians
};

// One sentence naming the conventions `use` marks, for the first step of a derivation; empty
// when none of them matters.
std::string describe(const Conventions& c, ConventionUse use = {});

}  // namespace frustum
