#include "grader/compare.hpp"

#include "solver/util/exact_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace frustum {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::Correct: return "correct";
    case Verdict::Incorrect: return "incorrect";
    case Verdict::Partial: return "partial";
    case Verdict::Unparseable: return "unparseable";
    case Verdict::Missing: return "missing";
  }
  return "incorrect";
}

double window(double expected, const Tolerance& tol, double scale) {
  if (tol.decimals) return std::max(tol.abs, 0.5 * std::pow(10.0, -*tol.decimals));
  if (tol.sigfigs) {
    if (expected == 0) return tol.abs;
    const double digit = std::floor(std::log10(std::abs(expected)));
    return std::max(tol.abs, 0.5 * std::pow(10.0, digit - *tol.sigfigs + 1));
  }
  return std::max(tol.abs, tol.rel * std::abs(scale));
}

bool close(double expected, double got, const Tolerance& tol, double scale) {
  if (!std::isfinite(got)) return false;
  // A little slack for the rounding of the window itself (0.5 at the last digit).
  return std::abs(got - expected) <= window(expected, tol, scale) * (1 + 1e-12);
}

namespace {

Comparison correct(std::string why) { return {Verdict::Correct, 1.0, std::move(why)}; }
Comparison incorrect(std::string why) { return {Verdict::Incorrect, 0.0, std::move(why)}; }

bool exactly_equal(const Value& a, const Value& b) {
  if (a.exact.empty() || b.exact.empty() || a.exact.size() != b.exact.size()) return false;
  // Values whose doubles already differ cannot be equal: skip the exact simplification
  // (most wrong and most decimal answers end here, cheaply).
  if (a.numbers.size() == a.exact.size() && b.numbers.size() == b.exact.size())
    for (std::size_t i = 0; i < a.numbers.size(); ++i) {
      const double x = a.numbers[i], y = b.numbers[i];
      if (std::isfinite(x) && std::isfinite(y) && std::abs(x - y) > 1e-9 * std::max({1.0, std::abs(x), std::abs(y)}))
        return false;
    }
  for (std::size_t i = 0; i < a.exact.size(); ++i)
    if (!canonical(a.exact[i] - b.exact[i]).is_zero()) return false;
  return true;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

// Componentwise within tolerance, relative to the largest component of the expected value
// (a vector's small components need not be more precise than its large ones), or, for
// matrices, relative to each entry (a translation column must not excuse the rotation).
bool close_all(const std::vector<double>& e, const std::vector<double>& g, const Tolerance& tol,
               bool per_entry = false) {
  if (e.size() != g.size()) return false;
  const double scale = max_abs(e);
  for (std::size_t i = 0; i < e.size(); ++i)
    if (!close(e[i], g[i], tol, per_entry ? e[i] : scale)) return false;
  return true;
}

// How many components are within tolerance (for partial credit).
std::size_t count_close(const std::vector<double>& e, const std::vector<double>& g,
                        const Tolerance& tol, bool per_entry) {
  if (e.size() != g.size()) return 0;
  const double scale = max_abs(e);
  std::size_t n = 0;
  for (std::size_t i = 0; i < e.size(); ++i) n += close(e[i], g[i], tol, per_entry ? e[i] : scale);
  return n;
}

// A polygon's vertex list as rows of `cols` numbers.
std::vector<std::vector<double>> vertices(const Value& v) {
  std::vector<std::vector<double>> out;
  const std::size_t cols = v.cols > 0 ? static_cast<std::size_t>(v.cols) : 1;
  for (std::size_t i = 0; i + cols <= v.numbers.size(); i += cols)
    out.emplace_back(v.numbers.begin() + static_cast<long>(i), v.numbers.begin() + static_cast<long>(i + cols));
  return out;
}

std::vector<double> scaled(const std::vector<double>& v, double k) {
  std::vector<double> out(v);
  for (double& x : out) x *= k;
  return out;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

// The scale λ minimising ‖g − λe‖ (least squares), when g is a multiple of e.
double best_scale(const std::vector<double>& e, const std::vector<double>& g) {
  const double ee = dot(e, e);
  return ee == 0 ? 0 : dot(g, e) / ee;
}

Comparison compare_numbers(const Value& expected, const Value& got, const Tolerance& tol) {
  if (exactly_equal(expected, got)) return correct("exactly equal");
  if (close_all(expected.numbers, got.numbers, tol, expected.shape == Value::Shape::Matrix))
    return correct(fmt::format("within tolerance (relative {}, absolute {})", tol.rel, tol.abs));
  return incorrect("");
}

}  // namespace

Comparison compare(const Value& expected, const Value& got, const AnswerSpec& spec,
                   const Tolerance& tol, bool partial) {
  if (expected.shape == Value::Shape::Null) {
    return got.shape == Value::Shape::Null ? correct("there is no such value")
                                           : incorrect("there is no such value here");
  }
  if (got.shape == Value::Shape::Null) return incorrect("there is a value here");
  switch (spec.kind) {
    case AnswerKind::Scalar: return compare_numbers(expected, got, tol);
    case AnswerKind::Vector:
    case AnswerKind::Point:
    case AnswerKind::Matrix:
    case AnswerKind::UnitVector: {
      if (got.numbers.size() != expected.numbers.size())
        return incorrect(fmt::format("expected {} components, got {}", expected.numbers.size(),
                                     got.numbers.size()));
      Comparison c = compare_numbers(expected, got, tol);
      if (c.verdict == Verdict::Correct) return c;
      if (spec.kind == AnswerKind::Point) {
        // Homogeneous coordinates: (x, y, z, w) and (kx, ky, kz, kw), k > 0, are one point.
        const double k = best_scale(expected.numbers, got.numbers);
        if (k > 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
          return correct("the same homogeneous point (a positive multiple)");
      }
      if (spec.kind == AnswerKind::UnitVector) {
        const double k = best_scale(expected.numbers, got.numbers);
        if (k > 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
          return incorrect(fmt::format(
              "the direction is right but the length is {} — a unit vector has length 1 "
              "(divide by the length)",
              format_approx(std::sqrt(dot(got.numbers, got.numbers)))));
        if (k < 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
          return incorrect("it points the opposite way: check the order of the cross product");
      }
      if ((spec.kind == AnswerKind::Vector || spec.kind == AnswerKind::Matrix) && partial) {
        const bool per_entry = expected.shape == Value::Shape::Matrix;
        const std::size_t right = count_close(expected.numbers, got.numbers, tol, per_entry);
        if (right > 0)
          return {Verdict::Partial, static_cast<double>(right) / static_cast<double>(expected.numbers.size()),
                  fmt::format("{} of {} {} right", right, expected.numbers.size(), per_entry ? "entries" : "components")};
      }
      return c;
    }
    case AnswerKind::Direction: {
      if (got.numbers.size() != expected.numbers.size())
        return incorrect(fmt::format("expected {} components, got {}", expected.numbers.size(),
                                     got.numbers.size()));
      const double k = best_scale(expected.numbers, got.numbers);
      if (k > 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
        return correct(k == 1 || exactly_equal(expected, got)
                           ? "equal"
                           : "the same direction (a normal is right up to a positive factor)");
      if (k < 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
        return incorrect("it points the opposite way: check the order of the cross product");
      return incorrect("");
    }
    case AnswerKind::Plane: {
      if (got.numbers.size() != 4) return incorrect("a plane has 4 coefficients");
      const double k = best_scale(expected.numbers, got.numbers);
      if (k != 0 && close_all(scaled(expected.numbers, k), got.numbers, tol))
        return correct("the same plane (equations agree up to a non-zero factor)");
      return incorrect("");
    }
    case AnswerKind::Bool:
      return got.flag == expected.flag ? correct("") : incorrect("");
    case AnswerKind::Category:
    case AnswerKind::BitString:
      return got.word == expected.word ? correct("") : incorrect("");
    case AnswerKind::WordList: {
      std::vector<std::string> a = expected.words, b = got.words;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a == b) return correct("the same set (order does not matter)");
      std::size_t common = 0;
      for (const std::string& w : b) common += std::binary_search(a.begin(), a.end(), w);
      if (common > 0 && !a.empty()) {
        Comparison c{Verdict::Partial, static_cast<double>(common) / static_cast<double>(std::max(a.size(), b.size())),
                     fmt::format("{} of the {} expected items, and {} that should not be there", common,
                                 a.size(), b.size() - common)};
        return c;
      }
      return incorrect("");
    }
    case AnswerKind::Sequence:
      return got.words == expected.words ? correct("") : incorrect("the order differs");
    case AnswerKind::WordMap: {
      std::size_t right = 0;
      for (const auto& [k, w] : expected.entries)
        for (const auto& [gk, gw] : got.entries)
          if (gk == k && gw == w) ++right;
      if (right == expected.entries.size() && got.entries.size() == right) return correct("");
      if (right > 0)
        return {Verdict::Partial, static_cast<double>(right) / static_cast<double>(expected.entries.size()),
                fmt::format("{} of {} entries right", right, expected.entries.size())};
      return incorrect("");
    }
    case AnswerKind::Polygon: {
      // The same vertex cycle, starting anywhere (orientation must match).
      const auto e = vertices(expected), g = vertices(got);
      if (e.size() != g.size() || e.empty()) return incorrect(fmt::format("expected {} vertices, got {}", e.size(), g.size()));
      for (std::size_t shift = 0; shift < e.size(); ++shift) {
        bool all = true;
        for (std::size_t i = 0; i < e.size() && all; ++i) all = close_all(e[i], g[(i + shift) % g.size()], tol);
        if (all) return correct(shift ? "the same polygon, starting at another vertex" : "equal");
      }
      return incorrect("");
    }
    default:
      return incorrect("answers of this kind cannot be graded yet");
  }
}

}  // namespace frustum
