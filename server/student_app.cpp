#include "server/student_app.hpp"

#include <charconv>

#include "server/answer_api.hpp"
#include "server/author_page.hpp"
#include "server/instructor_app.hpp"
#include "server/pages.hpp"
#include "server/session.hpp"
#include "server/set_page.hpp"
#include "server/static_assets.hpp"

namespace frustum::server {

namespace {

// "/set/S/rest" → {S, rest}; nothing when the path is not under /set/.
std::optional<std::pair<std::string, std::string>> set_path(const std::string& path) {
  constexpr std::string_view kSet = "/set/";
  if (path.rfind(kSet, 0) != 0) return std::nullopt;
  const std::string tail = path.substr(kSet.size());
  const auto slash = tail.find('/');
  if (slash == std::string::npos) return std::pair{tail, std::string()};
  return std::pair{tail.substr(0, slash), tail.substr(slash + 1)};
}

std::optional<std::int64_t> number(const std::string& s) {
  std::int64_t v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

Response set_routes(StudentApp& app, const Visitor& v, const Request& r, const CourseSet& set,
                    const std::string& rest, Millis now) {
  const Lang lang = set.set.lang;
  if (rest.empty() && r.method == "GET") return set_page(app, v, set, now);
  if (rest == "submit" && r.method == "POST") {
    const auto form = parse_form(r.body);
    if (!same_origin(r) || !csrf_ok(v, r, form)) return message_page(403, lang, kRefused);
    return submit_answers(app, v, set, r, form, now);
  }
  constexpr std::string_view kSubmissionPath = "submission/", kFigurePath = "figure/";
  if (r.method == "GET" && rest.rfind(kSubmissionPath, 0) == 0)
    if (const auto id = number(rest.substr(kSubmissionPath.size())))
      return submission_page(app, v, set, *id, now);
  if (r.method == "GET" && rest.rfind(kFigurePath, 0) == 0 && rest.size() > 4 &&
      rest.compare(rest.size() - 4, 4, ".svg") == 0)
    return figure_svg(
        app, v, set,
        url_decode(rest.substr(kFigurePath.size(), rest.size() - 4 - kFigurePath.size())), now);
  return message_page(404, lang, kNotFound);
}

Response api_routes(StudentApp& app, const Visitor& v, const Request& r, Millis now) {
  if (r.method != "POST") return message_page(405, course_lang(app.course()), kNotFound);
  const auto form = parse_form(r.body);
  if (!same_origin(r) || !csrf_ok(v, r, form)) return json_response(403, R"({"error":"refused"})");
  if (r.path() == "/api/preview") return preview_answer(app, v, form, now);
  if (r.path() == "/api/draft") return save_draft(app, v, form, now);
  return json_response(404, R"({"error":"not found"})");
}

Response route(StudentApp& app, const Request& r, Millis now) {
  const std::string path = r.path();
  if (path.rfind("/static/", 0) == 0 && r.method == "GET") {
    if (auto a = static_asset(path.substr(8))) return *a;
    return message_page(404, course_lang(app.course()), kNotFound);
  }
  if (path == "/start" && r.method == "GET") return start_session(app, r, now);
  const std::optional<Visitor> v = visitor_of(app, r, now);
  if (!v) return message_page(path == "/" ? 200 : 403, course_lang(app.course()), kSignInFirst);
  // /instructor/… is the instructors' (a student's session is refused); the rest the students'.
  if (path == "/instructor" || path.rfind("/instructor/", 0) == 0) {
    if (v->role != Role::Instructor) return message_page(403, course_lang(app.course()), kRefused);
    constexpr std::string_view kAuthor = "/instructor/author/";
    if (path.rfind(kAuthor, 0) == 0)
      return author_routes(app, *v, r, path.substr(kAuthor.size()), now);
    return handle_instructor(app, *v, r, now);
  }
  if (v->role == Role::Instructor) {
    if (path == "/" && r.method == "GET") return Response{303, {{"Location", "/instructor/"}}, ""};
    // A student's pages and requests are refused; anything else is not here (a favicon).
    if (path.rfind("/set/", 0) == 0 || path.rfind("/api/", 0) == 0)
      return message_page(403, course_lang(app.course()), kRefused);
    return message_page(404, course_lang(app.course()), kNotFound);
  }
  if (path == "/" && r.method == "GET") return sets_page(app, *v);
  if (path.rfind("/api/", 0) == 0) return api_routes(app, *v, r, now);
  if (const auto sp = set_path(path))
    if (const CourseSet* set = app.course().find(sp->first); set && set->for_student(v->student))
      return set_routes(app, *v, r, *set, sp->second, now);
  return message_page(404, course_lang(app.course()), kNotFound);
}

// The course the request on this thread began with (handle_student holds it to the end).
thread_local const Course* t_request_course = nullptr;

}  // namespace

const Course& StudentApp::course() const {
  if (t_request_course) return *t_request_course;
  return *live.current();  // outside a request: valid until the next reload
}

Response handle_student(StudentApp& app, const Request& request, Millis now) {
  const std::shared_ptr<const Course> held = app.live.at(now);
  struct Hold {  // restores the outer request's course (none) on every way out
    const Course* outer;
    explicit Hold(const Course* c) : outer(t_request_course) { t_request_course = c; }
    ~Hold() { t_request_course = outer; }
  } hold(held.get());
  Response r;
  try {
    r = route(app, request, now);
  } catch (const StoreError&) {
    r = message_page(503, course_lang(app.course()), kBusy, 1);
  }
  secure_headers(r);
  return r;
}

}  // namespace frustum::server
