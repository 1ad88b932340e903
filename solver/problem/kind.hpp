// A problem kind, the unit of extension: it turns `given` into answers plus derivation
// steps. Each kind is one file with `parse` and `solve` and its answer metadata; the
// registry (registry.hpp) lists them all.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <any>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/derivation/derivation.hpp"
#include "solver/derivation/value.hpp"
#include "solver/problem/numeric_result.hpp"
#include "solver/viewing/conventions.hpp"

namespace frustum {

class GivenReader;
class Rng;
struct GenerateOptions;  // generate.hpp
struct Drawable;         // solver/visibility/drawable.hpp

// The type of an answer: how a student writes it, how it is read and compared with the key
// (the equivalences the grader applies) and how a platform asks for it — each in its own file of
// grader/answer_types/ (grader/answer_type.hpp).
enum class AnswerKind {
  Scalar,      // a number
  Angle,       // a number in the set's angle unit; written with a degree sign, in degrees
  Vector,      // componentwise
  Direction,   // a vector up to positive scale (a normal; "unnormalised" is accepted)
  UnitVector,  // a vector of length 1, componentwise
  Plane,       // a, b, c, d of ax + by + cz = d, up to any non-zero scale
  Matrix,      // componentwise, row by row (a list of points: each row judged at its own scale)
  Transform,   // a square homogeneous transformation matrix: entries judged per block (linear
               // part, translation column, bottom row); a purely linear one may be given as its
               // linear part (3×3 in 3D) unless the set says grading: {linear_matrix: false}
  Segment,     // two endpoints (rows), in either order
  PointSet,    // rows in any order (the pixels a triangle covers)
  Point,       // a point; homogeneous points up to w
  Bool,
  Category,   // one word of a fixed list (front/back/edge_on; 表/裏)
  WordMap,    // "i-j" → word
  WordList,   // an unordered set of words (edge lists)
  Sequence,   // an ordered list of words (a drawing order)
  Polygon,    // vertex list up to cyclic rotation
  BitString,  // outcodes
  Statements  // which numbered statements are true: their numbers, or one true/false each;
              // credit per statement (grader/statement_choice.hpp)
};

// How finely a numeric answer is judged, per component (docs/grading.md §2): `magnitude` is
// the size of the terms the component is computed from (the tolerance's absolute floor is
// rel × magnitude), `thresholds` the values whose side matters (0 for a sign-bearing D_f, ±1
// for NDC): a component on the other side is never accepted unless the expected one lies
// within that floor of the threshold. Empty: the grader's default for the answer kind.
struct AnswerScale {
  std::vector<double> magnitude;
  std::vector<std::vector<double>> thresholds;
};
using AnswerScales = std::vector<std::pair<std::string, AnswerScale>>;
// n components of one magnitude, each with the same thresholds.
inline AnswerScale uniform_scale(std::size_t n, double magnitude,
                                 std::vector<double> thresholds = {}) {
  return {std::vector<double>(n, magnitude), thresholds.empty()
                                                 ? std::vector<std::vector<double>>{}
                                                 : std::vector<std::vector<double>>(n, thresholds)};
}
// The largest |x| (0 when empty or absent): a vector's scale without squaring it.
inline double largest(const std::vector<double>& v) {
  double m = 0;
  for (const double x : v) m = std::max(m, x < 0 ? -x : x);
  return m;
}
inline double largest(const Value* v) { return v ? largest(v->numbers) : 0.0; }

struct AnswerSpec {
  std::string name;
  AnswerKind kind;
  std::vector<std::string> depends_on = {};  // earlier answers it is computed from
  std::vector<std::string> words = {};       // Category: the allowed words
  std::string needs_given = {};  // asked only when the problem gives this field (e.g. points)
  // Matrix: each row is a point (transformed points), so one point may be written as a flat list
  // or a column, and points in homogeneous coordinates with w = 1.
  bool point_rows = false;
  // WordList, WordMap keys: items are unordered pairs "a-b" (an edge, two polygons in conflict),
  // so "b-a" is the same item.
  bool unordered_pairs = false;
  // The symbols the derivation writes for this answer, which a student may repeat before `=`
  // as well as its name ("D_f = 27", "s = -415.7"); compared without case, spaces, `_`, braces
  // and with Unicode subscripts, primes and ⁻¹ read as their ASCII spellings.
  std::vector<std::string> symbols = {};
  // Matrix: the number that stands for +∞ in the key (the z-buffer's empty depth, 1e30), so that
  // a student may write +∞ as inf, ∞ or infinity; 0: +∞ is read as no number.
  double infinity = 0;
  // What the answer is called where a student reads its name alone (an exam sheet's answer line)
  // and it has no symbol: "the view matrix", in every language; its English is the answer's
  // name. Empty: the sheet writes the name as it is.
  Said label = {};
};

// A common mistake, as the answers it produces: the grader names it when a student's wrong
// answer matches one of these.
struct Misconception {
  Said name;        // "reversed cross product"
  Said feedback;    // what went wrong, for the student
  Said step;        // title of the derivation step where it goes wrong (as the step says it)
  Answers answers;  // the answers the mistake leads to
  // What went wrong said in the form the student wrote the answer in (ParsedAnswer::form, such
  // as "equation" for a plane), where `feedback` would describe another form.
  std::vector<std::pair<std::string, Said>> feedback_by_form = {};
};

// An answer the method gives as rightly as the key's, by another choice it leaves open (the
// view vector from another vertex of the face), with why it is right, for the student.
struct AlsoRight {
  std::string answer;
  Value value;
  Said why;
};

struct KindInfo {
  std::string name;
  Said summary;  // what the kind asks, in a line (a problem without a text is asked by it)
  std::vector<std::string> given_fields;  // for messages and suggestions
  std::vector<AnswerSpec> answers;
  // Reads and validates `given`; throws InputError with the location of the bad field.
  std::function<std::any(GivenReader&, const Conventions&)> parse;
  // Solves; records steps when `steps` is not null. Throws DomainError naming the field.
  std::function<Answers(const std::any& given, Derivation* steps)> solve;
  // Optional. Error carried forward: the later answers recomputed from the student's own
  // earlier answers (only those it can recompute; a trivial earlier answer such as a zero
  // normal yields nothing).
  std::function<Answers(const std::any& given, const Answers& student)> carry_forward;
  // Optional. Answers as right as the key's by another choice the method leaves open.
  std::function<std::vector<AlsoRight>(const std::any& given)> also_right;
  // Optional. The answers that common mistakes produce.
  std::function<std::vector<Misconception>(const std::any& given)> misconceptions;
  // Optional. Per answer, how finely it is judged (AnswerScale), from the given and the key;
  // answers left out get the grader's defaults.
  std::function<AnswerScales(const std::any& given, const Answers& key)> scales;
  // Optional. The numeric path in a backend (values only, no steps; `frustum solve
  // --precision`, `frustum bench accuracy`): inputs converted once, run() only computes.
  std::function<std::unique_ptr<NumericSolver>(const std::any& given, Precision)> solve_numeric;
  // Optional. The kind's default generator (generate.hpp): a fresh `given`, as YAML that then
  // goes through `parse` like a hand-written one; used when a varied problem has no `vary`.
  std::function<YAML::Node(Rng&, const GenerateOptions&)> generate;
  // Optional. Why a solved variant is ill-conditioned ("" when it is fine): a near-degenerate
  // triangle, the eye in a face's plane, a point behind the eye. Such draws are redrawn.
  std::function<std::string(const std::any& given, const Answers& answers)> ill_conditioned;
  // ill_conditioned reads the given alone (K::ill_conditioned(given)): a draw can be refused
  // before it is solved.
  bool ill_conditioned_given_only = false;
  // Optional. The geometry `frustum draw` pictures (hidden lines, painter vs z-buffer).
  std::function<Drawable(const std::any& given)> drawable;
  // The conventions the answers depend on, stated in the derivation's first step (K::kUses;
  // default: all of them).
  ConventionUse uses;
  // Nothing to draw (K::kFixed): the instructor's own statements and key. Variants keep such a
  // problem as written, and `vary:` on it is an error.
  bool fixed = false;

  // Where the kind stands in `frustum kinds`, the kinds table of docs/kinds.md and every other
  // listing of kinds (smaller first): set in the kind's `<name>_kind()`; the registry sorts by it.
  int order = 0;
  // The kinds table of docs/kinds.md (Markdown): what `given` takes and what the answers are.
  // The table is generated from these (kinds_table_markdown) and tests/registry_test.cpp
  // checks docs/kinds.md against it.
  std::string doc_given;
  std::string doc_answers;
  // Optional. One draw of a well-conditioned `given` for `frustum bench accuracy`, as a YAML
  // flow mapping, or nullopt to draw again (kinds with solve_numeric only).
  std::function<std::optional<std::string>(Rng&)> accuracy_given;

  const AnswerSpec* answer(const std::string& name) const;
};

// Adapts a kind struct (CONTRIBUTING.md, "The kind file") to the type-erased KindInfo.
template <typename K>
KindInfo make_kind() {
  KindInfo k;
  k.name = K::kName;
  k.summary = Said(K::kSummary);
  k.given_fields = K::given_fields();
  k.answers = K::answers();
  k.parse = [](GivenReader& r, const Conventions& c) -> std::any { return K::parse(r, c); };
  k.solve = [](const std::any& g, Derivation* steps) {
    return K::solve(std::any_cast<const typename K::Given&>(g), steps);
  };
  using G = typename K::Given;
  if constexpr (requires(const G& g, const Answers& a) { K::carry_forward(g, a); })
    k.carry_forward = [](const std::any& g, const Answers& a) {
      return K::carry_forward(std::any_cast<const G&>(g), a);
    };
  if constexpr (requires(const G& g) { K::also_right(g); })
    k.also_right = [](const std::any& g) { return K::also_right(std::any_cast<const G&>(g)); };
  if constexpr (requires(const G& g) { K::misconceptions(g); })
    k.misconceptions = [](const std::any& g) {
      return K::misconceptions(std::any_cast<const G&>(g));
    };
  if constexpr (requires(const G& g, const Answers& a) { K::scales(g, a); })
    k.scales = [](const std::any& g, const Answers& a) {
      return K::scales(std::any_cast<const G&>(g), a);
    };
  if constexpr (requires(const G& g) { K::solve_numeric(g, Precision::Double); })
    k.solve_numeric = [](const std::any& g, Precision p) {
      return K::solve_numeric(std::any_cast<const G&>(g), p);
    };
  if constexpr (requires(Rng & r, const GenerateOptions& o) { K::generate(r, o); })
    k.generate = [](Rng& r, const GenerateOptions& o) { return K::generate(r, o); };
  if constexpr (requires(const G& g, const Answers& a) { K::ill_conditioned(g, a); })
    k.ill_conditioned = [](const std::any& g, const Answers& a) {
      return K::ill_conditioned(std::any_cast<const G&>(g), a);
    };
  if constexpr (requires(const G& g) { K::ill_conditioned(g); }) {
    k.ill_conditioned = [](const std::any& g, const Answers&) {
      return K::ill_conditioned(std::any_cast<const G&>(g));
    };
    k.ill_conditioned_given_only = true;
  }
  if constexpr (requires(const G& g) { K::drawable(g); })
    k.drawable = [](const std::any& g) { return K::drawable(std::any_cast<const G&>(g)); };
  if constexpr (requires { K::kUses; }) k.uses = K::kUses;
  if constexpr (requires { K::kFixed; }) k.fixed = K::kFixed;
  return k;
}

}  // namespace frustum
