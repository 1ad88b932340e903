// Questions in Moodle XML (Question bank → Import → Moodle XML format): one embedded-answers
// (Cloze) question per problem and variant, each problem's variants in a category of its own
// (CATEGORY/PROBLEM-ID) so a quiz's "random question" from it gives each student a variant; with a
// NUMERICAL field per number whose tolerance is the window `frustum grade` accepts, MULTICHOICE for
// words and SHORTANSWER for bit strings. Answers no Cloze field can check (planes, polygons, label
// sets) are named in the question text and left to `frustum grade`.
#pragma once

#include <string>
#include <vector>

#include "export/quiz_items.hpp"

namespace frustum {

// Past this common denominator of the fields' shares, weights are hundredths of a point.
inline constexpr long long kMaxClozeScale = 1000000;

// The Cloze weight of each field of `q`, in order. Moodle ignores <defaultgrade> for Cloze and
// marks the question out of the sum of its weights (whole numbers), so: an answer's points split
// equally over its fields, as the points themselves when they split into whole numbers (a
// 4-point problem is marked out of 4), else the smallest whole numbers in the same proportion
// (the quiz's maximum mark for the question then gives Frustum's weight).
std::vector<long long> cloze_weights(const QuizQuestion& q);

std::string export_moodle(const std::vector<QuizVariant>& variants, const std::string& category,
                          Lang lang = Lang::En);

}  // namespace frustum
