// Text for pdflatex: special characters escaped in prose, and the Unicode that derivations use
// (−, ·, ×, √, π, ′, ₀…₉, ⁻¹, ‖, ≈, ∞ …) mapped to LaTeX by declarations in the preamble.
// Characters outside that table and outside CJK are shown as [U+XXXX] (a document with Japanese
// needs LuaLaTeX with luatexja; the caller chooses latex_preamble(true) when has_cjk).
#pragma once

#include <string>
#include <string_view>

namespace frustum {

// Prose: \ { } $ & # ^ _ % ~ escaped.
std::string latex_prose(std::string_view text);
// Math already in LaTeX (a MathText's latex): kept, with unmapped characters replaced.
std::string latex_math(std::string_view latex);
// \documentclass … \begin{document}: pdflatex with inputenc and the Unicode declarations, or
// LuaLaTeX with luatexja when `cjk` (texlive-lang-japanese).
std::string latex_preamble(bool cjk);
// Whether the text holds Chinese or Japanese characters (kana, CJK ideographs, full-width forms).
bool has_cjk(std::string_view text);

}  // namespace frustum
