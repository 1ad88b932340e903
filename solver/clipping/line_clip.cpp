#include "solver/clipping/line_clip.hpp"

namespace frustum {

std::string outcode_string(unsigned code, int dims) {
  std::string s;
  for (int b = 2 * dims - 1; b >= 0; --b) s += (code >> b) & 1u ? '1' : '0';
  return s;
}

std::string outcode_bit_meaning(unsigned bit) {
  switch (bit) {
    case outcode_bit(0, false):
      return "left (x < xmin)";
    case outcode_bit(0, true):
      return "right (x > xmax)";
    case outcode_bit(1, false):
      return "bottom (y < ymin)";
    case outcode_bit(1, true):
      return "top (y > ymax)";
    case outcode_bit(2, false):
      return "z < zmin";
    case outcode_bit(2, true):
      return "z > zmax";
    default:
      return "?";
  }
}

std::string outcode_meaning(unsigned code) {
  if (code == 0) return "inside";
  std::string s;
  for (int b = 5; b >= 0; --b)
    if (code & (1u << b)) s += (s.empty() ? "" : ", ") + outcode_bit_meaning(1u << b);
  return s;
}

}  // namespace frustum
