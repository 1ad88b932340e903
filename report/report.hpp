// Rendering a grade report: text for a person (the derivation once per problem, each wrong
// answer pointing at its step) and the JSON of problem-format.md §3.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "grader/grade.hpp"
#include "solver/derivation/render.hpp"

namespace frustum {

// A score as a teacher writes it: at most two decimals, trailing zeros dropped (21.33, 2, 0.5).
std::string score_text(double v);
// An answer's common mistake as feedback states it, in `lang`: the misconception, then where
// the derivation goes wrong when that is known ("… (Where it goes wrong: …)").
std::string misconception_text(const AnswerGrade& a, Lang lang);
std::string render_grade_text(const GradeReport& r, const TextStyle& style);
nlohmann::ordered_json render_grade_json(const GradeReport& r);

}  // namespace frustum
