// One step of the `transform` kind's format (translate, scale, rotate_x/y/z, rotate, shear),
// read into its matrix, title and inverse. Shared by every kind that takes transform steps
// (transform, render's scene objects).
#pragma once

#include "solver/derivation/math_text.hpp"
#include "solver/viewing/conventions.hpp"
#include "solver/viewing/transforms.hpp"

#include <functional>
#include <optional>
#include <string>

namespace frustum {

class GivenReader;

struct TransformStep {
  std::string title;  // "translate (2, 3)"
  MatX<Exact> matrix;
  std::string note;
  MatX<Exact> inverse = {};  // empty when the step is singular (a zero scale factor)
  Exact det = 1;
  MathText formula = {};       // the step's matrix in symbols (rotations: cos θ, sin θ; Rodrigues)
  MathText substitution = {};  // the values put into it (c = cos θ, s = sin θ, the unit axis)
  // Rotations only: the angle (radians) and the step's matrix for another angle (the grader's
  // "degrees taken as radians").
  std::optional<Exact> angle = std::nullopt;
  std::function<MatX<Exact>(const Exact&)> rotation = nullptr;
};

// Reads the one-key mapping `s` ({translate: [2, 3]}) of dimension dim (2 or 3); angles in
// the conventions' unit. Throws InputError located at the bad field.
TransformStep read_transform_step(GivenReader& s, int dim, const Conventions& c);

}  // namespace frustum
