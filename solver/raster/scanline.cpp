#include "solver/raster/scanline.hpp"

#include <algorithm>
#include <numeric>

#include "solver/raster/frame_work.hpp"

namespace frustum {

Image<std::uint32_t> render_scanline(const std::vector<WindowTriangle>& triangles, int width,
                                     int height, Rgb background, ScanlineStats* stats,
                                     Image<float>* depth_out, std::int64_t max_work,
                                     std::vector<std::vector<int>>* ties) {
  FrameWork work(width, height, max_work);
  for (const WindowTriangle& t : triangles) work.add(t);
  Image<std::uint32_t> image(width, height, pack(background));
  if (depth_out) *depth_out = Image<float>(width, height, kDepthClear);
  ScanlineStats st;
  st.row_depth_bytes = static_cast<std::size_t>(width) * sizeof(float);
  st.zbuffer_depth_bytes = st.row_depth_bytes * static_cast<std::size_t>(height);
  // The edge table: triangles sorted by their first row (stable: drawing order within a row).
  std::vector<RasterTriangle> setup;
  setup.reserve(triangles.size());
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    RasterTriangle t = setup_raster(triangles[k], static_cast<int>(k));
    if (!t.setup.degenerate && t.setup.j_max >= 0 && t.setup.j_min < height && t.setup.i_max >= 0 &&
        t.setup.i_min < width)
      setup.push_back(t);
  }
  std::vector<std::size_t> by_row(setup.size());
  std::iota(by_row.begin(), by_row.end(), std::size_t{0});
  std::stable_sort(by_row.begin(), by_row.end(), [&](std::size_t a, std::size_t b) {
    return std::max(setup[a].setup.j_min, 0) < std::max(setup[b].setup.j_min, 0);
  });
  std::vector<std::size_t> active;  // indices into setup, kept in drawing order
  std::vector<float> row_depth(static_cast<std::size_t>(width));
  std::size_t next = 0;
  for (int j = 0; j < height; ++j) {
    // Leave after the last row; enter at the first.
    std::erase_if(active, [&](std::size_t a) { return setup[a].setup.j_max < j; });
    bool entered = false;
    for (; next < by_row.size() && std::max(setup[by_row[next]].setup.j_min, 0) <= j; ++next) {
      active.push_back(by_row[next]);
      entered = true;
    }
    if (entered) std::sort(active.begin(), active.end());
    st.active_max = std::max(st.active_max, active.size());
    std::fill(row_depth.begin(), row_depth.end(), kDepthClear);
    std::uint32_t* color = &image.at(0, j);
    for (std::size_t a : active) {
      const RasterTriangle& t = setup[a];
      const Span sp = span_on_row(t.setup, j);
      const int i0 = std::max(sp.i0, 0), i1 = std::min(sp.i1, width - 1);
      if (i0 > i1) continue;
      ++st.spans;
      for (int i = i0; i <= i1; ++i) {
        const float z = depth_at(t, i, j);
        if (ties && (!t.depth_decided || depth_tie(z, row_depth[static_cast<std::size_t>(i)])))
          (*ties)[static_cast<std::size_t>(j)].push_back(i);
        if (z < row_depth[static_cast<std::size_t>(i)]) {
          row_depth[static_cast<std::size_t>(i)] = z;
          color[i] = t.color;
        }
      }
    }
    if (depth_out) std::copy(row_depth.begin(), row_depth.end(), &depth_out->at(0, j));
  }
  if (stats) *stats = st;
  return image;
}

}  // namespace frustum
