// Questions in Moodle XML (Question bank → Import → Moodle XML format): one embedded-answers
// (Cloze) question per problem and variant, each problem's variants in a category of its own
// (CATEGORY/PROBLEM-ID) so a quiz's "random question" from it gives each student a variant; with a
// NUMERICAL field per number whose tolerance is the window `frustum grade` accepts, MULTICHOICE for
// words and SHORTANSWER for bit strings. Answers no Cloze field can check (planes, polygons, label
// sets) are named in the question text and left to `frustum grade`.
#pragma once

#include <string>

#include "export/quiz_items.hpp"

namespace frustum {

std::string export_moodle(const std::vector<QuizVariant>& variants, const std::string& category);

}  // namespace frustum
