// Copy signals, for the instructor only: a submission whose answers are not all right for the
// student's own variant but are all right for another student's — the answers were most likely
// worked out on that student's numbers. The check is the grader's own: the submission graded
// against each other variant of the class, as a worker grades it. The evidence is the answers
// as written with their verdicts for both variants.
#pragma once

#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

#include "server/class_view.hpp"
#include "server/grade_job.hpp"

namespace frustum::server {

inline constexpr std::size_t kMaxCopyGradings = 5'000;  // gradings one look may take

struct CopySignal {
  std::string student, problem;
  std::int64_t submission = 0;
  int attempt = 0;
  std::string fits;  // the student whose variant the answers fit
  double own_score = 0, fit_score = 0, max_score = 0;
  struct Answer {
    std::string name, written, own, fit;  // verdicts: "correct", "incorrect", …
  };
  std::vector<Answer> answers;
};

struct CopyReport {
  std::vector<CopySignal> signals;
  std::size_t gradings = 0;  // submissions graded against another variant
  bool truncated = false;    // stopped at kMaxCopyGradings
};

// Each student's latest graded submission to each problem of a set that varies per student
// (a set that does not vary has no other variant to fit). `exact_math` is held for each grading
// (not for the whole look: previews go on meanwhile); `cache` keeps the class's solved variants
// between looks.
CopyReport copy_signals(const Course& course, const ClassView& view, SolvedCache& cache,
                        std::mutex& exact_math, Millis now);

}  // namespace frustum::server
