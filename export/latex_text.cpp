#include "export/latex_text.hpp"

#include <fmt/format.h>

#include <cctype>
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
        cyrillic_fonts +
        "\\usepackage{luatexja}\n"
        // Sub- and superscript digits (E₀, x²) from the Latin font: the Japanese fonts have none.
        "\\ltjdefcharrange{200}{\"2070-\"209F}\\ltjsetparameter{jacharrange={-200}}\n";
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

namespace {

bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A name as mathematics, or nothing when it is a plain word: "E_BC" → E_{BC}, "xmin" →
// x_{\min}, "D_f" → D_{f}, "z" → z.
std::string symbol_math(const std::string& w) {
  if (w.size() == 1 && std::isalpha(static_cast<unsigned char>(w[0]))) return w;
  if (w.size() == 4 && std::isalpha(static_cast<unsigned char>(w[0])) &&
      (w.substr(1) == "min" || w.substr(1) == "max"))
    return w.substr(0, 1) + "_{\\" + w.substr(1) + "}";
  const std::size_t u = w.find('_');
  if (u == std::string::npos || u == 0 || u + 1 >= w.size() || u > 2 ||
      w.find('_', u + 1) != std::string::npos || w.size() - u - 1 > 3)
    return {};
  const std::string sub = w.substr(u + 1);
  return w.substr(0, u) + "_{" + (sub == "min" || sub == "max" ? "\\" + sub : sub) + "}";
}

std::string name_latex(const std::string& name) {
  const std::string m = symbol_math(name);
  return m.empty() ? "\\text{" + latex_prose(name) + "}" : m;
}

// A YAML scalar as mathematics: an expression's text is kept (√ and π mapped by latex_math).
std::string value_latex(const YAML::Node& n) {
  if (n.IsScalar()) {
    std::string t = n.Scalar();
    std::string out;
    for (const char c : t) {
      if (c == '*')
        out += "\\cdot ";
      else if (c == '_' || c == '#' || c == '%' || c == '&' || c == '$')
        out += std::string("\\") + c;
      else
        out += c;
    }
    return latex_math(out);
  }
  if (n.IsSequence()) {
    std::string out = "(";
    for (std::size_t i = 0; i < n.size(); ++i) out += (i ? ",\\, " : "") + value_latex(n[i]);
    return out + ")";
  }
  if (n.IsMap()) {
    std::string out;
    for (auto it = n.begin(); it != n.end(); ++it)
      out += (out.empty() ? "" : ",\\; ") + name_latex(it->first.as<std::string>()) + " = " +
             value_latex(it->second);
    return out;
  }
  return {};
}

}  // namespace

std::string latex_prose_symbols(std::string_view text) {
  std::string out, plain;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!word_char(text[i])) {
      plain += text[i++];
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && word_char(text[j])) ++j;
    const std::string w(text.substr(i, j - i));
    const bool at_word_start = i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]));
    const std::string m = at_word_start && w.size() > 1 ? symbol_math(w) : std::string();
    if (m.empty()) {
      plain += w;
    } else {
      out += latex_prose(plain) + "\\(" + m + "\\)";
      plain.clear();
    }
    i = j;
  }
  return out + latex_prose(plain);
}

std::string latex_given(const std::string& name, const YAML::Node& value) {
  // A mapping (a window) is its own pairs: "x_min = 0, x_max = 4, …".
  if (value.IsMap()) return "\\(" + value_latex(value) + "\\)";
  return "\\(" + name_latex(name) + " = " + value_latex(value) + "\\)";
}

}  // namespace frustum
