// Whose session may use the instructor's pages. The one place the server decides it.
#pragma once

#include "server/session.hpp"

namespace frustum::server {

// An instructor's session. Until sessions carry a role of their own, an instructor is a
// roster id written `instructor:NAME` (roster.csv), issued a link like any other.
bool is_instructor(const Visitor& v);

}  // namespace frustum::server
