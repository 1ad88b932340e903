// A formula written once, in LaTeX, read into the Unicode the terminal and JSON show:
// \mathbf{n} → n, \cdot → ·, \times → ×, \frac{a + b}{c} → (a + b)/c, x_0 → x₀, x_{\text{eye}} →
// x_eye, M^{-1} → M⁻¹, \text{width} → width, ,\; → ",  ", - → −. math_text.hpp's formula() makes
// both notations from one string this way.
#pragma once

#include <string>
#include <string_view>

namespace frustum {

std::string unicode_of_latex(std::string_view latex);

}  // namespace frustum
