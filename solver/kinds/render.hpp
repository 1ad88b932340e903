// The render kind's parsed input, shared with `frustum render` (app/render_command.cpp),
// which draws the whole image of the same scene.
#pragma once

#include <array>
#include <vector>

#include "solver/shared/scene_reader.hpp"

namespace frustum {

struct RenderGiven {
  SceneSpec spec;
  Conventions conventions;
  std::vector<std::array<int, 2>>
      pixels;  // [i, j] in the API's window (y-down APIs: j from the top)
};

}  // namespace frustum
