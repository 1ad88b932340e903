#include "export/paper.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "export/answer_caption.hpp"
#include "export/latex_text.hpp"
#include "export/quiz_items.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/problem/solve_set.hpp"

namespace frustum {

namespace {

constexpr Phrase kExam{"exam", "試験", "контрольная работа"};
constexpr Phrase kAnswerKey{"answer key", "解答", "ответы"};
constexpr Phrase kName{"Name", "氏名", "Имя"};

// The whole document: LuaLaTeX with luatexja as soon as any Japanese appears (a problem's text,
// or a step's gloss such as 輪郭線), with a Cyrillic font as soon as any Russian does, pdflatex
// otherwise.
std::string document(const std::string& body) {
  return latex_preamble(has_cjk(body), has_cyrillic(body)) + "\\begin{document}\n" + body +
         "\\end{document}\n";
}

// A derivation's math in LaTeX; a "formula" that is really words (reject: both endpoints are
// outside) is set as text, so its spaces survive.
std::string math_or_words(const std::string& latex) {
  int letters = 0, run = 0;
  for (const char c : latex) {
    run = std::isalpha(static_cast<unsigned char>(c)) ? run + 1 : 0;
    letters = std::max(letters, run);
  }
  const bool words = latex.find_first_of("\\^_{}") == std::string::npos && letters >= 4;
  return words ? "\\text{" + latex_prose(latex) + "}" : latex_math(latex);
}

// "2 points", "2 点", "2 балла" (Russian: 1 балл, 2–4 балла, 5 баллов; a fraction: балла).
std::string points_text(double points, Lang lang) {
  if (lang == Lang::Ja) return fmt::format("{:g} 点", points);
  if (lang == Lang::Ru) {
    const long n = std::lround(points);
    const char* form = "балла";
    if (static_cast<double>(n) == points) {
      const RuForm f = russian_form(n);
      form = f == RuForm::One ? "балл" : f == RuForm::Few ? "балла" : "баллов";
    }
    return fmt::format("{:g} {}", points, form);
  }
  return fmt::format("{:g} point{}", points, points == 1 ? "" : "s");
}

std::string sheet_head(const std::string& title, const PaperSheet& s, const Phrase& what,
                       Lang lang) {
  return fmt::format(
      "\\section*{{{} --- {}}}\n\\textbf{{{}}} \\hfill {}: \\rule{{5cm}}{{0.4pt}}\n\n",
      latex_prose(title), latex_prose(what.in(lang)), latex_prose(s.student),
      latex_prose(kName.in(lang)));
}

// What an answer line is labelled with, in the sheet's language (answer_caption.hpp), its
// symbols as mathematics.
std::string answer_label(const ProblemSpec& p, const std::string& name, Lang lang) {
  return latex_prose_symbols(answer_caption(p, name, lang));
}

}  // namespace

std::string exam_sheets_latex(const std::vector<PaperSheet>& sheets, const std::string& title,
                              Lang lang) {
  std::string out;
  for (std::size_t k = 0; k < sheets.size(); ++k) {
    const PaperSheet& s = sheets[k];
    if (k) out += "\\clearpage\n";
    out += sheet_head(title, s, kExam, lang);
    int n = 0;
    for (const ProblemSpec& p : s.set.problems) {
      if (p.error || !p.info) continue;
      // A problem, its figure and its answer lines on one page: a minipage is never split.
      out += "\\par\\noindent\\begin{minipage}{\\linewidth}\n";
      out += fmt::format("\\subsection*{{{}. \\normalfont\\small({})}}\n", ++n,
                         latex_prose(points_text(p.max_score(), lang)));
      out += latex_prose_symbols(question_text(s.set, p, lang)) + "\n\n";
      // The givens as mathematics (x_min = 0, A = (0, 0, 6)), not as YAML; an empty itemize
      // does not compile (a statements problem shows no given).
      if (!given_lines(p).empty()) {
        out += "\\begin{itemize}\\setlength{\\itemsep}{0pt}\n";
        for (auto it = p.given_node.begin(); it != p.given_node.end(); ++it)
          out += "\\item " + latex_given(it->first.as<std::string>(), it->second) + "\n";
        out += "\\end{itemize}\n";
      }
      // Which statements are true: the statements numbered, never their truths.
      if (const std::vector<std::string> statements = statement_texts(p, lang);
          !statements.empty()) {
        out += "\\begin{enumerate}\n";
        for (const std::string& text : statements) out += "\\item " + latex_prose(text) + "\n";
        out += "\\end{enumerate}\n";
      }
      if (const auto figure = problem_figure(p, lang); figure && !figure->tikz.empty())
        out += "\\begin{center}\n" + figure->tikz + "\\end{center}\n";
      for (const std::string& name : p.ask)
        out += answer_label(p, name, lang) + ": \\hrulefill\\par\\vspace{1.2em}\n";
      out += "\\end{minipage}\\par\\bigskip\n";
    }
  }
  return document(out);
}

std::string answer_key_latex(const std::vector<PaperSheet>& sheets, const std::string& title,
                             Lang lang) {
  std::string out;
  for (std::size_t k = 0; k < sheets.size(); ++k) {
    const PaperSheet& s = sheets[k];
    if (k) out += "\\clearpage\n";
    out += sheet_head(title, s, kAnswerKey, lang);
    int n = 0;
    for (const ProblemSpec& p : s.set.problems) {
      if (p.error || !p.info) continue;
      const ProblemResult r = solve_problem(p, s.set.file, true);
      out += fmt::format("\\subsection*{{{}. \\normalfont\\small {}}}\n", ++n, latex_prose(p.id));
      if (r.error) {
        out += "\\emph{" + latex_prose(r.error->message) + "}\n";
        continue;
      }
      for (const std::string& name : p.ask)
        if (const Value* v = r.answers.find(name))
          out += fmt::format("\\texttt{{{}}} ({}): \\(\\displaystyle {}\\)\\par\n",
                             latex_prose(name), points_text(p.answer_points(name), lang),
                             latex_math(tr(v->shown(), lang).latex));
      std::string steps;
      for (const Step& step : r.derivation.steps()) {
        if (step.formula.empty() && step.substitution.empty() && step.result.empty()) continue;
        steps += "\\item " + latex_prose_symbols(step.title.in(lang));
        for (const MathText* m : {&step.formula, &step.substitution, &step.result})
          if (!m->latex.empty()) steps += "\\\\ \\(" + math_or_words(tr(*m, lang).latex) + "\\)";
        steps += "\n";
      }
      if (!steps.empty()) out += "\\begin{enumerate}\\small\n" + steps + "\\end{enumerate}\n";
    }
  }
  return document(out);
}

}  // namespace frustum
