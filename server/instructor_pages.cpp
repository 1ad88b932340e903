#include "server/instructor_pages.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <ctime>
#include <nlohmann/json.hpp>

#include "report/report.hpp"
#include "server/feedback_html.hpp"
#include "server/instructor_phrases.hpp"
#include "server/phrases.hpp"
#include "server/set_page.hpp"

namespace frustum::server {

namespace {

std::string esc(const std::string& s) { return html_escape(s); }
std::string t(const Phrase& phrase, Lang lang) { return html_escape(phrase.in(lang)); }

std::string title_of(const CourseSet& set) {
  return set.set.title.empty() ? set.id : set.set.title.in(set.set.lang);
}

std::string base(const CourseSet& set) { return "/instructor/set/" + url_encode(set.id); }

std::string verdict_text(const std::string& v, Lang lang) {
  if (v == "correct") return t(kCorrect, lang);
  if (v == "partial") return t(kPartial, lang);
  if (v == "unparseable") return t(kUnreadable, lang);
  if (v == "missing") return t(kMissing, lang);
  return t(kIncorrect, lang);
}

std::string status_text(const std::string& status, Lang lang) {
  if (status == "graded") return t(kStatusGraded, lang);
  if (status == "pending") return t(kStatusPending, lang);
  return t(kStatusNone, lang);
}

double percent(const BatchRow& r) { return r.max_score > 0 ? r.score / r.max_score : -1; }

// A column header that sorts by `key` (the other way when it already does).
std::string sort_link(const CourseSet& set, const GradebookView& how, const std::string& key,
                      const std::string& label) {
  const bool on = how.sort == key;
  return fmt::format(
      "<th><a href=\"{}?sort={}{}\"{}>{}{}</a></th>", base(set), esc(url_encode(key)),
      on && !how.descending ? "&amp;desc=1" : "",
      on ? " aria-sort=\"" + std::string(how.descending ? "descending" : "ascending") + "\"" : "",
      label, on ? (how.descending ? " ▼" : " ▲") : "");
}

std::string gradebook_html(const CourseSet& set, const std::vector<BatchRow>& rows,
                           const GradebookView& how, Lang lang) {
  std::string out = fmt::format(
      "<section id=\"gradebook\">\n<h2>{0}</h2>\n<p class=\"downloads\">{1}: <a "
      "href=\"{2}/gradebook.csv\">CSV</a> · <a href=\"{2}/canvas.csv\">Canvas</a> · <a "
      "href=\"{2}/moodle.csv\">Moodle</a></p>\n<table class=\"gradebook\">\n<thead><tr>",
      t(kGradebook, lang), t(kDownloadAs, lang), base(set));
  out += sort_link(set, how, "student", t(kStudent, lang));
  out += sort_link(set, how, "score", t(kScore, lang));
  out += sort_link(set, how, "percent", t(kPercent, lang));
  out += sort_link(set, how, "status", t(kStatus, lang));
  for (const ProblemSpec& p : set.set.problems) out += sort_link(set, how, "p." + p.id, esc(p.id));
  out += "</tr></thead>\n<tbody>\n";
  const std::size_t first = how.page * kGradebookPage;
  for (std::size_t i = first; i < rows.size() && i < first + kGradebookPage; ++i) {
    const BatchRow& r = rows[i];
    const std::string student = base(set) + "/student/" + url_encode(r.student);
    out += fmt::format(
        "<tr data-student=\"{}\"><td><a href=\"{}\">{}</a></td><td>{} / {}</td><td>{}</td>"
        "<td class=\"status-{}\">{}</td>",
        esc(r.student), esc(student), esc(r.student), score_text(r.score), score_text(r.max_score),
        r.max_score > 0 ? fmt::format("{:.1f}", 100 * r.score / r.max_score) : "", esc(r.status),
        status_text(r.status, lang));
    for (std::size_t p = 0; p < set.set.problems.size(); ++p)
      out += fmt::format("<td><a href=\"{}#p-{}\">{}</a></td>", esc(student),
                         esc(url_encode(set.set.problems[p].id)),
                         r.status == "error" || p >= r.problem_scores.size()
                             ? "–"
                             : score_text(r.problem_scores[p]));
    out += "</tr>\n";
  }
  out += "</tbody>\n</table>\n";
  if (rows.size() > kGradebookPage) {
    out += fmt::format("<p class=\"pages\">{}:", t(kPage, lang));
    for (std::size_t p = 0; p * kGradebookPage < rows.size(); ++p)
      out += p == how.page ? fmt::format(" <strong>{}</strong>", p + 1)
                           : fmt::format(" <a href=\"{}?sort={}{}&amp;page={}\">{}</a>", base(set),
                                         esc(url_encode(how.sort)),
                                         how.descending ? "&amp;desc=1" : "", p, p + 1);
    out += "</p>\n";
  }
  return out + "</section>\n";
}

std::string counts_html(const std::vector<AnswerCount>& counts, Lang lang) {
  std::string out = fmt::format(
      "<section id=\"answers\">\n<h2>{}</h2>\n<table class=\"counts\">\n<thead><tr><th>{}</th>"
      "<th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>"
      "</thead>\n<tbody>\n",
      t(kProblemsAndAnswers, lang), t(kProblem, lang), t(kAnswer, lang), t(kSubmitted, lang),
      t(kRight, lang), t(kPartlyRight, lang), t(kWrong, lang), t(kInstructorUnreadable, lang),
      t(kMedianAttempts, lang));
  for (const AnswerCount& c : counts)
    out += fmt::format(
        "<tr class=\"{}\" data-problem=\"{}\" data-answer=\"{}\"><td>{}</td><td>{}</td>"
        "<td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
        c.answer.empty() ? "problem" : "answer", esc(c.problem), esc(c.answer),
        c.answer.empty() ? esc(c.problem) : "",
        c.answer.empty() ? "" : "<code>" + esc(c.answer) + "</code>", c.submitted, c.right,
        c.partly, c.wrong, c.unreadable, score_text(c.median_attempts));
  return out + "</tbody>\n</table>\n</section>\n";
}

std::string mistakes_html(const CourseSet& set, const std::vector<MistakeRow>& mistakes,
                          Lang lang) {
  std::string out = fmt::format("<section id=\"mistakes\">\n<h2>{}</h2>\n", t(kMistakes, lang));
  if (mistakes.empty()) return out + fmt::format("<p>{}</p>\n</section>\n", t(kNoMistakes, lang));
  out += fmt::format(
      "<table class=\"mistakes\">\n<thead><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th>"
      "</tr></thead>\n<tbody>\n",
      t(kProblem, lang), t(kAnswer, lang), t(kMistake, lang), t(kTheStudents, lang));
  for (const MistakeRow& m : mistakes) {
    std::string who;
    for (const std::string& student : m.students)
      who +=
          fmt::format("{}<a href=\"{}/student/{}#p-{}\">{}</a>", who.empty() ? "" : ", ", base(set),
                      esc(url_encode(student)), esc(url_encode(m.problem)), esc(student));
    out += fmt::format(
        "<tr><td>{}</td><td><code>{}</code></td><td class=\"mistake\">{}</td><td>{} "
        "<span class=\"who\">({})</span></td></tr>\n",
        esc(m.problem), esc(m.answer), esc(m.mistake), m.students.size(), who);
  }
  return out + "</tbody>\n</table>\n</section>\n";
}

std::string regrade_form(const CourseSet& set, const Visitor& v, Lang lang) {
  std::string options = fmt::format("<option value=\"\">{}</option>", t(kWholeSet, lang));
  for (const ProblemSpec& p : set.set.problems)
    options += fmt::format("<option value=\"{0}\">{0}</option>", esc(p.id));
  return fmt::format(
      "<section id=\"regrade\">\n<h2>{}</h2>\n<p>{}</p>\n<form method=\"post\" "
      "action=\"{}/regrade\">\n<input type=\"hidden\" name=\"csrf\" value=\"{}\">\n<label>{} "
      "<select name=\"problem\">{}</select></label>\n<button type=\"submit\">{}</button>\n"
      "</form>\n</section>\n",
      t(kRegrade, lang), t(kRegradeHelp, lang), base(set), esc(v.csrf), t(kProblem, lang), options,
      t(kDryRun, lang));
}

std::string back_link(const CourseSet& set) {
  return fmt::format("<p><a href=\"{}\">{}</a></p>\n", base(set), esc(title_of(set)));
}

}  // namespace

std::string utc_text(Millis ms) {
  const std::time_t seconds = static_cast<std::time_t>(ms / 1000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char buffer[32];
  std::strftime(buffer, sizeof buffer, "%Y-%m-%d %H:%M:%S UTC", &tm);
  return buffer;
}

void sort_gradebook(std::vector<BatchRow>& rows, const CourseSet& set, const GradebookView& how) {
  std::size_t problem = set.set.problems.size();
  for (std::size_t i = 0; i < set.set.problems.size(); ++i)
    if (how.sort == "p." + set.set.problems[i].id) problem = i;
  const auto key_less = [&](const BatchRow& a, const BatchRow& b) {
    if (how.sort == "student") return a.student < b.student;
    if (how.sort == "score") return a.score < b.score;
    if (how.sort == "percent") return percent(a) < percent(b);
    if (how.sort == "status") return a.status < b.status;
    if (problem < set.set.problems.size()) {
      const auto at = [&](const BatchRow& r) {
        return problem < r.problem_scores.size() && r.status != "error" ? r.problem_scores[problem]
                                                                        : -1.0;
      };
      return at(a) < at(b);
    }
    return false;
  };
  std::stable_sort(rows.begin(), rows.end(), [&](const BatchRow& a, const BatchRow& b) {
    return how.descending ? key_less(b, a) : key_less(a, b);
  });
}

std::string course_page(const Course& course, const std::vector<std::size_t>& submissions,
                        Lang lang) {
  std::string out = fmt::format("<main>\n<h1>{}</h1>\n<ul class=\"sets\">\n", t(kYourCourse, lang));
  for (std::size_t i = 0; i < course.sets.size(); ++i)
    out += fmt::format(
        "<li><a href=\"{}\">{}</a> ({}: {}) · <a href=\"/instructor/author/{}\">{}</a></li>\n",
        base(course.sets[i]), esc(title_of(course.sets[i])), t(kSubmitted, lang),
        i < submissions.size() ? submissions[i] : 0, esc(url_encode(course.sets[i].id)),
        t(kEdit, lang));
  return out + "</ul>\n</main>\n";
}

// The set's policy as its students meet it: when each part of the feedback shows, the attempts,
// their penalty, the deadline and each extension.
std::string policy_html(const ServePolicy& p, Lang lang) {
  const auto when = [&](const FeedbackWhen& w) {
    using K = FeedbackWhen::Kind;
    switch (w.kind) {
      case K::AfterSubmit:
        return t(kAtOnce, lang);
      case K::AfterAttempts:
        return t(kFromAttempt, lang) + " " + std::to_string(w.attempts);
      case K::AfterDeadline:
        return t(kAfterTheirDeadline, lang);
      case K::AtDate:
        return t(kFromDate, lang) + " " + esc(utc_text(w.at));
      case K::Never:
        return t(kNever, lang);
    }
    return std::string();
  };
  constexpr const Phrase* kParts[] = {&kPartVerdicts, &kPartCredit, &kPartMistakes, &kPartKey,
                                      &kPartDerivation};
  std::string out =
      fmt::format("<section class=\"policy\">\n<h2>{}</h2>\n<dl>\n", t(kWhatStudentsSee, lang));
  for (std::size_t i = 0; i < p.feedback.size(); ++i)
    out += fmt::format("<dt>{}</dt><dd>{}</dd>\n", t(*kParts[i], lang), when(p.feedback[i]));
  out += fmt::format("<dt>{}</dt><dd>{}</dd>\n", t(kAttempts, lang),
                     p.attempts ? std::to_string(*p.attempts) : t(kUnlimited, lang));
  if (p.penalty > 0)
    out += fmt::format("<dt>{}</dt><dd>{}</dd>\n", t(kInstructorPenaltyPerAttempt, lang),
                       esc(p.penalty_text));
  if (p.deadline_ms)
    out += fmt::format("<dt>{}</dt><dd><time>{}</time></dd>\n", t(kDeadline, lang),
                       esc(p.deadline_text));
  for (const auto& [student, e] : p.extensions)
    out += fmt::format("<dt>{}</dt><dd>{}: <time>{}</time></dd>\n", t(kExtensions, lang),
                       esc(student), esc(e.text));
  return out + "</dl>\n</section>\n";
}

std::string class_page(const CourseSet& set, const ClassView& view,
                       const std::vector<BatchRow>& sorted_rows, const GradebookView& how,
                       const std::vector<AnswerCount>& counts,
                       const std::vector<MistakeRow>& mistakes, const Visitor& v, std::int64_t mark,
                       Lang lang) {
  std::string out = fmt::format(
      "<main data-events=\"/instructor/events?set={}&amp;mark={}\">\n<p><a "
      "href=\"/instructor/\">{}</a></p>\n<h1>{}: {}</h1>\n<p class=\"live\">{}</p>\n",
      esc(url_encode(set.id)), mark, t(kYourCourse, lang), esc(title_of(set)), t(kClassTitle, lang),
      t(kLive, lang));
  if (view.truncated)
    out +=
        fmt::format("<p class=\"note\">{} {}</p>\n", t(kCheckedOnly, lang), kMaxClassSubmissions);
  out += gradebook_html(set, sorted_rows, how, lang);
  out += counts_html(counts, lang);
  out += mistakes_html(set, mistakes, lang);
  if (!set.variants.empty())
    out += fmt::format("<p><a href=\"{}/copies\">{}</a></p>\n", base(set), t(kCopySignals, lang));
  out += policy_html(set.policy, lang);
  out += regrade_form(set, v, lang);
  return out + "</main>\n";
}

std::string student_page(const CourseSet& set, const std::string& student,
                         const std::vector<SubmissionRecord>& submissions,
                         const std::vector<std::vector<GradeRecord>>& histories, Millis now,
                         Lang lang) {
  std::string out =
      fmt::format("<main>\n{}<h1>{}: {}</h1>\n", back_link(set), esc(title_of(set)), esc(student));
  for (const ProblemSpec& p : set.set.problems) {
    out += fmt::format("<section class=\"problem\" id=\"p-{}\">\n<h2>{} {}</h2>\n", esc(p.id),
                       t(kProblem, lang), esc(p.id));
    int attempts = 0;
    for (const SubmissionRecord& sub : submissions) attempts += sub.problem == p.id;
    for (std::size_t i = 0; i < submissions.size(); ++i) {
      const SubmissionRecord& sub = submissions[i];
      if (sub.problem != p.id) continue;
      const std::vector<GradeRecord>& history = histories[i];
      out += fmt::format(
          "<article class=\"submission\" id=\"s-{}\">\n<h3>{} {} · <time>{}</time></h3>\n", sub.id,
          t(kAttempt, lang), sub.attempt, esc(utc_text(sub.received)));
      // The answers as written.
      out += fmt::format(
          "<table class=\"written\"><thead><tr><th>{}</th><th>{}</th></tr></thead>"
          "<tbody>\n",
          t(kAnswer, lang), t(kAsWritten, lang));
      const nlohmann::json written = nlohmann::json::parse(sub.answers, nullptr, false);
      if (written.is_object())
        for (const auto& [name, text] : written.items())
          out += fmt::format("<tr><td><code>{}</code></td><td><code>{}</code></td></tr>\n",
                             esc(name), esc(text.is_string() ? text.get<std::string>() : ""));
      out += "</tbody></table>\n";
      // What the student sees of it, under the set's feedback policy.
      const std::optional<GradeRecord> last =
          history.empty() ? std::nullopt : std::optional<GradeRecord>(history.back());
      out += fmt::format("<details class=\"seen\" open><summary>{}</summary>\n{}</details>\n",
                         t(kAsSeen, lang),
                         submission_html(sub, last, set.policy.shown(sub.student, attempts, now),
                                         set.policy.credit_factor(sub.attempt), lang));
      if (!history.empty()) {
        out += fmt::format(
            "<table class=\"history\"><caption>{}</caption><thead><tr><th>{}</th><th>{}</th>"
            "<th>{}</th><th>{}</th></tr></thead><tbody>\n",
            t(kHistory, lang), t(kScore, lang), t(kSetVersion, lang), t(kWhen, lang), t(kBy, lang));
        for (const GradeRecord& g : history)
          out += fmt::format(
              "<tr><td>{}</td><td><code title=\"{}\">{}</code></td><td>{}</td><td>{}</td></tr>\n",
              g.failed ? t(kFailed, lang) : score_text(g.score) + " / " + score_text(g.max_score),
              esc(g.set_version), esc(g.set_version.substr(0, 12)), esc(utc_text(g.graded)),
              esc(g.graded_by));
        out += "</tbody></table>\n";
      }
      out += "</article>\n";
    }
    out += "</section>\n";
  }
  return out + "</main>\n";
}

std::string regrade_page(const CourseSet& set, const RegradePlan& plan, const std::string& problem,
                         const Visitor& v, Lang lang) {
  std::string out =
      fmt::format("<main>\n{}<h1>{}: {} — {}</h1>\n", back_link(set), t(kRegrade, lang),
                  esc(title_of(set)), problem.empty() ? t(kWholeSet, lang) : esc(problem));
  out += fmt::format("<p>{}: <code>{}</code></p>\n", t(kSetVersion, lang), esc(plan.version));
  if (plan.truncated)
    out += fmt::format("<p class=\"note\">{} {}</p>\n", t(kCheckedOnly, lang), kMaxRegrade);
  if (plan.changes.empty()) {
    out += fmt::format("<p class=\"no-changes\">{}</p>\n", t(kNoChanges, lang));
  } else {
    out += fmt::format(
        "<table class=\"changes\">\n<thead><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th>"
        "<th>{}</th><th>{}</th></tr></thead>\n<tbody>\n",
        t(kStudent, lang), t(kProblem, lang), t(kAttempt, lang), t(kBefore, lang), t(kAfter, lang),
        t(kWhy, lang));
    for (const RegradeChange& c : plan.changes) {
      std::string why;
      for (const RegradeChange::Answer& a : c.answers)
        why += fmt::format("<li><code>{}</code>: {} → {}</li>", esc(a.name),
                           verdict_text(a.before, lang), verdict_text(a.after, lang));
      if (c.failed_before != c.failed_after) why += "<li>" + t(kFailed, lang) + "</li>";
      if (why.empty()) why = "<li>" + t(kSameVerdicts, lang) + "</li>";
      out += fmt::format(
          "<tr data-student=\"{0}\" data-problem=\"{1}\"><td><a href=\"{2}/student/{3}#s-{4}\">"
          "{0}</a></td><td>{1}</td><td>{5}</td><td class=\"before\">{6}</td>"
          "<td class=\"after\">{7}</td><td><ul>{8}</ul></td></tr>\n",
          esc(c.student), esc(c.problem), base(set), esc(url_encode(c.student)), c.submission,
          c.attempt, c.failed_before ? t(kFailed, lang) : score_text(c.before),
          c.failed_after ? t(kFailed, lang) : score_text(c.after), why);
    }
    out += "</tbody>\n</table>\n";
  }
  if (!plan.grades.empty())
    out += fmt::format(
        "<form method=\"post\" action=\"{}/regrade\">\n<input type=\"hidden\" name=\"csrf\" "
        "value=\"{}\">\n<input type=\"hidden\" name=\"problem\" value=\"{}\">\n<input "
        "type=\"hidden\" name=\"version\" value=\"{}\">\n<input type=\"hidden\" name=\"apply\" "
        "value=\"1\">\n<button type=\"submit\">{}</button>\n</form>\n",
        base(set), esc(v.csrf), esc(problem), esc(plan.version), t(kApply, lang));
  return out + "</main>\n";
}

std::string regrade_done_page(const CourseSet& set, std::size_t written, Lang lang) {
  return fmt::format("<main>\n{}<p class=\"applied\">{} <strong>{}</strong></p>\n</main>\n",
                     back_link(set), t(kApplied, lang), written);
}

std::string copies_page(const CourseSet& set, const CopyReport& report, Lang lang) {
  std::string out = fmt::format("<main>\n{}<h1>{}</h1>\n<p>{}</p>\n", back_link(set),
                                t(kCopySignals, lang), t(kCopyHelp, lang));
  if (report.truncated)
    out += fmt::format("<p class=\"note\">{} {}</p>\n", t(kCheckedOnly, lang), kMaxCopyGradings);
  if (report.signals.empty()) return out + fmt::format("<p>{}</p>\n</main>\n", t(kNoCopies, lang));
  for (const CopySignal& c : report.signals) {
    out += fmt::format(
        "<article class=\"copy\" data-student=\"{0}\" data-fits=\"{1}\">\n<h2><a "
        "href=\"{2}/student/{3}#s-{4}\">{0}</a> · {5} {6} · {7} {8}</h2>\n<p>{9}: <a "
        "href=\"{2}/student/{10}\">{1}</a> ({11}: {12} / {14}; {13}: {15} / {14})</p>\n",
        esc(c.student), esc(c.fits), base(set), esc(url_encode(c.student)), c.submission,
        t(kProblem, lang), esc(c.problem), t(kAttempt, lang), c.attempt, t(kFitsVariantOf, lang),
        esc(url_encode(c.fits)), t(kOwnVerdict, lang), score_text(c.own_score),
        t(kOtherVerdict, lang), score_text(c.max_score), score_text(c.fit_score));
    out += fmt::format(
        "<table><thead><tr><th>{}</th><th>{}</th><th>{}</th><th>{}</th></tr>"
        "</thead><tbody>\n",
        t(kAnswer, lang), t(kAsWritten, lang), t(kOwnVerdict, lang), t(kOtherVerdict, lang));
    for (const CopySignal::Answer& a : c.answers)
      out += fmt::format(
          "<tr><td><code>{}</code></td><td><code>{}</code></td><td>{}</td>"
          "<td>{}</td></tr>\n",
          esc(a.name), esc(a.written), verdict_text(a.own, lang), verdict_text(a.fit, lang));
    out += "</tbody></table>\n</article>\n";
  }
  return out + "</main>\n";
}

}  // namespace frustum::server
