// What a LaTeX formula would show a reader wrongly: characters that TeX and KaTeX have no math
// metrics for (Unicode operators such as − · ‖ ≤, which belong in the Unicode form), and words
// set in math italic (outcode read as o·u·t·c·o·d·e), which belong in \text{} or \mathrm{}.
// The derivation tests run it over every formula of every kind.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace frustum {

// One sentence per problem found (empty when the formula is clean). Letters inside \text{},
// \mathrm{}, \mathbf{} (upright names), \operatorname{}, \overrightarrow{} (point names) and
// environment names are words by intent; outside them a run of
// two or more letters is a word, except the products a formula writes without a sign
// (2fn, xy(1 − c)) and two or three capitals naming points (E_{AB}, OA).
std::vector<std::string> latex_problems(std::string_view latex);

}  // namespace frustum
