// Loading a problem set (problem-format.md §1): conventions, tolerance defaults, problems with
// `ask`, `points` and `given`. Loading never throws: every mistake becomes a Diagnostic on the
// set or on its problem, and one broken problem never stops the rest.
#pragma once

#include <yaml-cpp/yaml.h>

#include <any>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/derivation/local_text.hpp"
#include "solver/problem/kind.hpp"
#include "solver/problem/samples.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

class VaryPlan;       // vary_spec.hpp
struct YamlDocument;  // yaml_document.hpp

// Largest `points` of one problem or answer: far beyond any course's weights, and small enough
// that a set's total and a class's sums stay finite doubles.
inline constexpr double kMaxPoints = 1'000'000;
// Problems of one set: each problem's work is bounded by its kind's limits, so a set's is at
// most this many times the slowest (the largest bundled set has 15; a 1 000-problem set is a
// term's worth of exercises).
inline constexpr std::size_t kMaxSetProblems = 1'000;

// Grading defaults (docs/grading.md): relative 1e-3 like WeBWorK, per component; the absolute
// floor comes from the problem's own magnitudes (rel × what the component is computed from),
// so `abs` is 0 unless the instructor sets it.
inline constexpr double kRelTolDefault = 1e-3;
inline constexpr double kAbsTolDefault = 0;

// Error carried forward: the fraction of an answer's points given when it follows correctly
// from the student's own wrong earlier answer.
inline constexpr double kEcfCreditDefault = 0.5;
// Vectors and matrices are all-or-nothing by default, like WeBWorK and PrairieLearn's matrix
// input; `grading: {partial: true}` gives credit per component that shows work.
inline constexpr bool kPartialDefault = false;
// A purely linear 3D (2D) transform may be answered with its 3×3 (2×2) linear part.
inline constexpr bool kLinearMatrixDefault = true;

// Accepted window for component i of an expected value e (docs/grading.md §2), with mᵢ the
// magnitude of the terms it is computed from (AnswerScale):
//   rel:       max(rel·|eᵢ|, rel·mᵢ, abs)
//   sigfigs:   max(½·10^(⌊log₁₀|eᵢ|⌋ − sigfigs + 1), rel·mᵢ, abs)   half a unit in the last digit
//   decimals:  max(½·10^(−decimals), rel·mᵢ, abs)
struct Tolerance {
  double rel = kRelTolDefault;
  double abs = kAbsTolDefault;
  std::optional<int> sigfigs;
  std::optional<int> decimals;
};

struct Grading {
  double ecf = kEcfCreditDefault;             // 0 turns error carried forward off
  bool partial = kPartialDefault;             // credit per component for vectors and matrices
  bool linear_matrix = kLinearMatrixDefault;  // 3×3 accepted for a purely linear 3D transform
};

struct ProblemSpec {
  std::string id;
  std::string kind;
  LocalText text;        // `text:`, in every language the set gives it
  YAML::Node text_node;  // where it is written (placeholders' errors point there)
  Conventions conventions;
  Tolerance tolerance;
  std::map<std::string, Tolerance> answer_tolerance;  // tolerance: {answers: {z: {...}}}
  Grading grading;
  std::vector<std::string> ask;           // every answer of the kind when the file has no `ask`
  std::optional<double> points;           // total weight; default 1 per asked answer
  std::map<std::string, double> weights;  // points: {normal: 1, z: 2}
  SourceLocation where;                   // the problem's mapping
  std::string field;                      // "problems[2]"
  const KindInfo* info = nullptr;
  std::any given;  // the kind's parsed Given
  // The answers found when a variant was drawn (variants.cpp: each draw is solved to be
  // checked), reused by solve_problem without steps instead of solving the same given again.
  std::shared_ptr<const Answers> drawn_answers;
  YAML::Node given_node;
  YAML::Node vary;  // the `vary:` block (generate.hpp); undefined when absent
  // `vary` read once for drawing (set by the variants of a set); null: read at each draw.
  std::shared_ptr<const VaryPlan> vary_plan;
  bool nice = false;            // nice: true — integer or simple exact answers
  bool hard = false;            // difficulty: hard — near-degenerate cases on purpose
  std::vector<Sample> samples;  // answers with the verdicts their author expects (samples.hpp)
  std::optional<Diagnostic> error;

  double max_score() const;
  // Points of one asked answer: its weight, or an equal share of `points`, or 1.
  double answer_points(const std::string& name) const;
  const Tolerance& tolerance_for(const std::string& name) const;
};

// Which per-student variant a set is (variants.hpp): the student and the variant's seed.
struct VariantInfo {
  std::string student;
  std::uint64_t seed = 0;
  int draw = 1;  // > 1: drawn again so that a class's variants differ (variants_for_class)
};

// What a variant file written by `frustum generate` was drawn from (its `drawn_from:` field):
// the source set's fingerprint (variants.hpp: set_fingerprint) when it was drawn, and whose
// variant it is. Grading against such a file checks the fingerprint against the set as it is now.
struct DrawnFrom {
  std::string set;          // the source set's file name
  std::string fingerprint;  // set_fingerprint of the source set when the variant was drawn
  std::string student;      // empty for a --seed variant
  int draw = 1;             // > 1: drawn again for a class (VariantInfo::draw)
};

struct ProblemSet {
  std::string file;
  Lang lang = Lang::En;  // `lang:` the language the set is written in; other texts fall back to it
  LocalText title;
  std::string source;  // what the set follows (a course's lecture, a textbook), cited in headers
  bool per_student = false;             // variants: per_student
  std::optional<VariantInfo> variant;   // set when this is a generated variant
  std::optional<DrawnFrom> drawn_from;  // set when read from a variant file
  Conventions conventions;
  Tolerance tolerance;
  Grading grading;
  std::vector<ProblemSpec> problems;
  std::vector<Diagnostic> errors;  // of the file as a whole

  const ProblemSpec* find(const std::string& id) const;
  // Every diagnostic: the file's and each problem's.
  std::vector<Diagnostic> all_errors() const;
};

ProblemSet load_problem_set(const std::string& path);
// From a file already read and parsed (load_yaml_file): `name` stands for the file in messages.
ProblemSet load_problem_set(const YamlDocument& doc, const std::string& name);
// `name` stands for the file in messages.
ProblemSet load_problem_set_from_string(const std::string& yaml, const std::string& name);

// Fails at the first key of `map` not in `known` (with "did you mean"), as `prefix.key`.
void check_keys(const YAML::Node& map, const std::vector<std::string>& known,
                const std::string& file, const std::string& prefix);

// Reads `conventions:` / `tolerance:` mappings (also used by the answer loader).
Conventions read_conventions(const YAML::Node& n, const std::string& file, const std::string& field,
                             Conventions base);
Tolerance read_tolerance(const YAML::Node& n, const std::string& file, const std::string& field,
                         Tolerance base);
Grading read_grading(const YAML::Node& n, const std::string& file, const std::string& field,
                     Grading base);

}  // namespace frustum
