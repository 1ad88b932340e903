#include "solver/derivation/plane_drawing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/derivation/math_text.hpp"
#include "solver/derivation/svg.hpp"

namespace frustum {

namespace {

bool open_pen(PlaneDrawing::Pen pen) {
  using Pen = PlaneDrawing::Pen;
  return pen == Pen::Open || pen == Pen::KeyOpen || pen == Pen::StudentOpen;
}

constexpr double kTikzSide = 6.5;  // cm
constexpr double kSvgSide = 320;   // px
constexpr double kSvgMargin = 28;  // px around the box, for the axes' names and labels

const char* tikz_place(PlaneDrawing::Place p) {
  switch (p) {
    case PlaneDrawing::Place::AboveLeft:
      return "above left";
    case PlaneDrawing::Place::AboveRight:
      return "above right";
    case PlaneDrawing::Place::BelowRight:
      return "below right";
  }
  return "above right";
}

// A coordinate as TikZ reads it: fixed point (TikZ's math parser takes no exponent, so 1e-07
// would stop the document), trailing zeros dropped.
std::string tikz_number(double v) {
  std::string s = fmt::format("{:.4f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace

PlaneDrawing::PlaneDrawing(double x0, double y0, double x1, double y1, bool grid)
    : x0_(std::floor(x0)),
      y0_(std::floor(y0)),
      x1_(std::ceil(x1)),
      y1_(std::ceil(y1)),
      grid_(grid) {
  if (x1_ <= x0_) x1_ = x0_ + 1;
  if (y1_ <= y0_) y1_ = y0_ + 1;
  grid_ = grid_ && x1_ - x0_ <= kMaxGridUnits && y1_ - y0_ <= kMaxGridUnits;
}

bool PlaneDrawing::drawable() const {
  return std::isfinite(x0_) && std::isfinite(y0_) && std::isfinite(x1_) && std::isfinite(y1_) &&
         x1_ - x0_ <= kMaxUnits && y1_ - y0_ <= kMaxUnits;
}

PlaneDrawing PlaneDrawing::around(const std::vector<Eigen::Vector2d>& points, bool grid,
                                  double margin) {
  Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
  if (!points.empty()) lo = hi = points[0];
  for (const Eigen::Vector2d& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return PlaneDrawing(std::min(0.0, lo.x() - margin), std::min(0.0, lo.y() - margin),
                      hi.x() + margin, hi.y() + margin, grid);
}

bool PlaneDrawing::contains(const std::vector<Eigen::Vector2d>& points) const {
  for (const Eigen::Vector2d& q : points)
    if (!(q.x() >= x0_ && q.x() <= x1_ && q.y() >= y0_ && q.y() <= y1_)) return false;
  return true;
}

void PlaneDrawing::polyline(const std::vector<Eigen::Vector2d>& points, Pen pen) {
  strokes_.push_back({points, pen});
}

void PlaneDrawing::label(const Eigen::Vector2d& at, const std::string& text, bool math,
                         Place where) {
  labels_.push_back({at, text, math, where});
}

std::string PlaneDrawing::tikz() const {
  const double scale = kTikzSide / std::max(x1_ - x0_, y1_ - y0_);
  std::string out =
      fmt::format("\\begin{{tikzpicture}}[x={:.4f}cm,y={:.4f}cm,font=\\small]\n", scale, scale);
  // step=1 without a unit is one unit of the picture's coordinates (x=…cm), so the lines
  // fall on whole coordinates, a pixel's edges; TikZ's default step is 1 cm on the page.
  if (grid_)
    out +=
        fmt::format("\\draw[gray!40,very thin,step=1] ({},{}) grid ({},{});\n", x0_, y0_, x1_, y1_);
  out += fmt::format("\\draw[->,gray] ({},{}) -- ({},{}) node[right] {{$x$}};\n", x0_, y0_,
                     x1_ + 0.3, y0_);
  out += fmt::format("\\draw[->,gray] ({},{}) -- ({},{}) node[above] {{$y$}};\n", x0_, y0_, x0_,
                     y1_ + 0.3);
  out += fmt::format("\\node[below left,gray] at ({},{}) {{${}, {}$}};\n", x0_, y0_, x0_, y0_);
  for (const Stroke& s : strokes_) {
    out += s.pen == Pen::Window                         ? "\\draw[thick,blue] "
           : s.pen == Pen::Key || s.pen == Pen::KeyOpen ? "\\draw[line width=2pt,green!50!black] "
           : s.pen == Pen::Student || s.pen == Pen::StudentOpen ? "\\draw[thick,red,dashed] "
                                                                : "\\draw[thick] ";
    for (std::size_t i = 0; i < s.points.size(); ++i)
      out += fmt::format("{}({},{})", i ? " -- " : "", tikz_number(s.points[i].x()),
                         tikz_number(s.points[i].y()));
    out += open_pen(s.pen) ? ";\n" : " -- cycle;\n";
  }
  for (const Label& l : labels_)
    out += fmt::format("\\fill ({},{}) circle[radius=1.5pt] node[{}] {{{}}};\n",
                       tikz_number(l.at.x()), tikz_number(l.at.y()), tikz_place(l.where),
                       l.math ? "$" + l.text + "$" : latex_text(l.text));
  return out + "\\end{tikzpicture}\n";
}

std::string PlaneDrawing::svg() const {
  const double scale = kSvgSide / std::max(x1_ - x0_, y1_ - y0_);
  const double width = (x1_ - x0_) * scale + 2 * kSvgMargin,
               height = (y1_ - y0_) * scale + 2 * kSvgMargin;
  // Picture coordinates: x to the right, y upward, from the box's lower-left corner.
  auto at = [&](double x, double y) {
    return Eigen::Vector2d(kSvgMargin + (x - x0_) * scale, height - kSvgMargin - (y - y0_) * scale);
  };
  Svg svg(width, height);
  svg.style(
      ".grid { stroke: #d6d9de; stroke-width: 0.6 } .axis { stroke: #8a9099; stroke-width: 1 } "
      ".window { stroke: #1f5fbf; stroke-width: 2.2; fill: none } .shape { stroke: #1d232a; "
      "stroke-width: 2.2; fill: none } .key { stroke: #1a7f37; stroke-width: 4; fill: none; "
      "stroke-opacity: 0.75 } .student { stroke: #c4262e; stroke-width: 2.2; "
      "stroke-dasharray: 7 4; fill: none } .dot { fill: #1d232a } text { font: 13px sans-serif; "
      "fill: #1d232a } .axis-name, .corner { fill: #8a9099 } .math { font-style: italic }");
  if (grid_) {
    for (double x = x0_; x <= x1_; ++x) svg.line(at(x, y0_), at(x, y1_), "grid");
    for (double y = y0_; y <= y1_; ++y) svg.line(at(x0_, y), at(x1_, y), "grid");
  }
  // The axes run a fixed 12 px past the box (inside the margin), their names beside the tips.
  const Eigen::Vector2d x_tip = at(x1_, y0_) + Eigen::Vector2d(12, 0),
                        y_tip = at(x0_, y1_) + Eigen::Vector2d(0, -12);
  svg.line(at(x0_, y0_), x_tip, "axis");
  svg.line(at(x0_, y0_), y_tip, "axis");
  svg.text(x_tip + Eigen::Vector2d(3, 4), "x", "axis-name math");
  svg.text(y_tip + Eigen::Vector2d(5, 4), "y", "axis-name math");
  // The corner's coordinates under it (to its left they would leave the picture).
  svg.text(at(x0_, y0_) + Eigen::Vector2d(-kSvgMargin + 4, 18), fmt::format("{}, {}", x0_, y0_),
           "corner");
  for (const Stroke& s : strokes_) {
    std::vector<Eigen::Vector2d> p;
    for (const Eigen::Vector2d& q : s.points) p.push_back(at(q.x(), q.y()));
    const char* cls = s.pen == Pen::Window                                 ? "window"
                      : s.pen == Pen::Key || s.pen == Pen::KeyOpen         ? "key"
                      : s.pen == Pen::Student || s.pen == Pen::StudentOpen ? "student"
                                                                           : "shape";
    if (open_pen(s.pen)) {
      for (std::size_t i = 1; i < p.size(); ++i) svg.line(p[i - 1], p[i], cls);
    } else {
      svg.polygon(p, cls);
    }
  }
  for (const Label& l : labels_) {
    const Eigen::Vector2d p = at(l.at.x(), l.at.y());
    svg.circle(p, 3, "dot");
    const bool left = l.where == Place::AboveLeft, below = l.where == Place::BelowRight;
    svg.text(p + Eigen::Vector2d(left ? -6 : 6, below ? 16 : -6), l.text, l.math ? "math" : "",
             left ? R"(text-anchor="end")" : "");
  }
  return svg.str();
}

}  // namespace frustum
