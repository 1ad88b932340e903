// A direction (a normal): a vector right up to a positive factor.
#include <cmath>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedComponentsGot{"expected {0} components, got {1}",
                                        "成分は {0} 個のはずですが, {1} です",
                                        "ожидалось компонент: {0}, получено: {1}"};
constexpr Phrase kZeroVectorHasNoDirection{"The zero vector has no direction: it is no normal.",
                                           "零ベクトルには向きがなく, 法線になりません.",
                                           "У нулевого вектора нет направления: это не нормаль."};
constexpr Phrase kSameDirection{
    "the same direction (a normal is right up to a positive factor)",
    "同じ向き (法線は正の定数倍を除いて正しい)",
    "то же направление (нормаль верна с точностью до положительного множителя)"};
constexpr Phrase kZeroVectorNoDirection{"a zero vector has no direction",
                                        "零ベクトルには向きがない",
                                        "у нулевого вектора нет направления"};
constexpr Phrase kScaledToLength1{"scaled to length 1", "長さ 1 に正規化して",
                                  "нормированный к длине 1"};

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  if (got.numbers.size() != expected.numbers.size())
    return incorrect(say(kExpectedComponentsGot, expected.numbers.size(), got.numbers.size()));
  if (exactly_equal(expected, got)) return correct(say(kEqual));
  if (max_abs(got.numbers) == 0 && all_finite_and_faithful(got)) {
    Comparison c = incorrect(say(kZeroVectorHasNoDirection));
    c.trivial = say(kZeroVectorAnswer);
    c.no_work = true;
    return c;
  }
  const Multiple m = multiple_of(expected, got, r);
  if (m == Multiple::Positive) return correct(say(kSameDirection));
  if (m == Multiple::Negative) return incorrect(say(kPointsTheOppositeWay));
  // A vertex or another given copied as the normal.
  if (auto c = trivial_match(expected, got, judge_of(expected, r), r)) return *c;
  return incorrect();
}

// Right up to a positive factor: the quiz asks for the one of length 1.
QuizAsk quiz_ask(const AnswerSpec&, const Value& key, const Conventions&) {
  Value unit = key;
  double norm = 0;
  for (double x : unit.numbers) norm += x * x;
  norm = std::sqrt(norm);
  if (norm == 0) return refused(kZeroVectorNoDirection);
  for (double& x : unit.numbers) x /= norm;
  unit.exact.clear();
  QuizAsk a = numbers_asked(unit);
  a.notes.push_back(say(kScaledToLength1));
  return a;
}

}  // namespace

AnswerType direction_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Direction;
  t.syntax = {{"normal", R"md(a vector; right up to a positive factor)md",
               R"md(`[1, 1, -1]` or `[9, 9, -9]` or `"9(1, 1, -1)"`)md"}};
  t.read = read_vector;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kVectorSuchAs;
  t.componentwise = false;
  return t;
}

}  // namespace frustum
