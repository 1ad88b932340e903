#include "export/quiz_items.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/answer_caption.hpp"
#include "export/export_tolerance.hpp"
#include "export/xml_text.hpp"
#include "grader/answer_type.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

using namespace quiz_phrases;

namespace {

constexpr Phrase kTheTrueStatements{"the true statements", "正しい記述", "верные утверждения"};
constexpr Phrase kInfinityStandsFor{"1e30 stands for +∞, the depth of a pixel no polygon covers",
                                    "1e30 は +∞ (どの多角形にも覆われない画素の奥行き) を表す",
                                    "1e30 обозначает +∞ — глубину пикселя, не покрытого ни одним "
                                    "многоугольником"};
// Why an answer is not asked in a quiz.
constexpr Phrase kNoValueHere{"it has no value here", "ここでは値がない",
                              "здесь у него нет значения"};
constexpr Phrase kNotAskedHere{"Not asked here:", "ここでは問わない:", "Здесь не спрашивается:"};
constexpr Phrase kUseTheValuesGivenBelow{"(Use the values given below.)", "(下に示す値を使うこと.)",
                                         "(Используйте значения, данные ниже.)"};
constexpr Phrase kRowColumn{"row {0}, column {1}", "{0} 行 {1} 列", "строка {0}, столбец {1}"};
constexpr Phrase kComponent{"component {0}", "成分 {0}", "компонента {0}"};

std::vector<QuizField> numbers(const Value& v, const std::vector<double>& windows, Lang lang) {
  static const char* const kAxes[] = {"x", "y", "z", "w"};
  std::vector<QuizField> out;
  for (std::size_t i = 0; i < v.numbers.size(); ++i) {
    QuizField f;
    f.value = v.numbers[i];
    f.window = windows[i];
    if (v.shape == Value::Shape::Matrix)
      f.label = say(kRowColumn, i / static_cast<std::size_t>(v.cols) + 1,
                    i % static_cast<std::size_t>(v.cols) + 1)
                    .in(lang);
    else if (v.shape == Value::Shape::Vector)
      f.label = v.numbers.size() <= 4 ? kAxes[i] : say(kComponent, i + 1).in(lang);
    out.push_back(f);
  }
  return out;
}

void statement_boxes(const ProblemSpec& p, const Value& expected, QuizAnswer& a, Lang lang) {
  QuizField f = statement_checkboxes(p, expected, lang);
  // A multiple-answer question needs a right choice (Moodle: fractions adding up to 100 %):
  // when no statement is true, the right one is "none", which Frustum scores as the blank
  // answer — full marks, and each false statement ticked costs 1/F.
  if (std::find(f.right.begin(), f.right.end(), true) == f.right.end()) {
    f.choices.emplace_back(kNoStatementIsTrue.in(lang));
    f.right.push_back(true);
    f.reasons.emplace_back();
    f.correct = "none";
  }
  a.prompt = kTheTrueStatements.in(lang);
  a.fields = {f};
}

// A choice among words, in the students' language (front → 表): the words as `frustum grade`
// prints them in that language, which it reads back; the word as written in the set is kept as
// another right spelling where it differs (a platform that compares texts accepts both).
QuizField word_choice(const std::vector<std::string>& words, const std::string& right, Lang lang) {
  QuizField f;
  f.type = QuizField::Type::Choice;
  for (const std::string& w : words)
    f.choices.push_back(frustum::words::vocabulary_word(w).in(lang));
  f.correct = frustum::words::vocabulary_word(right).in(lang);
  if (f.correct != right) f.also = {right};
  return f;
}

// A given that is the problem's key (statements: each statement's truth).
bool given_is_key(const ProblemSpec& p) {
  return p.info &&
         std::any_of(p.info->answers.begin(), p.info->answers.end(), [](const AnswerSpec& a) {
           return answer_type(a.kind).input == TypedInput::Checkboxes;
         });
}

// The fields of one answer as its type asks for it, or the reason it cannot be a quiz field.
Said fields_of(const ProblemSpec& p, const Answers& key, const AnswerSpec& spec,
               const Value& expected, QuizAnswer& a, Lang lang) {
  if (expected.shape == Value::Shape::Null) return say(kNoValueHere);
  const QuizAsk ask = answer_type(spec.kind).quiz(spec, expected, p.conventions);
  if (!ask.refused.empty()) return ask.refused;
  for (const Said& note : ask.notes) a.prompt += fmt::format(" ({})", note.in(lang));
  switch (ask.field) {
    case QuizAsk::Field::Numbers:
      if (std::find(ask.numbers.numbers.begin(), ask.numbers.numbers.end(), kQuizInfinity) !=
          ask.numbers.numbers.end())
        a.prompt += fmt::format(" ({})", kInfinityStandsFor.in(lang));
      a.fields = numbers(ask.numbers, accepted_windows(p, key, spec.name, ask.numbers), lang);
      break;
    case QuizAsk::Field::Choice:
      a.fields = {word_choice(ask.words, ask.right, lang)};
      break;
    case QuizAsk::Field::Text: {
      QuizField f;
      f.type = QuizField::Type::Text;
      f.correct = ask.right;
      f.also = ask.also;
      a.fields = {f};
      break;
    }
    case QuizAsk::Field::Statements:
      statement_boxes(p, expected, a, lang);
      break;
  }
  return {};
}

}  // namespace

namespace {

// A statement's `text` or `reason` in `lang`, or in the set's own language (text_reader.hpp).
std::string statement_field(const ProblemSpec& p, const YAML::Node& statement, const char* key,
                            Lang lang) {
  const YAML::Node n =
      statement.IsMap() ? local_text_node(statement[key], lang, p.text.lang) : YAML::Node();
  return n.IsDefined() && n.IsScalar() ? n.Scalar() : "";
}

}  // namespace

std::size_t field_count(const QuizQuestion& q) {
  std::size_t n = 0;
  for (const QuizAnswer& a : q.answers) n += a.fields.size();
  return n;
}

std::string question_html(const QuizQuestion& q) {
  std::string html = "<p>" + xml_escape(q.text) + "</p><ul>";
  for (const std::string& g : q.given) html += "<li><code>" + xml_escape(g) + "</code></li>";
  return html + "</ul>";
}

std::string left_out_html(const QuizQuestion& q, Lang lang) {
  if (q.left_out.empty()) return {};
  std::string html = "<p>" + xml_escape(kNotAskedHere.in(lang));
  for (const std::string& l : q.left_out) html += " " + xml_escape(l) + ";";
  return html + "</p>";
}

std::vector<std::string> statement_texts(const ProblemSpec& p, Lang lang) {
  std::vector<std::string> out;
  const YAML::Node statements = given_is_key(p) ? p.given_node["statements"] : YAML::Node();
  if (statements.IsSequence())
    for (const YAML::Node& s : statements) out.push_back(statement_field(p, s, "text", lang));
  return out;
}

QuizField statement_checkboxes(const ProblemSpec& p, const Value& key, Lang lang) {
  QuizField f;
  f.type = QuizField::Type::Checkboxes;
  const YAML::Node statements = p.given_node["statements"];
  f.choices = statement_texts(p, lang);
  f.choices.resize(key.entries.size());
  for (std::size_t i = 0; i < key.entries.size(); ++i) {
    const YAML::Node s =
        statements.IsSequence() && i < statements.size() ? statements[i] : YAML::Node();
    f.reasons.push_back(statement_field(p, s, "reason", lang));
    f.right.push_back(key.entries[i].second == "true");
    if (f.right.back()) f.correct += (f.correct.empty() ? "" : ", ") + std::to_string(i + 1);
  }
  return f;
}

std::string question_text(const ProblemSet& set, const ProblemSpec& p, Lang lang) {
  if (p.text.empty()) return p.info ? p.info->summary.in(lang) : p.kind;
  const std::string& written = p.text.in(lang);
  std::string text = fill_text(written, p.given_node);
  if (set.variant && written.find('{') == std::string::npos)
    text += fmt::format(" {}", kUseTheValuesGivenBelow.in(lang));
  return text;
}

std::vector<std::string> given_lines(const ProblemSpec& p) {
  std::vector<std::string> out;
  if (p.given_node.IsMap() && !given_is_key(p))
    for (auto it = p.given_node.begin(); it != p.given_node.end(); ++it)
      out.push_back(it->first.as<std::string>() + ": " + emit_flow(it->second));
  return out;
}

std::vector<QuizQuestion> quiz_questions(const ProblemSet& set, Lang lang) {
  std::vector<QuizQuestion> out;
  for (const ProblemSpec& p : set.problems) {
    if (p.error || !p.info) continue;
    const ProblemResult r = solve_problem(p, set.file, false);
    if (r.error) continue;
    QuizQuestion q;
    q.id = p.id;
    q.kind = p.kind;
    q.text = question_text(set, p, lang);
    q.given = given_lines(p);
    for (const std::string& name : p.ask) {
      const AnswerSpec* spec = p.info->answer(name);
      const Value* expected = r.answers.find(name);
      if (!spec || !expected) continue;
      QuizAnswer a;
      a.name = name;
      a.prompt = answer_caption(p, name, lang);
      a.points = p.answer_points(name);
      const Said reason = fields_of(p, r.answers, *spec, *expected, a, lang);
      if (reason.empty())
        q.answers.push_back(a);
      else
        q.left_out.push_back(a.prompt + ": " + reason.in(lang));
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace frustum
