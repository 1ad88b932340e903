// A number (a dot product, a depth, a distance): one number or exact expression.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kNumberSuchAs{"a number such as 15/2, sqrt(3)/2 or 0.25",
                               "15/2, sqrt(3)/2, 0.25 のような数",
                               "число, например 15/2, sqrt(3)/2 или 0.25"};

Said read_answer(const YAML::Node& node, const AnswerSpec&, AnswerReading& in, ParsedAnswer& p) {
  Exact v;
  if (Said error = read_number(node, in.budget, v); !error.empty()) return error;
  p.value = Value::scalar(v);
  return {};
}

}  // namespace

AnswerType scalar_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Scalar;
  t.syntax = {{"number", R"md(one number or expression)md",
               R"md(`z: 8`, `cos: "1/sqrt(3)"`, `distance: 6/7`)md"}};
  t.read = read_answer;
  t.compare = compare_number;
  t.quiz = ask_numbers;
  t.typed_hint = &kNumberSuchAs;
  return t;
}

}  // namespace frustum
