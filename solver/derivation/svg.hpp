// A small SVG writer for the pictures a teacher puts on a slide: lines, polygons, rectangles
// and text in a fixed-size canvas, styled by CSS classes declared once in a <style> element.
// Coordinates are SVG's: origin top-left, y down, in pixels. It builds a string; it never
// prints.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace frustum {

class Svg {
 public:
  Svg(double width, double height);

  // CSS rules for the whole picture (".hidden { stroke-dasharray: 6 4 }").
  void style(std::string_view css);
  // <title>: what a viewer shows as the picture's name.
  void title(std::string_view text);

  // Each element carries a CSS class (may be empty) and optional inline attributes
  // (`extra`, e.g. R"(fill="#ffcc00")"), written as given.
  void line(const Eigen::Vector2d& a, const Eigen::Vector2d& b, std::string_view cls,
            std::string_view extra = {});
  void polygon(const std::vector<Eigen::Vector2d>& points, std::string_view cls,
               std::string_view extra = {});
  void rect(double x, double y, double w, double h, std::string_view cls,
            std::string_view extra = {});
  void circle(const Eigen::Vector2d& c, double r, std::string_view cls,
              std::string_view extra = {});
  // Text is escaped (&, <, >, ").
  void text(const Eigen::Vector2d& at, std::string_view text, std::string_view cls,
            std::string_view extra = {});
  void begin_group(std::string_view cls, std::string_view extra = {});
  void end_group();

  // The document: XML declaration, <svg> with width, height and viewBox, style, elements.
  std::string str() const;

 private:
  void open(std::string_view tag, std::string_view cls, std::string_view extra,
            std::string_view attrs);
  double width_, height_;
  std::string title_, css_, body_;
  int depth_ = 0;  // open groups
};

// How wide a line of text is drawn at `font_px` in a sans-serif font, at most: a Latin or Cyrillic
// letter about 0.62 em, a CJK character (scripts.hpp's is_cjk) a whole em (for canvases that
// must hold their captions).
double text_width(std::string_view text, double font_px);
// A coordinate for an SVG attribute: at most two decimals, no trailing zeros ("12.5", "3").
std::string svg_number(double v);
// The entity that stands for c in XML and HTML text and attributes (&amp; &lt; &gt; &quot;
// &#39;), or nothing for any other character.
std::string_view xml_entity(char c);
// &, <, >, " and ' as entities (XML and HTML alike).
std::string svg_escape(std::string_view text);

}  // namespace frustum
