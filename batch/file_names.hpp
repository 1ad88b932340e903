// Student ids as file names. Ids are untrusted text ("a/b", "../x", "=cmd", "A" beside "a"),
// and two students must never share a file: the mapping is injective, and a batch also keeps
// names apart that a case-insensitive file system would merge.
#pragma once

#include <string>
#include <vector>

#include "solver/problem/problem_set.hpp"

namespace frustum {

// Letters, digits and '_' kept, '.' and '-' kept except first; every other byte written %HH
// ("a/b" → "a%2Fb", "a_b" stays), so different ids give different names. Names longer than
// 120 bytes are cut and end in "~" and a hash of the whole id. Never empty.
std::string file_name_for(const std::string& id);

// file_name_for each id, made unique within the list with "~2", "~3", … ('~' appears in no
// encoded id), comparing without case: ids "a-2", "a", "a" give "a-2", "a", "a~2".
std::vector<std::string> unique_file_names(const std::vector<std::string>& ids);

// Problem ids of one set that differ only in case, in their Unicode form or in characters other
// than letters and digits ("q 1", "q/1", "q_1", "Q_1"): every export keeps each under a name of
// its own, but those names differ only in their encoding, and a student may write one for the
// other. One warning for each id after the first that looks like it, at the problem.
std::vector<Diagnostic> look_alike_problem_ids(const ProblemSet& set);

}  // namespace frustum
