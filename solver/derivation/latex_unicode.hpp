// A formula written once, in LaTeX, read into the Unicode the terminal and JSON show:
// \mathbf{n} → n, \cdot → ·, \times → " × ", \frac{a + b}{c} → (a + b)/c, x_0 → x₀,
// x_{\text{eye}} → x_eye, p_{i+1} → pᵢ₊₁, M^{-1} → M⁻¹, \text{width} → width, ,\; → ",  ",
// - → −, \sin\theta → sin θ, n\tan\frac{a}{2} → n·tan(a/2), a\,x → a·x, a bmatrix → [a, b; c, d].
// math_text.hpp's tex() makes both notations from one string this way.
#pragma once

#include <string>
#include <string_view>

namespace frustum {

std::string unicode_of_latex(std::string_view latex);

// A fraction written on one line: each part in parentheses where it would otherwise be read
// wrongly ((a + b)/c, d/(a·z), (height/2)/tan 30° but a·b/‖a‖ and (x, y)/w).
std::string fraction_unicode(std::string_view numerator, std::string_view denominator);

}  // namespace frustum
