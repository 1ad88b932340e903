#include "solver/problem/serve_policy.hpp"

#include <algorithm>
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

// One part's WHEN: submit | {attempts: N} | deadline | DATE | never (and {after: submit},
// {deadline: DATE}).
FeedbackWhen read_when(const YAML::Node& n, const std::string& file, const std::string& field,
                       bool set_has_deadline) {
  using K = FeedbackWhen::Kind;
  FeedbackWhen w;
  if (n.IsScalar()) {
    const std::string& v = n.Scalar();
    if (v == "submit") return w;
    if (v == "never") return FeedbackWhen{K::Never};
    if (v == "deadline") {
      if (!set_has_deadline)
        fail_at(n, file, field, "'deadline' needs the set's deadline: (there is none)");
      return FeedbackWhen{K::AfterDeadline};
    }
    if (const auto ms = parse_iso8601(v)) return FeedbackWhen{K::AtDate, 0, *ms};
  } else if (n.IsMap() && n.size() == 1) {
    if (n["after"].IsDefined()) {
      if (!n["after"].IsScalar() || n["after"].Scalar() != "submit")
        fail_at(n["after"], file, field + ".after", "expected submit");
      return w;
    }
    if (n["attempts"].IsDefined())
      return FeedbackWhen{K::AfterAttempts,
                          static_cast<int>(read_count(n["attempts"], file, field + ".attempts"))};
    if (n["deadline"].IsDefined())
      return FeedbackWhen{K::AtDate, 0, read_date(n["deadline"], file, field + ".deadline")};
    fail_at(n.begin()->first, file, field + "." + n.begin()->first.as<std::string>(),
            field == "feedback"
                ? "unknown field (expected attempts, or the parts verdicts, credit, mistakes, "
                  "key and derivation)"
                : "unknown field (expected attempts)");
  }
  fail_at(n, file, field,
          "expected submit, {attempts: N}, deadline, a date like 2026-12-10T23:59:00+09:00, "
          "or never");
}

constexpr std::array<const char*, static_cast<std::size_t>(FeedbackPart::Count)> kPartNames = {
    "verdicts", "credit", "mistakes", "key", "derivation"};

void read_feedback(const YAML::Node& n, const std::string& file, ServePolicy& p) {
  const bool has_deadline = p.deadline_ms.has_value();
  const bool per_part =
      n.IsMap() && n.size() > 0 && std::any_of(n.begin(), n.end(), [](const auto& kv) {
        const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "";
        return std::find(kPartNames.begin(), kPartNames.end(), key) != kPartNames.end();
      });
  if (!per_part) {
    p.feedback.fill(read_when(n, file, "feedback", has_deadline));
    return;
  }
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string key = it->first.IsScalar() ? it->first.Scalar() : "";
    const auto at = std::find(kPartNames.begin(), kPartNames.end(), key);
    if (at == kPartNames.end())
      fail_at(it->first, file, "feedback." + key,
              "unknown part (expected verdicts, credit, mistakes, key or derivation)");
    p.feedback[static_cast<std::size_t>(at - kPartNames.begin())] =
        read_when(it->second, file, "feedback." + key, has_deadline);
  }
}

// 10% (or 10 %) or a fraction 0.1, from 0 to 100 %.
void read_penalty(const YAML::Node& n, const std::string& file, ServePolicy& p) {
  static const std::regex kPercent(R"(([0-9]{1,3}(?:\.[0-9]{1,4})?) ?%)");
  static const std::regex kFraction(R"([01](?:\.[0-9]{1,6})?)");
  std::smatch m;
  const std::string v = n.IsScalar() ? n.Scalar() : "";
  double value = -1;
  if (std::regex_match(v, m, kPercent))
    value = std::stod(m[1].str()) / 100;
  else if (std::regex_match(v, kFraction))
    value = std::stod(v);
  if (!(value >= 0 && value <= 1))
    fail_at(n, file, "penalty",
            "expected the share of the credit lost per further attempt, from 0% to 100% "
            "(10% or 0.1)");
  p.penalty = value;
  p.penalty_text = v;
}

void read_extensions(const YAML::Node& n, const std::string& file, ServePolicy& p) {
  if (!p.deadline_ms)
    fail_at(n, file, "extensions", "extensions need the set's deadline: (there is none)");
  if (!n.IsMap())
    fail_at(
        n, file, "extensions",
        "expected each student's id and their deadline, like {alice: 2026-12-12T23:59:00+09:00}");
  for (auto it = n.begin(); it != n.end(); ++it) {
    const std::string student = it->first.IsScalar() ? it->first.Scalar() : "";
    if (student.empty())
      fail_at(it->first, file, "extensions", "expected a student's id from the roster");
    const std::string field = "extensions." + student;
    p.extensions[student] = {read_date(it->second, file, field), it->second.Scalar()};
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
  if (root["penalty"].IsDefined()) read_penalty(root["penalty"], file, p);
  if (root["deadline"].IsDefined()) {
    p.deadline_ms = read_date(root["deadline"], file, "deadline");
    p.deadline_text = root["deadline"].Scalar();
  }
  if (root["extensions"].IsDefined()) read_extensions(root["extensions"], file, p);
  if (root["feedback"].IsDefined()) read_feedback(root["feedback"], file, p);
  return p;
}

bool FeedbackWhen::shown(int attempts_made, std::int64_t now_ms,
                         std::optional<std::int64_t> deadline) const {
  switch (kind) {
    case Kind::AfterSubmit:
      return true;
    case Kind::AfterAttempts:
      return attempts_made >= attempts;
    case Kind::AfterDeadline:
      return deadline && now_ms > *deadline;
    case Kind::AtDate:
      return now_ms >= at;
    case Kind::Never:
      return false;
  }
  return false;
}

std::optional<std::int64_t> ServePolicy::deadline_for(const std::string& student) const {
  if (const auto it = extensions.find(student); it != extensions.end()) return it->second.ms;
  return deadline_ms;
}

const std::string& ServePolicy::deadline_text_for(const std::string& student) const {
  if (const auto it = extensions.find(student); it != extensions.end()) return it->second.text;
  return deadline_text;
}

bool ServePolicy::closed_for(const std::string& student, std::int64_t now_ms) const {
  const std::optional<std::int64_t> d = deadline_for(student);
  return d && now_ms > *d;
}

FeedbackShown ServePolicy::shown(const std::string& student, int attempts_made,
                                 std::int64_t now_ms) const {
  const std::optional<std::int64_t> deadline = deadline_for(student);
  const auto part = [&](FeedbackPart which) {
    return feedback[static_cast<std::size_t>(which)].shown(attempts_made, now_ms, deadline);
  };
  FeedbackShown s;
  s.verdicts = part(FeedbackPart::Verdicts);
  s.credit = s.verdicts && part(FeedbackPart::Credit);
  s.mistakes = s.verdicts && part(FeedbackPart::Mistakes);
  s.key = part(FeedbackPart::Key);
  s.derivation = s.key && part(FeedbackPart::Derivation);
  return s;
}

double ServePolicy::credit_factor(std::int64_t attempt) const {
  return std::max(0.0, 1.0 - penalty * static_cast<double>(std::max<std::int64_t>(0, attempt - 1)));
}

}  // namespace frustum
