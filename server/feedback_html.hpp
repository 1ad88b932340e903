// One submission as its student sees it: received and pending, failed, or graded — verdicts,
// credit (and what a further attempt's penalty leaves of it), the named mistake and the step where
// it happens, credit carried from earlier answers (with those answers), the right answers and the
// derivation — each part as the set's policy shows it now.
#pragma once

#include <optional>
#include <string>

#include "server/store.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/problem/serve_policy.hpp"

namespace frustum::server {

std::string submission_html(const SubmissionRecord& s, const std::optional<GradeRecord>& grade,
                            const FeedbackShown& shown, double credit_factor, Lang lang);

}  // namespace frustum::server
