#include "solver/derivation/line_breaks.hpp"

namespace frustum {

std::size_t characters(std::string_view utf8) {
  std::size_t n = 0;
  for (const unsigned char c : utf8) n += (c & 0xC0) != 0x80;  // UTF-8 lead bytes
  return n;
}

bool long_math(const MathText& m, std::size_t limit) {
  if (m.latex.find("\\begin{bmatrix}") != std::string::npos) return false;
  return characters(m.unicode) > limit;
}

}  // namespace frustum
