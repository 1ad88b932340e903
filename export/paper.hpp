// The paper route: exam sheets (one per student or drawn variant, each on its own pages, with
// the problem's text, givens, a figure where the kind has one, and room for each answer) and
// the answer key (each sheet's answers in exact form with decimals, and the derivation steps),
// as LaTeX documents that compile with Debian's TeX (pdflatex; LuaLaTeX with luatexja when the
// text is Japanese).
#pragma once

#include <string>
#include <vector>

#include "solver/problem/problem_set.hpp"

namespace frustum {

struct PaperSheet {
  std::string student;  // shown on the sheet ("s1234567", "seed7-0")
  ProblemSet set;       // the student's variant
};

// The problems' texts (and the key's step titles) in `lang`, the set's own where not given.
std::string exam_sheets_latex(const std::vector<PaperSheet>& sheets, const std::string& title,
                              Lang lang = Lang::En);
std::string answer_key_latex(const std::vector<PaperSheet>& sheets, const std::string& title,
                             Lang lang = Lang::En);

}  // namespace frustum
