// The course's instructors: COURSE/instructors.csv, a CSV with an `instructor` column (other
// columns are ignored). An instructor signs in with a link as a student does and sees the whole
// class at /instructor/; an id is a student's or an instructor's, never both.
#pragma once

#include <string>
#include <vector>

namespace frustum::server {

inline constexpr std::size_t kMaxInstructors = 1000;

// The ids, in the file's order. Throws InputError (file, line, column) for a file without an
// `instructor` column, an id that no one can have (read_student_id), a repeated id, or more than
// kMaxInstructors.
std::vector<std::string> read_instructors(const std::string& path);

}  // namespace frustum::server
