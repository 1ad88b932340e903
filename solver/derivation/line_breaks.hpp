// When a piece of mathematics is too long for one line of a page: more than `limit` characters
// as written in Unicode. The formatters then let it break (inline math in \displaystyle, which
// TeX and KaTeX break after = and + and at \allowbreak) instead of setting it in one display
// line that would run off the page; a long vector's brackets and commas allow it (vec()).
#pragma once

#include <cstddef>
#include <string_view>

#include "solver/derivation/math_text.hpp"

namespace frustum {

// Characters (Unicode code points) of UTF-8 text: what "long" is measured in.
std::size_t characters(std::string_view utf8);

// A matrix ([…; …] / bmatrix) cannot break: mathematics holding one counts as short, to be
// displayed on its own centred line.
bool long_math(const MathText& m, std::size_t limit = 64);

}  // namespace frustum
