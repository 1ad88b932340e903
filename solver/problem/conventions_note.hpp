// The sentence that opens a derivation with the conventions it is solved in, in every language.
#pragma once

#include "solver/util/said.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

// The title of the derivation's step that states the conventions (conventions_note).
inline constexpr Phrase kConventionsTitle{"Conventions", "規約", "Соглашения"};

// One sentence naming the conventions `use` marks, for the first step of a derivation, in each
// language; empty when none of them matters.
Said conventions_note(const Conventions& c, ConventionUse use = {});

}  // namespace frustum
