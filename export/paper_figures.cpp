#include "export/paper_figures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "export/latex_text.hpp"
#include "solver/core/exact.hpp"
#include "solver/util/expression.hpp"

namespace frustum {

namespace {

constexpr double kFigureSize = 6.5;  // cm, the longer side

struct Pt {
  double x, y;
};

// A given number (exact text such as 5/2 or sqrt(3) allowed); throws when it is not one.
double number(const YAML::Node& n) {
  if (!n.IsScalar()) throw std::invalid_argument("not a number");
  const ExpressionResult r = parse_expression(n.Scalar());
  if (!r) throw std::invalid_argument(r.error);
  return to_double(*r.value);
}

std::vector<Pt> points(const YAML::Node& list) {
  std::vector<Pt> out;
  if (!list.IsSequence()) throw std::invalid_argument("not a list");
  for (std::size_t i = 0; i < list.size(); ++i)
    out.push_back({number(list[i][0]), number(list[i][1])});
  return out;
}

// A figure over the box [x0, x1] × [y0, y1]: scaled to kFigureSize, with a grid of unit cells
// when `grid`, then the drawing commands.
class Figure {
 public:
  Figure(double x0, double y0, double x1, double y1, bool grid)
      : x0_(std::floor(x0)), y0_(std::floor(y0)), x1_(std::ceil(x1)), y1_(std::ceil(y1)) {
    if (x1_ <= x0_) x1_ = x0_ + 1;
    if (y1_ <= y0_) y1_ = y0_ + 1;
    const double scale = kFigureSize / std::max(x1_ - x0_, y1_ - y0_);
    body_ =
        fmt::format("\\begin{{tikzpicture}}[x={:.4f}cm,y={:.4f}cm,font=\\small]\n", scale, scale);
    // step=1 without a unit is one unit of the picture's coordinates (x=…cm), so the lines
    // fall on whole coordinates, a pixel's edges; TikZ's default step is 1 cm on the page.
    if (grid)
      body_ += fmt::format("\\draw[gray!40,very thin,step=1] ({},{}) grid ({},{});\n", x0_, y0_,
                           x1_, y1_);
    body_ += fmt::format("\\draw[->,gray] ({},{}) -- ({},{}) node[right] {{$x$}};\n", x0_, y0_,
                         x1_ + 0.3, y0_);
    body_ += fmt::format("\\draw[->,gray] ({},{}) -- ({},{}) node[above] {{$y$}};\n", x0_, y0_, x0_,
                         y1_ + 0.3);
    body_ += fmt::format("\\node[below left,gray] at ({},{}) {{${}, {}$}};\n", x0_, y0_, x0_, y0_);
  }
  void polygon(const std::vector<Pt>& p, const std::string& style, bool closed = true) {
    body_ += "\\draw[" + style + "] ";
    for (std::size_t i = 0; i < p.size(); ++i)
      body_ += fmt::format("{}({:g},{:g})", i ? " -- " : "", p[i].x, p[i].y);
    body_ += closed ? " -- cycle;\n" : ";\n";
  }
  void label(Pt p, const std::string& text, const std::string& where) {
    body_ += fmt::format("\\fill ({:g},{:g}) circle[radius=1.5pt] node[{}] {{{}}};\n", p.x, p.y,
                         where, text);
  }
  std::string done() const { return body_ + "\\end{tikzpicture}\n"; }

 private:
  double x0_, y0_, x1_, y1_;
  std::string body_;
};

Figure around(const std::vector<Pt>& p, bool grid, double margin = 0.5) {
  double x0 = p[0].x, x1 = p[0].x, y0 = p[0].y, y1 = p[0].y;
  for (const Pt& q : p) {
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  return Figure(std::min(0.0, x0 - margin), std::min(0.0, y0 - margin), x1 + margin, y1 + margin,
                grid);
}

std::vector<Pt> window_of(const YAML::Node& w) {
  const double x0 = number(w["xmin"]), x1 = number(w["xmax"]), y0 = number(w["ymin"]),
               y1 = number(w["ymax"]);
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::optional<std::string> draw(const ProblemSpec& p) {
  const YAML::Node g = p.given_node;
  if (p.kind == "clip_line" && g["window"] && g["p"].size() == 2) {
    const std::vector<Pt> w = window_of(g["window"]);
    const std::vector<Pt> seg = {{number(g["p"][0]), number(g["p"][1])},
                                 {number(g["q"][0]), number(g["q"][1])}};
    std::vector<Pt> all = w;
    all.insert(all.end(), seg.begin(), seg.end());
    Figure f = around(all, true);
    f.polygon(w, "thick,blue");
    f.polygon(seg, "thick", false);
    f.label(seg[0], "$P$", "above left");
    f.label(seg[1], "$Q$", "above right");
    return f.done();
  }
  if (p.kind == "clip_polygon" && g["window"]) {
    const std::vector<Pt> w = window_of(g["window"]), poly = points(g["points"]);
    std::vector<Pt> all = w;
    all.insert(all.end(), poly.begin(), poly.end());
    Figure f = around(all, true);
    f.polygon(w, "thick,blue");
    f.polygon(poly, "thick");
    for (std::size_t i = 0; i < poly.size(); ++i)
      f.label(poly[i], fmt::format("${}$", i), "above right");
    return f.done();
  }
  if (p.kind == "scan_convert" || p.kind == "depth_at_pixel") {
    const std::vector<Pt> tri = points(g["triangle"]);
    std::vector<Pt> all = tri;
    std::optional<Pt> pixel;
    if (g["pixel"]) all.push_back(*(pixel = Pt{number(g["pixel"][0]), number(g["pixel"][1])}));
    Figure f = around(all, true);
    f.polygon(tri, "thick");
    static const char* const kNames[] = {"A", "B", "C"};
    for (std::size_t i = 0; i < tri.size() && i < 3; ++i)
      f.label(tri[i], fmt::format("${}$", kNames[i]), "above right");
    if (pixel) f.label(*pixel, "pixel", "below right");
    return f.done();
  }
  if (p.kind == "zbuffer" && g["size"]) {
    const double w = number(g["size"][0]), h = number(g["size"][1]);
    Figure f(0, 0, w, h, true);
    for (std::size_t i = 0; i < g["polygons"].size(); ++i) {
      const YAML::Node poly = g["polygons"][i];
      const std::vector<Pt> pts = points(poly["points"]);
      f.polygon(pts, "thick");
      const std::string label =
          poly["label"] ? latex_prose(poly["label"].as<std::string>()) : std::to_string(i);
      f.label(pts[0], label, "above right");
    }
    return f.done();
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> tikz_figure(const ProblemSpec& problem) {
  try {
    return draw(problem);
  } catch (const std::exception&) {  // YAML errors too: givens a figure cannot show
    return std::nullopt;
  }
}

}  // namespace frustum
