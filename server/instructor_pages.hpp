// The instructors' pages as HTML, from plain data (class_view.hpp, regrade.hpp,
// copy_signals.hpp): the class at a glance, one student's submissions, a regrade's dry run and
// the copy signals. Every text in the course's language; plain links and forms (no script
// needed), and the dashboard's <main data-events> for the module that reloads it live.
#pragma once

#include <string>
#include <vector>

#include "server/class_view.hpp"
#include "server/copy_signals.hpp"
#include "server/regrade.hpp"
#include "server/session.hpp"

namespace frustum::server {

inline constexpr std::size_t kGradebookPage = 100;  // students per page of the gradebook
inline constexpr std::size_t kMistakeRows = 20;

// How the gradebook is shown: sorted by a column ("student", "score", "percent", "status" or
// "p.PROBLEM"; "" keeps the roster's order), and which page.
struct GradebookView {
  std::string sort;
  bool descending = false;
  std::size_t page = 0;
};
// The rows sorted as asked (stable: ties keep the roster's order).
void sort_gradebook(std::vector<BatchRow>& rows, const CourseSet& set, const GradebookView& how);

std::string course_page(const Course& course, const std::vector<std::size_t>& submissions,
                        Lang lang);
std::string class_page(const CourseSet& set, const ClassView& view,
                       const std::vector<BatchRow>& sorted_rows, const GradebookView& how,
                       const std::vector<AnswerCount>& counts,
                       const std::vector<MistakeRow>& mistakes, const Visitor& v, std::int64_t mark,
                       Lang lang);
std::string student_page(const CourseSet& set, const std::string& student,
                         const std::vector<SubmissionRecord>& submissions,
                         const std::vector<std::vector<GradeRecord>>& histories, Millis now,
                         Lang lang);
std::string regrade_page(const CourseSet& set, const RegradePlan& plan, const std::string& problem,
                         const Visitor& v, Lang lang);
std::string regrade_done_page(const CourseSet& set, std::size_t written, Lang lang);
std::string copies_page(const CourseSet& set, const CopyReport& report, Lang lang);

// "2026-12-05 08:40:12 UTC"
std::string utc_text(Millis ms);

}  // namespace frustum::server
