// Grading a problem's sample answers (solver/problem/samples.hpp) against its key, as a student's
// would be, and telling which ones the grader judges otherwise than their author expects.
#pragma once

#include <string>
#include <vector>

#include "grader/grade.hpp"

namespace frustum {

// Two credits closer than this are the same (a third written as 0.333).
inline constexpr double kSampleCreditTolerance = 1e-3;

struct SampleOutcome {
  const Sample* sample = nullptr;
  std::string problem;
  SampleVerdict verdict = SampleVerdict::Wrong;  // what the grader made of the sample
  double credit = 0;                             // score / max over the sample's answers
  std::vector<AnswerGrade> answers;              // the sample's answers, graded
  bool as_expected = true;
  Diagnostic mismatch;  // at the sample, saying expected and got (when !as_expected)
};

// Every sample of every problem that can be solved; `solved` (solve_for_grading of `set`) saves
// solving again. A problem with an error has its samples left out (its error is reported).
std::vector<SampleOutcome> grade_samples(const ProblemSet& set, const SolvedSet* solved = nullptr);

}  // namespace frustum
