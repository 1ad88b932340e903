// Parsing a student's answer (untrusted) into a Value of the answer's kind. A format error is
// recorded with its reason, so an unparseable answer is never graded as wrong.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

struct ParsedAnswer {
  bool ok = false;
  Said error;        // why it could not be read
  std::string raw;   // the answer as the student wrote it (for reports)
  Said note;         // how it was read, when not exactly (over its work budget)
  std::string form;  // the form it was written in, where a kind has several ("equation", "list")
  Value value;
};

// `angles`: the set's unit, in which an angle answer (AnswerSpec::angle) written with a degree
// sign is given.
ParsedAnswer parse_answer(const YAML::Node& node, const AnswerSpec& spec, AngleUnit angles);

// The text of a student's answer as written (scalars as is, lists as [a, b, c]).
std::string raw_text(const YAML::Node& node);

}  // namespace frustum
