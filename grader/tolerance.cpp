#include "grader/tolerance.hpp"

#include <algorithm>
#include <cmath>

#include "grader/answer_type.hpp"

namespace frustum {

double max_abs(const std::vector<double>& v, std::size_t begin, std::size_t end) {
  double m = 0;
  for (std::size_t i = begin; i < std::min(end, v.size()); ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

double window(double expected, const Tolerance& tol, double magnitude, int unit_exponent) {
  const double abs = unit_exponent == 0 ? tol.abs : std::ldexp(tol.abs, -unit_exponent);
  const double floor = std::max(abs, tol.rel * std::abs(magnitude));
  // log10 of 2ᵏ: the decimal digits the scaled numbers are shifted by.
  const double shift = unit_exponent * 0.30102999566398120;
  if (tol.decimals) return std::max(floor, 0.5 * std::pow(10.0, -*tol.decimals - shift));
  if (tol.sigfigs) {
    if (expected == 0) return floor;
    const double digit = std::floor(std::log10(std::abs(expected)) + shift);
    return std::max(floor, 0.5 * std::pow(10.0, digit - *tol.sigfigs + 1 - shift));
  }
  return std::max(floor, tol.rel * std::abs(expected));
}

bool close(double expected, double got, const Tolerance& tol, double magnitude, int unit_exponent) {
  if (!std::isfinite(got) || !std::isfinite(expected)) return false;
  // A little slack for the rounding of the window itself (0.5 at the last digit).
  return std::abs(got - expected) <= window(expected, tol, magnitude, unit_exponent) * (1 + 1e-12);
}

namespace {

// Default magnitudes (docs/grading.md §2): what each component is computed from.
std::vector<double> default_magnitudes(const Value& e, AnswerKind kind) {
  const std::vector<double>& x = e.numbers;
  std::vector<double> m(x.size());
  const bool rows = e.shape == Value::Shape::Matrix && e.cols > 0;
  const bool blocks = answer_type(kind).block_magnitudes;
  if (blocks && rows && e.rows == e.cols && e.rows >= 2) {
    // Blocks of a homogeneous matrix: the linear part, the translation column, the bottom row.
    const std::size_t n = static_cast<std::size_t>(e.rows);
    enum Block { kLinear, kTranslation, kBottom };
    const auto block = [n](std::size_t i, std::size_t j) {
      return i == n - 1 ? kBottom : j == n - 1 ? kTranslation : kLinear;
    };
    double size[3] = {0, 0, 0};
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        size[block(i, j)] = std::max(size[block(i, j)], std::abs(x[i * n + j]));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j) m[i * n + j] = size[block(i, j)];
    return m;
  }
  if (rows && !blocks) {
    const std::size_t c = static_cast<std::size_t>(e.cols);
    for (std::size_t r = 0; r * c < x.size(); ++r) {
      const double row = max_abs(x, r * c, (r + 1) * c);
      for (std::size_t j = r * c; j < std::min(x.size(), (r + 1) * c); ++j) m[j] = row;
    }
    return m;
  }
  return {};  // vectors and scalars: see the constructor (no allocation)
}

}  // namespace

ComponentJudge::ComponentJudge(const Value& expected, AnswerKind kind, const Tolerance& tol,
                               const AnswerScale* declared, int unit_exponent)
    : tol_(tol), unit_exponent_(unit_exponent) {
  const std::size_t n = expected.numbers.size();
  if (declared && declared->magnitude.size() == n)
    declared_ = &declared->magnitude;
  else if (expected.shape == Value::Shape::Matrix && expected.cols > 0)
    computed_ = default_magnitudes(expected, kind);  // rows or blocks
  if (!declared_ && computed_.empty()) {
    own_ = expected.shape == Value::Shape::Scalar;  // a scalar: its own size
    uniform_ = max_abs(expected.numbers);           // a vector's components share one scale
  }
  if (declared && declared->thresholds.size() == n) thresholds_ = &declared->thresholds;
}

double ComponentJudge::magnitude(std::size_t i, double e) const {
  if (declared_) return (*declared_)[i];
  if (i < computed_.size()) return computed_[i];
  return own_ ? std::abs(e) : uniform_;
}

double ComponentJudge::window(std::size_t i, double e) const {
  return frustum::window(e, tol_, magnitude(i, e), unit_exponent_);
}

bool ComponentJudge::ok(std::size_t i, double e, double g) const {
  const double m = magnitude(i, e);
  if (!close(e, g, tol_, m, unit_exponent_)) return false;
  if (!thresholds_) return true;
  // The side of each threshold: a student's number strictly on the other side is wrong unless
  // the expected one is within the noise floor of the threshold (its side is then not
  // meaningful at the problem's precision).
  for (const double t : (*thresholds_)[i]) {
    const double de = e - t, dg = g - t;
    if (((de > 0 && dg < 0) || (de < 0 && dg > 0)) && std::abs(de) > tol_.rel * m) return false;
  }
  return true;
}

bool ComponentJudge::all(const std::vector<double>& e, const std::vector<double>& g) const {
  if (e.size() != g.size()) return false;
  for (std::size_t i = 0; i < e.size(); ++i)
    if (!ok(i, e[i], g[i])) return false;
  return true;
}

}  // namespace frustum
