// The student side of `frustum serve` as one handler: a plain function of a request, the time
// and the app's state, giving a response (no sockets; tests/server_student_app_test.cpp calls it).
//
//   GET  /start?token=T        the link: token → session cookie, redirect to / (token gone)
//   GET  /                     the student's sets
//   GET  /set/S                their variant of set S, drafts, submissions and feedback
//   POST /set/S/submit         answers committed, then 303 back (JSON 202 when asked)
//   GET  /set/S/submission/N   one of their submissions
//   GET  /set/S/figure/P.svg   a problem's figure
//   POST /api/preview          how an answer is read (never whether it is right)
//   POST /api/draft            an answer as typed so far
//   GET  /static/…             the page's module, style and KaTeX
//   …    /instructor/…         the instructors' pages (server/instructor_app.hpp)
//   …    /instructor/author/S  the authoring page (author_page.hpp), instructors only
#pragma once

#include <functional>
#include <mutex>
#include <string>

#include "server/course.hpp"
#include "server/http.hpp"
#include "server/instructor_state.hpp"
#include "server/live_course.hpp"
#include "server/rate_limit.hpp"
#include "server/store.hpp"

namespace frustum::server {

struct StudentAppOptions {
  bool secure_cookies = false;                   // behind a TLS proxy: cookies marked Secure
  Millis session_ms = 14LL * 24 * 3600 * 1000;   // a session lasts this long
  double preview_rate = 10, preview_burst = 30;  // per session, a second
  double submit_rate = 1, submit_burst = 10;
  // /instructor/events waits this long for the class to change (under the server's request
  // time), with at most `event_waiters` requests waiting at once (others answer at once).
  Millis events_wait_ms = 8000;
  int event_waiters = 32;
  // The authoring page's previews: this binary, run as `serve COURSE --author-preview`, each
  // given this long (the tests name the built binary, not themselves).
  std::string self_binary = "/proc/self/exe";
  double author_seconds = 10;
  // How often the set files are looked at for changes (live_course.hpp), and where the errors
  // of a changed file that no longer loads go.
  Millis look_every_ms = 1000;
  std::function<void(const std::vector<Diagnostic>&)> report;
};

struct StudentApp {
  StudentApp(Course c, Store& s, StudentAppOptions o)
      : store(s),
        options(o),
        preview_limit(o.preview_rate, o.preview_burst),
        draft_limit(o.preview_rate, o.preview_burst),
        submit_limit(o.submit_rate, o.submit_burst),
        live(std::move(c), exact_math, o.look_every_ms, o.report) {}
  // The course this request sees: the snapshot handle_student took when the request began (the
  // sets as their files were then); outside a request, the course as it is now.
  const Course& course() const;
  Store& store;
  StudentAppOptions options;
  RateLimiter preview_limit, draft_limit, submit_limit;
  // GiNaC (the exact numbers in parsed answers and in the course's givens) is not thread-safe:
  // its expressions share reference counts and tables. Every handler that touches exact values
  // — parsing a preview, drawing a figure — holds this; the rest of a page is strings and YAML.
  std::mutex exact_math;
  InstructorState instructor;
  // A set file's save (compare its version, check, keep the old one, write) is one at a time.
  std::mutex author_files;
  LiveCourse live;  // after exact_math, which it uses
};

Response handle_student(StudentApp& app, const Request& request, Millis now);

}  // namespace frustum::server
