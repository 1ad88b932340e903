// Formatters of derivations and solved sets: text for the terminal, Markdown with LaTeX math,
// JSON in the shape of problem-format.md §3, typeset HTML and LaTeX (format_*.cpp; the
// functions keep their names, render_text, render_json, …).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "solver/derivation/figure.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/derivation/local_text.hpp"
#include "solver/derivation/problem_result.hpp"

namespace frustum {

struct TextStyle {
  bool color = false;    // ANSI colour: only when writing to a terminal
  Lang lang = Lang::En;  // step titles and fixed phrases (i18n.hpp)
};

std::string render_steps_text(const std::vector<Step>& steps, const TextStyle& style,
                              const std::string& indent = "  ");
std::string render_problem_text(const ProblemResult& p, const TextStyle& style);
std::string render_text(const SetResult& set, const TextStyle& style);

std::string render_steps_markdown(const std::vector<Step>& steps, Lang lang = Lang::En);
std::string render_problem_markdown(const ProblemResult& p, Lang lang = Lang::En);
std::string render_markdown(const SetResult& set, Lang lang = Lang::En);

// Typeset HTML (format_html.cpp): formulas typeset by KaTeX, inlined from Debian's libjs-katex
// (no network); each formula's Unicode form stays inside its element as the fallback.
// A page typesets formulas itself (KaTeX, html_math_script()), or its host does: a course
// platform whose pages run MathJax over \( … \) and \[ … \] (PrairieLearn).
enum class MathMarkup { KaTeX, Delimited };
std::string html_math(const MathText& m, Lang lang = Lang::En, bool display = true,
                      MathMarkup markup = MathMarkup::KaTeX);
std::string html_steps(const std::vector<Step>& steps, Lang lang = Lang::En,
                       MathMarkup markup = MathMarkup::KaTeX);
// KaTeX's style (fonts inlined) and script for a page's <head>; empty when KaTeX is absent.
std::string html_math_head();
// KaTeX as files, for many pages that link one shared copy instead of each carrying it:
// (path relative to the copy, bytes) for katex.min.js, katex.min.css (woff2 fonts only) and
// fonts/*.woff2; empty when KaTeX is absent.
std::vector<std::pair<std::string, std::string>> katex_files();
// The <head> part of a page that uses the copy of katex_files() at `prefix` ("../katex/").
std::string html_math_head_linked(const std::string& prefix);
// The script that typesets every formula element; put it at the end of the <body>.
std::string html_math_script();
// A problem's picture on a page: its SVG as an image (its styles stay its own), captioned.
// With `with_key`, a feedback figure's picture that also draws the right answer; a figure with
// the student's answer drawn says under it which line is whose.
std::string html_figure(const Figure& figure, Lang lang = Lang::En, bool with_key = false);
// `figures`: each problem's picture by id (problem_figure.hpp), shown under its text.
std::string render_html(const SetResult& set, Lang lang = Lang::En,
                        const Figures* figures = nullptr);
// A LaTeX document (format_latex.cpp) that compiles with lualatex: for printing.
std::string render_latex(const SetResult& set, Lang lang = Lang::En,
                         const Figures* figures = nullptr);

// A number that round-trips: integral doubles become JSON integers (8, not 8.0).
nlohmann::ordered_json number_json(double v);
nlohmann::ordered_json value_json(const Value& v);  // "value"
nlohmann::ordered_json exact_json(const Value& v);  // "exact" (null when not exact)
// The steps in `lang` (titles, notes and the words inside formulas).
nlohmann::ordered_json steps_json(const std::vector<Step>& steps, Lang lang = Lang::En);
// `text` and `title` in `lang` (the set's own when it does not give that language); `texts` and
// `titles` map every language given ({"en": …, "ja": …}); `lang` is the set's own language.
nlohmann::ordered_json problem_json(const ProblemResult& p, Lang lang = Lang::En);
nlohmann::ordered_json render_json(const SetResult& set, Lang lang = Lang::En);

// JSON as text, never throwing on bytes that are not UTF-8 (they become U+FFFD): student and
// instructor text reaches many fields, and yaml-cpp can hand back such bytes (a YAML NEL as the
// single byte 0x85) even from a file whose invalid bytes were already replaced. Every JSON the
// program writes goes through this; indent −1 is compact.
template <typename Json>
std::string json_text(const Json& j, int indent = 2) {
  return j.dump(indent, ' ', false, Json::error_handler_t::replace);
}

}  // namespace frustum
