#include "server/session.hpp"

#include "server/pages.hpp"
#include "server/tokens.hpp"

namespace frustum::server {

std::optional<Visitor> visitor_of(StudentApp& app, const Request& request, Millis now) {
  const auto cookie = request.header("cookie");
  if (!cookie) return std::nullopt;
  const auto cookies = parse_cookies(*cookie);
  const auto it = cookies.find(kSessionCookie);
  if (it == cookies.end() || it->second.size() != 32) return std::nullopt;
  const std::string hash = sha256_hex(it->second);
  const std::optional<SessionRecord> s = app.store.session(hash, now);
  if (!s) return std::nullopt;
  if (s->role == Role::Instructor ? !app.course().instructs(s->student)
                                  : !app.course().enrolled(s->student))
    return std::nullopt;
  return Visitor{s->student, s->csrf, hash, s->role};
}

Response start_session(StudentApp& app, const Request& request, Millis now) {
  const std::string token = parse_form(request.query())["token"];
  Role role = Role::Student;
  std::optional<std::string> who;
  if (token.size() == 32) {
    const std::string hash = sha256_hex(token);
    who = app.store.student_by_token(hash);
    if (who && !app.course().enrolled(*who)) who.reset();
    if (!who) {
      who = app.store.instructor_by_token(hash);
      role = Role::Instructor;
      if (who && !app.course().instructs(*who)) who.reset();
    }
  }
  if (!who) return message_page(404, course_lang(app.course()), kLinkInvalid);
  const std::string session = random_token();
  app.store.put_session(sha256_hex(session),
                        SessionRecord{*who, random_token(), now + app.options.session_ms, role});
  Response r{303, {{"Location", role == Role::Instructor ? "/instructor/" : "/"}}, ""};
  r.set("Set-Cookie", std::string(kSessionCookie) + "=" + session +
                          "; Path=/; HttpOnly; SameSite=Strict; Max-Age=" +
                          std::to_string(app.options.session_ms / 1000) +
                          (app.options.secure_cookies ? "; Secure" : ""));
  return r;
}

bool same_origin(const Request& request) {
  const auto origin = request.header("origin");
  if (!origin) return true;  // not a browser's cross-site request; the CSRF token still holds
  const auto host = request.header("host");
  return host && (*origin == "http://" + *host || *origin == "https://" + *host);
}

bool csrf_ok(const Visitor& visitor, const Request& request,
             const std::map<std::string, std::string>& form) {
  std::string given;
  if (const auto it = form.find("csrf"); it != form.end())
    given = it->second;
  else if (const auto h = request.header("x-csrf-token"))
    given = *h;
  return !given.empty() && constant_time_equal(given, visitor.csrf);
}

}  // namespace frustum::server
