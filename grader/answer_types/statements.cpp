// Which numbered statements are true: their numbers, or one truth each; credit per statement
// (statement_choice.hpp).
#include <utility>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"
#include "grader/statement_choice.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

Said read_answer(const YAML::Node& node, const AnswerSpec&, AnswerReading&, ParsedAnswer& p) {
  StatementChoice c = read_statement_choice(node);
  if (!c.error.empty()) return c.error;
  p.value = std::move(c.value);
  return {};
}

// "none" chooses no statement.
Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules&) {
  return compare_statement_choice(expected, got);
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  QuizAsk a;
  a.field = QuizAsk::Field::Statements;
  return a;
}

}  // namespace

AnswerType statements_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Statements;
  t.syntax = {
      {"true statements",
       R"md(the numbers of the true statements, in any order, repeats ignored (`[1, 3]`, `1`, `"1, 3"`, `"1 3"`, `1、3`; `[]`, `none`, なし for none); or one truth per statement (`[true, false, false, false]`, `○×××`, はい/いいえ, да/нет, верно/неверно); or a mapping `{1: true, 2: false, …}`. Digits are statement numbers, never truths; a number with no statement, a wrong count of truths, or numbers mixed with truths is unparseable. Each true statement ticked earns 1/T of the points and each false one costs 1/F (T true, F false statements), never below 0)md",
       R"md(`true_statements: [1]`, `true_statements: [○, ×, ×, ×]`)md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.input = TypedInput::Checkboxes;
  t.numeric = false;
  t.compares_none = true;
  return t;
}

}  // namespace frustum
