#include "batch/class_variants.hpp"

#include <fmt/format.h>

#include <filesystem>

#include "batch/variant_files.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

RosterVariants roster_variants(const ProblemSet& set, const std::vector<std::string>& roster) {
  RosterVariants out;
  if (!set_varies(set)) {
    for (const std::string& student : roster) out.emplace(student, set);
    return out;
  }
  const std::vector<ProblemSet> drawn = variants_for_class(set, roster, false);
  for (std::size_t i = 0; i < roster.size(); ++i) out.emplace(roster[i], drawn[i]);
  return out;
}

std::optional<RosterVariants> read_class_variants(const ProblemSet& set,
                                                  const VariantSource& source) {
  if (!source.roster) return std::nullopt;
  return roster_variants(set, read_roster(*source.roster));
}

namespace {

ProblemSet refused(const ProblemSet& set, const std::string& where, const std::string& why) {
  ProblemSet none = set;
  none.problems.clear();
  none.errors.push_back(Diagnostic{SourceLocation{where, 0, 0}, "student", why});
  return none;
}

const char* kRedrawHint =
    "grade the class against the files `frustum generate -o DIR` wrote (--variants DIR) or against "
    "the roster it "
    "was generated from (--roster ROSTER)";

}  // namespace

// A class of a varying set graded without --variants or --roster: each student is graded against
// the variant drawn from their own id (as `generate --student` draws it), so each result depends
// on that student's file alone. When two students' variants from their ids share a problem and the
// class was generated together (`generate --roster`), one of them was drawn again, and which
// depends on the roster: those pairs are named to the instructor (never in a student's result).
std::vector<std::string> shared_draws(const ProblemSet& set,
                                      const std::vector<BatchEntry>& entries) {
  std::vector<std::string> said;
  std::map<std::string, std::string> first;  // problem id + given → the first student with it
  for (const BatchEntry& e : entries) {
    if (e.student.empty() || e.error) continue;
    const ProblemSet v = variant_for(set, e.student);
    for (std::size_t i = 0; i < v.problems.size() && i < set.problems.size(); ++i) {
      const ProblemSpec& p = v.problems[i];
      if (!problem_varies(set, set.problems[i]) || p.error) continue;
      const auto [it, fresh] = first.emplace(p.id + "\x1f" + emit_flow(p.given_node), e.student);
      if (!fresh && it->second != e.student)
        said.push_back(fmt::format(
            "the variants of {} and {} drawn from their ids share problem {}; each was graded "
            "against the variant from their own id, which is right if the class was generated "
            "with `frustum generate --student`; if it was generated with --roster, one of them "
            "was drawn again: {}",
            it->second, e.student, p.id, kRedrawHint));
    }
  }
  return said;
}

// The set a student is graded against: with --variants, the file `frustum generate` wrote for
// them; with --roster, their variant in the class drawn from that roster; otherwise their own
// variant when the set varies.
ProblemSet set_for_student(const ProblemSet& set, const VariantSource& source,
                           const RosterVariants* roster, const std::string& student,
                           std::string& variant) {
  if (source.variants_dir) {
    const std::string file = variant_file(*source.variants_dir, set.file, variant_name(student));
    std::error_code ec;
    if (student.empty() || !std::filesystem::is_regular_file(file, ec))
      return refused(
          set, file,
          student.empty()
              ? "the answers need `student:` to find the student's generated set"
              : "no generated set for student " + student + " in " + *source.variants_dir);
    variant = "graded against " + file;
    return load_problem_set(file);
  }
  if (roster) {
    const auto it = roster->find(student);
    if (it == roster->end())
      return refused(set, *source.roster,
                     student.empty()
                         ? "the answers need `student:` to find the student in the roster"
                         : "student " + student + " is not in the roster " + *source.roster);
    const ProblemSet& v = it->second;
    if (v.variant)
      variant = fmt::format(
          "graded against the variant of student {} in the class of {} (draw {}, seed {:016x})",
          student, *source.roster, v.variant->draw, v.variant->seed);
    return v;
  }
  if (!set_varies(set)) return set;
  ProblemSet v = variant_for(set, student);
  if (v.variant)
    variant = fmt::format(
        "graded against the variant of student {} (seed {:016x}) drawn from the id, as "
        "`frustum generate --student` draws it; a class generated with --roster may have drawn "
        "this "
        "student again: then {}",
        v.variant->student, v.variant->seed, kRedrawHint);
  return v;
}

}  // namespace frustum
