// A mapping from a face or an edge to a word (front/back; visible/silhouette/hidden): credit per
// entry.
#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"
#include "grader/list_items.hpp"
#include "solver/derivation/vocabulary.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedMapping{"expected a mapping like {0}", "{0} のような対応付けが必要です",
                                  "ожидалось сопоставление вида {0}"};
constexpr Phrase kValueNotWord{"the value of '{0}' is not a word", "`{0}` の値は語ではありません",
                               "значение `{0}` — не слово"};
constexpr Phrase kEntryTwiceSameWord{"an entry written twice with the same word counts once",
                                     "同じ語で二度書いた項目は一度と数える",
                                     "элемент, записанный дважды одним словом, считается один раз"};
constexpr Phrase kEntriesRightBeyondConstant{
    "{0} of {1} entries right; answering \"{2}\" everywhere would get {3}, so the credit counts "
    "the entries beyond that.",
    "{1} 個中 {0} 個が正しい. どこにも「{2}」と答えると {3} 個になるので, "
    "得点はそれを超えた分だけ数える.",
    "верно {0} из {1}; ответ «{2}» везде дал бы {3}, поэтому засчитываются только элементы сверх "
    "этого."};
constexpr Phrase kEntriesRightNoMoreThanConstant{
    "{0} of {1} entries right, no more than one word written everywhere would get.",
    "{1} 個中 {0} 個が正しいが, どこにも同じ一語を書いた場合を超えていない.",
    "верно {0} из {1}, не больше, чем дало бы одно слово, написанное везде."};
constexpr Phrase kEntryTwiceDifferentWords{
    "{0} entry is written twice with different words: neither word counts as right.",
    "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
    "{0} элемент записан дважды разными словами: ни одно из слов не засчитывается."};
constexpr Phrase kEntriesTwiceDifferentWords{
    "{0} entries are written twice with different words: neither word counts as right.",
    "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
    "Записано дважды разными словами элементов: {0}; ни одно из этих слов не засчитывается."};
constexpr Phrase kEntryNamesNoSuchFace{
    "{0} entry names a face the problem does not have; it counts as a wrong entry.",
    "{0} 個の項目は問題にない面を指しています. 誤った項目として数えます.",
    "{0} элемент называет грань, которой нет в задаче; он считается неверным."};
constexpr Phrase kEntryNamesNoSuchEdge{
    "{0} entry names an edge the problem does not have; it counts as a wrong entry.",
    "{0} 個の項目は問題にない稜線を指しています. 誤った項目として数えます.",
    "{0} элемент называет ребро, которого нет в задаче; он считается неверным."};
constexpr Phrase kEntriesNameNoSuchFaces{
    "{0} entries name faces the problem does not have; each counts as a wrong entry.",
    "{0} 個の項目は問題にない面を指しています. それぞれ誤った項目として数えます.",
    "Элементов с гранями, которых нет в задаче: {0}; каждый считается неверным."};
constexpr Phrase kEntriesNameNoSuchEdges{
    "{0} entries name edges the problem does not have; each counts as a wrong entry.",
    "{0} 個の項目は問題にない稜線を指しています. それぞれ誤った項目として数えます.",
    "Элементов с рёбрами, которых нет в задаче: {0}; каждый считается неверным."};
constexpr Phrase kMappingSuchAs{"a mapping such as {0-1: visible, 1-2: hidden}",
                                "{0-1: visible, 1-2: hidden} のような対応",
                                "соответствие, например {0-1: visible, 1-2: hidden}"};

// The words a word map's entries may take (faces, edges).
const std::vector<std::string> kMapWords = {"front",   "back",   "edge_on",
                                            "visible", "hidden", "silhouette"};

Said read_answer(const YAML::Node& node, const AnswerSpec& spec, AnswerReading&, ParsedAnswer& p) {
  if (!node.IsMap()) {
    // The example in this answer's own terms: a face or an edge, and one of its words.
    const Said example =
        Said::verbatim(fmt::format("{{\"{}\": ", spec.unordered_pairs ? "0-1" : "0"))
            .append(word_said(spec.words.empty() ? "visible" : spec.words.front()))
            .append(Said::verbatim("}"));
    return say(kExpectedMapping, example);
  }
  std::vector<std::pair<std::string, std::string>> entries;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (!it->second.IsScalar()) return say(kValueNotWord, it->first.as<std::string>());
    entries.emplace_back(it->first.as<std::string>(), known_word(it->second.Scalar(), kMapWords));
  }
  p.value = Value::word_map(entries);
  return {};
}

// A word map's keys ("1-0": an edge) in the key's spelling when they are unordered pairs.
Value keys_read(const Value& got, const Value& expected, const AnswerRules& r) {
  if (!r.spec->unordered_pairs) return got;
  std::vector<std::string> keys;
  for (const auto& [k, w] : expected.entries) keys.push_back(k);
  Value out = got;
  for (auto& [k, w] : out.entries) k = pair_as_in_key(k, keys);
  return out;
}

// Word maps (faces, edges): credit per entry, corrected for the best constant answer ("every
// face front"), which shows no work. An entry of the key is right when the student wrote it and
// every copy of it says its word: written twice with the same word it counts once, with two
// words neither is chosen. An entry the key does not have (a face or an edge the problem does
// not have) counts as a wrong one, so a wrong answer never earns full points.
Comparison compare_word_map(const Value& expected, const Value& got, const AnswerRules& r) {
  const std::size_t n = expected.entries.size();
  std::size_t right = 0, undecided = 0;
  for (const auto& entry : expected.entries) {  // (clang 14 cannot capture a structured binding)
    bool said = false, other = false;
    for (const auto& e : got.entries)
      if (e.first == entry.first) (e.second == entry.second ? said : other) = true;
    right += said && !other;
    undecided += said && other;
  }
  std::set<std::string> extra;
  for (const auto& entry : got.entries)
    if (std::none_of(expected.entries.begin(), expected.entries.end(),
                     [&](const auto& e) { return e.first == entry.first; }))
      extra.insert(entry.first);
  if (right == n && extra.empty())
    return correct(got.entries.size() > n ? say(kEntryTwiceSameWord) : Said());
  std::size_t best_constant = 0;
  std::string best_word;
  for (const auto& [k, w] : expected.entries) {
    std::size_t same = 0;
    for (const auto& [k2, w2] : expected.entries) same += w2 == w;
    if (same > best_constant) {
      best_constant = same;
      best_word = w;
    }
  }
  // What else was counted, each a sentence of its own.
  Said notes;
  if (undecided > 0)
    notes +=
        say(undecided == 1 ? kEntryTwiceDifferentWords : kEntriesTwiceDifferentWords, undecided);
  if (!extra.empty()) {
    const bool one = extra.size() == 1, edges = r.spec->unordered_pairs;
    notes += say(one ? (edges ? kEntryNamesNoSuchEdge : kEntryNamesNoSuchFace)
                     : (edges ? kEntriesNameNoSuchEdges : kEntriesNameNoSuchFaces),
                 extra.size());
  }
  const std::size_t total = n + extra.size();
  if (right > best_constant && total > best_constant)
    return {Verdict::Partial,
            static_cast<double>(right - best_constant) / static_cast<double>(total - best_constant),
            say(kEntriesRightBeyondConstant, right, total, words::vocabulary_word(best_word),
                best_constant) +
                notes,
            {},
            false,
            {}};
  if (right == 0) return incorrect(notes);
  return incorrect(say(kEntriesRightNoMoreThanConstant, right, total) + notes);
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_word_map(expected, keys_read(got, expected, r), r);
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kLabelSetAnyOrder);
}

}  // namespace

AnswerType word_map_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::WordMap;
  t.syntax = {
      {"word map",
       R"md(a mapping from a face number or an edge `i-j` to a word: `front`/`back` for faces, `visible`/`silhouette`/`hidden` for edges (表/裏, 可視/輪郭線/不可視); an edge either way round (`1-0` is `0-1`); an entry written twice with the same word counts once, with two words neither counts; an entry the problem does not have counts as a wrong one)md",
       R"md(`faces: {"0": front, "1": back}`, `edges: {0-1: visible, 1-2: hidden}`)md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kMappingSuchAs;
  t.numeric = false;
  return t;
}

}  // namespace frustum
