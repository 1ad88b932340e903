// Text for pdflatex: special characters escaped in prose, and the Unicode that derivations use
// (−, ·, ×, √, π, ′, ₀…₉, ⁻¹, ‖, ≈, ∞ …) mapped to LaTeX by declarations in the preamble.
// Characters outside that table, CJK and Cyrillic are shown as [U+XXXX] (a document with
// Japanese needs LuaLaTeX with luatexja, one with Russian LuaLaTeX with a Cyrillic font; the
// caller chooses latex_preamble(has_cjk, has_cyrillic)).
#pragma once

#include <string>
#include <string_view>

#include "solver/util/scripts.hpp"  // has_cjk, has_cyrillic: which preamble

namespace frustum {

// Prose: \ { } $ & # ^ _ % ~ escaped.
std::string latex_prose(std::string_view text);
// Math already in LaTeX (a MathText's latex): kept, with unmapped characters replaced.
std::string latex_math(std::string_view latex);
// \documentclass … \begin{document}: pdflatex with inputenc and the Unicode declarations, or
// LuaLaTeX — with luatexja when `cjk` (texlive-lang-japanese), with fontspec and DejaVu (which
// has Cyrillic) when `cyrillic`. A LuaLaTeX preamble's first line starts "% LuaLaTeX".
std::string latex_preamble(bool cjk, bool cyrillic = false);

}  // namespace frustum
