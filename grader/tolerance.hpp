// Judging one number against its own expected value (docs/grading.md §2): a relative window
// around each component, an absolute floor from the magnitude of the terms the component is
// computed from (the problem's own noise, not a fixed constant), and thresholds whose side a
// student's number must share with the expected one.
#pragma once

#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/problem/kind.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

// The accepted half-width around `expected`: max(rel·|e|, rel·magnitude, abs) in rel mode;
// sigfigs and decimals replace rel·|e| (see Tolerance). `unit_exponent` k: the numbers are
// the true values times 2⁻ᵏ (values beyond double's range, scaled exactly), so the absolute
// parts of the window (abs, a decimal's or a significant digit's half unit) scale with them.
double window(double expected, const Tolerance& tol, double magnitude, int unit_exponent = 0);
// |got − expected| ≤ window (and both finite).
bool close(double expected, double got, const Tolerance& tol, double magnitude,
           int unit_exponent = 0);

// How each component of one expected value is judged: the kind's AnswerScale where it declares
// one of the right size, else the default for the answer kind — a vector's or point's own
// largest component, a list of points row by row, a transform's block (linear part,
// translation column, bottom row), a scalar's own size.
class ComponentJudge {
 public:
  // `unit_exponent`: see window().
  ComponentJudge(const Value& expected, AnswerKind kind, const Tolerance& tol,
                 const AnswerScale* declared, int unit_exponent = 0);

  // Component i of the expected value e against the student's g: within the window, and on
  // the same side of every threshold unless e lies within the noise floor of it.
  bool ok(std::size_t i, double e, double g) const;
  // Every component (sizes must agree).
  bool all(const std::vector<double>& e, const std::vector<double>& g) const;
  // The whole window of component i around e.
  double window(std::size_t i, double e) const;

 private:
  double magnitude(std::size_t i, double e) const;

  const Tolerance& tol_;
  int unit_exponent_ = 0;
  const std::vector<double>* declared_ = nullptr;  // the kind's
  std::vector<double> computed_;                   // a matrix's rows or blocks
  double uniform_ = 0;                             // a vector's largest component
  bool own_ = false;                               // a scalar: its own size
  const std::vector<std::vector<double>>* thresholds_ = nullptr;
};

// The largest |x| of v[begin, end) (0 when empty): a vector's scale without squaring it.
double max_abs(const std::vector<double>& v, std::size_t begin = 0, std::size_t end = SIZE_MAX);

}  // namespace frustum
