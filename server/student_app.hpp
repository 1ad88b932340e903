// The student side of `frustum serve` as one handler: a plain function of a request, the time
// and the app's state, giving a response (no sockets; tests/server_handlers_test.cpp calls it).
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
//   …    /instructor/author/S  the authoring page (author_page.hpp), instructors only
#pragma once

#include <mutex>
#include <string>

#include "server/course.hpp"
#include "server/http.hpp"
#include "server/rate_limit.hpp"
#include "server/store.hpp"

namespace frustum::server {

struct AppConfig {
  bool secure_cookies = false;                   // behind a TLS proxy: cookies marked Secure
  Millis session_ms = 14LL * 24 * 3600 * 1000;   // a session lasts this long
  double preview_rate = 10, preview_burst = 30;  // per session, a second
  double submit_rate = 1, submit_burst = 10;
  // The authoring page's previews: this binary, run as `serve COURSE --author-preview`, each
  // given this long (the tests name the built binary, not themselves).
  std::string self_binary = "/proc/self/exe";
  double author_seconds = 10;
};

struct StudentApp {
  StudentApp(const Course& c, Store& s, AppConfig cfg)
      : course(c),
        store(s),
        config(cfg),
        preview_limit(cfg.preview_rate, cfg.preview_burst),
        draft_limit(cfg.preview_rate, cfg.preview_burst),
        submit_limit(cfg.submit_rate, cfg.submit_burst) {}
  const Course& course;
  Store& store;
  AppConfig config;
  RateLimiter preview_limit, draft_limit, submit_limit;
  // GiNaC (the exact numbers in parsed answers and in the course's givens) is not thread-safe:
  // its expressions share reference counts and tables. Every handler that touches exact values
  // — parsing a preview, drawing a figure — holds this; the rest of a page is strings and YAML.
  std::mutex exact_math;
  // A set file's save (compare its version, check, keep the old one, write) is one at a time.
  std::mutex author_files;
};

Response handle_student(StudentApp& app, const Request& request, Millis now);

}  // namespace frustum::server
