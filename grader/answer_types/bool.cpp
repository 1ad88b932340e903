// True or false (inside, accept): yes/no and the answer's own pair of words, in any language.
#include <algorithm>
#include <string>
#include <utility>
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

constexpr Phrase kExpectedTrueOrFalse{"expected true or false", "true か false が必要です",
                                      "ожидалось true или false"};
constexpr Phrase kNotTrueOrFalse{"'{0}' is not true or false", "`{0}` は 真 でも 偽 でもありません",
                                 "`{0}` — не истина и не ложь"};
constexpr Phrase kNotTrueOrFalseOr{"'{0}' is not true or false (or {1} or {2})",
                                   "`{0}` は 真 でも 偽 でも ({1} でも {2} でも) ありません",
                                   "`{0}` — не истина и не ложь (и не {1}, не {2})"};

const std::vector<std::pair<std::string, bool>> kBoolWords = {
    {"true", true},   {"yes", true},     {"y", true},  {"t", true},
    {"1", true},      {"はい", true},    {"○", true},  {"〇", true},
    {"false", false}, {"no", false},     {"n", false}, {"f", false},
    {"0", false},     {"いいえ", false}, {"×", false}, {"✕", false}};

Said read_answer(const YAML::Node& node, const AnswerSpec& spec, AnswerReading&, ParsedAnswer& p) {
  if (!node.IsScalar()) return say(kExpectedTrueOrFalse);
  // true/false, yes/no, and the answer's own pair of words (inside/outside), in any language.
  std::vector<std::string> pair = {"true", "false", "yes", "no"};
  pair.insert(pair.end(), spec.words.begin(), spec.words.end());
  const std::string w = known_word(node.Scalar(), pair);
  const auto it = std::find_if(kBoolWords.begin(), kBoolWords.end(),
                               [&](const auto& b) { return b.first == w; });
  const auto named = std::find(spec.words.begin(), spec.words.end(), w);
  if (it == kBoolWords.end() && named == spec.words.end())
    return spec.words.size() == 2 ? say(kNotTrueOrFalseOr, excerpt(node.Scalar()),
                                        word_said(spec.words[0]), word_said(spec.words[1]))
                                  : say(kNotTrueOrFalse, excerpt(node.Scalar()));
  p.value = Value::boolean(it != kBoolWords.end() ? it->second : named == spec.words.begin());
  return {};
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules&) {
  return got.flag == expected.flag ? correct() : incorrect();
}

std::vector<std::string> choices(const AnswerSpec&) { return {"true", "false"}; }
std::string chosen(const Value& key) { return key.flag ? "true" : "false"; }

QuizAsk quiz_ask(const AnswerSpec& spec, const Value& key, const Conventions&) {
  return chosen_among(choices(spec), chosen(key));
}

}  // namespace

AnswerType bool_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Bool;
  t.syntax = {
      {"true / false",
       R"md(`true`/`false`, `yes`/`no`, `y`/`n`, `t`/`f`, `1`/`0`, はい/いいえ, ○/×; the answer's own words (`inside`/`outside`, `convex`/`concave`); and every word the key prints under `--lang ja` or `--lang ru` (真/偽, да/нет, внутри/снаружи), in any case)md",
       R"md(`inside: true`, `inside: да`)md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.choices = choices;
  t.chosen = chosen;
  t.input = TypedInput::Choice;
  t.numeric = false;
  return t;
}

}  // namespace frustum
