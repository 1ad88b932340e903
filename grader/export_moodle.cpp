#include "grader/export_moodle.hpp"

#include <fmt/format.h>

#include <cmath>

#include "grader/xml_text.hpp"

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
    case QuizField::Type::Text: {
      std::string answers = "=" + cloze_literal(f.correct);
      for (const std::string& also : f.also) answers += "~=" + cloze_literal(also);
      return fmt::format("{{{}:SHORTANSWER:{}}}", weight, answers);
    }
  }
  return {};
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
          questions += cloze_question(q, v.name.empty() ? id : id + " " + v.name);
    if (questions.empty()) continue;  // nothing in it a Cloze field can check
    out += "  <question type=\"category\">\n    <category><text>$course$/top/" +
           xml_escape(category) + "/" + xml_escape(id) + "</text></category>\n  </question>\n" +
           questions;
  }
  return out + "</quiz>\n";
}

}  // namespace frustum
