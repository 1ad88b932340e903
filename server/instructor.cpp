#include "server/instructor.hpp"

namespace frustum::server {

bool is_instructor(const Visitor& v) { return v.student.rfind("instructor:", 0) == 0; }

}  // namespace frustum::server
