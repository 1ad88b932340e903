#include "server/regrade.hpp"

#include <cmath>

#include "server/class_view.hpp"

namespace frustum::server {

namespace {

// Each answer whose verdict moved.
std::vector<RegradeChange::Answer> moved(const GradeRecord& before, const GradeRecord& after) {
  std::vector<RegradeChange::Answer> out;
  const auto was = answer_verdicts(before), is = answer_verdicts(after);
  for (const auto& [name, verdict] : is) {
    const auto it = was.find(name);
    const std::string old = it == was.end() ? "missing" : it->second;
    if (old != verdict) out.push_back({name, old, verdict});
  }
  return out;
}

}  // namespace

RegradePlan plan_regrade(const Course& course, const CourseSet& fresh, Store& store,
                         const std::string& problem, const std::string& by, Millis now) {
  RegradePlan plan;
  plan.version = fresh.version;
  // The course as it would be with the set file as it is now.
  Course now_course{course.dir, course.roster, course.instructors, {fresh}, {}};
  SolvedCache cache;
  const ClassView view = read_class(store, fresh);
  for (const SubmissionRecord& s : view.submissions) {
    if (!problem.empty() && s.problem != problem) continue;
    const auto old = view.grades.find(s.id);
    if (old == view.grades.end()) continue;  // pending: a grader has it
    if (plan.regraded == kMaxRegrade) {
      plan.truncated = true;
      break;
    }
    ++plan.regraded;
    SubmissionRecord again = s;
    again.variant = fresh.variant_id(s.student);
    GradeRecord g = grade_submission(now_course, cache, again, by, now);
    const GradeRecord& before = old->second;
    std::vector<RegradeChange::Answer> answers = moved(before, g);
    const bool changed =
        !answers.empty() || before.failed != g.failed || std::abs(before.score - g.score) > 1e-9;
    if (changed)
      plan.changes.push_back(RegradeChange{s.student, s.problem, s.id, s.attempt, before.score,
                                           g.score, g.max_score, before.set_version, g.set_version,
                                           std::move(answers), before.failed, g.failed});
    if (changed || before.set_version != g.set_version || before.result != g.result)
      plan.grades.push_back(std::move(g));
  }
  return plan;
}

}  // namespace frustum::server
