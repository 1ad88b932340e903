#include "export/export_qti.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "export/xml_text.hpp"

namespace frustum {

namespace {

// Numbers as QTI and Canvas read them: shortest round-trip decimal.
std::string num(double v) { return fmt::format("{}", v); }

std::string metadata(const std::string& type, double points) {
  return fmt::format(
      "        <itemmetadata><qtimetadata>\n"
      "          "
      "<qtimetadatafield><fieldlabel>question_type</fieldlabel><fieldentry>{}</fieldentry></"
      "qtimetadatafield>\n"
      "          "
      "<qtimetadatafield><fieldlabel>points_possible</fieldlabel><fieldentry>{}</fieldentry></"
      "qtimetadatafield>\n"
      "        </qtimetadata></itemmetadata>\n",
      type, num(points));
}

std::string stem(const QuizQuestion& q, const QuizAnswer& a, const QuizField& f, Lang lang) {
  std::string html = "<p>" + xml_escape(q.text) + "</p><ul>";
  for (const std::string& g : q.given) html += "<li><code>" + xml_escape(g) + "</code></li>";
  html += "</ul><p>" + xml_escape(a.prompt) + (f.label.empty() ? "" : ", " + xml_escape(f.label)) +
          "</p>";
  if (!q.left_out.empty()) {
    html += "<p>" + xml_escape(tr("Not asked here:", lang));
    for (const std::string& l : q.left_out) html += " " + xml_escape(l) + ";";
    html += "</p>";
  }
  // Canvas scores a multiple-answers question by its own rule (each right box ticked +1/T, each
  // wrong one −1/T, T right boxes), which is not Frustum's (−1/F for a wrong one, F wrong
  // boxes) and cannot be changed by the import: stated so the students know what counts.
  if (f.type == QuizField::Type::Checkboxes) {
    const auto right = std::count(f.right.begin(), f.right.end(), true);
    html += "<p>" +
            xml_escape(tr(fmt::format("Canvas scores this question by its own rule: each right "
                                      "choice ticked earns 1/{0} of the points and each wrong one "
                                      "ticked loses 1/{0} ({0} right choices), never below 0.",
                                      right),
                          lang)) +
            "</p>";
  }
  return "          <material><mattext texttype=\"text/html\">" + xml_escape(html) +
         "</mattext></material>\n";
}

std::string item(const QuizQuestion& q, const QuizAnswer& a, const QuizField& f,
                 const std::string& ident, Lang lang) {
  const double points = a.points / static_cast<double>(a.fields.size());
  const std::string title = q.id + " " + a.name + (f.label.empty() ? "" : " " + f.label);
  std::string out =
      fmt::format("      <item ident=\"{}\" title=\"{}\">\n", ident, xml_escape(title));
  std::string presentation = "        <presentation>\n" + stem(q, a, f, lang);
  std::string condition;
  switch (f.type) {
    case QuizField::Type::Number:
      out += metadata("numerical_question", points);
      presentation +=
          "          <response_str ident=\"response1\" rcardinality=\"Single\"><render_fib "
          "fibtype=\"Decimal\">"
          "<response_label ident=\"answer1\"/></render_fib></response_str>\n";
      condition = fmt::format(
          "<or><varequal respident=\"response1\">{0}</varequal><and><vargte "
          "respident=\"response1\">{1}</vargte>"
          "<varlte respident=\"response1\">{2}</varlte></and></or>",
          num(f.value), num(f.value - f.window), num(f.value + f.window));
      break;
    case QuizField::Type::Choice:
      out += metadata("multiple_choice_question", points);
      presentation +=
          "          <response_lid ident=\"response1\" rcardinality=\"Single\"><render_choice>";
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        presentation += fmt::format(
            "<response_label ident=\"c{}\"><material><mattext "
            "texttype=\"text/plain\">{}</mattext></material>"
            "</response_label>",
            i, xml_escape(f.choices[i]));
      presentation += "</render_choice></response_lid>\n";
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        if (f.choices[i] == f.correct)
          condition = fmt::format("<varequal respident=\"response1\">c{}</varequal>", i);
      break;
    case QuizField::Type::Checkboxes:
      // Canvas's multiple-answers question: right when exactly the right boxes are ticked
      // (Canvas scores partial selections by its own setting, not Frustum's 1/T and 1/F).
      out += metadata("multiple_answers_question", points);
      presentation +=
          "          <response_lid ident=\"response1\" rcardinality=\"Multiple\"><render_choice>";
      for (std::size_t i = 0; i < f.choices.size(); ++i) {
        presentation += fmt::format(
            "<response_label ident=\"c{}\"><material><mattext "
            "texttype=\"text/plain\">{}. {}</mattext></material></response_label>",
            i, i + 1, xml_escape(f.choices[i]));
        const std::string ticked =
            fmt::format("<varequal respident=\"response1\">c{}</varequal>", i);
        condition += f.right[i] ? ticked : "<not>" + ticked + "</not>";
      }
      presentation += "</render_choice></response_lid>\n";
      condition = "<and>" + condition + "</and>";
      break;
    case QuizField::Type::Text:
      out += metadata("short_answer_question", points);
      presentation +=
          "          <response_str ident=\"response1\" rcardinality=\"Single\"><render_fib>"
          "<response_label ident=\"answer1\" rshuffle=\"No\"/></render_fib></response_str>\n";
      condition = "<varequal respident=\"response1\">" + xml_escape(f.correct) + "</varequal>";
      for (const std::string& also : f.also)
        condition += "<varequal respident=\"response1\">" + xml_escape(also) + "</varequal>";
      if (!f.also.empty()) condition = "<or>" + condition + "</or>";
      break;
  }
  out += presentation + "        </presentation>\n";
  out +=
      "        <resprocessing>\n          <outcomes><decvar maxvalue=\"100\" minvalue=\"0\" "
      "varname=\"SCORE\" "
      "vartype=\"Decimal\"/></outcomes>\n";
  out += "          <respcondition continue=\"No\"><conditionvar>" + condition +
         "</conditionvar><setvar action=\"Set\" varname=\"SCORE\">100</setvar></respcondition>\n";
  out += "        </resprocessing>\n      </item>\n";
  return out;
}

std::string assessment(const std::vector<QuizQuestion>& questions, const std::string& title,
                       const std::string& ident, Lang lang) {
  std::string body = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<questestinterop xmlns=\"http://www.imsglobal.org/xsd/ims_qtiasiv1p2\">\n"
      "  <assessment ident=\"{}\" title=\"{}\">\n"
      "    <section ident=\"root_section\">\n",
      ident, xml_escape(title));
  int n = 0;
  for (const QuizQuestion& q : questions)
    for (const QuizAnswer& a : q.answers)
      for (const QuizField& f : a.fields)
        body += item(q, a, f, fmt::format("{}_i{}", ident, ++n), lang);
  return body + "    </section>\n  </assessment>\n</questestinterop>\n";
}

}  // namespace

std::map<std::string, std::string> export_qti(const std::vector<QuizVariant>& variants,
                                              const std::string& title, const std::string& ident,
                                              Lang lang) {
  std::map<std::string, std::string> files;
  std::string resources;
  for (const QuizVariant& v : variants) {
    const std::string id = v.name.empty() ? ident : ident + "-" + v.name;
    files[id + ".xml"] =
        assessment(v.questions, v.name.empty() ? title : title + " (" + v.name + ")", id, lang);
    // An href is a URI: the '%' of an encoded name is written %25.
    std::string href;
    for (const char c : id) href += c == '%' ? std::string("%25") : std::string(1, c);
    resources += fmt::format(
        "    <resource identifier=\"{0}\" type=\"imsqti_xmlv1p2\" href=\"{1}.xml\"><file "
        "href=\"{1}.xml\"/></resource>\n",
        xml_escape(id), href);
  }
  files["imsmanifest.xml"] = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<manifest identifier=\"{}_manifest\" xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\">\n"
      "  <metadata><schema>IMS Content</schema><schemaversion>1.1.3</schemaversion></metadata>\n"
      "  <organizations/>\n"
      "  <resources>\n{}  </resources>\n"
      "</manifest>\n",
      ident, resources);
  return files;
}

}  // namespace frustum
