#include "solver/visibility/painter_vs_zbuffer.hpp"

#include <algorithm>
#include <string>

#include "solver/geometry/triangulate.hpp"

namespace frustum {

namespace {

constexpr int kMinRaster = 4, kMaxRaster = 512;

int orient2(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double d = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

struct Piece {
  TriangleSetup setup;
  std::array<double, 3> z;
};

}  // namespace

PainterVsZBuffer painter_vs_zbuffer(const std::vector<Polygon3<Exact>>& polygons,
                                    const DepthViewer& viewer, Api api, int size) {
  size = std::clamp(size, kMinRaster, kMaxRaster);
  PainterVsZBuffer r;
  r.sort = depth_sort(polygons, viewer);  // also rejects a bad viewer
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (const Vec3<Exact>& g : r.sort.centroids) center += to_double(g);
  center /= static_cast<double>(std::max<std::size_t>(1, polygons.size()));
  r.view = draw_view(viewer, center, api);

  // Fit the projection into the window, one pixel of margin, y up.
  std::vector<std::vector<Eigen::Vector2d>> screen;
  std::vector<std::vector<double>> depth;
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (const Polygon3<Exact>& p : polygons) {
    screen.emplace_back();
    depth.emplace_back();
    for (const Vec3<Exact>& v : p) {
      const Eigen::Vector3d x = to_double(v);
      const double d = r.view.depth(x);
      screen.back().push_back(r.view.project(x));
      depth.back().push_back(r.view.perspective ? -1 / d : d);
      lo = lo.cwiseMin(screen.back().back());
      hi = hi.cwiseMax(screen.back().back());
    }
  }
  const Eigen::Vector2d extent = (hi - lo).cwiseMax(Eigen::Vector2d(1e-12, 1e-12));
  const double scale = (size - 2) / std::max(extent.x(), extent.y());
  const Eigen::Vector2d offset = Eigen::Vector2d(size, size) / 2 - scale * (lo + hi) / 2;
  for (auto& poly : screen) {
    r.window.emplace_back();
    for (const Eigen::Vector2d& s : poly) r.window.back().push_back(offset + scale * s);
  }

  // Each polygon as triangles on screen (ear clipping: concave polygons too).
  std::vector<std::vector<Piece>> pieces(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    std::vector<Eigen::Vector2d> ccw = r.window[k];
    std::vector<int> index(ccw.size());
    for (std::size_t m = 0; m < index.size(); ++m) index[m] = static_cast<int>(m);
    double area = 0;
    for (std::size_t m = 0; m < ccw.size(); ++m) {
      const Eigen::Vector2d &a = ccw[m], &b = ccw[(m + 1) % ccw.size()];
      area += a.x() * b.y() - a.y() * b.x();
    }
    if (area == 0) continue;  // edge-on: covers no pixels
    if (area < 0) {
      std::reverse(ccw.begin(), ccw.end());
      std::reverse(index.begin(), index.end());
    }
    for (const std::array<int, 3>& t : ear_clip(ccw, orient2)) {
      Piece piece;
      std::array<Vec2<double>, 3> w;
      for (std::size_t c = 0; c < 3; ++c) {
        const auto v = static_cast<std::size_t>(index[static_cast<std::size_t>(t[c])]);
        w[c] = r.window[k][v];
        piece.z[c] = depth[k][v];
      }
      piece.setup = setup_triangle(w);
      pieces[k].push_back(piece);
    }
  }

  // The painter: back to front, every fragment written. The z-buffer: listed order, less wins.
  r.painter = FrameBuffer(size, size, kBackground);
  r.zbuffer = FrameBuffer(size, size, kBackground);
  DepthBuffer<double> unused(size, size, std::nullopt), z(size, size, std::nullopt);
  for (int k : r.sort.order)
    for (const Piece& p : pieces[static_cast<std::size_t>(k)])
      draw_triangle(p.setup, p.z, std::to_string(k), unused, r.painter,
                    [](double, double) { return true; });
  for (std::size_t k = 0; k < polygons.size(); ++k)
    for (const Piece& p : pieces[k]) draw_triangle(p.setup, p.z, std::to_string(k), z, r.zbuffer);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i)
      if (r.painter.at(i, j) != r.zbuffer.at(i, j)) r.differing.emplace_back(i, j);
  return r;
}

}  // namespace frustum
