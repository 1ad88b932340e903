// A LaTeX document of a solved set, for instructors who print: every formula in display math,
// matrices as bmatrix, prose escaped for text mode. Compiled with LuaLaTeX (fontspec, DejaVu
// fonts for the Unicode in titles and notes, luatexja for Japanese), as Debian's texlive packages
// provide.
#include <fmt/format.h>

#include "solver/derivation/formats.hpp"
#include "solver/derivation/labels.hpp"
#include "solver/derivation/line_breaks.hpp"
#include "solver/util/scripts.hpp"

namespace frustum {

namespace {

// Prose for LaTeX's text mode: special characters escaped, line breaks kept as paragraphs.
std::string prose(const std::string& text) {
  std::string out;
  for (const char c : latex_text(text))
    out += c == '\n' ? std::string("\\\\\n") : std::string(1, c);
  return out;
}

// A formula on its own line: displayed when it fits, else inline math in display style in a
// ragged-right paragraph, which TeX breaks after = and + and at \\allowbreak.
std::string display(const MathText& m, Lang lang) {
  const std::string latex = tr(m, lang).latex;
  return long_math(m) ? "\\par{\\raggedright\\noindent $\\displaystyle " + latex + "$\\par}\n"
                      : "\\[ " + latex + " \\]\n";
}

std::string steps_latex(const std::vector<Step>& steps, Lang lang) {
  std::string out = "\\begin{enumerate}\n";
  for (const Step& s : steps) {
    const bool info = s.level == Step::Level::Info;
    out += info ? "\\item " : "\\item[\\textbullet] ";
    out += (s.level == Step::Level::Warning
                ? "\\textbf{" + prose(labels::in(labels::kWarning, lang)) + ": "
                : "\\textbf{") +
           prose(s.title.in(lang)) + "}\n";
    for (const MathText* m : {&s.formula, &s.substitution})
      if (!m->empty()) out += display(*m, lang);
    if (!s.result.empty()) out += display(tex("\\Rightarrow\\;") + s.result, lang);
    if (!s.note.empty()) out += "{\\small " + prose(s.note.in(lang)) + "}\n";
  }
  return out + "\\end{enumerate}\n";
}

}  // namespace

// luatexja, with the sub- and superscript digits (e₀ × e₁) left to the Latin font: the Japanese
// fonts have none.
constexpr const char* kLuatexja =
    "\\usepackage{luatexja}\n\\ltjdefcharrange{200}{\"2070-\"209F}"
    "\\ltjsetparameter{jacharrange={-200}}\n";

std::string render_latex(const SetResult& set, Lang lang, const Figures* figures) {
  bool pictures = false;
  const std::string title = set.title.empty() ? set.file : set.title.in(lang);
  std::string out = "\\section*{" + prose(title) + "}\n";
  if (!set.source.empty())
    out +=
        "\\emph{" + prose(labels::in(labels::kSource, lang)) + ": " + prose(set.source) + "}\n\n";
  for (const Diagnostic& d : set.errors)
    out += "\\textbf{" + prose(labels::in(labels::kErrorLower, lang)) + ":} \\texttt{" +
           prose(d.format()) + "}\n\n";
  for (const ProblemResult& p : set.problems) {
    out += "\\subsection*{" + prose(p.id) + " \\normalfont(\\texttt{" + prose(p.kind) + "})}\n";
    if (!p.text.empty()) out += prose(p.text.in(lang)) + "\n\n";
    if (const Figure* f = find_figure(figures, p.id); f && !f->tikz.empty()) {
      out += "\\begin{center}\n" + f->tikz + "\\end{center}\n";
      pictures = true;
    }
    if (p.error) {
      out += "\\textbf{" + prose(labels::in(labels::kErrorLower, lang)) + ":} \\texttt{" +
             prose(p.error->format()) + "}\n\n";
      continue;
    }
    out += steps_latex(p.derivation.steps(), lang);
    out += "\\paragraph{" + prose(labels::in(labels::kAnswers, lang)) + "}\n";
    // Aligned when every answer fits a line; otherwise one breakable line each.
    bool fits = true;
    for (const std::string& name : p.ask)
      if (const Value* v = p.answers.find(name)) fits = fits && !long_math(v->shown());
    out += fits ? "\\begin{align*}\n" : "";
    for (const std::string& name : p.ask)
      if (const Value* v = p.answers.find(name))
        out +=
            fits ? "\\texttt{" + latex_text(name) + "} &= " + tr(v->shown(), lang).latex + " \\\\\n"
                 : "\\par{\\raggedright\\noindent\\texttt{" + latex_text(name) +
                       "} $\\displaystyle = " + tr(v->shown(), lang).latex + "$\\par}\n";
    out += fits ? "\\end{align*}\n" : "";
  }
  // Japanese needs luatexja (DejaVu has no kana or kanji: without it every Japanese character
  // is missing from the PDF); DejaVu covers Latin, Cyrillic and the Unicode of the notes.
  const std::string preamble =
      "% Compile with lualatex.\n\\documentclass[11pt]{article}\n\\usepackage{amsmath,amssymb}\n"
      "\\usepackage{fontspec}\n\\setmainfont{DejaVu Serif}\n\\setsansfont{DejaVu "
      "Sans}\n\\setmonofont{DejaVu Sans Mono}\n" +
      std::string(has_cjk(out) ? kLuatexja : "") +
      std::string(pictures ? "\\usepackage{tikz}\n" : "") +
      // Lines of prose may stretch rather than run into the margin: words Debian's TeX has no
      // hyphenation patterns for (Russian without texlive-lang-cyrillic, long identifiers).
      "\\usepackage[margin=2cm]{geometry}\n\\setcounter{MaxMatrixCols}{20}\n\\allowdisplaybreaks\n"
      "\\setlength{\\emergencystretch}{3em}\n"
      "\\begin{document}\n";
  return preamble + out + "\\end{document}\n";
}

}  // namespace frustum
