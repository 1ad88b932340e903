// The student's pages: the list of their sets, a set as their variant (text, givens typeset,
// figures, one input per asked answer with its draft, their submissions and feedback), one
// submission, and a problem's figure.
#pragma once

#include "server/session.hpp"

namespace frustum::server {

Response sets_page(StudentApp& app, const Visitor& v);
Response set_page(StudentApp& app, const Visitor& v, const CourseSet& set, Millis now);
Response submission_page(StudentApp& app, const Visitor& v, const CourseSet& set, std::int64_t id,
                         Millis now);
// A problem's figure, once its feedback is shown (it shows the answers).
Response figure_svg(StudentApp& app, const Visitor& v, const CourseSet& set,
                    const std::string& problem, Millis now);

// Submissions made to one problem.
int attempts_at(const std::vector<SubmissionRecord>& mine, const std::string& problem);

}  // namespace frustum::server
