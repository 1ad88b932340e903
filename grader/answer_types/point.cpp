// A point; a homogeneous point (x, y, z, w) is right up to the scale of w.
#include <fmt/format.h>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kSameHomogeneousPoint{
    "the same homogeneous point (a positive multiple)", "同じ同次座標の点 (正の定数倍)",
    "та же точка в однородных координатах (положительное кратное)"};
constexpr Phrase kScaledSoThatW{"scaled so that w = {0}", "w = {0} となるように定数倍して",
                                "умноженный на число так, чтобы w = {0}"};

std::optional<Comparison> up_to_w(const Value& expected, const Value& got, const ComponentJudge&,
                                  const AnswerRules& r) {
  if (multiple_of(expected, got, r) == Multiple::Positive)
    return correct(say(kSameHomogeneousPoint));
  return std::nullopt;
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_components(expected, got, r, {up_to_w, false, true});
}

// Homogeneous (x, y, z, w) is right up to the scale of w: the quiz asks for the key's w.
QuizAsk quiz_ask(const AnswerSpec&, const Value& key, const Conventions&) {
  QuizAsk a = numbers_asked(key);
  if (key.numbers.size() == 4)
    a.notes.push_back(say(kScaledSoThatW, fmt::format("{}", key.numbers[3])));
  return a;
}

}  // namespace

AnswerType point_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Point;
  t.syntax = {{"homogeneous point", R"md(a vector [x, y, z, w]; right up to the scale of w)md",
               R"md(`[0, 0, -10, 10]`)md"}};
  t.read = read_vector;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kVectorSuchAs;
  t.homogeneous_copies = true;
  return t;
}

}  // namespace frustum
