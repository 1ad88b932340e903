// What a set allows its students when it is served (`frustum serve`): how many submissions,
// until when, and when the feedback is shown. Top-level keys of a problem set:
//   feedback: {after: submit | attempts: N | deadline: DATE | never}   (default: after submit)
//   attempts: N          submissions per problem (default: unlimited)
//   deadline: DATE       ISO 8601 with an offset, 2026-12-10T23:59:00+09:00 (default: none)
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <optional>
#include <string>

namespace frustum {

struct ServePolicy {
  enum class Feedback { AfterSubmit, AfterAttempts, AfterDeadline, Never };
  Feedback feedback = Feedback::AfterSubmit;
  int feedback_attempts = 0;                         // AfterAttempts: shown from this attempt on
  std::optional<std::int64_t> feedback_deadline_ms;  // AfterDeadline: shown from then on
  std::optional<std::int64_t> attempts;              // submissions allowed per problem
  std::optional<std::int64_t> deadline_ms;           // ms since the epoch (UTC)
  std::string deadline_text;                         // as written

  // Whether feedback may be shown for a problem with `attempts_made` submissions at `now_ms`.
  bool feedback_shown(int attempts_made, std::int64_t now_ms) const;
};

// Reads feedback / attempts / deadline from a set's root; throws InputError located at the
// field (for example "deadline: '2026-12-10 23:59' has no offset").
ServePolicy read_serve_policy(const YAML::Node& root, const std::string& file);

// "2026-12-10T23:59:00+09:00" (seconds optional, Z for UTC) → ms since the epoch; nullopt when
// it is not such a date with an offset.
std::optional<std::int64_t> parse_iso8601(const std::string& text);

}  // namespace frustum
