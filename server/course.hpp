// The course `frustum serve` serves: a directory of problem sets (*.yaml) and a roster. Each
// student's variant of a set is the one `frustum generate --roster` and `frustum grade --roster`
// draw for the same roster (variants_for_class), so paper, files and the browser agree.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "solver/problem/problem_set.hpp"
#include "solver/problem/serve_policy.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::server {

struct CourseSet {
  std::string id;       // the file name without .yaml: the set's part of every URL
  std::string file;     // its path
  std::string version;  // sha-256 of the file's bytes
  ProblemSet set;       // as written
  ServePolicy policy;
  std::map<std::string, ProblemSet> variants;  // per student, when the set varies

  // The student's variant (the set itself when it does not vary); null for a stranger.
  const ProblemSet* for_student(const std::string& student) const;
  // Which variant that is, as stored with a submission: "" when the set does not vary, else
  // "student:ID" or "student:ID#N" for a redraw.
  std::string variant_id(const std::string& student) const;
};

struct Course {
  std::string dir;
  std::vector<std::string> roster;
  std::vector<std::string> instructors;  // instructors.csv (none without it)
  std::vector<CourseSet> sets;           // by id
  std::vector<Diagnostic> errors;        // sets that cannot be served, located

  const CourseSet* find(const std::string& id) const;
  bool enrolled(const std::string& student) const;
  bool instructs(const std::string& id) const;
};

// A set id travels in URLs: letters, digits, - and _ only.
bool set_id_ok(const std::string& id);

// Reads every DIR/*.yaml (a subdirectory's files are not sets) for the given roster (from
// DIR/roster.csv, read by the caller). A set with errors is left out and its errors reported.
Course load_course(const std::string& dir, const std::vector<std::string>& roster);
// One set as load_course reads it (for a regrade against the file as it is now); nothing, with
// `errors` filled, when it cannot be served.
std::optional<CourseSet> load_course_set(const std::string& file,
                                         const std::vector<std::string>& roster,
                                         std::vector<Diagnostic>& errors);

}  // namespace frustum::server
