#include "solver/viewing/conventions.hpp"

namespace frustum {

std::string_view to_string(Api api) {
  switch (api) {
    case Api::OpenGL:
      return "opengl";
    case Api::Processing:
      return "processing";
    case Api::DirectX:
      return "directx";
  }
  return "opengl";
}

std::string_view to_string(AngleUnit unit) {
  return unit == AngleUnit::Degrees ? "degrees" : "radians";
}

std::optional<Api> parse_api(std::string_view text) {
  if (text == "opengl") return Api::OpenGL;
  if (text == "processing") return Api::Processing;
  if (text == "directx") return Api::DirectX;
  return std::nullopt;
}

std::optional<AngleUnit> parse_angle_unit(std::string_view text) {
  if (text == "degrees") return AngleUnit::Degrees;
  if (text == "radians") return AngleUnit::Radians;
  return std::nullopt;
}

Handedness handedness_of(const Conventions& c) {
  return c.handedness.value_or(c.api == Api::DirectX ? Handedness::Left : Handedness::Right);
}

bool left_handed_columns(const Conventions& c) {
  return c.api != Api::DirectX && handedness_of(c) == Handedness::Left;
}

std::string describe(const Conventions& c, ConventionUse use) {
  const std::string_view unit = c.angles == AngleUnit::Degrees ? "degrees" : "radians";
  if (!use.api) {
    // Kinds with no eye space state a left-handed course's frame (the front normal flips).
    if (use.handedness && left_handed_columns(c))
      return use.angles ? "Left-handed coordinates; angles in " + std::string(unit)
                        : "Left-handed coordinates";
    return use.angles ? "Angles in " + std::string(unit) : "";
  }
  std::string s;
  const bool left = left_handed_columns(c);
  switch (c.api) {
    case Api::OpenGL:
      s = left ? "OpenGL, left-handed: eye space looking down +z, column vectors (p′ = M·p), "
                 "NDC cube [−1, 1]³ with near → −1, window origin bottom-left"
               : "OpenGL: right-handed eye space looking down −z, column vectors (p′ = M·p), "
                 "NDC cube [−1, 1]³ with near → −1, window origin bottom-left";
      break;
    case Api::Processing:
      s = left ? "Processing, left-handed: eye space looking down +z, OpenGL's NDC cube "
                 "[−1, 1]³, column vectors, window origin top-left with y pointing down"
               : "Processing: OpenGL's matrices and NDC cube [−1, 1]³, column vectors, "
                 "window origin top-left with y pointing down";
      break;
    case Api::DirectX:
      s = "DirectX: left-handed eye space looking down +z, row vectors (p′ = p·M), "
          "NDC z in [0, 1], window origin top-left with y pointing down";
      break;
  }
  if (c.z_planes == ZPlanes::Coordinates)
    s += "; ortho's near and far are the z coordinates z_min, z_max";
  if (c.fov == FovAxis::Horizontal) s += "; the field of view is horizontal (fovx)";
  if (use.angles) s += "; angles in " + std::string(unit);
  return s;
}

}  // namespace frustum
