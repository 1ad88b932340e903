// An ordered list of words (a drawing order, z-buffer rows).
#include <algorithm>
#include <string>
#include <vector>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kRightItemsWrongOrder{"the right items in the wrong order",
                                       "要素は正しいが順序が違います",
                                       "верные элементы в неверном порядке"};
constexpr Phrase kLabelOrderNoField{"an order of labels has no quiz field",
                                    "ラベルの順序を問う欄はない",
                                    "для порядка меток нет поля теста"};
constexpr Phrase kListInOrder{"a list in order, such as [2, 0, 1]",
                              "[2, 0, 1] のように順に並べたリスト",
                              "список по порядку, например [2, 0, 1]"};

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  const std::vector<std::string> items = items_read(got, expected, r);
  if (auto c = unreadable_list(items, expected, r)) return *c;
  const std::vector<std::string> a = folded(expected.words, expected.words),
                                 b = folded(items, expected.words);
  if (a == b) return correct();
  std::vector<std::string> sa = a, sb = b;
  std::sort(sa.begin(), sa.end());
  std::sort(sb.begin(), sb.end());
  return incorrect(sa == sb ? say(kRightItemsWrongOrder) : Said());
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kLabelOrderNoField);
}

}  // namespace

AnswerType sequence_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Sequence;
  t.syntax = {
      {"sequence",
       R"md(a list, in order, or one string of items separated by arrows (`→`, `->`, `⇒`), commas, semicolons, slashes or spaces (a separator that the items themselves hold, like the `/` inside a z-buffer step, separates nothing): polygons back to front; z-buffer rows top first, one character per pixel (`.` background))md",
       R"md(`order: ["1", "0"]`, `order: "1 → 0"`, `frame: ["..11", "22.."]`, `frame: "..11/22.."`)md"}};
  t.read = read_words;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kListInOrder;
  t.numeric = false;
  return t;
}

}  // namespace frustum
