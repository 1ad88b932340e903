#include "server/feedback_html.hpp"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "report/report.hpp"
#include "server/http.hpp"
#include "server/phrases.hpp"

namespace frustum::server {

namespace {

using Json = nlohmann::json;

const Phrase& verdict_phrase(const std::string& v) {
  if (v == "correct") return kCorrect;
  if (v == "partial") return kPartial;
  if (v == "unparseable") return kUnreadable;
  if (v == "missing") return kMissing;
  return kIncorrect;
}

std::string text_of(const Json& j, const char* key) {
  return j.contains(key) && j[key].is_string() ? j[key].get<std::string>() : "";
}

std::string labelled(const char* cls, const Phrase& label, const std::string& text, Lang lang) {
  if (text.empty()) return "";
  return fmt::format("<p class=\"{}\"><strong>{}</strong>: {}</p>\n", cls,
                     html_escape(label.in(lang)), html_escape(text));
}

std::string carried_html(const Json& a, Lang lang) {
  if (!a.value("carried_forward", false)) return "";
  std::string used;
  for (const Json& c : a.value("carried_from", Json::array()))
    used += fmt::format("{}<code>{}</code> = <code>{}</code>", used.empty() ? "" : ", ",
                        html_escape(text_of(c, "name")), html_escape(text_of(c, "text")));
  return fmt::format("<p class=\"carried\"><strong>{}</strong>{}{}</p>\n",
                     html_escape(kCarried.in(lang)), used.empty() ? "" : ": ", used);
}

std::string answer_html(const Json& a, const FeedbackShown& shown, Lang lang) {
  const std::string verdict = text_of(a, "verdict");
  // Without the verdicts, not even the class (its colour) tells them.
  std::string out = fmt::format(
      "<div class=\"answer verdict-{0}\" data-answer=\"{1}\">\n<h4><code>{1}</code>",
      shown.verdicts ? html_escape(verdict) : "hidden", html_escape(text_of(a, "name")));
  if (shown.verdicts)
    out += fmt::format(": <span class=\"verdict\">{}</span>",
                       html_escape(verdict_phrase(verdict).in(lang)));
  if (shown.credit)
    out += fmt::format(" <span class=\"points\">{} / {}</span>", score_text(a.value("score", 0.0)),
                       score_text(a.value("max_score", 0.0)));
  out += "</h4>\n";
  if (!text_of(a, "got_text").empty())
    out += fmt::format("<p class=\"got\">{}: <code>{}</code></p>\n",
                       html_escape(kYourAnswer.in(lang)), html_escape(text_of(a, "got_text")));
  if (shown.mistakes) {
    if (verdict != "correct") out += labelled("feedback", kFeedback, text_of(a, "feedback"), lang);
    out += labelled("mistake", kMistake, text_of(a, "mistake"), lang);
    out += labelled("where", kWhereWrong, text_of(a, "wrong_step"), lang);
    out += carried_html(a, lang);
  }
  // The right answer, typeset by the page from the LaTeX Frustum made (its Unicode without
  // JavaScript); grades stored before it was recorded have none.
  if (shown.key && verdict != "correct" && !text_of(a, "key_tex").empty())
    out += fmt::format(
        "<p class=\"key\"><strong>{}</strong>: <span class=\"tex\" data-tex=\"{}\">{}</span></p>\n",
        html_escape(kRightAnswer.in(lang)), html_escape(text_of(a, "key_tex")),
        html_escape(text_of(a, "key_text")));
  // Made by the server from the grader's steps, its texts escaped there (html_steps).
  if (shown.derivation && !text_of(a, "derivation_html").empty())
    out += fmt::format("<details class=\"derivation\"><summary>{}</summary>\n{}</details>\n",
                       html_escape(kDerivation.in(lang)), text_of(a, "derivation_html"));
  return out + "</div>\n";
}

std::string graded_html(const GradeRecord& g, std::int64_t attempt, const FeedbackShown& shown,
                        double credit_factor, Lang lang) {
  if (g.failed)
    return fmt::format("<p class=\"failed\">{}</p>\n", html_escape(kGradingFailed.in(lang)));
  if (!shown.any())
    return fmt::format("<p class=\"later\">{}</p>\n", html_escape(kFeedbackLater.in(lang)));
  const Json result = Json::parse(g.result, nullptr, false);
  std::string out;
  if (shown.credit) {
    out = fmt::format("<p class=\"score\">{}: {} / {}</p>\n", html_escape(kScore.in(lang)),
                      score_text(g.score), score_text(g.max_score));
    if (credit_factor < 1)
      out +=
          fmt::format("<p class=\"credited\">{} ({} {}): {} / {}</p>\n",
                      html_escape(kCreditedAfterPenalty.in(lang)), html_escape(kAttempt.in(lang)),
                      attempt, score_text(g.score * credit_factor), score_text(g.max_score));
  }
  if (result.is_object())
    for (const Json& a : result.value("answers", Json::array())) out += answer_html(a, shown, lang);
  return out;
}

}  // namespace

std::string submission_html(const SubmissionRecord& s, const std::optional<GradeRecord>& grade,
                            const FeedbackShown& shown, double credit_factor, Lang lang) {
  const char* state = !grade ? "pending" : grade->failed ? "failed" : "graded";
  std::string out =
      fmt::format("<div class=\"submission\" id=\"s-{0}\" data-state=\"{1}\">\n<h3>{2} {3}</h3>\n",
                  s.id, state, html_escape(kAttempt.in(lang)), s.attempt);
  if (!grade)
    return out +
           fmt::format("<p class=\"pending\">{}</p>\n</div>\n", html_escape(kReceived.in(lang)));
  return out + graded_html(*grade, s.attempt, shown, credit_factor, lang) + "</div>\n";
}

}  // namespace frustum::server
