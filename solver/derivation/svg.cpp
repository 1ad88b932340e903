#include "solver/derivation/svg.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "solver/util/scripts.hpp"

namespace frustum {

double text_width(std::string_view text, double font_px) {
  double ems = 0;
  for (std::size_t i = 0; i < text.size();) ems += is_cjk(next_code_point(text, i)) ? 1.0 : 0.62;
  return ems * font_px;
}

std::string svg_number(double v) {
  if (!std::isfinite(v)) throw std::invalid_argument("svg: coordinate is not finite");
  std::string s = fmt::format("{:.2f}", v);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

std::string_view xml_entity(char c) {
  switch (c) {
    case '&':
      return "&amp;";
    case '<':
      return "&lt;";
    case '>':
      return "&gt;";
    case '"':
      return "&quot;";
    case '\'':
      return "&#39;";  // valid in HTML too
    default:
      return {};
  }
}

std::string svg_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  // Runs without a special character are copied whole (feedback pages escape a lot of text).
  for (std::size_t start = 0; start < text.size();) {
    // One comparison chain a character (find_first_of searches its set with memchr for each).
    std::size_t end = start;
    while (end < text.size() && text[end] != '&' && text[end] != '<' && text[end] != '>' &&
           text[end] != '"' && text[end] != '\'')
      ++end;
    out.append(text.substr(start, end - start));
    if (end == text.size()) break;
    out += xml_entity(text[end]);
    start = end + 1;
  }
  return out;
}

Svg::Svg(double width, double height) : width_(width), height_(height) {}

void Svg::style(std::string_view css) { css_ += css; }

void Svg::title(std::string_view text) { title_ = svg_escape(text); }

void Svg::open(std::string_view tag, std::string_view cls, std::string_view extra,
               std::string_view attrs) {
  body_ += std::string(static_cast<std::size_t>(2 * (depth_ + 1)), ' ') + "<" + std::string(tag);
  if (!cls.empty()) body_ += " class=\"" + std::string(cls) + "\"";
  body_ += std::string(attrs);
  if (!extra.empty()) body_ += " " + std::string(extra);
}

void Svg::line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, std::string_view cls,
               std::string_view extra) {
  open("line", cls, extra,
       fmt::format(" x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\"", svg_number(a.x()), svg_number(a.y()),
                   svg_number(b.x()), svg_number(b.y())));
  body_ += "/>\n";
}

void Svg::polygon(const std::vector<Eigen::Vector2d>& points, std::string_view cls,
                  std::string_view extra) {
  std::string pts;
  for (const Eigen::Vector2d& p : points)
    pts += (pts.empty() ? "" : " ") + svg_number(p.x()) + "," + svg_number(p.y());
  open("polygon", cls, extra, " points=\"" + pts + "\"");
  body_ += "/>\n";
}

void Svg::rect(double x, double y, double w, double h, std::string_view cls,
               std::string_view extra) {
  open("rect", cls, extra,
       fmt::format(" x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"", svg_number(x), svg_number(y),
                   svg_number(w), svg_number(h)));
  body_ += "/>\n";
}

void Svg::circle(const Eigen::Vector2d& c, double r, std::string_view cls, std::string_view extra) {
  open("circle", cls, extra,
       fmt::format(" cx=\"{}\" cy=\"{}\" r=\"{}\"", svg_number(c.x()), svg_number(c.y()),
                   svg_number(r)));
  body_ += "/>\n";
}

void Svg::text(const Eigen::Vector2d& at, std::string_view text, std::string_view cls,
               std::string_view extra) {
  open("text", cls, extra,
       fmt::format(" x=\"{}\" y=\"{}\"", svg_number(at.x()), svg_number(at.y())));
  body_ += ">" + svg_escape(text) + "</text>\n";
}

void Svg::begin_group(std::string_view cls, std::string_view extra) {
  open("g", cls, extra, "");
  body_ += ">\n";
  ++depth_;
}

void Svg::end_group() {
  if (depth_ == 0) throw std::logic_error("svg: end_group without begin_group");
  --depth_;
  body_ += std::string(static_cast<std::size_t>(2 * (depth_ + 1)), ' ') + "</g>\n";
}

std::string Svg::str() const {
  if (depth_ != 0) throw std::logic_error("svg: a group is still open");
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} "
      "{1}\">\n",
      svg_number(width_), svg_number(height_));
  if (!title_.empty()) s += "  <title>" + title_ + "</title>\n";
  if (!css_.empty()) s += "  <style>\n" + css_ + "  </style>\n";
  s += body_;
  s += "</svg>\n";
  return s;
}

}  // namespace frustum
