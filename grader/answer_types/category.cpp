// One word of a fixed list (front/back/edge_on; 表/裏).
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

constexpr Phrase kExpectedOneWord{"expected one word", "語が一つ必要です", "ожидалось одно слово"};
constexpr Phrase kNotOneOf{"'{0}' is not one of {1}", "`{0}` は次のいずれでもありません: {1}",
                           "`{0}` — не одно из: {1}"};

Said read_answer(const YAML::Node& node, const AnswerSpec& spec, AnswerReading&, ParsedAnswer& p) {
  if (!node.IsScalar()) return say(kExpectedOneWord);
  const std::string w = known_word(node.Scalar(), spec.words);
  if (std::find(spec.words.begin(), spec.words.end(), w) == spec.words.end()) {
    Said list;
    for (const auto& a : spec.words) {
      if (!list.empty()) list.append(Said::verbatim(", "));
      list.append(word_said(a));
    }
    return say(kNotOneOf, excerpt(node.Scalar()), list);
  }
  p.value = Value::category(w);
  return {};
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules&) {
  return got.word == expected.word ? correct() : incorrect();
}

std::vector<std::string> choices(const AnswerSpec& spec) { return spec.words; }
std::string chosen(const Value& key) { return key.word; }

QuizAsk quiz_ask(const AnswerSpec& spec, const Value& key, const Conventions&) {
  return chosen_among(choices(spec), chosen(key));
}

}  // namespace

AnswerType category_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Category;
  t.syntax = {
      {"word",
       R"md(`front`, `back`, `edge_on` (also `front-facing`, `edge-on`, 表, 裏, 真横, and the Russian words the key prints: лицевая, обратная, с ребра))md",
       R"md(`facing: back`)md"}};
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
