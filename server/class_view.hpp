// The class as an instructor reads it from the store: every submission to a set and the latest
// grade of each, and what they add up to — the gradebook's rows (the columns of `grade -o`'s
// gradebook.csv, written by batch/'s own code), per problem and per answer how many submitted
// and how many of those are right, partly right, wrong or unreadable with the median attempts,
// and the named mistakes with the students who made them. Plain data; the pages lay it out.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "server/course.hpp"
#include "server/store.hpp"

namespace frustum::server {

// A class's submissions read at once, at most (a semester of a large class is far below).
inline constexpr std::size_t kMaxClassSubmissions = 200'000;

struct ClassView {
  const CourseSet* set = nullptr;
  std::vector<SubmissionRecord> submissions;   // oldest first
  std::map<std::int64_t, GradeRecord> grades;  // the latest grade, by submission
  bool truncated = false;                      // more than kMaxClassSubmissions

  // The latest submission of `student` to `problem` (null when none).
  const SubmissionRecord* latest(const std::string& student, const std::string& problem) const;
  // Its grade, when it has one and it did not fail.
  const GradeRecord* graded(const SubmissionRecord& s) const;
};

ClassView read_class(Store& store, const CourseSet& set);

// One row per problem (answer empty) and per asked answer, in the set's order. Each student is
// counted once, by their latest submission to the problem.
struct AnswerCount {
  std::string problem, answer;
  int submitted = 0, right = 0, partly = 0, wrong = 0, unreadable = 0;
  double median_attempts = 0;  // of the students who submitted it
};
std::vector<AnswerCount> answer_counts(const ClassView& view);

// The named mistakes in the students' latest submissions, the most frequent (by students) first.
struct MistakeRow {
  std::string problem, answer, mistake;
  std::vector<std::string> students;  // sorted
};
std::vector<MistakeRow> frequent_mistakes(const ClassView& view, std::size_t limit);

// One row per roster student, in the roster's order: the latest graded submission of each
// problem counts. A student without a submission is an error row ("no submission", as `grade`
// writes a roster id without answers), one with a submission still being graded is "pending".
std::vector<BatchRow> gradebook_rows(const Course& course, const ClassView& view);

// The verdicts of a stored grade's answers, by answer name ("correct", "partial", …).
std::map<std::string, std::string> answer_verdicts(const GradeRecord& grade);

}  // namespace frustum::server
