// Gradescope's autograder results (results.json): one test per problem, with its score,
// max_score, status, Markdown output and visibility, and the total.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grader/grade.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum {

nlohmann::ordered_json gradescope_results(const GradeReport& r, Lang lang = Lang::En);
// The same with each problem's Markdown already made (problem_feedback_markdown(r, lang)).
nlohmann::ordered_json gradescope_results(const GradeReport& r,
                                          const std::vector<std::string>& problem_markdown);

// For a submission that could not be graded at all: score 0, the reason in the output.
nlohmann::ordered_json gradescope_failure(const std::string& reason);

}  // namespace frustum
