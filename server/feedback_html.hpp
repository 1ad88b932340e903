// One submission as its student sees it: received and pending, failed, or graded — verdicts,
// credit, the named mistake and the step where it happens, credit carried from earlier answers
// (with those answers), and the derivation — when the set's policy shows feedback.
#pragma once

#include <optional>
#include <string>

#include "server/store.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum::server {

std::string submission_html(const SubmissionRecord& s, const std::optional<GradeRecord>& grade,
                            bool feedback_shown, Lang lang);

}  // namespace frustum::server
