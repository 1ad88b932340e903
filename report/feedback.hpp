// A student's feedback as a document: Markdown (for an LMS or a repository) and one
// self-contained HTML page (inline style and script, no network), each with the verdicts, the
// answers side by side, the named mistakes and the derivation under every answer that lost
// points.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "grader/grade.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum {

std::string render_feedback_markdown(const GradeReport& r, Lang lang = Lang::En);
// The same with each problem's part already made (problem_feedback_markdown(r, lang)): a batch
// makes the parts once for the page and for Gradescope's results.
std::string render_feedback_markdown(const GradeReport& r, Lang lang,
                                     const std::vector<std::string>& problem_markdown);
std::string render_feedback_html(const GradeReport& r, Lang lang = Lang::En);
// The same page with `math_head` in its head: html_math_head() (KaTeX with its fonts inlined,
// ~0.7 MB) for a page on its own, or html_math_head_linked() for the pages of a batch, which
// link one shared copy written beside them.
std::string render_feedback_html(const GradeReport& r, Lang lang, const std::string& math_head);
// With each problem's picture (problem_figure.hpp, of the set the student was graded against)
// under its heading; a picture that shows answers only where the key is shown.
std::string render_feedback_html(const GradeReport& r, Lang lang, const std::string& math_head,
                                 const Figures* figures);

// The pictures of a student's feedback page, graded against `set` (the student's variant):
// each problem's picture, with the student's own answer drawn in where it can be (a clipped
// segment or polygon; feedback_figures in problem_figure.hpp).
Figures student_figures(const ProblemSet& set, const GradeReport& r, Lang lang);

// One problem's part of that page (a <section>); without the key (the expected answers and
// the derivations) where the platform shows the key by its own policy, with formulas for the
// page's own KaTeX or for its host's MathJax.
std::string render_problem_feedback_html(const ProblemGrade& p, Lang lang, bool with_key = true,
                                         MathMarkup markup = MathMarkup::KaTeX,
                                         const Figure* figure = nullptr);

// Untrusted text (a student id, an answer as written, a message quoting it) as Markdown that
// shows it literally: HTML is written as entities (<img onerror=…> stays text in every
// renderer), the characters that make emphasis, links, images, code and table cells
// (\ ` * _ [ ] |) are backslash-escaped, as is a leading # - + >, control characters are
// dropped and line breaks become spaces.
std::string markdown_escape(std::string_view text);
// The same for the inside of a `code span`: backticks, which would end it, become ʼ.
std::string markdown_code(std::string_view text);

// The problem's part of the Markdown feedback (Gradescope shows one per test).
std::string render_problem_feedback_markdown(const ProblemGrade& p, Lang lang = Lang::En);
// render_problem_feedback_markdown of each problem of the report, in order.
std::vector<std::string> problem_feedback_markdown(const GradeReport& r, Lang lang);

}  // namespace frustum
