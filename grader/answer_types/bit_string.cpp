// A bit string (an outcode): 0s and 1s, leading zeros restored.
#include <string>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kExpectedBitString{"expected a bit string like 0101",
                                    "0101 のようなビット列が必要です",
                                    "ожидалась строка битов, например 0101"};
constexpr Phrase kNotBitString{"'{0}' is not a bit string of 0 and 1",
                               "`{0}` は 0 と 1 のビット列ではありません",
                               "`{0}` — не строка битов из 0 и 1"};
constexpr Phrase kReadWithLeadingZeros{"read as {0} (the leading zeros restored)",
                                       "{0} と読みました (先頭の 0 を補いました)",
                                       "прочитано как {0} (ведущие нули восстановлены)"};
constexpr Phrase kBitsOnePerWindowEdge{"{0} bits, one per window edge",
                                       "ウィンドウの辺ごとに 1 ビット、計 {0} ビットです",
                                       "{0} бит, по одному на каждую сторону окна"};
constexpr Phrase kBitStringSuchAs{"a bit string such as 0101", "0101 のようなビット列",
                                  "битовая строка, например 0101"};

Said read_answer(const YAML::Node& node, const AnswerSpec&, AnswerReading&, ParsedAnswer& p) {
  if (!node.IsScalar()) return say(kExpectedBitString);
  std::string bits;
  for (char c : node.Scalar())
    if (c == '0' || c == '1')
      bits += c;
    else if (c != ' ' && c != '_')
      return say(kNotBitString, excerpt(node.Scalar()));
  p.value = Value::category(bits);
  return {};
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules&) {
  if (got.word == expected.word) return correct();
  // Written as a number, an outcode loses its leading zeros (0 for 0000, 101 for 0101):
  // the same bits, read with the zeros restored.
  if (!got.word.empty() && got.word.size() < expected.word.size() &&
      std::string(expected.word.size() - got.word.size(), '0') + got.word == expected.word)
    return correct(say(kReadWithLeadingZeros, expected.word));
  if (got.word.size() != expected.word.size())
    return incorrect(say(kBitsOnePerWindowEdge, expected.word.size()));
  return incorrect();
}

// The bits as text; as `frustum grade` does, the bits with leading zeros dropped are right too
// (an outcode written as a number: 101 for 0101, 0 for 0000).
QuizAsk quiz_ask(const AnswerSpec&, const Value& key, const Conventions&) {
  QuizAsk a;
  a.field = QuizAsk::Field::Text;
  a.right = key.word;
  for (std::size_t k = 1; k < a.right.size() && a.right[k - 1] == '0'; ++k)
    a.also.push_back(a.right.substr(k));
  a.notes.push_back(say(kBitStringSuchAs));
  return a;
}

}  // namespace

AnswerType bit_string_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::BitString;
  t.syntax = {
      {"bit string",
       R"md(0s and 1s; spaces and `_` ignored; leading zeros may be dropped, as when the code is written as a number (`0` is 0000, `1` is 0001))md",
       R"md(`outcode_p: "0010"` (2D TBRL; 3D has two more leading bits))md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.typed_hint = &kBitStringSuchAs;
  t.numeric = false;
  return t;
}

}  // namespace frustum
