// TikZ figures for paper exams, drawn from a problem's given values: the window and the segment
// or polygon of a 2D clipping problem, the pixel grid and triangle of scan conversion and the
// z-buffer, the projected triangle and the pixel of the plane method. Other kinds have none.
#pragma once

#include <optional>
#include <string>

#include "solver/problem/problem_set.hpp"

namespace frustum {

// A tikzpicture, or nothing when the kind has no figure (or its givens are not 2D numbers).
std::optional<std::string> tikz_figure(const ProblemSpec& problem);

}  // namespace frustum
