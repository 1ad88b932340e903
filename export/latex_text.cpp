#include "export/latex_text.hpp"

#include <fmt/format.h>

#include <map>

namespace frustum {

namespace {

// The Unicode characters Frustum's derivations and answers use, as LaTeX.
const std::map<char32_t, const char*>& unicode_latex() {
  static const std::map<char32_t, const char*> table = {{U'−', "\\ensuremath{-}"},
                                                        {U'·', "\\ensuremath{\\cdot}"},
                                                        {U'×', "\\ensuremath{\\times}"},
                                                        {U'…', "\\ensuremath{\\dots}"},
                                                        {U'≈', "\\ensuremath{\\approx}"},
                                                        {U'√', "\\ensuremath{\\surd}"},
                                                        {U'π', "\\ensuremath{\\pi}"},
                                                        {U'θ', "\\ensuremath{\\theta}"},
                                                        {U'φ', "\\ensuremath{\\varphi}"},
                                                        {U'α', "\\ensuremath{\\alpha}"},
                                                        {U'β', "\\ensuremath{\\beta}"},
                                                        {U'λ', "\\ensuremath{\\lambda}"},
                                                        {U'′', "\\ensuremath{'}"},
                                                        {U'‖', "\\ensuremath{\\|}"},
                                                        {U'∞', "\\ensuremath{\\infty}"},
                                                        {U'≤', "\\ensuremath{\\le}"},
                                                        {U'≥', "\\ensuremath{\\ge}"},
                                                        {U'≠', "\\ensuremath{\\ne}"},
                                                        {U'⇒', "\\ensuremath{\\Rightarrow}"},
                                                        {U'→', "\\ensuremath{\\to}"},
                                                        {U'∈', "\\ensuremath{\\in}"},
                                                        {U'°', "\\ensuremath{^\\circ}"},
                                                        {U'±', "\\ensuremath{\\pm}"},
                                                        {U'∓', "\\ensuremath{\\mp}"},
                                                        {U'⁻', "\\ensuremath{^{-}}"},
                                                        {U'⁰', "\\ensuremath{^{0}}"},
                                                        {U'¹', "\\ensuremath{^{1}}"},
                                                        {U'²', "\\ensuremath{^{2}}"},
                                                        {U'³', "\\ensuremath{^{3}}"},
                                                        {U'₀', "\\ensuremath{_{0}}"},
                                                        {U'₁', "\\ensuremath{_{1}}"},
                                                        {U'₂', "\\ensuremath{_{2}}"},
                                                        {U'₃', "\\ensuremath{_{3}}"},
                                                        {U'₄', "\\ensuremath{_{4}}"},
                                                        {U'ₓ', "\\ensuremath{_{x}}"},
                                                        {U'ᵧ', "\\ensuremath{_{y}}"},
                                                        {U'ₛ', "\\ensuremath{_{s}}"},
                                                        {U'ᵢ', "\\ensuremath{_{i}}"},
                                                        {U'\u0302', "\\ensuremath{\\hat{}}"},
                                                        {U'\u0303', "\\ensuremath{\\tilde{}}"},
                                                        {U'①', "\\textcircled{\\scriptsize 1}"},
                                                        {U'②', "\\textcircled{\\scriptsize 2}"},
                                                        {U'③', "\\textcircled{\\scriptsize 3}"},
                                                        {U'④', "\\textcircled{\\scriptsize 4}"},
                                                        {U'“', "``"},
                                                        {U'”', "''"},
                                                        {U'’', "'"},
                                                        {U'—', "---"},
                                                        {U'–', "--"},
                                                        {U'∠', "\\ensuremath{\\angle}"},
                                                        {U'△', "\\ensuremath{\\triangle}"},
                                                        {U'∘', "\\ensuremath{\\circ}"}};
  return table;
}

// Non-ASCII characters: kept when the preamble declares them (or CJK under LuaLaTeX), else
// shown as their code point (\unknownchar{2A01} prints [U+2A01]) so nothing vanishes unseen.
void append_unicode(std::string& out, std::string_view s, std::size_t start, std::size_t end,
                    char32_t cp) {
  if (unicode_latex().count(cp) || is_cjk(cp) || is_cyrillic(cp))
    out.append(s.substr(start, end - start));
  else
    out += fmt::format("\\unknownchar{{{:04X}}}", static_cast<unsigned>(cp));
}

}  // namespace

std::string latex_prose(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t start = i;
    const char32_t cp = next_code_point(text, i);
    switch (cp) {
      case '\\':
        out += "\\textbackslash{}";
        break;
      case '{':
        out += "\\{";
        break;
      case '}':
        out += "\\}";
        break;
      case '$':
        out += "\\$";
        break;
      case '&':
        out += "\\&";
        break;
      case '#':
        out += "\\#";
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '_':
        out += "\\_";
        break;
      case '%':
        out += "\\%";
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      case '<':
        out += "\\textless{}";
        break;
      case '>':
        out += "\\textgreater{}";
        break;
      default:
        if (cp < 0x80)
          out += static_cast<char>(cp);
        else
          append_unicode(out, text, start, i, cp);
    }
  }
  return out;
}

std::string latex_math(std::string_view latex) {
  std::string out;
  for (std::size_t i = 0; i < latex.size();) {
    const std::size_t start = i;
    const char32_t cp = next_code_point(latex, i);
    if (cp < 0x80)
      out += static_cast<char>(cp);
    else
      append_unicode(out, latex, start, i, cp);
  }
  return out;
}

std::string latex_preamble(bool cjk, bool cyrillic) {
  std::string out;
  // Cyrillic in DejaVu (fonts-dejavu-core): Latin Modern, LuaLaTeX's default, has none.
  const std::string cyrillic_fonts =
      cyrillic ? "\\usepackage{fontspec}\n\\setmainfont{DejaVu Serif}\n"
                 "\\setsansfont{DejaVu Sans}\n\\setmonofont{DejaVu Sans Mono}\n"
               : "";
  if (cjk) {
    out =
        "% LuaLaTeX: Japanese text — compile with lualatex (Debian: texlive-luatex, "
        "texlive-lang-japanese).\n"
        "\\documentclass[a4paper,11pt]{article}\n" +
        cyrillic_fonts + "\\usepackage{luatexja}\n";
  } else if (cyrillic) {
    out =
        "% LuaLaTeX: Russian text — compile with lualatex (Debian: texlive-luatex, "
        "fonts-dejavu-core).\n"
        "\\documentclass[a4paper,11pt]{article}\n" +
        cyrillic_fonts;
  } else {
    out =
        "\\documentclass[a4paper,11pt]{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage[T1]{"
        "fontenc}\n";
    for (const auto& [cp, tex] : unicode_latex())
      out += fmt::format("\\DeclareUnicodeCharacter{{{:04X}}}{{{}}}\n", static_cast<unsigned>(cp),
                         tex);
  }
  return out +
         "\\newcommand{\\unknownchar}[1]{\\ensuremath{[\\mathrm{U{+}#1}]}}\n\\usepackage{amsmath,"
         "amssymb}\n\\usepackage[margin=2cm]{geometry}\n\\usepackage{tikz}\n"
         "\\setlength{\\parindent}{0pt}\n\\setlength{\\parskip}{4pt}\n";
}

}  // namespace frustum
