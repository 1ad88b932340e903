#include "export/export_qti.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "export/xml_text.hpp"

namespace frustum {

namespace {

// Slots {0}, {1}, {2} hold the same number T (a slot is filled once per use).
constexpr Phrase kCanvasScoresByItsOwnRule{
    "Canvas scores this question by its own rule: each right choice ticked earns 1/{0} of the "
    "points and each wrong one ticked loses 1/{1} ({2} right choices), never below 0.",
    "この問題は Canvas の規則で採点される: 正しい選択肢 1 つごとに配点の 1/{0} を得て, "
    "誤った選択肢 1 つごとに 1/{1} を失う (正しい選択肢は {2} 個, 0 点未満にはならない).",
    "Этот вопрос Canvas оценивает по своему правилу: каждый отмеченный верный вариант даёт 1/{0} "
    "баллов, каждый отмеченный неверный отнимает 1/{1} (верных вариантов: {2}), но не меньше 0."};
constexpr Phrase kEachBoxScoredOnItsOwn{
    "Each box is scored on its own here, by its text: write each number as a decimal rounded "
    "as asked.",
    "ここでは欄ごとに, 書かれた文字列で採点される: 各数は指示どおりに丸めた小数で書くこと.",
    "Здесь каждое поле оценивается отдельно, по записанному тексту: пишите каждое число "
    "десятичной дробью, округлённой как указано."};
constexpr Phrase kToDecimalPlaces{"to {0} decimal places", "小数第 {0} 位まで",
                                  "с {0} знаками после запятой"};
constexpr Phrase kInfinityIsWrittenInf{"+∞ is written inf", "+∞ は inf と書く", "+∞ пишется inf"};
constexpr Phrase kOneOf{"one of:", "次のいずれか:", "одно из:"};
constexpr Phrase kNumbersOfTheTrueStatements{"the numbers of the true statements, such as 1, 3",
                                             "正しい記述の番号 (例: 1, 3)",
                                             "номера верных утверждений, например 1, 3"};

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
  std::string html = question_html(q) + "<p>" + xml_escape(a.prompt) +
                     (f.label.empty() ? "" : ", " + xml_escape(f.label)) + "</p>" +
                     left_out_html(q, lang);
  // Canvas scores a multiple-answers question by its own rule (each right box ticked +1/T, each
  // wrong one −1/T, T right boxes), which is not Frustum's (−1/F for a wrong one, F wrong
  // boxes) and cannot be changed by the import: stated so the students know what counts.
  if (f.type == QuizField::Type::Checkboxes) {
    const auto right = std::count(f.right.begin(), f.right.end(), true);
    html +=
        "<p>" + xml_escape(say(kCanvasScoresByItsOwnRule, right, right, right).in(lang)) + "</p>";
  }
  return "          <material><mattext texttype=\"text/html\">" + xml_escape(html) +
         "</mattext></material>\n";
}

// One field as its own item (a problem with a single field): Canvas's own question type
// for it, numbers with the grader's window.
std::string single_item(const QuizQuestion& q, const QuizAnswer& a, const QuizField& f,
                        const std::string& ident, const std::string& title, Lang lang) {
  std::string out =
      fmt::format("      <item ident=\"{}\" title=\"{}\">\n", ident, xml_escape(title));
  std::string presentation = "        <presentation>\n" + stem(q, a, f, lang);
  std::string condition;
  switch (f.type) {
    case QuizField::Type::Number:
      out += metadata("numerical_question", a.points);
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
      out += metadata("multiple_choice_question", a.points);
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
      out += metadata("multiple_answers_question", a.points);
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
      out += metadata("short_answer_question", a.points);
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

double points_of(const QuizQuestion& q) {
  double points = 0;
  for (const QuizAnswer& a : q.answers) points += a.points;
  return points;
}

// A problem with several fields as one fill-in-multiple-blanks item: a blank per field, each
// with the texts Canvas accepts for it (canvas_blank). Canvas scores such an item as the share
// of its blanks answered right (each blank the same), comparing texts trimmed and lower-cased.
std::string blanks_item(const QuizQuestion& q, const std::string& ident, const std::string& title,
                        Lang lang) {
  std::string html = question_html(q);
  std::string responses;
  std::vector<std::pair<std::string, std::string>> right;  // (blank, label) pairs
  for (std::size_t k = 0; k < q.answers.size(); ++k) {
    const QuizAnswer& a = q.answers[k];
    html += "<p>" + xml_escape(a.prompt) + ":";
    for (std::size_t i = 0; i < a.fields.size(); ++i) {
      const QuizField& f = a.fields[i];
      const CanvasBlank b = canvas_blank(f, lang);
      const std::string id = fmt::format("b{}_{}", k + 1, i + 1);
      html += " " + xml_escape(f.label.empty() ? "" : f.label + " ") + "[" + id + "]";
      if (!b.hint.empty()) html += " (" + xml_escape(b.hint) + ")";
      if (i + 1 < a.fields.size()) html += ",";
      responses += fmt::format(
          "          <response_lid ident=\"response_{0}\"><material><mattext>{0}</mattext>"
          "</material><render_choice>",
          id);
      for (std::size_t t = 0; t < b.texts.size(); ++t) {
        const std::string label = fmt::format("{}_{}", id, t + 1);
        responses += fmt::format(
            "<response_label ident=\"{}\"><material><mattext "
            "texttype=\"text/plain\">{}</mattext></material></response_label>",
            label, xml_escape(b.texts[t]));
        right.emplace_back(id, label);
      }
      responses += "</render_choice></response_lid>\n";
    }
    html += "</p>";
  }
  html += "<p>" + xml_escape(kEachBoxScoredOnItsOwn.in(lang)) + "</p>" + left_out_html(q, lang);
  const std::size_t blanks = field_count(q);
  std::string scored;
  for (const auto& [id, label] : right)
    scored += fmt::format(
        "          <respcondition continue=\"Yes\"><conditionvar><varequal "
        "respident=\"response_{}\">{}</varequal>"
        "</conditionvar><setvar action=\"Add\" varname=\"SCORE\">{}</setvar></respcondition>\n",
        id, label, num(100.0 / static_cast<double>(blanks)));
  return fmt::format("      <item ident=\"{}\" title=\"{}\">\n", ident, xml_escape(title)) +
         metadata("fill_in_multiple_blanks_question", points_of(q)) +
         "        <presentation>\n          <material><mattext texttype=\"text/html\">" +
         xml_escape(html) + "</mattext></material>\n" + responses + "        </presentation>\n" +
         "        <resprocessing>\n          <outcomes><decvar maxvalue=\"100\" minvalue=\"0\" "
         "varname=\"SCORE\" vartype=\"Decimal\"/></outcomes>\n" +
         scored + "        </resprocessing>\n      </item>\n";
}

// A problem as one item: its single field's own question type, or blanks for several.
std::string item(const QuizQuestion& q, const std::string& ident, const std::string& title,
                 Lang lang) {
  if (field_count(q) == 1)
    for (const QuizAnswer& a : q.answers)
      if (a.fields.size() == 1) return single_item(q, a, a.fields[0], ident, title, lang);
  return blanks_item(q, ident, title, lang);
}

}  // namespace

std::map<std::string, std::string> export_qti(const std::vector<QuizVariant>& variants,
                                              const std::string& title, const std::string& ident,
                                              Lang lang) {
  std::string body = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<questestinterop xmlns=\"http://www.imsglobal.org/xsd/ims_qtiasiv1p2\">\n"
      "  <assessment ident=\"{}\" title=\"{}\">\n"
      "    <section ident=\"root_section\">\n",
      ident, xml_escape(title));
  // Problem i of every variant: one item each, in a question group from which Canvas draws
  // one for each student (selection_number 1), or the item alone when there is one variant.
  const std::size_t problems = variants.empty() ? 0 : variants.front().questions.size();
  const bool group = variants.size() > 1;
  for (std::size_t i = 0; i < problems; ++i) {
    const QuizQuestion& first = variants.front().questions[i];
    if (first.answers.empty()) continue;  // nothing a quiz can check (its note is on stderr)
    if (group)
      body += fmt::format(
          "    <section ident=\"{}_g{}\" title=\"{}\">\n      <selection_ordering><selection>"
          "<selection_number>1</selection_number><selection_extension><points_per_item>{}"
          "</points_per_item></selection_extension></selection></selection_ordering>\n",
          ident, i + 1, xml_escape(first.id), num(points_of(first)));
    for (std::size_t v = 0; v < variants.size(); ++v) {
      if (i >= variants[v].questions.size()) continue;
      const QuizQuestion& q = variants[v].questions[i];
      const std::string& name = variants[v].name;
      body += item(q, fmt::format("{}_q{}_v{}", ident, i + 1, v + 1),
                   name.empty() ? q.id : q.id + " (" + name + ")", lang);
    }
    if (group) body += "    </section>\n";
  }
  std::map<std::string, std::string> files;
  files[ident + ".xml"] = body + "    </section>\n  </assessment>\n</questestinterop>\n";
  // An href is a URI: the '%' of an encoded name is written %25.
  std::string href;
  for (const char c : ident) href += c == '%' ? std::string("%25") : std::string(1, c);
  files["imsmanifest.xml"] = fmt::format(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      "<manifest identifier=\"{0}_manifest\" xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\">\n"
      "  <metadata><schema>IMS Content</schema><schemaversion>1.1.3</schemaversion></metadata>\n"
      "  <organizations/>\n"
      "  <resources>\n"
      "    <resource identifier=\"{1}\" type=\"imsqti_xmlv1p2\" href=\"{2}.xml\"><file "
      "href=\"{2}.xml\"/></resource>\n"
      "  </resources>\n"
      "</manifest>\n",
      ident, xml_escape(ident), href);
  return files;
}

CanvasBlank canvas_blank(const QuizField& f, Lang lang) {
  CanvasBlank b;
  auto add = [&](const std::string& t) {
    if (std::find(b.texts.begin(), b.texts.end(), t) == b.texts.end()) b.texts.push_back(t);
  };
  switch (f.type) {
    case QuizField::Type::Number: {
      if (f.value == kQuizInfinity) {
        for (const char* t : {"inf", "+inf", "∞", "+∞", "infinity", "1e30"}) add(t);
        b.hint = kInfinityIsWrittenInf.in(lang);
        return b;
      }
      // The fewest decimals (at least 2) whose rounding stays inside the grader's window (a
      // window of 0 is an exact value such as a matrix's fixed 0 or 1: 2 decimals).
      while (f.window > 0 && b.places < 12 && 0.5 * std::pow(10.0, -b.places) > f.window)
        ++b.places;
      b.hint = say(kToDecimalPlaces, b.places).in(lang);
      // Rounded to that many places or up to two more; a value on a half of the last place is
      // accepted rounded either way; trailing zeros and a leading 0 may be left out.
      const double nudge = std::min(std::max(std::abs(f.value), 1.0) * 1e-12, f.window / 4);
      for (int d = b.places; d <= b.places + 2; ++d)
        for (const double v : {f.value - nudge, f.value, f.value + nudge}) {
          std::string t = fmt::format("{:.{}f}", v, d);
          if (t.find_first_not_of("-0.") == std::string::npos) t = fmt::format("{:.{}f}", 0.0, d);
          std::string trimmed = t;
          while (trimmed.back() == '0') trimmed.pop_back();
          if (trimmed.back() == '.') trimmed.pop_back();
          for (const std::string& u : {t, trimmed}) {
            add(u);
            if (u.rfind("0.", 0) == 0) add(u.substr(1));
            if (u.rfind("-0.", 0) == 0) add("-" + u.substr(2));
          }
        }
      return b;
    }
    case QuizField::Type::Choice:
      add(f.correct);
      for (const std::string& also : f.also) add(also);
      b.hint = kOneOf.in(lang);
      for (std::size_t i = 0; i < f.choices.size(); ++i) b.hint += (i ? ", " : " ") + f.choices[i];
      return b;
    case QuizField::Type::Text:
      add(f.correct);
      for (const std::string& also : f.also) add(also);
      return b;
    case QuizField::Type::Checkboxes: {
      // The numbers of the right choices, separated by ", ", "," or " ".
      std::string spaced, tight, words;
      for (std::size_t i = 0; i < f.right.size(); ++i) {
        if (!f.right[i]) continue;
        const std::string n = std::to_string(i + 1);
        spaced += (spaced.empty() ? "" : ", ") + n;
        tight += (tight.empty() ? "" : ",") + n;
        words += (words.empty() ? "" : " ") + n;
      }
      for (const std::string& t : {spaced, tight, words}) add(t);
      b.hint = fmt::format("{}:", kNumbersOfTheTrueStatements.in(lang));
      for (std::size_t i = 0; i < f.choices.size(); ++i)
        b.hint += fmt::format("{} {}. {}", i ? ";" : "", i + 1, f.choices[i]);
      return b;
    }
  }
  return b;
}

}  // namespace frustum
