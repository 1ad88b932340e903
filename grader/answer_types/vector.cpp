// A vector, judged component by component.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_components(expected, got, r, {nullptr, true, false});
}

}  // namespace

AnswerType vector_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Vector;
  t.syntax = {
      {"vector",
       R"md(a list, or a string of comma-separated numbers with optional parentheses; also a number times such a tuple, as the lectures write a unit normal (a vector, normal, unit vector or homogeneous point alike))md",
       R"md(`[1, 1, -1]`, `"(1, 1, −1)"`, `"(1/√21)(−2, 1, 4)"`, `"(-2, 1, 4)/sqrt(21)"`)md"}};
  t.read = read_vector;
  t.compare = compare_with_key;
  t.quiz = ask_numbers;
  t.typed_hint = &kVectorSuchAs;
  t.homogeneous_copies = true;
  return t;
}

}  // namespace frustum
