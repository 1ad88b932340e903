// A set of points (the pixels a triangle covers): the same rows in any order.
#include <algorithm>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedItemsGot{"expected {0} items, got {1}",
                                   "要素は {0} 個のはずですが, {1} 個です",
                                   "ожидалось элементов: {0}, получено: {1}"};
constexpr Phrase kSameItemsAnyOrder{"the same items (order does not matter)",
                                    "同じ要素 (順序は問いません)",
                                    "те же элементы (порядок не важен)"};
constexpr Phrase kPointSetAnyOrder{"a set of points is right in any order",
                                   "点の集合はどの順でも正しい",
                                   "множество точек верно в любом порядке"};

// The same rows in any order: each expected row matched by a distinct given row.
Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  const auto e = rows_of(expected), g = rows_of(got);
  if (e.size() != g.size() || (!e.empty() && expected.cols != got.cols))
    return incorrect(say(kExpectedItemsGot, e.size(), g.size()));
  // Sorted, the rows usually pair off at once (pixels are integers); otherwise each expected
  // row takes the first unused row within tolerance.
  auto se = e, sg = g;
  std::sort(se.begin(), se.end());
  std::sort(sg.begin(), sg.end());
  bool paired = true;
  for (std::size_t i = 0; i < se.size() && paired; ++i)
    paired = judge_of(numeric_value(expected, se[i]), r).all(se[i], sg[i]);
  if (paired) return correct(say(kSameItemsAnyOrder));
  std::vector<bool> used(g.size(), false);
  for (const auto& row : e) {
    const ComponentJudge judge = judge_of(numeric_value(expected, row), r);
    std::size_t j = 0;
    while (j < g.size() && (used[j] || !judge.all(row, g[j]))) ++j;
    if (j == g.size()) return incorrect();
    used[j] = true;
  }
  return correct(say(kSameItemsAnyOrder));
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kPointSetAnyOrder);
}

}  // namespace

AnswerType point_set_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::PointSet;
  t.syntax = {
      {"pixel set",
       R"md(the covered pixels [i, j] in any order, as a list of rows or one string; `none` when no pixel is covered)md",
       R"md(`pixels: [[1, 1], [1, 2]]`, `pixels: "(1, 2), (1, 1)"`)md"}};
  t.read = read_vertices;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kPointsInOrder;
  return t;
}

}  // namespace frustum
