// Grading one stored submission as a worker does: the student's variant of the set, solved
// once per (set version, variant) and kept, the answers read as an answers file, graded by the
// grader, and the problem's grade written as the JSON the pages show (its texts in the set's
// language, so the page only lays them out).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "grader/grade.hpp"
#include "server/course.hpp"
#include "server/store.hpp"

namespace frustum::server {

// Solved variants by (set version, variant); the exact solve is the expensive part of grading.
class SolvedCache {
 public:
  explicit SolvedCache(std::size_t capacity = 256) : capacity_(capacity) {}
  std::shared_ptr<const SolvedSet> get(const std::string& version, const std::string& variant,
                                       const ProblemSet& set);
  std::size_t solves() const { return solves_; }

 private:
  std::size_t capacity_;
  std::size_t solves_ = 0;
  std::map<std::string, std::shared_ptr<const SolvedSet>> cache_;
};

// The grade of `s` (failed = true with a message when the set, the student or the problem is
// no longer in the course).
GradeRecord grade_submission(const Course& course, SolvedCache& cache, const SubmissionRecord& s,
                             const std::string& worker, Millis now);

}  // namespace frustum::server
