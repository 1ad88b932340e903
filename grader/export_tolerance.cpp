#include "grader/export_tolerance.hpp"

#include <algorithm>
#include <cmath>

#include "grader/compare.hpp"

namespace frustum {

std::vector<double> accepted_windows(const ProblemSpec& problem, const std::string& answer,
                                     const Value& expected) {
  const Tolerance& tol = problem.tolerance_for(answer);
  double largest = 0;
  for (double x : expected.numbers) largest = std::max(largest, std::abs(x));
  const bool per_entry = expected.shape == Value::Shape::Matrix;
  std::vector<double> out;
  for (double x : expected.numbers) out.push_back(window(x, tol, per_entry ? x : largest));
  return out;
}

}  // namespace frustum
