#include "server/instructor_app.hpp"

#include <charconv>
#include <filesystem>

#include "batch/gradebook.hpp"
#include "export/export_gradebook.hpp"
#include "server/instructor_pages.hpp"
#include "server/instructor_phrases.hpp"
#include "server/pages.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::server {

namespace {

constexpr const char* kModule = "<script type=\"module\" src=\"/static/instructor.js\"></script>\n";

std::string title_of(const CourseSet& set) {
  return set.set.title.empty() ? set.id : set.set.title.in(set.set.lang);
}

Response page(Lang lang, const std::string& title, const std::string& body, const Visitor& v) {
  return html_response(200, page_html(lang, title, body + kModule, v.csrf));
}

std::optional<std::int64_t> number(const std::string& s) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::vector<BatchRow> class_rows(StudentApp& app, const ClassView& view) {
  return gradebook_rows(app.course(), view);
}

Response csv(const std::string& name, std::string text) {
  return Response{200,
                  {{"Content-Type", "text/csv; charset=utf-8"},
                   {"Content-Disposition", "attachment; filename=\"" + name + "\""},
                   {"Cache-Control", "no-store"}},
                  std::move(text)};
}

Response download(StudentApp& app, const CourseSet& set, const std::string& what) {
  const ClassView view = read_class(app.store, set);
  const std::string text = gradebook_csv(set.set, class_rows(app, view));
  if (what == "gradebook.csv") return csv(set.id + "-gradebook.csv", text);
  const GradebookFormat format =
      what == "canvas.csv" ? GradebookFormat::Canvas : GradebookFormat::Moodle;
  return csv(set.id + "-" + what,
             export_gradebook(text, set.id + "-gradebook.csv", format, title_of(set)));
}

Response class_at_a_glance(StudentApp& app, const Visitor& v, const CourseSet& set,
                           const Request& r) {
  const Lang lang = set.set.lang;
  const auto query = parse_form(r.query());
  GradebookView how;
  if (const auto it = query.find("sort"); it != query.end()) how.sort = it->second;
  how.descending = query.count("desc") && query.at("desc") == "1";
  if (const auto it = query.find("page"); it != query.end())
    if (const auto n = number(it->second); n && *n >= 0 && *n < 100000)
      how.page = static_cast<std::size_t>(*n);
  const std::int64_t mark = app.store.change_mark();
  const ClassView view = read_class(app.store, set);
  std::vector<BatchRow> rows = class_rows(app, view);
  sort_gradebook(rows, set, how);
  const std::string body = class_page(set, view, rows, how, answer_counts(view),
                                      frequent_mistakes(view, kMistakeRows), v, mark, lang);
  return page(lang, title_of(set), body, v);
}

Response student_submissions(StudentApp& app, const Visitor& v, const CourseSet& set,
                             const std::string& student, Millis now) {
  const Lang lang = set.set.lang;
  if (!app.course().enrolled(student) || !set.for_student(student))
    return message_page(404, lang, kNotFound);
  const std::vector<SubmissionRecord> mine = app.store.submissions(student, set.id);
  std::vector<std::vector<GradeRecord>> histories;
  for (const SubmissionRecord& s : mine) histories.push_back(app.store.grade_history(s.id));
  return page(lang, title_of(set) + ": " + student,
              student_page(set, student, mine, histories, now, lang), v);
}

Response copies(StudentApp& app, const Visitor& v, const CourseSet& set, Millis now) {
  const Lang lang = set.set.lang;
  CopyReport report;
  {
    // Looked at again only when the class has changed since.
    const std::lock_guard lock(app.instructor.mutex);
    const std::int64_t mark = app.store.change_mark();
    const auto it = app.instructor.copies.find(set.id);
    if (it != app.instructor.copies.end() && it->second.first == mark) {
      report = it->second.second;
    } else {
      const ClassView view = read_class(app.store, set);
      report = copy_signals(app.course(), view, app.instructor.solved, app.exact_math, now);
      app.instructor.copies[set.id] = {mark, report};
    }
  }
  return page(lang, std::string(kCopySignals.in(lang)), copies_page(set, report, lang), v);
}

// The set file as it is now, and the regrade it makes (empty with `errors` when it cannot be
// served); the lock on exact numbers is held throughout, the fresh set's copies included.
RegradePlan fresh_plan(StudentApp& app, const CourseSet& set, const std::string& problem,
                       const std::string& by, Millis now, std::vector<Diagnostic>& errors) {
  const std::lock_guard math(app.exact_math);
  try {
    const std::optional<CourseSet> fresh = load_course_set(set.file, app.course().roster, errors);
    if (fresh && errors.empty())
      return plan_regrade(app.course(), *fresh, app.store, problem, by, now);
  } catch (const InputError& e) {
    errors.push_back(e.diagnostic());
  }
  if (errors.empty())
    errors.push_back(Diagnostic{SourceLocation{set.file, 0, 0}, "", "cannot be read"});
  return {};
}

Response regrade_refused(const CourseSet& set, const Visitor& v, const std::string& why,
                         const std::string& details) {
  const Lang lang = set.set.lang;
  return html_response(
      409, page_html(lang, std::string(kRegrade.in(lang)),
                     "<main>\n<p class=\"message\">" + html_escape(why) + "</p>\n" + details +
                         "<p><a href=\"/instructor/set/" + url_encode(set.id) + "\">" +
                         html_escape(title_of(set)) + "</a></p>\n</main>\n",
                     v.csrf));
}

Response regrade(StudentApp& app, const Visitor& v, const CourseSet& set,
                 const std::map<std::string, std::string>& form, Millis now) {
  const Lang lang = set.set.lang;
  const auto field = [&](const char* name) {
    const auto it = form.find(name);
    return it == form.end() ? std::string() : it->second;
  };
  const std::string problem = field("problem");
  if (!problem.empty() && !set.set.find(problem)) return message_page(404, lang, kNotFound);
  std::vector<Diagnostic> errors;
  const RegradePlan plan = fresh_plan(app, set, problem, "instructor:" + v.student, now, errors);
  if (!errors.empty()) {
    std::string list = "<ul>\n";
    for (const Diagnostic& d : errors)
      list += "<li><code>" + html_escape(d.format()) + "</code></li>\n";
    return regrade_refused(set, v, std::string(kSetBroken.in(lang)), list + "</ul>\n");
  }
  if (field("apply") != "1")
    return page(lang, std::string(kRegrade.in(lang)), regrade_page(set, plan, problem, v, lang), v);
  // Applied only as the dry run showed it: against the same file.
  if (field("version") != plan.version)
    return regrade_refused(set, v, std::string(kSetChanged.in(lang)), "");
  app.store.record_regrades(plan.grades);
  return page(lang, std::string(kRegrade.in(lang)),
              regrade_done_page(set, plan.grades.size(), lang), v);
}

// Server-sent events: one event per response (the browser's EventSource asks again after
// `retry`), `change` when the class's mark moved past the one the page (or the last event)
// had, after waiting for it a bounded time; across instances the store wakes the wait.
Response events(StudentApp& app, const Request& r) {
  const auto query = parse_form(r.query());
  std::optional<std::int64_t> mark;
  if (const auto last = r.header("last-event-id")) mark = number(*last);
  if (!mark)
    if (const auto it = query.find("mark"); it != query.end()) mark = number(it->second);
  std::int64_t now_mark = app.store.change_mark();
  if (mark && *mark == now_mark && app.options.events_wait_ms > 0) {
    if (++app.instructor.waiting <= app.options.event_waiters)
      now_mark = app.store.wait_for_change(*mark, app.options.events_wait_ms);
    --app.instructor.waiting;
  }
  std::string body = "retry: 1000\nid: " + std::to_string(now_mark) + "\n";
  if (mark && *mark != now_mark) body += "event: change\ndata: " + std::to_string(now_mark) + "\n";
  body += "\n";
  return Response{
      200,
      {{"Content-Type", "text/event-stream; charset=utf-8"}, {"Cache-Control", "no-store"}},
      body};
}

Response set_routes(StudentApp& app, const Visitor& v, const Request& r, const CourseSet& set,
                    const std::string& rest, Millis now) {
  const Lang lang = set.set.lang;
  if (r.method == "POST" && rest == "regrade") {
    const auto form = parse_form(r.body);
    if (!same_origin(r) || !csrf_ok(v, r, form)) return message_page(403, lang, kRefused);
    return regrade(app, v, set, form, now);
  }
  if (r.method != "GET") return message_page(405, lang, kNotFound);
  if (rest.empty()) return class_at_a_glance(app, v, set, r);
  if (rest == "gradebook.csv" || rest == "canvas.csv" || rest == "moodle.csv")
    return download(app, set, rest);
  if (rest == "copies") return copies(app, v, set, now);
  constexpr std::string_view kStudentPath = "student/";
  if (rest.rfind(kStudentPath, 0) == 0)
    return student_submissions(app, v, set, url_decode(rest.substr(kStudentPath.size())), now);
  return message_page(404, lang, kNotFound);
}

}  // namespace

Response handle_instructor(StudentApp& app, const Visitor& v, const Request& r, Millis now) {
  const std::string path = r.path();
  const Lang lang = course_lang(app.course());
  if (path == "/instructor" || path == "/instructor/") {
    if (r.method != "GET") return message_page(405, lang, kNotFound);
    std::vector<std::size_t> counts;
    for (const CourseSet& s : app.course().sets)
      counts.push_back(app.store.set_submissions(s.id, kMaxClassSubmissions).size());
    return page(lang, std::string(kYourCourse.in(lang)), course_page(app.course(), counts, lang),
                v);
  }
  if (path == "/instructor/events" && r.method == "GET") return events(app, r);
  constexpr std::string_view kSet = "/instructor/set/";
  if (path.rfind(kSet, 0) == 0) {
    const std::string tail = path.substr(kSet.size());
    const auto slash = tail.find('/');
    const std::string id = tail.substr(0, slash);
    if (const CourseSet* set = app.course().find(id))
      return set_routes(app, v, r, *set, slash == std::string::npos ? "" : tail.substr(slash + 1),
                        now);
  }
  return message_page(404, lang, kNotFound);
}

}  // namespace frustum::server
