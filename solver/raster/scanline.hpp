// The scan-line method (seed 000, p.105: "ピクセル横1行(スキャンライン)ごとにポリゴンの断面の
// 重なりを…計算し, 描画する"): the image is built one row at a time. Triangles enter an active
// list at their first row and leave after their last; on each row every active triangle
// contributes its span (fill.hpp's span_on_row), and a one-row depth buffer resolves the
// overlaps with the same depth_at() and `less` test as the z-buffer, in drawing order. So
// its image equals the z-buffer's pixel for pixel, while its working depth memory is one
// row (width floats) instead of width × height.
#pragma once

#include <cstddef>

#include "solver/raster/fill.hpp"

namespace frustum {

struct ScanlineStats {
  std::size_t row_depth_bytes = 0;      // the one-row depth buffer
  std::size_t zbuffer_depth_bytes = 0;  // what the full z-buffer would need
  std::size_t active_max = 0;           // most triangles active on one row
  long spans = 0;                       // non-empty row spans drawn
};

// The colour image (raster rows); `depth_out`, when given, receives each row's final depths
// (an output image, not working memory). Refused before any row is drawn when the triangles'
// price passes `max_work` (frame_work.hpp). `ties` (height rows): the undecided pixels of
// certified triangles, as Frame::ties.
Image<std::uint32_t> render_scanline(const std::vector<WindowTriangle>& triangles, int width,
                                     int height, Rgb background, ScanlineStats* stats = nullptr,
                                     Image<float>* depth_out = nullptr,
                                     std::int64_t max_work = kMaxFrameWork,
                                     std::vector<std::vector<int>>* ties = nullptr);

}  // namespace frustum
