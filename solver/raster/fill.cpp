#include "solver/raster/fill.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "solver/raster/certified_frame.hpp"
#include "solver/raster/frame_work.hpp"
#include "solver/raster/span_fill.hpp"

namespace frustum {

namespace {

// Boxes of at most this many pixels are filled pixel by pixel with incremental edge functions;
// larger ones row by row from spans (RowSpans: six divisions a triangle and a few additions a
// row, instead of a test of every pixel of the box, which for a thin triangle is mostly a test
// of pixels it does not cover).
constexpr long kSmallBoxPixels = 8;
constexpr int kPrefetchRows = 4;

struct Clamped {
  int i0, i1, j0, j1;
  bool empty() const { return i0 > i1 || j0 > j1; }
};

Clamped clamp_box(const TriangleSetup& s, int width, int height) {
  return {std::max(s.i_min, 0), std::min(s.i_max, width - 1), std::max(s.j_min, 0),
          std::min(s.j_max, height - 1)};
}

}  // namespace

RasterTriangle setup_raster(const WindowTriangle& w, int source) {
  RasterTriangle t;
  setup_triangle({Vec2<double>(w.v[0](0), w.v[0](1)), Vec2<double>(w.v[1](0), w.v[1](1)),
                  Vec2<double>(w.v[2](0), w.v[2](1))},
                 t.setup);  // in place: no copy of the setup
  t.color = pack(w.color);
  t.source = source;
  const TriangleSetup& s = t.setup;
  const double z[3] = {w.v[s.order[0]](2), w.v[s.order[1]](2), w.v[s.order[2]](2)};
  t.z0 = z[0];
  if (s.degenerate) return t;
  // The plane through the snapped vertices: A·dx + B·dy = dz at v1 and v2.
  const double dx1 = static_cast<double>(s.v[1].x - s.v[0].x),
               dy1 = static_cast<double>(s.v[1].y - s.v[0].y);
  const double dx2 = static_cast<double>(s.v[2].x - s.v[0].x),
               dy2 = static_cast<double>(s.v[2].y - s.v[0].y);
  const double dz1 = z[1] - z[0], dz2 = z[2] - z[0];
  const double area2 = static_cast<double>(s.area2);
  t.a = (dz1 * dy2 - dz2 * dy1) / area2;
  t.b = (dx1 * dz2 - dx2 * dz1) / area2;
  if (w.depth_error >= 0) {
    // The depth at a covered centre, z0 + b·dy + a·dx in doubles, against Σ λₖ zₖ of the exact
    // vertex depths (λₖ ≥ 0, Σ λₖ = 1 inside): the vertices' own error, the evaluation's
    // roundings, and those of a and b (numerators within γ₃ of their terms' magnitudes) times
    // the largest offsets from v0 in the box.
    constexpr double u = std::numeric_limits<double>::epsilon() / 2, g = 8 * u;
    const double span_x =
        std::max(std::abs(static_cast<double>(pixel_centre(s.i_min, 0).x - s.v[0].x)),
                 std::abs(static_cast<double>(pixel_centre(s.i_max, 0).x - s.v[0].x)));
    const double span_y =
        std::max(std::abs(static_cast<double>(pixel_centre(0, s.j_min).y - s.v[0].y)),
                 std::abs(static_cast<double>(pixel_centre(0, s.j_max).y - s.v[0].y)));
    const double ea = g * (std::abs(dz1 * dy2) + std::abs(dz2 * dy1)) / area2,
                 eb = g * (std::abs(dx1 * dz2) + std::abs(dx2 * dz1)) / area2;
    const double bound = w.depth_error +
                         g * (std::abs(t.z0) + std::abs(t.b) * span_y + std::abs(t.a) * span_x) +
                         ea * span_x + eb * span_y;
    t.depth_decided = bound <= kDepthTolerance;  // false for a NaN or infinite bound
  }
  return t;
}

Span span_on_row(const TriangleSetup& t, int j) {
  if (t.degenerate || j < t.j_min || j > t.j_max) return {};
  const std::int64_t yc = pixel_centre(0, j).y, half = kSubpixelScale / 2;
  std::int64_t lo = t.i_min, hi = t.i_max;
  for (const EdgeFunction& e : t.edge) {
    // a·xc + R ≥ bias with R = b·yc + c.
    const std::int64_t need = fill_bias(e) - (e.b * yc + e.c);
    if (e.a > 0) {
      lo = std::max(lo, ceil_div(ceil_div(need, e.a) - half, kSubpixelScale));
    } else if (e.a < 0) {
      hi = std::min(hi, floor_div(floor_div(-need, -e.a) - half, kSubpixelScale));
    } else if (need > 0) {
      return {};
    }
  }
  return {static_cast<int>(lo), static_cast<int>(hi)};
}

void draw_triangle(const RasterTriangle& t, Frame& frame, FillStats* stats) {
  if (stats) ++stats->triangles;
  draw_triangle_rows(t, frame, 0, frame.color.height - 1, stats);
}

void draw_triangle_rows(const RasterTriangle& t, Frame& frame, int j_lo, int j_hi,
                        FillStats* stats) {
  const TriangleSetup& s = t.setup;
  if (s.degenerate) return;
  const int width = frame.color.width;
  Clamped box = clamp_box(s, width, frame.color.height);
  box.j0 = std::max(box.j0, j_lo);
  box.j1 = std::min(box.j1, j_hi);
  if (box.empty()) return;
  const std::int64_t x0 = s.v[0].x, y0 = s.v[0].y;
  long fragments = 0, written = 0;
  std::vector<int>* const ties = frame.ties.empty() ? nullptr : frame.ties.data();
  float* depth = frame.depth.data.data();
  std::uint32_t* color = frame.color.data.data();
  const std::uint32_t c = t.color;
  if (static_cast<long>(box.i1 - box.i0 + 1) * (box.j1 - box.j0 + 1) <= kSmallBoxPixels) {
    // Incremental edge functions: E(i + 1, j) = E(i, j) + a·256, E(i, j + 1) = E(i, j) + b·256.
    const FixedPoint2 p = pixel_centre(box.i0, box.j0);
    std::int64_t row[3], step_x[3], step_y[3];
    for (int k = 0; k < 3; ++k) {
      const EdgeFunction& e = s.edge[k];
      row[k] = e.at(p.x, p.y) - fill_bias(e);
      step_x[k] = e.a * kSubpixelScale;
      step_y[k] = e.b * kSubpixelScale;
    }
    for (int j = box.j0; j <= box.j1; ++j) {
      std::int64_t e0 = row[0], e1 = row[1], e2 = row[2];
      const std::size_t base = static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
      const double row_z = t.z0 + t.b * static_cast<double>(pixel_centre(0, j).y - y0);
      double dx = static_cast<double>(p.x - x0);
      bool inside = false;
      for (int i = box.i0; i <= box.i1; ++i, dx += kSubpixelScale) {
        if ((e0 | e1 | e2) >= 0) {
          inside = true;
          ++fragments;
          const float z = static_cast<float>(row_z + t.a * dx);
          if (ties && (!t.depth_decided || depth_tie(z, depth[base + i]))) ties[j].push_back(i);
          if (z < depth[base + i]) {
            depth[base + i] = z;
            color[base + i] = c;
            ++written;
          }
        } else if (inside) {
          break;  // a triangle's covered centres on a row are contiguous
        }
        e0 += step_x[0];
        e1 += step_x[1];
        e2 += step_x[2];
      }
      for (int k = 0; k < 3; ++k) row[k] += step_y[k];
    }
  } else {
    RowSpans spans(s, box.j0);
    for (int j = box.j0; j <= box.j1; ++j) {
      const Span sp = spans.next();
      const int i0 = std::max(sp.i0, box.i0), i1 = std::min(sp.i1, box.i1);
      if (i0 > i1) continue;
      const std::size_t base = static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
      const double row_z = t.z0 + t.b * static_cast<double>(pixel_centre(0, j).y - y0);
      const double dx0 = static_cast<double>(pixel_centre(i0, 0).x - x0);
      float* d = depth + base;
      std::uint32_t* col = color + base;
      fragments += i1 - i0 + 1;
      const int n = i1 - i0 + 1;
      // The same columns kPrefetchRows rows on, where the span will most likely be then.
      if (j + kPrefetchRows <= box.j1) {
        const std::size_t ahead = base + kPrefetchRows * static_cast<std::size_t>(width);
        for (int i = i0; i <= i1; i += 16) {
          __builtin_prefetch(depth + ahead + i, 1);
          __builtin_prefetch(color + ahead + i, 1);
        }
      }
      std::vector<int>* row_ties = ties ? &ties[j] : nullptr;
      if (row_ties && !t.depth_decided) {
        for (int i = i0; i <= i1; ++i) row_ties->push_back(i);
        row_ties = nullptr;
      }
      written += fill_span(d + i0, col + i0, n, row_z, t.a, dx0, c, stats != nullptr, row_ties, i0);
    }
  }
  if (stats) {
    stats->fragments += fragments;
    stats->written += written;
  }
}

Frame render_zbuffer(const std::vector<WindowTriangle>& triangles, int width, int height,
                     Rgb background, FillStats* stats, std::int64_t max_work) {
  FrameWork work(width, height, max_work);
  for (const WindowTriangle& t : triangles) work.add(t);
  Frame frame(width, height, background);
  for (std::size_t k = 0; k < triangles.size(); ++k)
    draw_triangle(setup_raster(triangles[k], static_cast<int>(k)), frame, stats);
  return frame;
}

void render_zbuffer_streamed(const Scene& scene, Frame& frame, GeometryStats* geometry_stats,
                             FillStats* stats, FrameCertifier* certifier) {
  frame.ties.assign(certifier ? static_cast<std::size_t>(scene.height) : 0, {});
  GeometryStage stage(scene, certifier);
  FrameWork work(scene);
  int source = 0, drawn = 0;
  frame.reset(scene.width, scene.height, scene.background);
  std::vector<WindowTriangle> window;  // one world triangle's, reused
  for_each_world_triangle(
      scene,
      [&](const WorldTriangle& t) {
        window.clear();
        stage.add(t, source++, window);
        for (const WindowTriangle& w : window) {
          work.add(w);
          draw_triangle(setup_raster(w, drawn++), frame, stats);
        }
      },
      certifier != nullptr);
  if (geometry_stats) *geometry_stats = stage.stats;
  if (certifier) certifier->keep(std::move(stage.kept));
}

PixelTrace trace_pixel(const std::vector<WindowTriangle>& triangles, int i, int j, Rgb background) {
  PixelTrace p;
  p.i = i;
  p.j = j;
  p.color = background;
  const double xc = i + 0.5, yc = j + 0.5;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const WindowTriangle& w = triangles[k];
    // Screen bounds (a pixel of margin covers the snapping) before any setup.
    double x0 = w.v[0](0), x1 = x0, y0 = w.v[0](1), y1 = y0;
    for (const Vec3d& v : w.v) {
      x0 = std::min(x0, v(0));
      x1 = std::max(x1, v(0));
      y0 = std::min(y0, v(1));
      y1 = std::max(y1, v(1));
    }
    if (xc < x0 - 1 || xc > x1 + 1 || yc < y0 - 1 || yc > y1 + 1) continue;
    const RasterTriangle t = setup_raster(w, static_cast<int>(k));
    if (!covers(t.setup, i, j)) continue;
    Competitor c{static_cast<int>(k), depth_at(t, i, j), false};
    c.passed = c.depth < p.depth;
    p.add(c, w.color);
  }
  return p;
}

}  // namespace frustum
