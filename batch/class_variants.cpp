#include "batch/class_variants.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "batch/variant_files.hpp"
#include "solver/input/yaml_document.hpp"
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

// Whether two sets hold the same problems with the same givens (ids in order, givens as
// emit_flow writes them); `differs` receives the first problem id that does not.
bool same_givens(const ProblemSet& a, const ProblemSet& b, std::string& differs) {
  const std::size_t n = std::max(a.problems.size(), b.problems.size());
  for (std::size_t i = 0; i < n; ++i) {
    const ProblemSpec* p = i < a.problems.size() ? &a.problems[i] : nullptr;
    const ProblemSpec* q = i < b.problems.size() ? &b.problems[i] : nullptr;
    if (!p || !q || p->id != q->id || emit_flow(p->given_node) != emit_flow(q->given_node)) {
      differs = p ? p->id : q->id;
      return false;
    }
  }
  return true;
}

// The set a student is graded against with --variants, never a stale one: the file
// `frustum generate` wrote when the set has not changed since (its fingerprint); when it has
// (a key, tolerance or policy fixed), the student's variant drawn again from the set as it is
// now when that gives the student the same givens; otherwise refused, saying what to do.
ProblemSet generated_set_now(const ProblemSet& set, const std::string& file,
                             const std::string& student, std::string& variant) {
  ProblemSet written = load_problem_set(file);
  if (!written.errors.empty()) return written;
  if (!written.drawn_from)
    return refused(set, file,
                   "this generated set does not say which version of " + set.file +
                       " it was drawn from (written by an earlier frustum): generate the "
                       "variants again with this one");
  const YamlDocument now = load_yaml_file(set.file);
  if (!now.error && set_fingerprint(now.root) == written.drawn_from->fingerprint) {
    variant = "graded against " + file;
    return written;
  }
  const std::string changed = set.file + " changed since " + file + " was generated";
  if (written.drawn_from->draw > 1 || written.drawn_from->student != student)
    return refused(set, file,
                   changed + ", and this variant (" +
                       (written.drawn_from->student.empty()
                            ? std::string("a --seed variant")
                            : "draw " + std::to_string(written.drawn_from->draw) + " of student " +
                                  written.drawn_from->student) +
                       ") cannot be drawn again from the set alone: generate the variants again "
                       "(the same roster draws the same class) and grade against them");
  ProblemSet fresh = set_varies(set) ? variant_for(set, student) : set;
  std::string differs;
  if (!fresh.all_errors().empty() || !same_givens(fresh, written, differs))
    return refused(set, file,
                   changed + ", and the student's problem " + differs +
                       " drawn from the set as it is now differs from the one in the file: "
                       "generate the variants again and hand them out, or grade against the "
                       "set as it was");
  variant = "graded against the variant of student " + student + " drawn again from " + set.file +
            " as it is now (it changed since " + file +
            " was generated; the student's givens are the same)";
  return fresh;
}

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
    return generated_set_now(set, file, student, variant);
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
