#include "server/set_page.hpp"

#include <fmt/format.h>

#include <map>
#include <nlohmann/json.hpp>

#include "server/feedback_html.hpp"
#include "server/given_tex.hpp"
#include "server/pages.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/problem/variants.hpp"
#include "solver/visibility/pictures.hpp"

namespace frustum::server {

namespace {

std::string title_of(const CourseSet& s) {
  return s.set.title.empty() ? s.id : s.set.title.in(s.set.lang);
}

std::string givens_html(const ProblemSpec& p, Lang lang) {
  if (!p.given_node.IsMap() || p.given_node.size() == 0) return "";
  std::string out =
      fmt::format("<h3>{}</h3>\n<dl class=\"given\">\n", html_escape(kGiven.in(lang)));
  for (auto it = p.given_node.begin(); it != p.given_node.end(); ++it)
    out += fmt::format("<dt>{}</dt><dd><span class=\"tex\" data-tex=\"{}\">{}</span></dd>\n",
                       html_escape(it->first.as<std::string>()), html_escape(given_tex(it->second)),
                       html_escape(given_plain(it->second)));
  return out + "</dl>\n";
}

std::string inputs_html(const ProblemSpec& p, const std::map<std::string, std::string>& drafts) {
  std::string out;
  for (const std::string& name : p.ask) {
    const auto d = drafts.find(p.id + "\x1f" + name);
    out += fmt::format(
        "<div class=\"field\"><label><code>{0}</code> <input type=\"text\" name=\"a.{0}\" "
        "value=\"{1}\" data-answer=\"{0}\" autocomplete=\"off\" spellcheck=\"false\"></label>"
        "<output class=\"preview\" data-for=\"{0}\"></output></div>\n",
        html_escape(name), html_escape(d == drafts.end() ? "" : d->second));
  }
  return out;
}

// Why no more submissions are taken for this problem ("" when they are).
std::string closed_reason(const CourseSet& set, const Visitor& v, int attempts, Millis now,
                          Lang lang) {
  if (set.policy.closed_for(v.student, now)) return std::string(kDeadlinePassed.in(lang));
  if (set.policy.attempts && attempts >= *set.policy.attempts)
    return std::string(kNoAttemptsLeft.in(lang));
  return "";
}

std::string form_html(const CourseSet& set, const ProblemSpec& p, const Visitor& v,
                      const std::map<std::string, std::string>& drafts, int attempts, Millis now,
                      Lang lang) {
  const std::string closed = closed_reason(set, v, attempts, now, lang);
  std::string left;
  if (set.policy.attempts)
    left = fmt::format("<p class=\"left\">{}: {}</p>\n", html_escape(kAttemptsLeft.in(lang)),
                       std::max<std::int64_t>(0, *set.policy.attempts - attempts));
  if (set.policy.penalty > 0)
    left +=
        fmt::format("<p class=\"penalty\">{}: {}</p>\n", html_escape(kPenaltyPerAttempt.in(lang)),
                    html_escape(set.policy.penalty_text));
  return fmt::format(
      "<form method=\"post\" action=\"/set/{0}/submit\" class=\"answers\" data-set=\"{0}\" "
      "data-problem=\"{1}\">\n<input type=\"hidden\" name=\"csrf\" value=\"{2}\">\n"
      "<input type=\"hidden\" name=\"problem\" value=\"{1}\">\n{3}{4}{5}</form>\n",
      html_escape(set.id), html_escape(p.id), html_escape(v.csrf), inputs_html(p, drafts), left,
      closed.empty()
          ? fmt::format("<button type=\"submit\">{}</button>\n", html_escape(kSubmit.in(lang)))
          : fmt::format("<p class=\"closed\">{}</p>\n", html_escape(closed)));
}

// The latest submission to problem `id` (null when none).
const SubmissionRecord* latest_of(const std::vector<SubmissionRecord>& mine,
                                  const std::string& id) {
  for (auto it = mine.rbegin(); it != mine.rend(); ++it)
    if (it->problem == id) return &*it;
  return nullptr;
}

// The figure shows what the answers are (the painter's order, the hidden edges): it belongs to
// the key, shown once a submission is graded and the policy shows the key.
bool figure_allowed(const CourseSet& set, const Visitor& v, const ProblemSpec& p,
                    const std::vector<SubmissionRecord>& mine, bool graded, Millis now) {
  return p.info->drawable && graded &&
         set.policy.shown(v.student, attempts_at(mine, p.id), now).key;
}

std::string problem_html(StudentApp& app, const CourseSet& set, const ProblemSpec& p, int number,
                         const Visitor& v, const std::map<std::string, std::string>& drafts,
                         const std::vector<SubmissionRecord>& mine, Millis now, bool& pending) {
  const Lang lang = set.set.lang;
  const std::string text =
      p.text.empty() ? p.info->summary.in(lang) : fill_text(p.text.in(lang), p.given_node);
  std::string out = fmt::format(
      "<section class=\"problem\" id=\"p-{}\">\n<h2>{} {}</h2>\n<p class=\"text\">{}</p>\n",
      html_escape(p.id), html_escape(kProblem.in(lang)), number, html_escape(text));
  out += givens_html(p, lang);
  const int attempts = attempts_at(mine, p.id);
  out += form_html(set, p, v, drafts, attempts, now, lang);
  // The latest submission in full; earlier ones stay reachable by their own page.
  if (const SubmissionRecord* last = latest_of(mine, p.id)) {
    const std::optional<GradeRecord> g = app.store.latest_grade(last->id);
    pending = pending || !g;
    out += submission_html(*last, g, set.policy.shown(v.student, attempts, now),
                           set.policy.credit_factor(last->attempt), lang);
    if (figure_allowed(set, v, p, mine, g && !g->failed, now))
      out += fmt::format("<figure><img src=\"/set/{}/figure/{}.svg\" alt=\"{}\"></figure>\n",
                         html_escape(set.id), html_escape(url_encode(p.id)),
                         html_escape(kFigure.in(lang)));
  }
  return out + "</section>\n";
}

// What each input holds: the answer last written, a draft or the latest submission's.
std::map<std::string, std::string> answer_values(const std::vector<Draft>& drafts,
                                                 const std::vector<SubmissionRecord>& mine) {
  std::map<std::string, std::pair<std::string, Millis>> latest;
  const auto offer = [&](const std::string& key, const std::string& text, Millis at) {
    auto [it, fresh] = latest.try_emplace(key, text, at);
    if (!fresh && at >= it->second.second) it->second = {text, at};
  };
  for (const Draft& d : drafts) offer(d.problem + "\x1f" + d.answer, d.text, d.saved);
  for (const SubmissionRecord& s : mine) {
    const nlohmann::json answers = nlohmann::json::parse(s.answers, nullptr, false);
    if (!answers.is_object()) continue;
    for (const auto& [name, text] : answers.items())
      if (text.is_string()) offer(s.problem + "\x1f" + name, text.get<std::string>(), s.received);
  }
  std::map<std::string, std::string> out;
  for (const auto& [key, value] : latest) out.emplace(key, value.first);
  return out;
}

}  // namespace

int attempts_at(const std::vector<SubmissionRecord>& mine, const std::string& problem) {
  int n = 0;
  for (const SubmissionRecord& s : mine) n += s.problem == problem;
  return n;
}

Response sets_page(StudentApp& app, const Visitor& v) {
  const Lang lang = course_lang(app.course());
  std::string body = fmt::format("<main>\n<h1>{}</h1>\n", html_escape(kYourSets.in(lang)));
  if (app.course().sets.empty()) body += fmt::format("<p>{}</p>\n", html_escape(kNoSets.in(lang)));
  body += "<ul class=\"sets\">\n";
  for (const CourseSet& s : app.course().sets)
    if (s.for_student(v.student))
      body += fmt::format("<li><a href=\"/set/{}\">{}</a></li>\n", html_escape(s.id),
                          html_escape(title_of(s)));
  body += "</ul>\n</main>\n";
  return html_response(200, page_html(lang, std::string(kYourSets.in(lang)), body));
}

Response set_page(StudentApp& app, const Visitor& v, const CourseSet& set, Millis now) {
  const ProblemSet* variant = set.for_student(v.student);
  const Lang lang = set.set.lang;
  if (!variant) return message_page(404, lang, kNotFound);
  const std::vector<SubmissionRecord> mine = app.store.submissions(v.student, set.id);
  const std::map<std::string, std::string> drafts =
      answer_values(app.store.drafts(v.student, set.id), mine);
  std::string body = fmt::format("<main>\n<p><a href=\"/\">{}</a></p>\n<h1>{}</h1>\n",
                                 html_escape(kAllSets.in(lang)), html_escape(title_of(set)));
  if (set.policy.deadline_for(v.student))
    body += fmt::format("<p class=\"deadline\">{}: <time>{}</time></p>\n",
                        html_escape(kDeadline.in(lang)),
                        html_escape(set.policy.deadline_text_for(v.student)));
  bool pending = false;
  int number = 0;
  for (const ProblemSpec& p : variant->problems)
    body += problem_html(app, set, p, ++number, v, drafts, mine, now, pending);
  body += "</main>\n";
  return html_response(200, page_html(lang, title_of(set), body, v.csrf, pending));
}

Response submission_page(StudentApp& app, const Visitor& v, const CourseSet& set, std::int64_t id,
                         Millis now) {
  const Lang lang = set.set.lang;
  const std::optional<SubmissionRecord> s = app.store.submission(v.student, id);
  if (!s || s->set != set.id) return message_page(404, lang, kNotFound);
  const std::vector<SubmissionRecord> mine = app.store.submissions(v.student, set.id);
  const std::optional<GradeRecord> g = app.store.latest_grade(s->id);
  const std::string body = fmt::format(
      "<main>\n<p><a href=\"/set/{}\">{}</a></p>\n{}</main>\n", html_escape(set.id),
      html_escape(title_of(set)),
      submission_html(*s, g, set.policy.shown(v.student, attempts_at(mine, s->problem), now),
                      set.policy.credit_factor(s->attempt), lang));
  return html_response(200, page_html(lang, title_of(set), body, v.csrf, !g));
}

Response figure_svg(StudentApp& app, const Visitor& v, const CourseSet& set,
                    const std::string& problem, Millis now) {
  const ProblemSet* variant = set.for_student(v.student);
  const ProblemSpec* p = variant ? variant->find(problem) : nullptr;
  if (!p || p->error) return message_page(404, set.set.lang, kNotFound);
  const std::vector<SubmissionRecord> mine = app.store.submissions(v.student, set.id);
  const SubmissionRecord* last = latest_of(mine, p->id);
  const std::optional<GradeRecord> g = last ? app.store.latest_grade(last->id) : std::nullopt;
  if (!figure_allowed(set, v, *p, mine, g && !g->failed, now))
    return message_page(404, set.set.lang, kNotFound);
  try {
    PictureOptions options;
    options.api = p->conventions.api;
    options.lang = set.set.lang;  // the set's pages' language
    Picture picture;
    {
      const std::lock_guard lock(app.exact_math);  // the given holds exact numbers
      picture = draw_picture(p->info->drawable(p->given), options);
    }
    return Response{200,
                    {{"Content-Type", "image/svg+xml"},
                     {"Cache-Control", "private, max-age=3600"},
                     {"Content-Security-Policy", "default-src 'none'; style-src 'unsafe-inline'"}},
                    picture.svg};
  } catch (const std::exception&) {
    return message_page(404, set.set.lang, kNotFound);
  }
}

}  // namespace frustum::server
