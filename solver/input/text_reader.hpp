// Reading what an instructor writes for students (local_text.hpp): a plain string, in the set's
// own language, or a mapping by language {en: …, ja: …, ru: …} that must give the set's own.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <string>

#include "solver/derivation/local_text.hpp"

namespace frustum {

// Throws InputError at the offending node: not text, an unknown language key (`text.de`), a
// mapping without the set's own language, or (max_bytes > 0) a text longer than max_bytes.
LocalText read_local_text(const YAML::Node& n, const std::string& file, const std::string& field,
                          Lang own, std::size_t max_bytes = 0);

// The node of the text in `lang` (the own text's when that language is not given): for
// placeholders' and errors' locations.
YAML::Node local_text_node(const YAML::Node& n, Lang lang, Lang own);

}  // namespace frustum
