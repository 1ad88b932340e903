// A number (a dot product, a depth, an angle): one number or exact expression.
#include <string>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedOneNumber{"expected one number", "数が一つ必要です",
                                    "ожидалось одно число"};
constexpr Phrase kNumberSuchAs{"a number such as 15/2, sqrt(3)/2 or 0.25",
                               "15/2, sqrt(3)/2, 0.25 のような数",
                               "число, например 15/2, sqrt(3)/2 или 0.25"};

Said read_answer(const YAML::Node& node, const AnswerSpec& spec, AnswerReading& in,
                 ParsedAnswer& p) {
  if (!node.IsScalar()) return say(kExpectedOneNumber);
  Said error;
  Exact v = parse_one(node.Scalar(), error, in.budget);
  if (!error.empty()) return error;
  // "66.42°" read 66.42·π/180: an angle asked in degrees is that many degrees.
  if (spec.angle && in.angles == AngleUnit::Degrees && node.Scalar().find("°") != std::string::npos)
    v = canonical(v * 180 / GiNaC::Pi, in.budget);
  p.value = Value::scalar(v);
  return {};
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  if (got.numbers.size() != 1 || expected.numbers.size() != 1)
    return incorrect(say(kExpectedOneNumber));
  if (exactly_equal(expected, got)) return correct(say(kExactlyEqual));
  if (judge_of(expected, r).ok(0, expected.numbers[0], got.numbers[0]))
    return correct(say(kWithinTolerance));
  return incorrect();
}

QuizAsk quiz_ask(const AnswerSpec&, const Value& key) { return numbers_asked(key); }

}  // namespace

AnswerType scalar_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Scalar;
  t.syntax = {
      {"number",
       R"md(one number or expression; an angle in the set's unit, or with the degree sign)md",
       R"md(`z: 8`, `cos: "1/sqrt(3)"`, `angle: 60`, `angle: "66.42°"`)md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kNumberSuchAs;
  return t;
}

}  // namespace frustum
