// Rendering a grade report: text for a person (with the derivation under each wrong answer)
// and the JSON of problem-format.md §3.
#pragma once

#include "grader/grade.hpp"
#include "solver/derivation/render.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace frustum {

std::string render_grade_text(const GradeReport& r, const TextStyle& style);
nlohmann::ordered_json render_grade_json(const GradeReport& r);

}  // namespace frustum
