// What a set allows its students when it is served (`frustum serve`): how many submissions and
// what each further one costs, until when (each student's own deadline), and when each part of
// the feedback is shown. Top-level keys of a problem set:
//   feedback: WHEN                 every part of the feedback at once, or one WHEN per part:
//   feedback: {verdicts: WHEN, credit: WHEN, mistakes: WHEN, key: WHEN, derivation: WHEN}
//       WHEN: submit (the default) | {attempts: N} | deadline (the student's own) | DATE | never
//       (and the older forms {after: submit}, {deadline: DATE})
//   attempts: N          submissions per problem (default: unlimited)
//   penalty: 10%         credit lost per attempt after the first (or 0.1; default 0)
//   deadline: DATE       ISO 8601 with an offset, 2026-12-10T23:59:00+09:00 (default: none)
//   extensions: {STUDENT: DATE, …}   a later deadline for some students
// A part that gives the others away waits for them: credit and mistakes are shown only with
// the verdicts, the derivation (which ends at the right answer) only with the key.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace frustum {

// When one part of the feedback is shown.
struct FeedbackWhen {
  enum class Kind { AfterSubmit, AfterAttempts, AfterDeadline, AtDate, Never };
  Kind kind = Kind::AfterSubmit;
  int attempts = 0;     // AfterAttempts: from this attempt on
  std::int64_t at = 0;  // AtDate: ms since the epoch (UTC)

  // `deadline`: the student's own (nullopt: none, so AfterDeadline never shows).
  bool shown(int attempts_made, std::int64_t now_ms, std::optional<std::int64_t> deadline) const;
};

enum class FeedbackPart { Verdicts, Credit, Mistakes, Key, Derivation, Count };

// What of a graded submission its student sees now.
struct FeedbackShown {
  bool verdicts = true;
  bool credit = true;
  bool mistakes = true;    // the feedback sentence, the named mistake and its step, carried credit
  bool key = true;         // the right answers (and a kind's figure, which shows them)
  bool derivation = true;  // the worked derivation
  bool any() const { return verdicts || credit || mistakes || key || derivation; }
};

struct ServePolicy {
  std::array<FeedbackWhen, static_cast<std::size_t>(FeedbackPart::Count)> feedback{};
  std::optional<std::int64_t> attempts;     // submissions allowed per problem
  double penalty = 0;                       // fraction of the credit lost per further attempt
  std::string penalty_text;                 // as written ("10%")
  std::optional<std::int64_t> deadline_ms;  // ms since the epoch (UTC)
  std::string deadline_text;                // as written
  struct Extension {
    std::int64_t ms = 0;
    std::string text;
  };
  std::map<std::string, Extension> extensions;  // by student id

  // The student's deadline: their extension's, else the set's.
  std::optional<std::int64_t> deadline_for(const std::string& student) const;
  const std::string& deadline_text_for(const std::string& student) const;
  bool closed_for(const std::string& student, std::int64_t now_ms) const;
  // What `student`, with `attempts_made` submissions to a problem, sees of its feedback now.
  FeedbackShown shown(const std::string& student, int attempts_made, std::int64_t now_ms) const;
  // The share of a submission's score it is credited with as attempt `attempt` (1, 2, …).
  double credit_factor(std::int64_t attempt) const;
};

// Reads the keys above from a set's root; throws InputError located at the field (for example
// "deadline: '2026-12-10 23:59' has no offset").
ServePolicy read_serve_policy(const YAML::Node& root, const std::string& file);

// "2026-12-10T23:59:00+09:00" (seconds optional, Z for UTC) → ms since the epoch; nullopt when
// it is not such a date with an offset.
std::optional<std::int64_t> parse_iso8601(const std::string& text);

}  // namespace frustum
