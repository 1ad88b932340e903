// What a student's answers do besides being shown: the preview of how one is read (the
// grader's own parser; never whether it is right), drafts as they type, and the submission —
// committed to the store before the response says it was received.
#pragma once

#include "server/session.hpp"

namespace frustum::server {

Response preview_answer(StudentApp& app, const Visitor& v,
                        const std::map<std::string, std::string>& form, Millis now);
Response save_draft(StudentApp& app, const Visitor& v,
                    const std::map<std::string, std::string>& form, Millis now);
Response submit_answers(StudentApp& app, const Visitor& v, const CourseSet& set,
                        const Request& request, const std::map<std::string, std::string>& form,
                        Millis now);

}  // namespace frustum::server
