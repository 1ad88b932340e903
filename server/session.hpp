// Sessions: a link's token is exchanged once for a session cookie (HttpOnly, SameSite=Strict,
// Secure behind TLS); the store keeps only hashes of both. A state-changing request must carry
// the session's CSRF token and, when the browser sends one, an Origin of this server.
#pragma once

#include <optional>
#include <string>

#include "server/student_app.hpp"

namespace frustum::server {

inline constexpr const char* kSessionCookie = "frustum_session";

struct Visitor {
  std::string student;  // the id (an instructor's, when role is Instructor)
  std::string csrf;
  std::string session_hash;
  Role role = Role::Student;
};

std::optional<Visitor> visitor_of(StudentApp& app, const Request& request, Millis now);
// GET /start?token=T: a session for T's student (or instructor) and a redirect to / (or
// /instructor/), or a refusal page.
Response start_session(StudentApp& app, const Request& request, Millis now);
// The Origin header, when present, names this server (its Host).
bool same_origin(const Request& request);
// A POST's CSRF token (form field or X-CSRF-Token header) is the session's.
bool csrf_ok(const Visitor& visitor, const Request& request,
             const std::map<std::string, std::string>& form);

}  // namespace frustum::server
