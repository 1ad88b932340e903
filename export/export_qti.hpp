// Quizzes in IMS QTI 1.2 as Canvas imports them ("QTI .zip file"): imsmanifest.xml and one
// assessment per variant (Canvas makes one quiz of each; a problem with several numbers cannot
// be one item of a random question group, so variants are whole quizzes), one item per number
// or choice. Numbers are numerical_question items whose
// accepted range is the window `frustum grade` accepts; words are multiple_choice_question;
// bit strings short_answer_question. Answers no QTI item can check (planes, polygons, label
// sets) are listed in the question text's note and left to `frustum grade`.
#pragma once

#include <map>
#include <string>

#include "export/quiz_items.hpp"

namespace frustum {

// File name → contents: "imsmanifest.xml" and "<ident>[-<variant>].xml" per variant. `ident`
// (letters, digits, '-', '_') names the assessments.
// `lang`: the notes the platform's rules need (what is not asked here; Canvas's own credit
// rule for multiple answers, and per-number credit), in the students' language.
std::map<std::string, std::string> export_qti(const std::vector<QuizVariant>& variants,
                                              const std::string& title, const std::string& ident,
                                              Lang lang = Lang::En);

}  // namespace frustum
