// Student ids as they are read — an answers file's `student:`, a roster's `student` column, a
// file's name, a gradebook's `student` column — and when two of them are one student.
//
// An id is trimmed of the spaces around it (Unicode's space separators: U+0020, U+00A0,
// U+3000…), and is refused when it is then empty, longer than kMaxStudentIdBytes, or holds a
// byte that is not UTF-8, a character that visible_text escapes (controls, line separators,
// bidirectional overrides) or U+FFFD (what the YAML reader puts in place of such bytes). A
// refused id is never rewritten: its file is an error row saying where and which character.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace frustum {

inline constexpr std::size_t kMaxStudentIdBytes = 256;  // Canvas's SIS ids: 255 characters

struct StudentId {
  std::string id;                      // trimmed
  std::optional<std::string> problem;  // why it is refused: "the student id is empty"
};
StudentId read_student_id(std::string_view written);

// The form under which ids are one student: NFKC_Casefold (Unicode's identifier caseless match,
// which also takes compatibility forms — full-width digits — and drops default-ignorable
// characters such as U+200B) of the trimmed id: "Alice", " alice " and "ALICE" are one student,
// as are "e" + U+0301 and U+00E9, or "１２３" and "123".
std::string student_id_key(std::string_view id);

}  // namespace frustum
