// Frustum's gradebook.csv (from `frustum grade SET CLASS_DIR`) in the CSV that Canvas's and
// Moodle's gradebook imports read. Only `graded` rows carry a score: a submission that timed
// out, crashed or could not be read leaves the cell empty (the platform keeps what it had)
// rather than filing a zero; a student with two rows is refused, never guessed.
#pragma once

#include <string>
#include <vector>

namespace frustum {

enum class GradebookFormat {
  Canvas,  // Student, ID, SIS User ID, SIS Login ID, Section, "ASSIGNMENT" (+ Points Possible row)
  Moodle  // "ID number", "ASSIGNMENT" (map ID number → user's ID number, the column → grade item)
};
enum class StudentKey { SisUserId, SisLoginId };  // Canvas: which column holds Frustum's student id

// Throws InputError (file, line) for a gradebook without student/score/max_score/status, or a
// student listed twice. A student whose id a spreadsheet would run as a formula (=cmd, @x,
// -x+1) is left out, not written with the spreadsheet guard (the LMS would match nobody), and
// named in `left_out`.
std::string export_gradebook(const std::string& gradebook_csv_text, const std::string& file,
                             GradebookFormat format, const std::string& assignment,
                             StudentKey key = StudentKey::SisUserId,
                             std::vector<std::string>* left_out = nullptr);

}  // namespace frustum
