// The answer to "which of these statements are true?" (AnswerKind::Statements). A student may
// write the numbers of the true statements ([1, 3], "1, 3", 1; [] or none for none; order and
// repeats do not matter), one truth per statement ([true, false, false, false], ○×××, はい/いいえ,
// да/нет), or a mapping {1: true, 2: false, …} (the form of the answer keys Frustum writes).
// Each statement is part of the mark, as Moodle scores a multiple-answer question: every true
// statement chosen earns 1/T of the points and every false one chosen costs 1/F (T true and F
// false statements), never below 0 — so no constant answer ("none", "all") earns anything.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "grader/compare.hpp"
#include "solver/derivation/value.hpp"
#include "solver/util/said.hpp"

namespace frustum {

// The student's answer read without knowing how many statements there are (compare checks the
// numbers against them): the numbers as a word list, truths and mappings as a word map from
// statement number to "true"/"false". An error says why the answer cannot be read.
struct StatementChoice {
  Value value;
  Said error;  // for the student
};
StatementChoice read_statement_choice(const YAML::Node& node);

// Judges `got` (as read above, or null for "none") against the key (a word map 1..n → truth).
Comparison compare_statement_choice(const Value& expected, const Value& got);

}  // namespace frustum
