// Where `frustum generate` writes a variant and where `frustum grade --variants` reads it back,
// and the roster that `frustum generate --roster` reads.
#pragma once

#include <string>
#include <vector>

namespace frustum {

// A student id as part of a file name, never shared by two ids (file_name_for: "a/b" is
// "a%2Fb", "a_b" stays; they once both became a_b and one student was graded on the other's
// key).
std::string variant_name(const std::string& student);

// DIR/STEM-NAME.yaml for the set SET_PATH (its key is DIR/answers/STEM-NAME.yaml).
std::string variant_file(const std::string& dir, const std::string& set_path,
                         const std::string& name);
std::string variant_key_file(const std::string& dir, const std::string& set_path,
                             const std::string& name);

// The student ids of a roster, in order: a CSV with a `student` column (the roster that
// `frustum grade` takes; other columns are ignored), or a text file with one id per line
// (blank lines and lines starting with # skipped). Throws InputError naming the file and line
// for a CSV without a student column, a repeated id, or an empty roster.
std::vector<std::string> read_roster(const std::string& path);

}  // namespace frustum
