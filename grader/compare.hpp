// Comparing a parsed answer with the expected one, by the answer kind's equivalences
// (docs/grading.md §2–4): exact equality when both are exact, else each component within its
// own window (grader/tolerance.hpp); a normal up to positive scale, a plane up to any non-zero
// scale, a homogeneous point up to w, a segment in either direction, a purely linear transform
// as its linear part; component credit only when the set asks for it, and never for what a
// trivial answer also gets right.
#pragma once

#include <string>
#include <vector>

#include "grader/tolerance.hpp"
#include "grader/trivial.hpp"
#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

enum class Verdict { Correct, Incorrect, Partial, Unparseable, Missing };

std::string_view to_string(Verdict v);

struct Comparison {
  Verdict verdict = Verdict::Incorrect;
  double credit = 0;     // fraction of the answer's points, 0..1
  Said feedback;         // why, for the student
  Said trivial;          // the trivial answer it is as a whole ("identity matrix"), if any
  bool no_work = false;  // that trivial answer takes no work (TrivialAnswer::no_work)
  // A mistake the comparison itself recognises ("not normalised": the right direction, another
  // length); a kind's own named mistake that fits the answer is said instead.
  Said mistake;
};

// How one asked answer of one problem is judged; prepared once per problem.
struct AnswerRules {
  const AnswerSpec* spec = nullptr;
  Tolerance tol;
  const AnswerScale* scale = nullptr;         // the kind's, when it declares one
  bool partial = false;                       // component credit
  bool linear_matrix = kLinearMatrixDefault;  // a purely linear transform as its linear part
  const std::vector<TrivialAnswer>* trivial = nullptr;  // of the key (trivial.hpp)
  // The numbers are the true values times 2⁻ᵏ (set by compare() itself for values beyond
  // double's range; see tolerance.hpp's window()).
  int unit_exponent = 0;
};

Comparison compare(const Value& expected, const Value& got, const AnswerRules& rules);

}  // namespace frustum
