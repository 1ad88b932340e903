#include "solver/problem/serve_policy.hpp"

#include <cstdio>
#include <regex>

#include "solver/input/given_reader.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

[[noreturn]] void fail_at(const YAML::Node& n, const std::string& file, const std::string& field,
                          const std::string& message) {
  throw InputError(Diagnostic{location_of(n, file), field, message});
}

// Days since 1970-01-01 of a proleptic Gregorian date (Howard Hinnant's days_from_civil).
std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

std::int64_t read_count(const YAML::Node& n, const std::string& file, const std::string& field) {
  if (!n.IsScalar() || !std::regex_match(n.Scalar(), std::regex("[0-9]{1,6}")) ||
      std::stoll(n.Scalar()) < 1)
    fail_at(n, file, field, "expected a whole number from 1 to 999999");
  return std::stoll(n.Scalar());
}

std::int64_t read_date(const YAML::Node& n, const std::string& file, const std::string& field) {
  const std::optional<std::int64_t> ms = n.IsScalar() ? parse_iso8601(n.Scalar()) : std::nullopt;
  if (!ms)
    fail_at(n, file, field,
            "expected a date and time with its offset, like 2026-12-10T23:59:00+09:00 "
            "(or …Z for UTC)");
  return *ms;
}

void read_feedback(const YAML::Node& n, const std::string& file, ServePolicy& p) {
  using F = ServePolicy::Feedback;
  if (n.IsScalar() && n.Scalar() == "never") {
    p.feedback = F::Never;
    return;
  }
  if (!n.IsMap() || n.size() != 1)
    fail_at(n, file, "feedback",
            "expected one of {after: submit}, {attempts: N}, {deadline: DATE} or never");
  if (n["after"].IsDefined()) {
    if (!n["after"].IsScalar() || n["after"].Scalar() != "submit")
      fail_at(n["after"], file, "feedback.after", "expected submit");
    p.feedback = F::AfterSubmit;
  } else if (n["attempts"].IsDefined()) {
    p.feedback = F::AfterAttempts;
    p.feedback_attempts = static_cast<int>(read_count(n["attempts"], file, "feedback.attempts"));
  } else if (n["deadline"].IsDefined()) {
    p.feedback = F::AfterDeadline;
    p.feedback_deadline_ms = read_date(n["deadline"], file, "feedback.deadline");
  } else {
    fail_at(n.begin()->first, file, "feedback." + n.begin()->first.as<std::string>(),
            "unknown field (expected after, attempts or deadline)");
  }
}

}  // namespace

std::optional<std::int64_t> parse_iso8601(const std::string& text) {
  static const std::regex kDate(
      R"((\d{4})-(\d{2})-(\d{2})T(\d{2}):(\d{2})(?::(\d{2}))?(Z|([+-])(\d{2}):(\d{2})))");
  std::smatch m;
  if (!std::regex_match(text, m, kDate)) return std::nullopt;
  const auto num = [&](int i) { return m[i].matched ? std::stoi(m[i].str()) : 0; };
  const int month = num(2), day = num(3), hour = num(4), minute = num(5), second = num(6);
  if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 59)
    return std::nullopt;
  std::int64_t offset = 0;
  if (m[7].str() != "Z") {
    if (num(9) > 23 || num(10) > 59) return std::nullopt;
    offset = (num(9) * 60 + num(10)) * (m[8].str() == "-" ? -1 : 1);
  }
  const std::int64_t days =
      days_from_civil(num(1), static_cast<unsigned>(month), static_cast<unsigned>(day));
  const std::int64_t minutes = days * 1440 + hour * 60 + minute - offset;
  return (minutes * 60 + second) * 1000;
}

ServePolicy read_serve_policy(const YAML::Node& root, const std::string& file) {
  ServePolicy p;
  if (root["attempts"].IsDefined()) p.attempts = read_count(root["attempts"], file, "attempts");
  if (root["deadline"].IsDefined()) {
    p.deadline_ms = read_date(root["deadline"], file, "deadline");
    p.deadline_text = root["deadline"].Scalar();
  }
  if (root["feedback"].IsDefined()) {
    read_feedback(root["feedback"], file, p);
  }
  return p;
}

bool ServePolicy::feedback_shown(int attempts_made, std::int64_t now_ms) const {
  switch (feedback) {
    case Feedback::AfterSubmit:
      return true;
    case Feedback::AfterAttempts:
      return attempts_made >= feedback_attempts;
    case Feedback::AfterDeadline:
      return feedback_deadline_ms && now_ms >= *feedback_deadline_ms;
    case Feedback::Never:
      return false;
  }
  return false;
}

}  // namespace frustum
