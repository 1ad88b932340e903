#include "solver/problem/problem_figure.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/derivation/plane_drawing.hpp"
#include "solver/problem/kind.hpp"
#include "solver/util/expression.hpp"
#include "solver/visibility/drawable.hpp"
#include "solver/visibility/pictures.hpp"

namespace frustum {

namespace {

using Pen = PlaneDrawing::Pen;
using Place = PlaneDrawing::Place;

constexpr Phrase kPixel{"pixel", "画素", "пиксель"};

// A given number (exact text such as 5/2 or sqrt(3) allowed); throws when it is not one.
double number(const YAML::Node& n) {
  if (!n.IsScalar()) throw std::invalid_argument("not a number");
  const ExpressionResult r = parse_expression(n.Scalar());
  if (!r) throw std::invalid_argument(r.error.en());
  return to_double(*r.value);
}

Eigen::Vector2d point(const YAML::Node& p) { return {number(p[0]), number(p[1])}; }

std::vector<Eigen::Vector2d> points(const YAML::Node& list) {
  if (!list.IsSequence()) throw std::invalid_argument("not a list");
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < list.size(); ++i) out.push_back(point(list[i]));
  return out;
}

std::vector<Eigen::Vector2d> window_of(const YAML::Node& w) {
  const double x0 = number(w["xmin"]), x1 = number(w["xmax"]), y0 = number(w["ymin"]),
               y1 = number(w["ymax"]);
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

std::vector<Eigen::Vector2d> joined(std::vector<Eigen::Vector2d> a,
                                    const std::vector<Eigen::Vector2d>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The kinds drawn in the plane from their givens.
std::optional<PlaneDrawing> plane_drawing(const ProblemSpec& p, Lang lang) {
  const YAML::Node g = p.given_node;
  if (p.kind == "clip_line" && g["window"] && g["p"].size() == 2) {
    const std::vector<Eigen::Vector2d> w = window_of(g["window"]),
                                       seg = {point(g["p"]), point(g["q"])};
    PlaneDrawing d = PlaneDrawing::around(joined(w, seg), true);
    d.polyline(w, Pen::Window);
    d.polyline(seg, Pen::Open);
    d.label(seg[0], "P", true, Place::AboveLeft);
    d.label(seg[1], "Q", true, Place::AboveRight);
    return d;
  }
  if (p.kind == "clip_polygon" && g["window"]) {
    const std::vector<Eigen::Vector2d> w = window_of(g["window"]), poly = points(g["points"]);
    PlaneDrawing d = PlaneDrawing::around(joined(w, poly), true);
    d.polyline(w, Pen::Window);
    d.polyline(poly, Pen::Shape);
    for (std::size_t i = 0; i < poly.size(); ++i)
      d.label(poly[i], std::to_string(i), true, Place::AboveRight);
    return d;
  }
  if (p.kind == "scan_convert" || p.kind == "depth_at_pixel" || p.kind == "barycentric") {
    const std::vector<Eigen::Vector2d> tri = points(g["triangle"]);
    std::vector<Eigen::Vector2d> all = tri;
    std::optional<Eigen::Vector2d> pixel;
    if (g["pixel"]) all.push_back(*(pixel = point(g["pixel"])));
    PlaneDrawing d = PlaneDrawing::around(all, true);
    d.polyline(tri, Pen::Shape);
    static const char* const kNames[] = {"A", "B", "C"};
    for (std::size_t i = 0; i < tri.size() && i < 3; ++i)
      d.label(tri[i], kNames[i], true, Place::AboveRight);
    if (pixel) d.label(*pixel, std::string(kPixel.in(lang)), false, Place::BelowRight);
    return d;
  }
  if (p.kind == "scanline" && g["y"] && g["polygons"]) {
    // The polygons on the screen and the scan line across them.
    std::vector<Eigen::Vector2d> all;
    for (std::size_t i = 0; i < g["polygons"].size(); ++i)
      all = joined(all, points(g["polygons"][i]["points"]));
    const double y = number(g["y"]);
    double x0 = all.empty() ? 0 : all[0].x(), x1 = x0;
    for (const Eigen::Vector2d& q : all) x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x());
    all.emplace_back(x0, y);
    PlaneDrawing d = PlaneDrawing::around(all, true);
    for (std::size_t i = 0; i < g["polygons"].size(); ++i) {
      const YAML::Node poly = g["polygons"][i];
      const std::vector<Eigen::Vector2d> pts = points(poly["points"]);
      d.polyline(pts, Pen::Shape);
      d.label(pts[0], poly["label"].as<std::string>(), false, Place::AboveRight);
    }
    d.polyline({{x0 - 0.5, y}, {x1 + 0.5, y}}, Pen::Window);
    d.label({x0 - 0.5, y}, "y = " + g["y"].as<std::string>(), true, Place::AboveRight);
    return d;
  }
  if (p.kind == "zbuffer" && g["size"]) {
    PlaneDrawing d(0, 0, number(g["size"][0]), number(g["size"][1]), true);
    for (std::size_t i = 0; i < g["polygons"].size(); ++i) {
      const YAML::Node poly = g["polygons"][i];
      const std::vector<Eigen::Vector2d> pts = points(poly["points"]);
      d.polyline(pts, Pen::Shape);
      if (poly["label"])
        d.label(pts[0], poly["label"].as<std::string>(), false, Place::AboveRight);
      else
        d.label(pts[0], std::to_string(i), true, Place::AboveRight);
    }
    return d;
  }
  return std::nullopt;
}

// The points of an answer that can be drawn in the plane: clip_line's and clip_polygon's
// `clipped` (rows of two numbers); nothing for `none`, other answers and other kinds.
std::optional<std::vector<Eigen::Vector2d>> drawn_answer(const ProblemSpec& p, const Answers& a) {
  if (p.kind != "clip_line" && p.kind != "clip_polygon") return std::nullopt;
  const Value* v = a.find("clipped");
  if (!v || v->shape != Value::Shape::Matrix || v->cols != 2 || v->rows < 2 ||
      v->numbers.size() != static_cast<std::size_t>(2 * v->rows))
    return std::nullopt;
  std::vector<Eigen::Vector2d> out;
  for (int r = 0; r < v->rows; ++r) out.emplace_back(v->numbers[2 * r], v->numbers[2 * r + 1]);
  return out;
}

// Whether two drawn answers are the same points (a right answer needs no second drawing).
bool same_points(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if ((a[i] - b[i]).norm() > 1e-9 * (1 + a[i].norm())) return false;
  return true;
}

}  // namespace

Figures feedback_figures(const ProblemSet& set, Lang lang,
                         const std::map<std::string, AnswerPair>& answers) {
  Figures out = problem_figures(set, lang);
  for (const ProblemSpec& p : set.problems) {
    const auto it = answers.find(p.id);
    if (it == answers.end() || p.error || !p.info) continue;
    try {
      std::optional<PlaneDrawing> d = plane_drawing(p, lang);
      const auto student = drawn_answer(p, it->second.student);
      const auto key = drawn_answer(p, it->second.key);
      if (!d || !d->drawable() || !student || !d->contains(*student) ||
          (key && same_points(*student, *key)))
        continue;
      const bool open = p.kind == "clip_line";
      d->polyline(*student, open ? Pen::StudentOpen : Pen::Student);
      Figure f{d->svg(), d->tikz()};
      f.student_answer = true;
      if (key && d->contains(*key)) {
        d->polyline(*key, open ? Pen::KeyOpen : Pen::Key);
        d->polyline(*student, open ? Pen::StudentOpen : Pen::Student);  // the dashes on top
        f.svg_with_key = d->svg();
      }
      out[p.id] = std::move(f);
    } catch (const std::exception&) {  // givens a figure cannot show: the plain figure stays
    }
  }
  return out;
}

std::optional<Figure> problem_figure(const ProblemSpec& p, Lang lang) {
  if (p.error || !p.info) return std::nullopt;
  try {
    if (const std::optional<PlaneDrawing> d = plane_drawing(p, lang)) {
      if (!d->drawable()) return std::nullopt;  // 10⁶ wide, or beyond double's range
      return Figure{d->svg(), d->tikz()};
    }
    if (p.info->drawable) {
      PictureOptions options;
      options.api = p.conventions.api;
      options.lang = lang;
      return Figure{draw_picture(p.info->drawable(p.given), options).svg, "", true};
    }
  } catch (const std::exception&) {  // YAML errors too: givens a figure cannot show
  }
  return std::nullopt;
}

Figures problem_figures(const ProblemSet& set, Lang lang) {
  Figures out;
  for (const ProblemSpec& p : set.problems)
    if (std::optional<Figure> f = problem_figure(p, lang)) out[p.id] = std::move(*f);
  return out;
}

}  // namespace frustum
