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

}  // namespace frustum
