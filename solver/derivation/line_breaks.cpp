#include "solver/derivation/line_breaks.hpp"

namespace frustum {

bool long_math(const MathText& m, std::size_t limit) {
  if (m.latex.find("\\begin{bmatrix}") != std::string::npos) return false;
  std::size_t n = 0;
  for (const unsigned char c : m.unicode) n += (c & 0xC0) != 0x80;  // UTF-8 lead bytes
  return n > limit;
}

}  // namespace frustum
