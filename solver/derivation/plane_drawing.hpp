// A drawing in the plane as data, written as TikZ (LaTeX derivations, paper exams) or as SVG
// (HTML derivations) from the same strokes: a box of whole units, optionally ruled into unit
// cells (pixels), the x and y axes from the box's lower-left corner, closed or open polylines
// and labelled dots. Both forms scale the box to the same longer side, so a vertex on a whole
// coordinate sits on a grid line in both.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

namespace frustum {

class PlaneDrawing {
 public:
  // A clip window (blue), a shape, an open segment; the right answer (green) and a student's
  // answer (dashed red), each closed or open.
  enum class Pen { Window, Shape, Open, Key, KeyOpen, Student, StudentOpen };
  enum class Place { AboveLeft, AboveRight, BelowRight };

  // Boxes wider or taller than this many units are not drawn (drawable() is false): a picture
  // at that scale shows nothing a reader could use, and its strokes would not fit TeX's
  // dimensions. A grid is ruled only up to kMaxGridUnits cells a side (pixels one could count).
  static constexpr double kMaxUnits = 10000;
  static constexpr double kMaxGridUnits = 200;

  // The box [⌊x0⌋, ⌈x1⌉] × [⌊y0⌋, ⌈y1⌉] (at least one unit each way).
  PlaneDrawing(double x0, double y0, double x1, double y1, bool grid);
  // Whether the box is finite and at most kMaxUnits a side.
  bool drawable() const;
  // The box around `points` widened by `margin`, always holding the origin.
  static PlaneDrawing around(const std::vector<Eigen::Vector2d>& points, bool grid,
                             double margin = 0.5);

  void polyline(const std::vector<Eigen::Vector2d>& points, Pen pen);
  // Whether every point lies in the box (an answer drawn outside it would leave the picture).
  bool contains(const std::vector<Eigen::Vector2d>& points) const;
  // A dot with a label: `math` labels (P, A, 0) are set as formulas, others as words.
  void label(const Eigen::Vector2d& at, const std::string& text, bool math, Place where);

  std::string tikz() const;  // a tikzpicture, the longer side 6.5 cm
  std::string svg() const;   // an SVG document, the longer side 320 px (y upward)

 private:
  struct Stroke {
    std::vector<Eigen::Vector2d> points;
    Pen pen;
  };
  struct Label {
    Eigen::Vector2d at;
    std::string text;
    bool math;
    Place where;
  };
  double x0_, y0_, x1_, y1_;
  bool grid_;
  std::vector<Stroke> strokes_;
  std::vector<Label> labels_;
};

}  // namespace frustum
