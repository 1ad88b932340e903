// Text for pdflatex: special characters escaped in prose, and the Unicode that derivations use
// (−, ·, ×, √, π, ′, ₀…₉, ⁻¹, ‖, ≈, ∞ …) mapped to LaTeX by declarations in the preamble.
// Characters outside that table, CJK and Cyrillic are shown as [U+XXXX] (a document with
// Japanese needs LuaLaTeX with luatexja, one with Russian LuaLaTeX with a Cyrillic font; the
// caller chooses latex_preamble(has_cjk, has_cyrillic)).
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>

#include "solver/util/scripts.hpp"  // has_cjk, has_cyrillic: which preamble

namespace frustum {

// Prose: \ { } $ & # ^ _ % ~ escaped.
std::string latex_prose(std::string_view text);
// Prose that names symbols, as a derivation's titles and a problem's text do: a word with a
// subscript (E_BC, x_min, D_f) and the window's bounds (xmin, ymax) are set as mathematics
// (E_{BC}, x_{\min}), the rest as latex_prose.
std::string latex_prose_symbols(std::string_view text);
// A given value (YAML) as mathematics: numbers as written (5/2, sqrt(3)), lists as tuples, a
// mapping as "name = value" pairs, names through the same rule as latex_prose_symbols.
std::string latex_given(const std::string& name, const YAML::Node& value);
// Math already in LaTeX (a MathText's latex): kept, with unmapped characters replaced.
std::string latex_math(std::string_view latex);
// \documentclass … \begin{document}: pdflatex with inputenc and the Unicode declarations, or
// LuaLaTeX — with luatexja when `cjk` (texlive-lang-japanese), with fontspec and DejaVu (which
// has Cyrillic) when `cyrillic`. A LuaLaTeX preamble's first line starts "% LuaLaTeX".
std::string latex_preamble(bool cjk, bool cyrillic = false);

}  // namespace frustum
