// What a student reads an answer by where it stands alone (an exam sheet's answer line, a quiz
// question's prompt, a PrairieLearn input's label): the symbol the derivation writes for it
// (a × b, S, D_f), else the label its kind gives it ("the view matrix", in the student's
// language), else its name. The name itself stays what an answer file is keyed by.
#pragma once

#include <string>

#include "solver/problem/problem_set.hpp"

namespace frustum {

std::string answer_caption(const ProblemSpec& p, const std::string& name, Lang lang);

}  // namespace frustum
