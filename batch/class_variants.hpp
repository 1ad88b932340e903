// Which set each student of a class is graded against (the redraw policy): the file
// `frustum generate -o DIR` wrote for them, their variant in the class `generate --roster` drew,
// or the variant drawn from their own id — and the pairs of students whose own-id variants
// share a problem, which the instructor is told about.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "batch/batch.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// Where the students' variants come from (none: each student's own id, when the set varies).
struct VariantSource {
  std::optional<std::string> variants_dir;  // the sets `frustum generate -o DIR` wrote
  std::optional<std::string> roster;        // the roster `frustum generate --roster` drew from
};

// The sets of a class as `frustum generate --roster` drew them (redraws included), by student.
using RosterVariants = std::map<std::string, ProblemSet>;

// A set that does not vary is every student's set: the roster then says only whose each file
// is. (Variants that `generate` drew from such a set are graded against its files, --variants.)
RosterVariants roster_variants(const ProblemSet& set, const std::vector<std::string>& roster);

// The class of source.roster, or none without one. Throws InputError (the roster's file and
// line) when the roster cannot be read.
std::optional<RosterVariants> read_class_variants(const ProblemSet& set,
                                                  const VariantSource& source);

// The set `student` is graded against; `variant` says which, for the report. A student who
// cannot be placed gets the set with no problems and one located error naming why.
ProblemSet set_for_student(const ProblemSet& set, const VariantSource& source,
                           const RosterVariants* roster, const std::string& student,
                           std::string& variant);

// A class of a varying set graded from the students' own ids: the pairs whose variants share a
// problem, each said as one sentence for the instructor (never in a student's result).
std::vector<std::string> shared_draws(const ProblemSet& set,
                                      const std::vector<BatchEntry>& entries);

}  // namespace frustum
