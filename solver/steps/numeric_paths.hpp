// The numeric paths of the kinds (values only, no steps), in any backend: each takes the
// kind's exact Given pieces, converts them to the backend's scalar once, and returns a
// prepared solver whose run() is only arithmetic. The math is the templated core of
// solver/geometry and solver/viewing; these adapters add the condition warnings.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <vector>

#include "solver/problem/numeric_result.hpp"
#include "solver/steps/kind_steps.hpp"
#include "solver/steps/viewing_steps.hpp"

namespace frustum {

std::unique_ptr<NumericSolver> vectors_numeric(const Vec3<Exact>& a, const Vec3<Exact>& b,
                                               AngleUnit unit, Precision p);
// order: the A, B, C form with its cross order; otherwise a polygon (e₀ × e₁ or Newell).
std::unique_ptr<NumericSolver> normal_numeric(const Polygon3<Exact>& points,
                                              const std::optional<CrossOrder>& order, Precision p);
// points, or (when empty) point + normal.
std::unique_ptr<NumericSolver> plane_numeric(const Polygon3<Exact>& points,
                                             const Vec3<Exact>& point, const Vec3<Exact>& normal,
                                             Precision p);
std::unique_ptr<NumericSolver> depth_at_pixel_numeric(const std::array<Vec3<Exact>, 3>& triangle,
                                                      const Vec2<Exact>& pixel,
                                                      const CrossOrder& order, Precision p);
std::unique_ptr<NumericSolver> backface_numeric(const Polygon3<Exact>& points,
                                                const Vec3<Exact>& eye, Precision p);
// model: the composite model matrix M (column form), when the point is in model coordinates.
std::unique_ptr<NumericSolver> project_point_numeric(
    const Vec3<Exact>& point, const std::optional<MatX<Exact>>& model,
    const std::optional<std::array<Vec3<Exact>, 3>>& camera, const ProjectionSpec& projection,
    const Exact& width, const Exact& height, Api api, Precision p);
// steps: each step's matrix; inverses: each step's inverse (used by the exact backend);
// invertible: false when a step is singular (the inverse is then null). Steps in column
// form; under DirectX the matrix and inverse are reported in row-vector form (transposed).
std::unique_ptr<NumericSolver> transform_numeric(int dim, const std::vector<MatX<Exact>>& steps,
                                                 const std::vector<MatX<Exact>>& inverses,
                                                 bool invertible,
                                                 const std::vector<std::vector<Exact>>& points,
                                                 Api api, Precision p);
std::unique_ptr<NumericSolver> viewport_numeric(const Vec3<Exact>& ndc, const Exact& width,
                                                const Exact& height, Api api, Precision p);

// Runs a prepared solver once and returns its answers.
NumericResult run_numeric(std::unique_ptr<NumericSolver> solver);

}  // namespace frustum
