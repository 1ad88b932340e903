// One step of the `transform` kind's format (translate, scale, rotate_x/y/z, rotate, shear),
// read into its matrix, title and inverse. Shared by every kind that takes transform steps
// (transform, render's scene objects).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/math_text.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/viewing/conventions.hpp"
#include "solver/viewing/transforms.hpp"

namespace frustum {

// "A1: translate (2, 3)": a step of a composite transform by its number and heading.
inline constexpr Phrase kStepTitle{"A{0}: {1}", "A{0}: {1}", "A{0}: {1}"};
// The misconception of a composite multiplied in the wrong order (wrong_order_feedback).
inline constexpr Phrase kCompositionInTheWrongOrder{
    "composition in the wrong order", "変換の合成順序が逆", "композиция в неверном порядке"};

struct TransformStep {
  Said heading;  // "translate (2, 3)", in every language
  MatX<Exact> matrix;
  Said note;
  MatX<Exact> inverse = {};  // empty when the step is singular (a zero scale factor)
  Exact det = 1;
  MathText formula = {};  // the step's matrix in symbols (rotations: cos θ, sin θ; Rodrigues)
  MathText substitution = {};  // the values put into it (c = cos θ, s = sin θ, the unit axis)
  // Rotations only: the angle (radians) and the step's matrix for another angle (the grader's
  // "degrees taken as radians").
  std::optional<Exact> angle = std::nullopt;
  std::function<MatX<Exact>(const Exact&)> rotation = nullptr;
};

// Which transform steps a kind accepts: how many, and whether shear is one of them.
struct TransformStepList {
  std::size_t min_count = 1, max_count = kMaxTransformSteps;
  bool shear = true;
};

// Reads the one-key mapping `s` ({translate: [2, 3]}) of dimension dim (2 or 3); angles in
// the conventions' unit. Throws InputError located at the bad field.
TransformStep read_transform_step(GivenReader& s, int dim, const Conventions& c,
                                  bool with_shear = true);

// The feedback for a composite multiplied in the wrong order (the order the steps are applied
// in, for column vectors; the reverse, for DirectX's row vectors).
Said wrong_order_feedback(Api api);

// Reads the list `key` of such steps (by default 1 to kMaxTransformSteps of them, shear
// included).
std::vector<TransformStep> read_transform_steps(GivenReader& r, const std::string& key, int dim,
                                                const Conventions& c,
                                                const TransformStepList& list = {});

// Composing and undoing transforms, one formula for the exact solve and every numeric backend
// (column vectors): the step applied next stands leftmost, M ← A·M, and its inverse rightmost,
// M⁻¹ ← M⁻¹·A⁻¹. The exact solve keeps each product in canonical form for its derivation; the
// numeric backends (the exact one included) keep the plain product, which is many times faster.
template <typename T>
MatX<T> then_apply(const MatX<T>& m, const MatX<T>& step) {
  return MatX<T>(step * m);
}
template <typename T>
MatX<T> then_undo(const MatX<T>& inverse, const MatX<T>& step_inverse) {
  return MatX<T>(inverse * step_inverse);
}

// The composite `name` = Aₙ·…·A₁ (column form: the step applied first stands rightmost), with
// one derivation step per Aᵢ and one for the composite, titled `title` (DirectX prints every
// matrix in row-vector form, `name` = A₁·…·Aₙ).
MatX<Exact> compose_with_steps(const std::vector<TransformStep>& steps, int dim, Api api,
                               const std::string& name, const Phrase& title,
                               Derivation* derivation);

}  // namespace frustum
