#include "server/copy_signals.hpp"

#include <nlohmann/json.hpp>
#include <set>

namespace frustum::server {

namespace {

CopySignal evidence(const SubmissionRecord& s, const GradeRecord& own, const GradeRecord& fit,
                    const std::string& other) {
  CopySignal signal{s.student, s.problem, s.id,          s.attempt, other,
                    own.score, fit.score, fit.max_score, {}};
  const nlohmann::json written = nlohmann::json::parse(s.answers, nullptr, false);
  const auto own_verdicts = answer_verdicts(own), fit_verdicts = answer_verdicts(fit);
  for (const auto& [name, verdict] : fit_verdicts) {
    const auto o = own_verdicts.find(name);
    std::string text;
    if (written.is_object() && written.contains(name) && written[name].is_string())
      text = written[name].get<std::string>();
    signal.answers.push_back(
        {name, text, o == own_verdicts.end() ? "missing" : o->second, verdict});
  }
  return signal;
}

}  // namespace

CopyReport copy_signals(const Course& course, const ClassView& view, SolvedCache& cache,
                        std::mutex& exact_math, Millis now) {
  CopyReport report;
  const CourseSet& set = *view.set;
  if (set.variants.empty()) return report;
  std::set<std::pair<std::string, std::string>> seen;  // (student, problem): the latest only
  for (auto it = view.submissions.rbegin(); it != view.submissions.rend(); ++it) {
    if (!seen.insert({it->student, it->problem}).second) continue;
    const GradeRecord* own = view.graded(*it);
    if (!own || own->score >= own->max_score) continue;
    for (const std::string& other : course.roster) {
      if (other == it->student || !set.for_student(other)) continue;
      if (report.gradings == kMaxCopyGradings) {
        report.truncated = true;
        return report;
      }
      ++report.gradings;
      SubmissionRecord as_other = *it;
      as_other.student = other;
      as_other.variant = set.variant_id(other);
      GradeRecord fit;
      {
        const std::lock_guard lock(exact_math);
        fit = grade_submission(course, cache, as_other, "copy check", now);
      }
      if (!fit.failed && fit.max_score > 0 && fit.score >= fit.max_score) {
        report.signals.push_back(evidence(*it, *own, fit, other));
        break;
      }
    }
  }
  return report;
}

}  // namespace frustum::server
