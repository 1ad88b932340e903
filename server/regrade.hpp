// Regrading a set's stored answers against its file as it is now (after a key, tolerance or
// policy fix): every graded submission (of one problem, or of the whole set) graded again, as a
// plan that lists each submission whose score or verdict would change — before → after, and
// why — and the grades to write. Applying writes them in one transaction; the grades before stay
// (a submission's grades are its history: the set's SHA-256, when, by whom).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "server/course.hpp"
#include "server/grade_job.hpp"
#include "server/store.hpp"

namespace frustum::server {

inline constexpr std::size_t kMaxRegrade = 20'000;  // submissions in one regrade

struct RegradeChange {
  std::string student, problem;
  std::int64_t submission = 0;
  int attempt = 0;
  double before = 0, after = 0, max_score = 0;
  std::string before_version, after_version;
  // Why: each answer whose verdict moves (name, before, after: "correct", "incorrect", …),
  // grading that failed before or fails now, or the credit alone (the same verdicts).
  struct Answer {
    std::string name, before, after;
  };
  std::vector<Answer> answers;
  bool failed_before = false, failed_after = false;
};

struct RegradePlan {
  std::string version;                 // the set file's SHA-256 now
  std::size_t regraded = 0;            // submissions graded again
  std::vector<RegradeChange> changes;  // those whose score or a verdict changes
  std::vector<GradeRecord> grades;     // to write: every regraded submission whose grade differs
  bool truncated = false;              // more than kMaxRegrade submissions: the first ones
};

// `fresh` is the set as load_course_set reads its file now; `problem` is a problem id, or ""
// for the whole set. Pending submissions are left to the graders (they grade against the
// version they were submitted with). The caller holds the lock on exact numbers (the fresh
// set's copies and solutions hold them too).
RegradePlan plan_regrade(const Course& course, const CourseSet& fresh, Store& store,
                         const std::string& problem, const std::string& by, Millis now);

}  // namespace frustum::server
