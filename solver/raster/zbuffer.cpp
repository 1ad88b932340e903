#include "solver/raster/zbuffer.hpp"

namespace frustum {

std::vector<std::string> frame_rows(const FrameBuffer& frame) {
  std::vector<std::string> rows;
  for (int j = frame.height - 1; j >= 0; --j) {
    std::string row;
    for (int i = 0; i < frame.width; ++i) row += frame.at(i, j);
    rows.push_back(row);
  }
  return rows;
}

}  // namespace frustum
