// The language of derivations and feedback. Text is said in all three languages where it is
// written (`Phrase`, `Said`: solver/util/said.hpp) and a formatter picks the reader's; this
// file names the languages and puts the words written inside mathematics (MathText::words)
// into one of them. Formulas and values are never translated.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "solver/derivation/math_text.hpp"
#include "solver/util/said.hpp"

namespace frustum {

std::optional<Lang> parse_lang(std::string_view code);  // "en", "ja", "ru"
std::string_view to_string(Lang lang);

// Mathematics in `lang`: its words (MathText::words, \text{…} in the LaTeX) translated, the
// formulas themselves unchanged.
MathText tr(const MathText& m, Lang lang);

// Which of its three forms a Russian word takes after the whole number n: one (1, 21, 31 …),
// few (2–4, 22–24 …) or many (0, 5–20, 25–30 …; 11–14 always).
enum class RuForm { One, Few, Many };
RuForm russian_form(long n);

}  // namespace frustum
