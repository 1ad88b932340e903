// A problem's picture beside its derivation: the window and the segment or polygon of a 2-D
// clipping problem, the pixel grid and triangle of scan conversion, the plane method and the
// z-buffer, the hidden lines or depth order of a visibility problem (solver/problem/
// problem_figure.hpp draws it from the problem's givens). The formatters take it beside the
// solved set: the SVG as an image in HTML (its own styles kept to itself), TikZ in LaTeX
// (empty where only one form exists).
#pragma once

#include <map>
#include <string>

namespace frustum {

struct Figure {
  std::string svg;   // an SVG document
  std::string tikz;  // a tikzpicture
  // The picture shows answers (the hidden edges, the painter's order), not only the givens:
  // feedback shows it only where it shows the key.
  bool shows_answers = false;
  // Feedback: the student's own answer drawn over the givens (dashed red; it never shows the
  // key), and `svg_with_key` the same picture with the right answer too (green), for pages
  // that show the key.
  bool student_answer = false;
  std::string svg_with_key = {};
};

using Figures = std::map<std::string, Figure>;  // by problem id

// The figure of problem `id`, or null (no figures given, or none for it).
inline const Figure* find_figure(const Figures* figures, const std::string& id) {
  if (!figures) return nullptr;
  const auto f = figures->find(id);
  return f == figures->end() ? nullptr : &f->second;
}

}  // namespace frustum
