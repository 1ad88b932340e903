// The language of derivations and feedback. Steps are recorded in English; a renderer asked
// for Japanese translates titles and fixed phrases through one catalogue (i18n.cpp), so the
// kinds never format for a language. Mathematics (formulas, values) is never translated.
#pragma once

#include "solver/derivation/math_text.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace frustum {

enum class Lang { En, Ja };

std::optional<Lang> parse_lang(std::string_view code);  // "en", "ja"
std::string_view to_string(Lang lang);

// A step title, note or interface phrase in `lang`: a whole-text match first, then the known
// phrases inside it (longest first); text the catalogue does not know stays as written.
std::string tr(std::string_view english, Lang lang);
// Mathematics in `lang`: its words (MathText::words, \text{…} in the LaTeX) translated, the
// formulas themselves unchanged.
MathText tr(const MathText& m, Lang lang);

}  // namespace frustum
