// Per-student and seeded variants of a problem set. A varied problem's `given` is
// drawn — from its `vary:` block, or from the kind's default generator — then read by the
// kind's `parse` and solved like a hand-written one; draws that fail, are ill-conditioned (unless
// `difficulty: hard`), are not nice (with `nice: true`) or repeat another variant are redrawn,
// at most kMaxDrawAttempts times, then the problem carries a clear error.
//
// Reproducibility: a problem's draws come from splitmix64 (rng.hpp) seeded with FNV-1a 64 over
// the UTF-8 bytes  "frustum-variant/1" US KEY US WHO US ID  (US = 0x1F), where KEY is the set's
// title (or its file name without directory and extension when it has none), WHO is
// "student:" + the student id or "seed:N:I" (variant I of --seed N), and ID the problem id.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <unordered_set>
#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

inline constexpr int kMaxDrawAttempts = 100;
// Generator draws per attempt looking for the shape of a written exercise's given.
inline constexpr int kShapeTries = 20;

// A problem varies when it has `vary`, or when the set says `variants: per_student`.
bool problem_varies(const ProblemSet& set, const ProblemSpec& p);
bool set_varies(const ProblemSet& set);

std::string set_key(const ProblemSet& set);
// Seed of a variant (WHO as above): the FNV-1a state after KEY and WHO.
std::uint64_t variant_seed(const std::string& key, const std::string& who);
// Seed of one problem of that variant: the same hash continued with US and the problem id.
std::uint64_t problem_seed(std::uint64_t variant_seed, const std::string& problem_id);

// Givens as emit_flow text, held to refuse repeats: only looked up and added to (a hash set: a
// 100,000-variant run looks each draw up among up to 100,000 texts, in the workers and here).
using GivenTexts = std::unordered_set<std::string>;

// One drawn problem: `base` with a new given (parsed and solvable), or with `error` set.
// `avoid` holds the givens (as emit_flow text) of other variants; `given_text` receives this one's,
// and `repeated` (when given) each draw refused because `avoid` holds it.
ProblemSpec draw_problem(const ProblemSpec& base, const std::string& file, std::uint64_t seed,
                         const GivenTexts& avoid = {}, std::string* given_text = nullptr,
                         std::vector<std::string>* repeated = nullptr);

// A problem "p" of the kind asking every answer, with no `vary` (so draw_problem uses the
// kind's default generator): for self-tests and benchmarks.
ProblemSpec default_problem(const KindInfo& kind, bool nice = false, bool hard = false);

// The errors of problems that variants draw anew (every one that can be drawn with vary_all)
// whose text states a given value literally in a way that cannot be tied to one field
// (text_literals.hpp): such a variant would print a stale value. Located at the text of the
// language, naming the problem and the literal. `generate` refuses the set, `check` reports them.
std::vector<Diagnostic> stale_text_errors(const ProblemSet& set, bool vary_all);

// The student's variant of the set: every varying problem drawn for that student. A set that
// does not vary is returned as it is; a varying set with an empty student id gets an error.
// This is the hook that grading (single and batch) calls before grade().
ProblemSet variant_for(const ProblemSet& set, const std::string& student);

// `count` variants from `seed`, pairwise distinct in every varying problem. With vary_all,
// every problem varies (a set that declares no variation at all).
std::vector<ProblemSet> variants_from_seed(const ProblemSet& set, std::uint64_t seed, int count,
                                           bool vary_all = false);
// The same variants handed to `take` one at a time, in order (index, variant), without keeping
// them: linear in `count` in time, and in memory only the givens drawn so far.
// Stops after the first variant in which a problem could not be drawn (its ranges used up).
void for_each_variant_from_seed(const ProblemSet& set, std::uint64_t seed, int count, bool vary_all,
                                const std::function<void(int, ProblemSet&&)>& take);

// A variant's givens as seen by the pairwise-distinct rule, so that variants drawn apart (in
// other processes, each knowing fewer earlier variants) can be checked against all of them:
// per problem, the text of the drawn given (none when the problem is not drawn anew or found no
// variant), and the draws refused because they repeated a given known where they were drawn.
struct VariantGivens {
  std::vector<std::optional<std::string>> given;
  std::vector<std::vector<std::string>> repeated;
  bool complete = true;  // every problem drawn anew found a variant
};

// The variants of for_each_variant_from_seed one at a time, with the givens drawn so far.
class SeedVariants {
 public:
  SeedVariants(const ProblemSet& set, std::uint64_t seed, int count, bool vary_all);
  // Variant i drawn against the givens held here, which then hold its own (and `givens`, when
  // given, receives them). A problem that found no new variant carries an error saying where
  // the run stops, and exhausted() is true from then on.
  ProblemSet draw(int i, VariantGivens* givens = nullptr);
  // Whether a variant drawn apart, against fewer earlier givens, is the one draw() would give
  // here — every draw it refused as a repeat repeats a given held here and none of its givens
  // does (the draws themselves do not depend on what is avoided) — and if so holds its givens.
  // False: draw it here instead.
  bool take(const VariantGivens& givens);
  bool exhausted() const { return exhausted_; }

 private:
  ProblemSet set_;  // texts templated for drawing (literal values → placeholders)
  std::uint64_t seed_;
  int count_;
  bool vary_all_;
  std::vector<GivenTexts> taken_;  // per problem: the givens drawn so far
  bool exhausted_ = false;
};

// The variants of variants_for_class one student at a time, with the givens drawn so far.
class ClassVariants {
 public:
  // allow_repeats: a problem whose ranges run out (every draw for a student repeated an earlier
  // student's) may repeat from then on, instead of leaving the rest of the class without a
  // variant; the other problems stay pairwise distinct.
  ClassVariants(const ProblemSet& set, bool vary_all, bool allow_repeats = false);
  // The student's first draw, independent of every other student's (`givens` receives its
  // givens): what take() checks.
  ProblemSet first_draw(const std::string& student, VariantGivens* givens = nullptr) const;
  // The student's variant against the givens held here, which then hold its own.
  ProblemSet draw(const std::string& student);
  // Whether a first draw made apart repeats no given held here; if so its givens are held.
  // False: draw() the student here.
  bool take(const VariantGivens& givens);
  // The ids of the problems whose ranges ran out (allowed to repeat with allow_repeats).
  std::vector<std::string> exhausted() const;

 private:
  // The problems of `givens` that repeat a given held here (and may not).
  std::vector<std::size_t> repeated(const VariantGivens& givens) const;
  void hold(const VariantGivens& givens);
  ProblemSet set_;  // texts templated for drawing (literal values → placeholders)
  bool vary_all_;
  bool allow_repeats_;
  std::vector<GivenTexts> taken_;
  std::vector<bool> exhausted_;  // per problem: every draw for some student repeated
};

// The student's variant, with vary_all as above.
ProblemSet variant_for_student(const ProblemSet& set, const std::string& student, bool vary_all);
// The variants of a class, in roster order, pairwise distinct in every varying problem. A
// student's variant is their own (variant_for_student) unless one of its problems repeats the
// same problem of an earlier student's; then it is drawn again with WHO "student:ID#2", "#3"…
// (VariantInfo::draw). Such a student's variant cannot be regenerated from the source set and
// the id alone, so a class generated this way is graded against the generated files
// (`frustum grade SET ANSWERS --variants DIR`). When a problem's ranges hold fewer variants
// than students, the students left over carry an error naming it — or, with allow_repeats, that
// problem repeats from then on (ClassVariants).
std::vector<ProblemSet> variants_for_class(const ProblemSet& set,
                                           const std::vector<std::string>& students, bool vary_all,
                                           bool allow_repeats = false);

// Why the answers are not nice ("" when they are): every number of an asked answer must be
// simple — a rational with denominator ≤ 100, a square root of a rational with denominator
// ≤ 10000 (p√r/q), or a rational multiple of π with denominator ≤ 12. Answers a kind computes
// in floating point (render's depths) are not judged.
std::string not_nice(const Answers& answers, const std::vector<std::string>& ask);

// The variant as a complete problem set in YAML: the source's fields in their order, `vary`,
// `nice`, `difficulty` and `variants` removed, each `given` replaced by the drawn one, and
// `{field}` in a problem's text replaced by that given field's value (the variant's text: the
// literal given values it states were made placeholders when it was drawn, text_literals.hpp).
// `header` is written as comment lines first.
std::string emit_variant_set(const YAML::Node& source_root, const ProblemSet& variant,
                             const std::string& header);
// A set's fingerprint: FNV-1a 64 (hex) of its YAML as parsed and written again in flow form
// (emit_flow), `drawn_from` left out: the same for any layout or comments, different when a
// value, a key or a text changes. A variant file records its source's (`drawn_from:`).
std::string set_fingerprint(const YAML::Node& root);
// The `drawn_from:` line of a variant file (one line, ending in a newline).
std::string drawn_from_line(const DrawnFrom& d);
// `header` as YAML comment lines ("# " before each line, "#" for an empty one).
std::string comment_lines(const std::string& header);
// `{field}` in a problem's text replaced by that given field's value as students read it: a
// number as written, a point as (1, 2, 3); dotted paths reach inside ({perspective.fovy},
// {points.0}). Placeholders that name nothing stay as written (check refuses them).
std::string fill_text(const std::string& text, const YAML::Node& given);
// Why a text's placeholders cannot be filled from the given (an unknown name, a mapping or a
// nested list), or nullopt when every one can.
std::optional<std::string> placeholder_error(const std::string& text, const YAML::Node& given);

// The answer key (problem-format.md §2) of a variant: every asked answer, exact where possible.
// A problem that cannot be solved is left out, and its error added to `errors` when given.
std::string emit_answer_key(const ProblemSet& variant, const std::string& student,
                            const std::string& header, std::vector<Diagnostic>* errors = nullptr);
// One answer value as YAML (a value with no value is the word `none`).
YAML::Node answer_node(const Value& v);

}  // namespace frustum
