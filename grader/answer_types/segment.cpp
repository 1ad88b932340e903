// A segment: its two endpoints (rows), in either order.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kSameSegmentOtherOrder{"the same segment, its endpoints in the other order",
                                        "同じ線分 (端点の順序が逆)",
                                        "тот же отрезок, концы в другом порядке"};
constexpr Phrase kSegmentEitherDirection{"a segment is right in either direction",
                                         "線分はどちらの向きでも正しい",
                                         "отрезок верен в обоих направлениях"};

std::optional<Comparison> reversed(const Value& expected, const Value& got,
                                   const ComponentJudge& judge, const AnswerRules&) {
  const auto g = rows_of(got);
  std::vector<double> other;
  for (auto it = g.rbegin(); it != g.rend(); ++it)
    other.insert(other.end(), it->begin(), it->end());
  if (judge.all(expected.numbers, other)) return correct(say(kSameSegmentOtherOrder));
  return std::nullopt;
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_components(expected, got, r, {reversed, false, false});
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kSegmentEitherDirection);
}

}  // namespace

AnswerType segment_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Segment;
  t.syntax = {{"segment",
               R"md(its two ends, in either order, as a list of two points or one string)md",
               R"md(`clipped: [[3, 4], [2, 5/2]]`, `clipped: "(2, 5/2), (3, 4)"`)md"}};
  t.read = read_vertices;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kPointsInOrder;
  return t;
}

}  // namespace frustum
