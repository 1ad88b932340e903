// What solving a problem set produces: per problem its answers and derivation, or its error.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/local_text.hpp"
#include "solver/derivation/value.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

struct ProblemResult {
  std::string id;
  std::string kind;
  LocalText text;  // placeholders filled, in every language the set gives
  Conventions conventions;
  std::vector<std::string> ask;  // answers to report, in order
  Answers answers;
  Derivation derivation;
  std::optional<Diagnostic> error;  // set instead of answers when the problem failed
};

struct SetResult {
  std::string file;
  LocalText title;
  std::string source;  // cited under the title
  std::vector<ProblemResult> problems;
  std::vector<Diagnostic> errors;  // errors of the set itself (bad YAML, no problems list)
};

}  // namespace frustum
