#include "solver/visibility/pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "solver/derivation/svg.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/hidden_lines.hpp"
#include "solver/visibility/painter_vs_zbuffer.hpp"

namespace frustum {

namespace {

// Canvas of the hidden-line picture and the height of its caption.
constexpr double kCanvas = 520, kMargin = 24, kCaptionLine = 16;
constexpr double kCaptionFont = 12;  // px: the larger of the two sizes the pictures' CSS sets text
// Painter vs z-buffer: pixels per raster pixel (at most), panel gap.
constexpr double kPanel = 360, kGap = 24, kDiffInset = 0.3;

constexpr const char* kLineCss =
    "    line { stroke: #000; stroke-linecap: round; }\n"
    "    .visible { stroke-width: 1.5; }\n"
    "    .silhouette { stroke-width: 3.5; }\n"
    "    .hidden { stroke: #777; stroke-width: 1; stroke-dasharray: 5 4; }\n"
    "    text { font-family: sans-serif; font-size: 11px; fill: #222; }\n"
    "    .vertex { font-size: 10px; fill: #1a5fb4; }\n"
    "    .vertex-back { font-size: 10px; fill: #aaa; }\n";

constexpr const char* kRasterCss =
    "    text { font-family: sans-serif; font-size: 12px; fill: #222; }\n"
    "    .pixel { stroke: none; shape-rendering: crispEdges; }\n"
    "    .grid { fill: none; stroke: #ccc; stroke-width: 0.5; }\n"
    "    .outline { fill: none; stroke: #000; stroke-width: 1; }\n"
    "    .label { font-size: 14px; font-weight: bold; }\n"
    "    .diff { fill: none; stroke: #e01b24; stroke-width: 1.2; }\n";

// Fill colours of polygons 0, 1, 2, … (cycled); the background is white.
constexpr std::array<const char*, 8> kPalette = {"#f6d32d", "#62a0ea", "#8ff0a4", "#f66151",
                                                 "#dc8add", "#ffa348", "#99c1f1", "#cdab8f"};

// What the pictures say: their <title> when the options give none, the caption lines under
// them and the summary. Counts, coordinates, polygon numbers and pair names as written.
constexpr Phrase kHiddenLinesTitle{"hidden lines", "隠線消去", "удаление невидимых линий"};
constexpr Phrase kLineLegend{
    "solid: visible · bold: silhouette · dashed: hidden or covered",
    "実線: 可視 · 太線: 輪郭線 · 破線: 不可視, または他の面に覆われた部分",
    "сплошная: видимое ребро · жирная: силуэт · пунктир: невидимое или закрытое"};
constexpr Phrase kEdgeSummary{
    "{0} edges: {1} visible, {2} silhouette, {3} hidden; {4} split",
    "稜線 {0} 本: 可視 {1}, 輪郭線 {2}, 不可視 {3}; 分割された稜線 {4}",
    "рёбер: {0}; видимых: {1}, силуэтных: {2}, невидимых: {3}; разбитых: {4}"};
constexpr Phrase kEdgeCaption{
    "{0} edges: {1} visible, {2} silhouette, {3} hidden; {4} split where other faces cover them",
    "稜線 {0} 本: 可視 {1}, 輪郭線 {2}, 不可視 {3}; 他の面に覆われて分割された稜線 {4}",
    "рёбер: {0}; видимых: {1}, силуэтных: {2}, невидимых: {3}; разбитых перекрытием: {4}"};
constexpr Phrase kPainterTitle{"painter vs z-buffer", "画家のアルゴリズムと Zバッファ",
                               "алгоритм художника и z-буфер"};
constexpr Phrase kPainterSummary{
    "painter (order {0}) vs z-buffer at {1}×{2}: {3} pixels differ; conflicts: {4}",
    "画家のアルゴリズム (順序 {0}) と Zバッファ ({1}×{2}): 異なる画素 {3} 個; 矛盾: {4}",
    "алгоритм художника (порядок {0}) и z-буфер на сетке {1}×{2}: различающихся пикселей — {3}; "
    "конфликты: {4}"};
constexpr Phrase kPainterSummaryOnePixel{
    "painter (order {0}) vs z-buffer at {1}×{2}: {3} pixel differ; conflicts: {4}",
    "画家のアルゴリズム (順序 {0}) と Zバッファ ({1}×{2}): 異なる画素 {3} 個; 矛盾: {4}",
    "алгоритм художника (порядок {0}) и z-буфер на сетке {1}×{2}: различающихся пикселей — {3}; "
    "конфликты: {4}"};
constexpr Phrase kPainterAndZBuffer{
    "painter: whole polygons back to front by centroid ({0}); z-buffer: nearest per pixel",
    "画家のアルゴリズム: 多角形を丸ごと, 重心の奥から手前へ描く ({0}); Zバッファ: "
    "画素ごとに最も手前",
    "художник: целые многоугольники по убыванию глубины центра ({0}); z-буфер: ближайший в "
    "пикселе"};
constexpr Phrase kPixelsDiffer{
    "{0} of {1} pixels differ (marked in red); conflicts: {2}",
    "{1} 画素のうち {0} 画素が異なる (赤で表示); 矛盾: {2}",
    "различаются пикселей: {0} из {1} (отмечены красным); конфликты: {2}"};
constexpr Phrase kPainterPanel{"painter's algorithm (depth sort)",
                               "画家のアルゴリズム (奥行きソート)",
                               "алгоритм художника (сортировка по глубине)"};
constexpr Phrase kZBufferPanel{"z-buffer", "Zバッファ", "z-буфер"};

// The canvas width the caption needs (its lines start half a margin in, at 12 px), or `width`
// when that is wider: a long caption (many polygons in the order, a scene of size 1e100)
// widens the picture instead of running off its edge.
double width_for_caption(double width, const std::vector<Said>& lines, Lang lang) {
  double widest = 0;
  for (const Said& l : lines) widest = std::max(widest, text_width(l.in(lang), kCaptionFont));
  return std::max(width, std::ceil(kMargin + widest));
}

void caption(Svg& svg, double y, const std::vector<Said>& lines, Lang lang) {
  for (const Said& l : lines) {
    svg.text({kMargin / 2, y}, l.in(lang), "");
    y += kCaptionLine;
  }
}

Picture hidden_line_picture(const Drawable& d, const PictureOptions& o) {
  const Mesh& m = d.mesh;
  const Vec3<Exact>& eye = *d.viewer.eye;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (const Vec3<Exact>& v : m.vertices) center += to_double(v);
  center /= static_cast<double>(std::max<std::size_t>(1, m.vertices.size()));
  const DrawView view = draw_view(d.viewer, center, o.api, d.left_handed);

  std::vector<Eigen::Vector3d> world;
  std::vector<Eigen::Vector2d> screen;
  for (std::size_t k = 0; k < m.vertices.size(); ++k) {
    world.push_back(to_double(m.vertices[k]));
    if (view.depth(world.back()) <= 0)
      throw DomainError("eye",
                        fmt::format("vertex {} is not in front of the eye (looking toward the "
                                    "centroid): the picture needs the eye outside the solid",
                                    k));
    screen.push_back(view.project(world.back()));
  }
  const HiddenLines h = hidden_lines(m, eye, o.max_hidden_line_pairs);
  const ScreenFit fit = fit_screen(screen, 0, 0, kCanvas, kCanvas, kMargin);

  int counts[3] = {0, 0, 0};
  for (const EdgeLines& e : h.edges) ++counts[static_cast<int>(e.cls)];
  const std::string summary =
      say(kEdgeSummary, h.edges.size(), counts[0], counts[1], counts[2], h.split_edges).in(o.lang);

  const std::vector<Said> lines = {
      Said::verbatim(o.title), view.description, Said(kLineLegend),
      say(kEdgeCaption, h.edges.size(), counts[0], counts[1], counts[2], h.split_edges)};
  Svg svg(width_for_caption(kCanvas, lines, o.lang),
          kCanvas + kCaptionLine * (static_cast<double>(lines.size()) + 1));
  svg.title(o.title.empty() ? kHiddenLinesTitle.in(o.lang) : o.title);
  svg.style(kLineCss);
  // Covered spans first, so solid lines lie on top of dashed ones where they meet.
  for (bool visible : {false, true}) {
    svg.begin_group(visible ? "drawn" : "covered");
    for (const EdgeLines& e : h.edges) {
      const Eigen::Vector3d a = world[static_cast<std::size_t>(e.edge.i)],
                            b = world[static_cast<std::size_t>(e.edge.j)];
      for (const EdgeSpan& s : e.spans) {
        if (s.visible != visible) continue;
        const char* cls = !s.visible                       ? "hidden"
                          : e.cls == EdgeClass::Silhouette ? "silhouette"
                                                           : "visible";
        // The span's end points in 3D, then projected (perspective keeps lines straight).
        svg.line(fit(view.project(a + s.t0 * (b - a))), fit(view.project(a + s.t1 * (b - a))), cls,
                 fmt::format("data-edge=\"{}\"", e.edge.name()));
      }
    }
    svg.end_group();
  }
  // Vertex numbers: on a front face in blue, else grey.
  std::vector<bool> on_front(m.vertices.size(), false);
  for (std::size_t f = 0; f < m.faces.size(); ++f)
    if (counts_as_front(h.faces[f].facing))
      for (int k : m.faces[f]) on_front[static_cast<std::size_t>(k)] = true;
  svg.begin_group("vertices");
  for (std::size_t k = 0; k < screen.size(); ++k)
    svg.text(fit(screen[k]) + Eigen::Vector2d(4, -4), std::to_string(k),
             on_front[k] ? "vertex" : "vertex-back");
  svg.end_group();
  caption(svg, kCanvas + kCaptionLine / 2, lines, o.lang);
  return {svg.str(), summary};
}

// One frame as rows of merged same-label runs, window row j at the top when j = size − 1.
void frame_panel(Svg& svg, const FrameBuffer& f, double x0, double y0, double cell) {
  for (int j = 0; j < f.height; ++j) {
    const double y = y0 + (f.height - 1 - j) * cell;
    for (int i = 0; i < f.width;) {
      int end = i + 1;
      while (end < f.width && f.at(end, j) == f.at(i, j)) ++end;
      if (f.at(i, j) != kBackground) {
        const std::size_t k = static_cast<std::size_t>(std::stoi(f.at(i, j)));
        svg.rect(x0 + i * cell, y, (end - i) * cell, cell, "pixel",
                 fmt::format("fill=\"{}\"", kPalette[k % kPalette.size()]));
      }
      i = end;
    }
  }
  svg.rect(x0, y0, f.width * cell, f.height * cell, "grid");
}

Picture painter_picture(const Drawable& d, const PictureOptions& o) {
  const PainterVsZBuffer r = painter_vs_zbuffer(d.polygons, d.viewer, o.api, o.raster);
  const int n = r.painter.width;
  const double cell = kPanel / n;
  std::string order;
  for (int k : r.sort.order) order += (order.empty() ? "" : " → ") + std::to_string(k);
  std::string conflicts;
  for (const std::string& c : r.sort.conflicts) conflicts += (conflicts.empty() ? "" : ", ") + c;
  const Said conflicts_said = conflicts.empty() ? Said(words::kNone) : Said::verbatim(conflicts);
  const std::string summary =
      say(r.differing.size() == 1 ? kPainterSummaryOnePixel : kPainterSummary, order, n, n,
          r.differing.size(), conflicts_said)
          .in(o.lang);
  const std::vector<Said> lines = {Said::verbatim(o.title), r.view.description,
                                   say(kPainterAndZBuffer, order),
                                   say(kPixelsDiffer, r.differing.size(), n * n, conflicts_said)};
  const double top = 2 * kCaptionLine;
  const double width = width_for_caption(2 * kPanel + 3 * kGap, lines, o.lang),
               height = top + kPanel + kCaptionLine * (static_cast<double>(lines.size()) + 1.5);
  Svg svg(width, height);
  svg.title(o.title.empty() ? kPainterTitle.in(o.lang) : o.title);
  svg.style(kRasterCss);
  const std::array<double, 2> x0 = {kGap, 2 * kGap + kPanel};
  const std::array<const FrameBuffer*, 2> frames = {&r.painter, &r.zbuffer};
  const std::array<const Phrase*, 2> names = {&kPainterPanel, &kZBufferPanel};
  for (std::size_t p = 0; p < 2; ++p) {
    svg.begin_group(p == 0 ? "painter" : "zbuffer");
    svg.text({x0[p], top - kCaptionLine / 2}, names[p]->in(o.lang), "");
    frame_panel(svg, *frames[p], x0[p], top, cell);
    // Polygon outlines and numbers over the pixels (window y up → SVG y down).
    for (std::size_t k = 0; k < r.window.size(); ++k) {
      std::vector<Eigen::Vector2d> pts;
      Eigen::Vector2d mid = Eigen::Vector2d::Zero();
      for (const Eigen::Vector2d& w : r.window[k]) {
        pts.emplace_back(x0[p] + w.x() * cell, top + (n - w.y()) * cell);
        mid += pts.back();
      }
      svg.polygon(pts, "outline");
      svg.text(mid / static_cast<double>(pts.size()), std::to_string(k), "label");
    }
    // A small square inside each differing pixel, so its colour stays visible.
    for (const auto& [i, j] : r.differing)
      svg.rect(x0[p] + (i + kDiffInset) * cell, top + (n - 1 - j + kDiffInset) * cell,
               (1 - 2 * kDiffInset) * cell, (1 - 2 * kDiffInset) * cell, "diff");
    svg.end_group();
  }
  caption(svg, top + kPanel + 1.5 * kCaptionLine, lines, o.lang);
  return {svg.str(), summary};
}

}  // namespace

Picture draw_picture(const Drawable& d, const PictureOptions& o) {
  if (d.picture == Drawable::Picture::HiddenLines) return hidden_line_picture(d, o);
  return painter_picture(d, o);
}

}  // namespace frustum
