// An unordered set of words (edge lists, conflicts): credit per item.
#include <algorithm>
#include <iterator>
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

constexpr Phrase kSameSetAnyOrder{"the same set (order does not matter)",
                                  "同じ集合 (順序は問いません)",
                                  "то же множество (порядок не важен)"};
constexpr Phrase kExpectedItemsAndExtra{
    "{0} of the {1} expected items, and {2} that should not be there",
    "期待される {1} 個のうち {0} 個, および余分なもの {2} 個",
    "{0} из {1} ожидаемых элементов и {2} лишних"};
constexpr Phrase kExpectedItemsExtraAndCopies{
    "{0} of the {1} expected items, and {2} that should not be there, {3} of them a second copy of "
    "an item (an item written twice is right once; the copy counts as one that should not be "
    "there)",
    "期待される {1} 個のうち {0} 個, および余分なもの {2} 個 (うち {3} 個は同じ項目の二度目: "
    "二度書いた項目は一度だけ正解とし, 二度目は余分なものと数える)",
    "{0} из {1} ожидаемых элементов и {2} лишних, из них {3} — повтор элемента (элемент, "
    "записанный дважды, верен один раз; повтор считается лишним)"};
constexpr Phrase kListSuchAs{"a list such as [1-3, 2-7]", "[1-3, 2-7] のようなリスト",
                             "список, например [1-3, 2-7]"};

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  const std::vector<std::string> items = items_read(got, expected, r);
  if (auto c = unreadable_list(items, expected, r)) return *c;
  std::vector<std::string> a = folded(expected.words, expected.words),
                           b = folded(items, expected.words);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  if (a == b) return correct(say(kSameSetAnyOrder));
  // An item written twice is right once; its second copy counts as one that should not be
  // there (common / max(expected, given)).
  std::vector<std::string> both;
  std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
  const std::size_t common = both.size();
  const std::size_t copies = b.size() - static_cast<std::size_t>(std::distance(
                                            b.begin(), std::unique(b.begin(), b.end())));
  const Said counted =
      copies == 0 ? say(kExpectedItemsAndExtra, common, a.size(), b.size() - common)
                  : say(kExpectedItemsExtraAndCopies, common, a.size(), b.size() - common, copies);
  if (common > 0 && !a.empty())
    return {Verdict::Partial,
            static_cast<double>(common) / static_cast<double>(std::max(a.size(), b.size())),
            counted,
            {},
            false,
            {}};
  return incorrect(copies == 0 ? Said() : counted);
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kLabelSetAnyOrder);
}

}  // namespace

AnswerType word_list_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::WordList;
  t.syntax = {
      {"word set",
       R"md(a list (any order) or one string of items separated by commas, semicolons, slashes or spaces; a pair (an edge, two polygons in conflict) either way round, with any dash or as `(i, j)` or `[i, j]`; partial credit per item: right items / max(expected, written), so an item written twice is right once and its second copy counts as an item that should not be there (`[1-2, 1-3, 2-3, 2-3]` earns 3/4))md",
       R"md(`hidden: [1-3, 2-7]`, `hidden: "3-1, 7-2"`, `conflicts: "(1, 0)"`)md"}};
  t.read = read_words;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kListSuchAs;
  t.numeric = false;
  return t;
}

}  // namespace frustum
