// An angle (between two vectors): one number in the set's angle unit (`angles:`); written with
// a degree sign ("66.42°") it is that many degrees whatever the unit. A quiz says the unit.
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

constexpr Phrase kAngleSuchAs{
    "an angle in the problem's unit, such as 60, or with the degree "
    "sign, such as 66.42°",
    "問題の単位での角度 (60 など), または度の記号をつけた角度 (66.42° など)",
    "угол в единицах задачи, например 60, или со знаком градуса, "
    "например 66.42°"};
constexpr Phrase kInDegrees{"in degrees", "度で", "в градусах"};
constexpr Phrase kInRadians{"in radians", "ラジアンで", "в радианах"};

Said read_answer(const YAML::Node& node, const AnswerSpec&, AnswerReading& in, ParsedAnswer& p) {
  Exact v;
  if (Said error = read_number(node, in.budget, v); !error.empty()) return error;
  // "66.42°" is read 66.42·π/180 (radians): an angle asked in degrees is that many degrees.
  if (in.angles == AngleUnit::Degrees && node.Scalar().find("°") != std::string::npos)
    v = canonical(v * 180 / GiNaC::Pi, in.budget);
  p.value = Value::scalar(v);
  return {};
}

// A number field, with the unit it is asked in.
QuizAsk quiz_ask(const AnswerSpec&, const Value& key, const Conventions& c) {
  QuizAsk a = numbers_asked(key);
  a.notes.push_back(say(c.angles == AngleUnit::Degrees ? kInDegrees : kInRadians));
  return a;
}

}  // namespace

AnswerType angle_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Angle;
  t.syntax = {
      {"angle",
       R"md(one number or expression in the set's unit (`angles:`), or with the degree sign, which is degrees in a set of either unit (`66.42°` in a set in radians is 1.159); `cos(30°)` is cos(π/6) anywhere)md",
       R"md(`angle: 60`, `angle: "66.42°"`)md"}};
  t.read = read_answer;
  t.compare = compare_number;
  t.quiz = quiz_ask;
  t.typed_hint = &kAngleSuchAs;
  return t;
}

}  // namespace frustum
