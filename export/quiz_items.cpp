#include "export/quiz_items.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/export_tolerance.hpp"
#include "export/xml_text.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

using namespace quiz_phrases;

namespace {

constexpr Phrase kTheTrueStatements{"the true statements", "正しい記述", "верные утверждения"};
constexpr Phrase kScaledSoThatW{"scaled so that w = {0}", "w = {0} となるように定数倍して",
                                "умноженный на число так, чтобы w = {0}"};
constexpr Phrase kInfinityStandsFor{"1e30 stands for +∞, the depth of a pixel no polygon covers",
                                    "1e30 は +∞ (どの多角形にも覆われない画素の奥行き) を表す",
                                    "1e30 обозначает +∞ — глубину пикселя, не покрытого ни одним "
                                    "многоугольником"};
constexpr Phrase kScaledToLength1{"scaled to length 1", "長さ 1 に正規化して",
                                  "нормированный к длине 1"};
constexpr Phrase kNotAskedHere{"Not asked here:", "ここでは問わない:", "Здесь не спрашивается:"};
constexpr Phrase kUseTheValuesGivenBelow{"(Use the values given below.)", "(下に示す値を使うこと.)",
                                         "(Используйте значения, данные ниже.)"};
// Why an answer is not asked in a quiz (no field type can express its equivalence).
constexpr Phrase kNoValueHere{"it has no value here", "ここでは値がない",
                              "здесь у него нет значения"};
constexpr Phrase kZeroVectorNoDirection{"a zero vector has no direction",
                                        "零ベクトルには向きがない",
                                        "у нулевого вектора нет направления"};
constexpr Phrase kPlaneUpToFactor{"a plane's equation is right up to any non-zero factor",
                                  "平面の方程式は 0 でない定数倍しても正しい",
                                  "уравнение плоскости верно с точностью до ненулевого множителя"};
constexpr Phrase kPolygonAnyStart{"a polygon is right from any starting vertex",
                                  "多角形はどの頂点から始めても正しい",
                                  "многоугольник верен при любой начальной вершине"};
constexpr Phrase kSegmentEitherDirection{"a segment is right in either direction",
                                         "線分はどちらの向きでも正しい",
                                         "отрезок верен в обоих направлениях"};
constexpr Phrase kPointSetAnyOrder{"a set of points is right in any order",
                                   "点の集合はどの順でも正しい",
                                   "множество точек верно в любом порядке"};
constexpr Phrase kLabelSetAnyOrder{"a set of labels is right in any order",
                                   "ラベルの集合はどの順でも正しい",
                                   "множество меток верно в любом порядке"};
constexpr Phrase kLabelOrderNoField{"an order of labels has no quiz field",
                                    "ラベルの順序を問う欄はない",
                                    "для порядка меток нет поля теста"};
constexpr Phrase kNoFieldFits{"no quiz field fits it", "合う欄がない",
                              "для него нет подходящего поля"};

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

// A given that is the problem's key (AnswerKind::Statements: each statement's truth).
bool given_is_key(const ProblemSpec& p) {
  return p.info &&
         std::any_of(p.info->answers.begin(), p.info->answers.end(),
                     [](const AnswerSpec& a) { return a.kind == AnswerKind::Statements; });
}

// The fields of one answer, or the reason it cannot be a quiz field.
Said fields_of(const ProblemSpec& p, const Answers& key, const AnswerSpec& spec,
               const Value& expected, QuizAnswer& a, Lang lang) {
  if (expected.shape == Value::Shape::Null) return say(kNoValueHere);
  switch (spec.kind) {
    case AnswerKind::Point:
      // Homogeneous (x, y, z, w) is right up to the scale of w: the quiz asks for the key's w.
      if (expected.numbers.size() == 4)
        a.prompt += fmt::format(
            " ({})", say(kScaledSoThatW, fmt::format("{}", expected.numbers[3])).in(lang));
      [[fallthrough]];
    case AnswerKind::Scalar:
    case AnswerKind::Vector:
    case AnswerKind::UnitVector:
    case AnswerKind::Matrix:
    case AnswerKind::Transform:
      if (std::find(expected.numbers.begin(), expected.numbers.end(), kQuizInfinity) !=
          expected.numbers.end())
        a.prompt += fmt::format(" ({})", kInfinityStandsFor.in(lang));
      a.fields = numbers(expected, accepted_windows(p, key, spec.name, expected), lang);
      return {};
    case AnswerKind::Direction: {
      // Right up to a positive factor: the quiz asks for the one of length 1.
      Value unit = expected;
      double norm = 0;
      for (double x : unit.numbers) norm += x * x;
      norm = std::sqrt(norm);
      if (norm == 0) return say(kZeroVectorNoDirection);
      for (double& x : unit.numbers) x /= norm;
      unit.exact.clear();
      a.prompt += fmt::format(" ({})", kScaledToLength1.in(lang));
      a.fields = numbers(unit, accepted_windows(p, key, spec.name, unit), lang);
      return {};
    }
    case AnswerKind::Bool:
      a.fields = {word_choice({"true", "false"}, expected.flag ? "true" : "false", lang)};
      return {};
    case AnswerKind::Category:
      a.fields = {word_choice(spec.words, expected.word, lang)};
      return {};
    case AnswerKind::BitString: {
      QuizField f;
      f.type = QuizField::Type::Text;
      f.correct = expected.word;
      // As `frustum grade` does, a platform accepts the bits with leading zeros dropped (an
      // outcode written as a number: 101 for 0101, 0 for 0000).
      for (std::size_t k = 1; k < f.correct.size() && f.correct[k - 1] == '0'; ++k)
        f.also.push_back(f.correct.substr(k));
      a.prompt += fmt::format(" ({})", kBitStringSuchAs.in(lang));
      a.fields = {f};
      return {};
    }
    case AnswerKind::Plane:
      return say(kPlaneUpToFactor);
    case AnswerKind::Polygon:
      return say(kPolygonAnyStart);
    case AnswerKind::Segment:
      return say(kSegmentEitherDirection);
    case AnswerKind::PointSet:
      return say(kPointSetAnyOrder);
    case AnswerKind::WordMap:
    case AnswerKind::WordList:
      return say(kLabelSetAnyOrder);
    case AnswerKind::Sequence:
      return say(kLabelOrderNoField);
    case AnswerKind::Statements:
      statement_boxes(p, expected, a, lang);
      return {};
  }
  return say(kNoFieldFits);
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
      a.prompt = name;
      a.points = p.answer_points(name);
      const Said reason = fields_of(p, r.answers, *spec, *expected, a, lang);
      if (reason.empty())
        q.answers.push_back(a);
      else
        q.left_out.push_back(name + ": " + reason.in(lang));
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace frustum
