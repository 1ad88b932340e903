// Quizzes in IMS QTI 1.2 as Canvas imports them ("QTI .zip file"): imsmanifest.xml and one
// assessment, one item per problem. With several variants each problem is a question group
// holding its item from every variant, from which Canvas draws one for each student (each
// student gets their own variant through Canvas's randomisation). A problem with one field
// keeps Canvas's own type for it: a number is a numerical_question whose accepted range is
// the window `frustum grade` accepts, a word a multiple_choice_question, a bit string a
// short_answer_question, the true statements a multiple_answers_question. A problem with
// several fields (a vector, a matrix, several answers) is one fill_in_multiple_blanks_question:
// Canvas compares each blank's text (trimmed, lower-cased) with a list, so each number is asked
// rounded to the fewest decimals (at least 2) that stay inside the grader's window, and the list
// holds that rounding and up to two more places, with or without trailing zeros. Answers no QTI
// item can check (planes, polygons, label sets) are listed in the question text's note and
// left to `frustum grade`.
#pragma once

#include <map>
#include <string>

#include "export/quiz_items.hpp"

namespace frustum {

// File name → contents: "imsmanifest.xml" and "<ident>.xml". `ident` (letters, digits, '-',
// '_') names the assessment.
// `lang`: the notes the platform's rules need (what is not asked here; Canvas's own credit
// rule for multiple answers, and per-number credit), in the students' language.
std::map<std::string, std::string> export_qti(const std::vector<QuizVariant>& variants,
                                              const std::string& title, const std::string& ident,
                                              Lang lang = Lang::En);

// What Canvas accepts in one blank of a fill-in-multiple-blanks item, and the hint beside it
// ("to 3 decimal places", "one of: front, back").
struct CanvasBlank {
  std::vector<std::string> texts;
  std::string hint;
  int places = 2;  // a number's decimals asked for
};
CanvasBlank canvas_blank(const QuizField& f, Lang lang = Lang::En);

}  // namespace frustum
