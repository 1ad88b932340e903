// A polygon: its vertex list, right from any starting vertex in the same cyclic order.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedVerticesGot{"expected {0} vertices, got {1}",
                                      "頂点は {0} 個のはずですが, {1} 個です",
                                      "ожидалось вершин: {0}, получено: {1}"};
constexpr Phrase kSamePolygonOtherStart{"the same polygon, starting at another vertex",
                                        "同じ多角形 (別の頂点から始まる)",
                                        "тот же многоугольник, начиная с другой вершины"};
constexpr Phrase kRightVerticesOppositeOrder{
    "the right vertices in the opposite order: the orientation decides which side is the front",
    "頂点は正しいが順序が逆です. 向きがどちらの側が表かを決めます",
    "верные вершины в обратном порядке: ориентация решает, какая сторона лицевая"};
constexpr Phrase kPolygonAnyStart{"a polygon is right from any starting vertex",
                                  "多角形はどの頂点から始めても正しい",
                                  "многоугольник верен при любой начальной вершине"};

// The same vertex cycle, starting anywhere (orientation must match).
Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  const auto e = rows_of(expected), g = rows_of(got);
  if (e.size() != g.size() || e.empty())
    return incorrect(say(kExpectedVerticesGot, e.size(), g.size()));
  const auto cycle_matches = [&](bool reversed) -> std::optional<std::size_t> {
    for (std::size_t shift = 0; shift < e.size(); ++shift) {
      bool all = true;
      for (std::size_t i = 0; i < e.size() && all; ++i) {
        const std::size_t j = reversed ? (shift + e.size() - i) % e.size() : (i + shift) % e.size();
        all = judge_of(numeric_value(expected, e[i]), r).all(e[i], g[j]);
      }
      if (all) return shift;
    }
    return std::nullopt;
  };
  if (const auto shift = cycle_matches(false))
    return correct(say(*shift ? kSamePolygonOtherStart : kEqual));
  if (cycle_matches(true)) return incorrect(say(kRightVerticesOppositeOrder));
  return incorrect();
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kPolygonAnyStart);
}

}  // namespace

AnswerType polygon_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Polygon;
  t.syntax = {
      {"polygon",
       R"md(a list of vertices; right from any starting vertex, in the same cyclic order)md",
       R"md(`[[9/2, 1], [4, 2], [5, 9/2], [5, 1]]`)md"}};
  t.read = read_vertices;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kPointsInOrder;
  return t;
}

}  // namespace frustum
