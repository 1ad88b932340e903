// The language of derivations and feedback. Steps are recorded in English; a renderer asked
// for Japanese or Russian translates titles, notes and fixed phrases through one catalogue
// (phrases_*.cpp), so the kinds never format for a language. Mathematics (formulas, values)
// is never translated; the words written inside it are (MathText::words).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "solver/derivation/math_text.hpp"
#include "solver/util/said.hpp"

namespace frustum {

std::optional<Lang> parse_lang(std::string_view code);  // "en", "ja", "ru"
std::string_view to_string(Lang lang);

// A step title, note or interface phrase in `lang`: a whole-text match first, then a pattern
// whose {0}, {1} … stand for values or names ("Clip against {0}"), then sentence by sentence,
// and inside a sentence the known phrases (longest first); text the catalogue does not know
// stays as written (the language test fails on it).
std::string tr(std::string_view english, Lang lang);
// Mathematics in `lang`: its words (MathText::words, \text{…} in the LaTeX) translated, the
// formulas themselves unchanged.
MathText tr(const MathText& m, Lang lang);

// Which of its three forms a Russian word takes after the whole number n: one (1, 21, 31 …),
// few (2–4, 22–24 …) or many (0, 5–20, 25–30 …; 11–14 always).
enum class RuForm { One, Few, Many };
RuForm russian_form(long n);

}  // namespace frustum
