// A student's feedback as a document: Markdown (for an LMS or a repository) and one
// self-contained HTML page (inline style and script, no network), each with the verdicts, the
// answers side by side, the named mistakes and the derivation under every answer that lost
// points.
#pragma once

#include "grader/grade.hpp"
#include "solver/derivation/i18n.hpp"

#include <string>

namespace frustum {

std::string render_feedback_markdown(const GradeReport& r, Lang lang = Lang::En);
std::string render_feedback_html(const GradeReport& r, Lang lang = Lang::En);

// The problem's part of the Markdown feedback (Gradescope shows one per test).
std::string render_problem_feedback_markdown(const ProblemGrade& p, Lang lang = Lang::En);

}  // namespace frustum
