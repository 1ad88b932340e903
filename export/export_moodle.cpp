#include "export/export_moodle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "export/xml_text.hpp"
#include "grader/visible_text.hpp"

namespace frustum {

namespace {

constexpr Phrase kEachNumberScoredOnItsOwn{"Each number is scored on its own here.",
                                           "ここでは数ごとに採点される.",
                                           "Здесь каждое число оценивается отдельно."};

// Cloze answers treat } # ~ / " \ as syntax: a backslash keeps them literal.
std::string cloze_literal(const std::string& s) {
  std::string out;
  for (const char c : s) {
    if (c == '}' || c == '#' || c == '~' || c == '/' || c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out;
}

// Moodle's grade of one ticked box in a multiple-answer question: each right choice earns
// 100/T percent, each wrong one costs 100/F (T right and F wrong choices), as `frustum grade`
// scores it; Moodle's XML import takes the nearest grade it offers.
std::string box_fraction(const QuizField& f, std::size_t i) {
  const auto right = static_cast<double>(std::count(f.right.begin(), f.right.end(), true));
  const double wrong = static_cast<double>(f.right.size()) - right;
  return fmt::format("{:.5g}", f.right[i] ? 100 / right : -100 / wrong);
}

// One Cloze field; its weight is the field's share of the answer's points (integers in Cloze:
// the points scaled by the fields' common denominator, at most 1000).
std::string cloze_field(const QuizField& f, int weight) {
  switch (f.type) {
    case QuizField::Type::Number:
      return fmt::format("{{{}:NUMERICAL:={}:{}}}", weight, f.value, f.window);
    case QuizField::Type::Choice: {
      std::string s = fmt::format("{{{}:MULTICHOICE:", weight);
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        s += (i ? "~" : "") + std::string(f.choices[i] == f.correct ? "=" : "") +
             cloze_literal(f.choices[i]);
      return s + "}";
    }
    case QuizField::Type::Checkboxes: {
      std::string s = fmt::format("{{{}:MULTIRESPONSE:", weight);
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        s += (i ? "~%" : "%") + box_fraction(f, i) + "%" + cloze_literal(f.choices[i]);
      return s + "}";
    }
    case QuizField::Type::Text: {
      std::string answers = "=" + cloze_literal(f.correct);
      for (const std::string& also : f.also) answers += "~=" + cloze_literal(also);
      return fmt::format("{{{}:SHORTANSWER:{}}}", weight, answers);
    }
  }
  return {};
}

// A question whose one answer is a set of checkboxes, as Moodle's own multiple-answer question
// (multichoice, single = false): the statements numbered 1, 2, … in the set's order, each with
// its reason as the choice's feedback.
std::string multichoice_question(const QuizQuestion& q, const std::string& name, Lang) {
  const QuizAnswer& a = q.answers[0];
  const QuizField& f = a.fields[0];
  std::string out = "  <question type=\"multichoice\">\n";
  out += "    <name><text>" + xml_escape(name) + "</text></name>\n";
  out += "    <questiontext format=\"html\"><text><![CDATA[<p>" + xml_escape(q.text) +
         "</p>]]></text></questiontext>\n";
  out += "    <generalfeedback format=\"html\"><text></text></generalfeedback>\n";
  out += fmt::format("    <defaultgrade>{}</defaultgrade>\n", a.points);
  out += "    <penalty>0</penalty>\n    <hidden>0</hidden>\n";
  out += "    <single>false</single>\n    <shuffleanswers>false</shuffleanswers>\n";
  out += "    <answernumbering>123</answernumbering>\n";
  for (std::size_t i = 0; i < f.choices.size(); ++i)
    out += "    <answer fraction=\"" + box_fraction(f, i) + "\" format=\"html\"><text><![CDATA[" +
           xml_escape(f.choices[i]) + "]]></text><feedback format=\"html\"><text><![CDATA[" +
           xml_escape(f.reasons[i]) + "]]></text></feedback></answer>\n";
  return out + "  </question>\n";
}

bool only_checkboxes(const QuizQuestion& q) {
  return q.answers.size() == 1 && q.answers[0].fields.size() == 1 &&
         q.answers[0].fields[0].type == QuizField::Type::Checkboxes && q.left_out.empty();
}

}  // namespace

std::vector<long long> cloze_weights(const QuizQuestion& q) {
  // Each field's share of its answer's points as a fraction num/den (points to 1/1000).
  std::vector<std::pair<long long, long long>> shares;
  long long common = 1;  // the least common denominator
  for (const QuizAnswer& a : q.answers) {
    const long long num = std::max(1LL, std::llround(a.points * 1000));
    const long long den = 1000 * static_cast<long long>(std::max<std::size_t>(1, a.fields.size()));
    const long long g = std::gcd(num, den);
    shares.emplace_back(num / g, den / g);
    common = std::lcm(common, den / g);
    if (common > kMaxClozeScale) break;
  }
  std::vector<long long> weights;
  long long all = 0;
  for (std::size_t i = 0; i < q.answers.size(); ++i)
    for (std::size_t k = 0; k < q.answers[i].fields.size(); ++k) {
      // Past the scale Moodle can hold, hundredths of a point (rounded, at least 1).
      const long long w = common > kMaxClozeScale
                              ? std::max(1LL, std::llround(100 * q.answers[i].points /
                                                           double(q.answers[i].fields.size())))
                              : shares[i].first * (common / shares[i].second);
      weights.push_back(w);
      all = std::gcd(all, w);
    }
  // Whole points already (common == 1): the weights are the points. Else the smallest whole
  // numbers in the same proportion.
  if (common > 1 && all > 1)
    for (long long& w : weights) w /= all;
  return weights;
}

namespace {

std::string cloze_question(const QuizQuestion& q, const std::string& name, Lang lang) {
  std::string html = question_html(q);
  double total = 0;
  const std::vector<long long> weights = cloze_weights(q);
  long long sum = 0;
  std::size_t field = 0;
  for (const QuizAnswer& a : q.answers) {
    html += "<p>" + xml_escape(a.prompt) + ": ";
    for (const QuizField& f : a.fields) {
      sum += weights[field];
      html += (f.label.empty() ? "" : xml_escape(f.label) + " ") +
              cloze_field(f, static_cast<int>(weights[field++])) + " ";
    }
    html += "</p>";
    total += a.points;
  }
  // Cloze credits each field alone; said where an answer has several numbers.
  if (std::any_of(q.answers.begin(), q.answers.end(),
                  [](const QuizAnswer& a) { return a.fields.size() > 1; }))
    html += "<p>" + xml_escape(kEachNumberScoredOnItsOwn.in(lang)) + "</p>";
  html += left_out_html(q, lang);
  // For the instructor (an XML comment is not imported): the mark Moodle gives the question.
  std::string out = fmt::format(
      "  <!-- {} points in Frustum; Moodle's mark is the sum of the field weights, {}{}. Moodle "
      "credits each field on its own, where Frustum gives an answer's points only when all "
      "its numbers are right. -->\n",
      total, sum,
      static_cast<double>(sum) == total
          ? ""
          : fmt::format(" (set the question's maximum mark in the quiz to {} for Frustum's "
                        "weight)",
                        total));
  out += "  <question type=\"cloze\">\n";
  out += "    <name><text>" + xml_escape(name) + "</text></name>\n";
  out += "    <questiontext format=\"html\"><text><![CDATA[" + html + "]]></text></questiontext>\n";
  out += "    <generalfeedback format=\"html\"><text></text></generalfeedback>\n";
  // Moodle sets a Cloze question's mark to the sum of its weights whatever this says; written
  // as that sum so the file says what Moodle will do.
  out += fmt::format("    <defaultgrade>{}</defaultgrade>\n", sum);
  out += "    <penalty>0</penalty>\n    <hidden>0</hidden>\n";
  return out + "  </question>\n";
}

// A name as one level of a category path: Moodle splits the path at '/' and reads "//" as a
// '/' of the name, so that problem "q/1" is its own category, not "1" inside "q". A control
// character, which XML cannot hold (xml_escape drops it), is written visibly (\u001B), so that
// "q/1" and "q/1" + ESC stay two categories.
std::string category_level(const std::string& name) {
  std::string out;
  for (const char c : visible_text(name)) out += c == '/' ? std::string("//") : std::string(1, c);
  return out;
}

}  // namespace

std::string export_moodle(const std::vector<QuizVariant>& variants, const std::string& category,
                          Lang lang) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n";
  const std::size_t problems = variants.empty() ? 0 : variants[0].questions.size();
  for (std::size_t i = 0; i < problems; ++i) {
    const std::string id = variants[0].questions[i].id;
    std::string questions;
    for (const QuizVariant& v : variants)
      for (const QuizQuestion& q : v.questions)
        if (q.id == id && !q.answers.empty())
          questions += (only_checkboxes(q) ? multichoice_question : cloze_question)(
              q, v.name.empty() ? id : id + " " + v.name, lang);
    if (questions.empty()) continue;  // nothing in it a Cloze field can check
    out += "  <question type=\"category\">\n    <category><text>$course$/top/" +
           xml_escape(category_level(category)) + "/" + xml_escape(category_level(id)) +
           "</text></category>\n  </question>\n" + questions;
  }
  return out + "</quiz>\n";
}

}  // namespace frustum
