// Answers that take no work (docs/grading.md §4): the zero vector or matrix, the identity, a
// list copied from the given, the transposed key. A component that one of them also gets
// right earns no partial credit, and an answer that is one of them as a whole is named.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"
#include "solver/util/said.hpp"

namespace frustum {

// Two trivial answers the grader names when it says why nothing is carried forward from them.
inline constexpr Phrase kZeroVectorAnswer{"zero vector", "零ベクトル", "нулевой вектор"};
inline constexpr Phrase kCopiedFromTheGiven{"copied from the given", "問題の値の写し",
                                            "скопировано из условия"};

struct TrivialAnswer {
  Said name;      // "identity matrix" (a misconception name)
  Said feedback;  // what it is, for the student
  Value value;
  // Zero, the identity, a copy of the given: written without any work, so nothing is carried
  // forward from it. The transposed key is a convention mistake made with the whole
  // computation: trivial for component credit, but what follows from it follows from work.
  bool no_work = true;
};

// Every list of numbers in a problem's `given`, by field path ("points", "camera.eye"); a
// list of lists is one matrix (rows). Items that are not numbers are left out.
struct GivenList {
  std::string field;
  Value value;
  // Zero, the identity, a copy of the given: written without any work, so nothing is carried
  // forward from it. The transposed key is a convention mistake made with the whole
  // computation: trivial for component credit, but what follows from it follows from work.
  bool no_work = true;
};
std::vector<GivenList> given_lists(const YAML::Node& given);

// The trivial answers of the shape of `key` (none for scalars and word answers); those equal
// to the key are left out — a key that is trivial is simply right.
std::vector<TrivialAnswer> trivial_answers(const Value& key, AnswerKind kind,
                                           const std::vector<GivenList>& given, Api api);

}  // namespace frustum
