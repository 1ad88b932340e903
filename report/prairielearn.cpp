#include "report/prairielearn.hpp"

#include <fmt/format.h>

#include "grader/visible_text.hpp"
#include "report/feedback.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"

namespace frustum {

using json = nlohmann::ordered_json;

namespace {

constexpr Phrase kSomeAnswersCouldNotBeRead{
    "Some answers could not be read; fix them and submit again (this attempt is not counted).",
    "読み取れない解答があります. 直して再提出してください (この提出は回数に数えません).",
    "Некоторые ответы не удалось прочитать; исправьте их и отправьте снова (эта попытка не "
    "засчитывается)."};
constexpr Phrase kSeeTheFeedbackBelow{"see the feedback below", "下のフィードバックを参照",
                                      "см. отзыв ниже"};

}  // namespace

json prairielearn_results(const GradeReport& r, Lang lang) {
  // Unreadable answers and an unreadable file are format errors, not wrong answers; why an
  // answer could not be read is said in the student's language.
  std::vector<std::string> format_errors;
  for (const Diagnostic& d : r.errors) format_errors.push_back(visible_text(d.format()));
  for (const ProblemGrade& p : r.problems)
    for (const AnswerGrade& a : p.answers)
      if (a.verdict == Verdict::Unparseable)
        format_errors.push_back(
            visible_text(fmt::format("{}.{}: {}", p.id, a.name, a.feedback.in(lang))));
  json j;
  j["gradable"] = format_errors.empty();
  if (!format_errors.empty()) {
    j["format_errors"] = format_errors;
    j["message"] = kSomeAnswersCouldNotBeRead.in(lang);
    return j;
  }
  j["score"] = r.max_score > 0 ? r.score / r.max_score : 0.0;
  j["message"] =
      fmt::format("{} / {}", number_json(r.score).dump(), number_json(r.max_score).dump());
  // The feedback as HTML for the question's submission panel ({{{feedback.results.frustum_html}}}:
  // pl-external-grader-results shows text only, in <pre>), formulas for PrairieLearn's MathJax;
  // without the key, which the answer panel shows when the assessment's policy allows.
  std::string html;
  for (const ProblemGrade& p : r.problems)
    html += render_problem_feedback_html(p, lang, false, MathMarkup::Delimited);
  j["frustum_html"] = html;
  json tests = json::array();
  for (const ProblemGrade& p : r.problems) {
    json t;
    t["name"] = p.id;
    t["points"] = number_json(p.score);
    t["max_points"] = number_json(p.max_score);
    t["message"] = p.error                  ? visible_text(p.error->format())
                   : p.score >= p.max_score ? std::string(verdict_phrase(Verdict::Correct).in(lang))
                                            : std::string(kSeeTheFeedbackBelow.in(lang));
    tests.push_back(t);
  }
  j["tests"] = tests;
  return j;
}

}  // namespace frustum
