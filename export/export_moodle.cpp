#include "export/export_moodle.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/xml_text.hpp"
#include "grader/visible_text.hpp"

namespace frustum {

namespace {

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
std::string multichoice_question(const QuizQuestion& q, const std::string& name) {
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

std::string cloze_question(const QuizQuestion& q, const std::string& name) {
  std::string html = "<p>" + xml_escape(q.text) + "</p><ul>";
  for (const std::string& g : q.given) html += "<li><code>" + xml_escape(g) + "</code></li>";
  html += "</ul>";
  double total = 0;
  for (const QuizAnswer& a : q.answers) {
    html += "<p>" + xml_escape(a.prompt) + ": ";
    // Weights: each field's share of its answer's points, in hundredths.
    const int weight =
        std::max(1, static_cast<int>(std::lround(100 * a.points / double(a.fields.size()))));
    for (const QuizField& f : a.fields)
      html += (f.label.empty() ? "" : xml_escape(f.label) + " ") + cloze_field(f, weight) + " ";
    html += "</p>";
    total += a.points;
  }
  if (!q.left_out.empty()) {
    html += "<p>Not asked here (graded by Frustum only):";
    for (const std::string& l : q.left_out) html += " " + xml_escape(l) + ";";
    html += "</p>";
  }
  std::string out = "  <question type=\"cloze\">\n";
  out += "    <name><text>" + xml_escape(name) + "</text></name>\n";
  out += "    <questiontext format=\"html\"><text><![CDATA[" + html + "]]></text></questiontext>\n";
  out += "    <generalfeedback format=\"html\"><text></text></generalfeedback>\n";
  out += fmt::format("    <defaultgrade>{}</defaultgrade>\n", total);
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

std::string export_moodle(const std::vector<QuizVariant>& variants, const std::string& category) {
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<quiz>\n";
  const std::size_t problems = variants.empty() ? 0 : variants[0].questions.size();
  for (std::size_t i = 0; i < problems; ++i) {
    const std::string id = variants[0].questions[i].id;
    std::string questions;
    for (const QuizVariant& v : variants)
      for (const QuizQuestion& q : v.questions)
        if (q.id == id && !q.answers.empty())
          questions += (only_checkboxes(q) ? multichoice_question : cloze_question)(
              q, v.name.empty() ? id : id + " " + v.name);
    if (questions.empty()) continue;  // nothing in it a Cloze field can check
    out += "  <question type=\"category\">\n    <category><text>$course$/top/" +
           xml_escape(category_level(category)) + "/" + xml_escape(category_level(id)) +
           "</text></category>\n  </question>\n" + questions;
  }
  return out + "</quiz>\n";
}

}  // namespace frustum
