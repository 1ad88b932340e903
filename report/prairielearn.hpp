// PrairieLearn's external-grading results (/grade/results/results.json): score in [0, 1], one
// test per problem with points, max_points, a message and Markdown output. An answer that
// could not be read makes the submission "not gradable" (PrairieLearn then neither charges an
// attempt nor records a score) with the reasons in format_errors, as PrairieLearn's own
// elements do for malformed input.
#pragma once

#include <nlohmann/json.hpp>

#include "grader/grade.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum {

nlohmann::ordered_json prairielearn_results(const GradeReport& r, Lang lang = Lang::En);

}  // namespace frustum
