// Comparing a parsed answer with the expected one, by the answer kind's equivalences:
// exact equality when both are exact, else within tolerance; a normal up to positive scale,
// a plane up to any non-zero scale.
#pragma once

#include "solver/derivation/value.hpp"
#include "solver/kinds/kind.hpp"
#include "solver/kinds/problem_set.hpp"

#include <string>

namespace frustum {

enum class Verdict { Correct, Incorrect, Partial, Unparseable, Missing };

std::string_view to_string(Verdict v);

struct Comparison {
  Verdict verdict = Verdict::Incorrect;
  double credit = 0;     // fraction of the answer's points, 0..1
  std::string feedback;  // why, for the student
};

// The accepted window around `expected` (see Tolerance); `scale` is what `rel` is relative to.
double window(double expected, const Tolerance& tol, double scale);
// |got − expected| ≤ window.
bool close(double expected, double got, const Tolerance& tol, double scale);

// partial: vectors and matrices with some components right get that fraction (Partial).
Comparison compare(const Value& expected, const Value& got, const AnswerSpec& spec,
                   const Tolerance& tol, bool partial = true);

}  // namespace frustum
