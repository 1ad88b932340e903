// A problem's picture, drawn from its givens: the window and the segment or polygon of a 2-D
// clipping problem, the pixel grid and triangle of scan conversion and of the plane method
// (with its pixel), the z-buffer's grid and polygons (PlaneDrawing: SVG and TikZ from the same
// strokes), and the hidden lines or the painter against the z-buffer of a kind that can be
// drawn (`frustum draw`'s picture, SVG only). The derivations (`solve --format html|latex`)
// and the exam sheets show it; it never decides anything.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "solver/derivation/figure.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/derivation/value.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// Nothing when the kind has no picture or its givens cannot be drawn (a problem with an error,
// givens that are not plain numbers, a vertex behind the eye).
std::optional<Figure> problem_figure(const ProblemSpec& problem, Lang lang = Lang::En);

// Every problem's figure in a set, by id.
Figures problem_figures(const ProblemSet& set, Lang lang = Lang::En);

// A student's answers and the key of one problem, for the picture of a feedback page.
struct AnswerPair {
  Answers student, key;
};
// The figures of a student's feedback: where a problem's answer can be drawn in its picture
// (the clipped segment of clip_line, the clipped polygon of clip_polygon) and the student gave
// a wrong one, it is drawn over the givens (Figure::student_answer), and svg_with_key adds the
// right one; the student's answer is left out when it lies outside the picture.
Figures feedback_figures(const ProblemSet& set, Lang lang,
                         const std::map<std::string, AnswerPair>& answers);

}  // namespace frustum
