// What the kinds' numeric paths (values only, no steps, in any backend) share: converting the
// exact Given pieces to the backend's scalar, power-of-two scaling, the condition warning, and a
// polygon's normal with its zero decision (the filtered test, else the exact one). Each kind's
// own numeric path lives in its file in solver/kinds; the math is the templated core of
// solver/geometry and solver/viewing, and these adapters add the condition warnings.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "solver/geometry/polygon_normal.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/geometry/zero_vector.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/numeric_result.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/digits_said.hpp"

namespace frustum {

// What the numeric paths' shared warnings and notes say.
inline constexpr Phrase kNumericIllConditioned{
    "{0} is ill-conditioned ({1}): {2}; solve with --precision exact for the exact value.",
    "{0} は条件が悪い ({1}): {2}. 厳密な値は `--precision exact` で解くこと.",
    "{0} плохо обусловлено ({1}): {2}; точное значение даёт решение с `--precision exact`."};
inline constexpr Phrase kNumericComputedExactly{
    "{0}: computed exactly on the given numbers (the floating-point computation could not tell it "
    "from zero); only its final rounding is in it.",
    "{0}: 与えられた数の厳密計算で求めた (浮動小数点の計算では 0 と区別できなかった). "
    "誤差は最後の丸めだけ.",
    "{0}: вычислено точно на данных числах (вычисление с плавающей точкой не отличило это от "
    "нуля); в нём только последнее округление."};
inline constexpr Phrase kNumericWhetherNormalIsZero{"whether the normal is zero",
                                                    "法線がゼロかどうか", "равна ли нормаль нулю"};
inline constexpr Phrase kNumericTheNormal{"the normal", "法線", "нормаль"};

// An exact input in T, recording in `range` (when given) whether it left T's normal range.
template <typename T>
T conv(const Exact& e, InputRange* range = nullptr) {
  const T v = from_exact<T>(e);
  if constexpr (!kIsExact<T>) {
    if (range && !std::isfinite(v)) range->overflow = true;
    if (range && std::isfinite(v) && !converts_relatively(e, v)) range->underflow = true;
  }
  return v;
}

template <typename T, int N>
Eigen::Matrix<T, N, 1> conv(const Eigen::Matrix<Exact, N, 1>& v, InputRange* range = nullptr) {
  Eigen::Matrix<T, N, 1> out;
  for (int i = 0; i < N; ++i) out(i) = conv<T>(v(i), range);
  return out;
}

template <typename T>
Polygon3<T> conv(const Polygon3<Exact>& p, InputRange* range = nullptr) {
  Polygon3<T> out;
  for (const Vec3<Exact>& v : p) out.push_back(conv<T>(v, range));
  return out;
}

template <typename T>
MatX<T> conv(const MatX<Exact>& m) {
  MatX<T> out(m.rows(), m.cols());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) out(i, j) = from_exact<T>(m(i, j));
  return out;
}

// The points as doubles (for the condition estimates).
std::vector<Eigen::Vector3d> double_points(const Polygon3<Exact>& p);

// Floating point: divides v by the power of two nearest its largest component (exact) and
// returns the exponent, so products of the scaled components neither overflow nor underflow.
template <typename T>
int power_of_two_scale(Vec3<T>& v) {
  const T largest = v.cwiseAbs().maxCoeff();
  if (!(largest > T(0)) || !std::isfinite(largest)) return 0;
  const int k = std::ilogb(largest);
  for (int i = 0; i < 3; ++i) v(i) = std::ldexp(v(i), -k);
  return k;
}

// v·2ᵏ; `underflow` is set when a non-zero v lands below the normal range (subnormal or 0):
// a product scaled back that its true value's magnitude no longer fits.
template <typename T>
T scaled_by(const T& v, int k, bool& underflow) {
  if constexpr (kIsExact<T>) {
    return v;
  } else {
    const T r = std::ldexp(v, k);
    underflow = underflow || (v != T(0) && std::abs(r) < std::numeric_limits<T>::min());
    return r;
  }
}

// The warning a numeric path gives when its answer's condition is poor.
template <typename T>
void warn_condition(NumericOut<T>& out, Precision p, double kappa, const Said& title,
                    const Said& what) {
  if (!(kappa > kIllConditioned) || p == Precision::Exact) return;
  out.warn(title,
           say(kNumericIllConditioned, what,
               std::isfinite(kappa) ? fmt::format("κ ≈ {:.1e}", kappa) : std::string("κ = ∞"),
               backend_digits(kappa, p)));
}

// A polygon's normal in T: e₀ × e₁ for a triangle (seed 003), Newell's Σ dᵢ × dᵢ₊₁ (dᵢ = pᵢ − p₀)
// otherwise. In floating point the offsets are first scaled by a power of two (exact) so that
// neither the products nor ‖n‖ overflow or underflow for huge, tiny or subnormal coordinates;
// the normal is scaled back (it may then overflow; the unit normal never does). Whether the
// normal is zero (a degenerate polygon) is a discrete answer: decided by the normal's error
// bound, else exactly on the exact points (zero_vector.hpp), which then also give the unit normal.
template <typename T>
struct NormalPair {
  Vec3<T> n = Vec3<T>::Zero();
  Vec3<T> unit = Vec3<T>::Zero();
  bool zero = false;
  bool exact_zero_test = false;  // the exact fallback decided whether n is zero
  bool exact_value = false;      // …and n and unit are the exact normal's nearest values
  bool underflow = false;        // n scaled back fell below the normal range
};

// The exact normal of the formula polygon_normal uses (e₀ × e₁ = Newell's for a triangle).
inline NormalPair<Exact> exact_polygon_normal(const Polygon3<Exact>& p) {
  NormalPair<Exact> out;
  out.n = polygon_normal_formula(p);
  out.zero = is_zero_vector(out.n);
  if (!out.zero) out.unit = out.n / stable_norm(out.n);
  return out;
}

// Whether the normal `computed` in T is zero, by its componentwise `bound` or else exactly:
// `exact_normal()` gives the exact normal of the same formula, of which `computed` is the
// rounded value times 2^−scale. When the exact fallback ran, the computed vector was not proven
// to hold even its signs, so the exact one, rounded once, replaces it; the unit normal comes
// from that, or from the exact normal itself when the rounded one is 0 or overflows.
template <typename T, typename ExactNormal>
void decide_normal_zero(NormalPair<T>& out, Vec3<T>& computed, const Vec3<T>& bound,
                        bool inputs_relative, int scale, ExactNormal&& exact_normal) {
  std::optional<Vec3<Exact>> exact_n;
  const ZeroDecision z = decide_zero(computed, bound, inputs_relative, [&] {
    exact_n = exact_normal();
    return is_zero_vector(*exact_n);
  });
  out.zero = z.zero;
  out.exact_zero_test = z.exact;
  if (out.zero) {
    computed = Vec3<T>::Zero();
    return;
  }
  if constexpr (!kIsExact<T>) {
    if (exact_n) {
      out.exact_value = true;
      const Exact factor = GiNaC::pow(GiNaC::numeric(2), -scale);
      for (int i = 0; i < 3; ++i) computed(i) = from_exact<T>((*exact_n)(i)*factor);
      const T length = stable_norm(computed);
      if (!(length > T(0)) || !std::isfinite(length)) {
        const Exact exact_length = stable_norm(*exact_n);
        for (int i = 0; i < 3; ++i) out.unit(i) = from_exact<T>((*exact_n)(i) / exact_length);
        return;
      }
    }
  }
  out.unit = computed / stable_norm(computed);
}

template <typename T>
NormalPair<T> polygon_normal(const Polygon3<T>& p, const Polygon3<Exact>& exact_points,
                             bool inputs_relative) {
  if constexpr (kIsExact<T>) {
    return exact_polygon_normal(p);
  } else {
    NormalPair<T> out;
    const bool triangle = p.size() == 3;
    Polygon3<T> d;
    Vec3<T> largest = Vec3<T>::Zero();
    for (const Vec3<T>& v : p) {
      d.push_back(v - p[0]);
      largest = largest.cwiseMax(d.back().cwiseAbs());
    }
    const int k = power_of_two_scale(largest);
    for (Vec3<T>& v : d)
      for (int i = 0; i < 3; ++i) v(i) = std::ldexp(v(i), -k);
    Vec3<T> ns = polygon_normal_formula(d);  // d₀ = 0: e₀ × e₁ = d₁ × (d₂ − d₁)
    // The bound on the scaled magnitudes: each offset dᵢ within |pᵢ| + |p₀|, e₁ = d₂ − d₁
    // within |p₂| + |p₁| + 2|p₀|.
    auto magnitude = [&](std::size_t i) {
      return Vec3<T>((p[i].cwiseAbs() + p[0].cwiseAbs()) * std::ldexp(T(1), -k));
    };
    Vec3<T> bound;
    if (triangle) {
      bound = cross_error_bound(magnitude(1), Vec3<T>(magnitude(2) + magnitude(1)), 3);
    } else {
      Vec3<T> terms = Vec3<T>::Zero();
      for (std::size_t i = 1; i + 1 < p.size(); ++i)
        terms += cross_permanent(magnitude(i), magnitude(i + 1));
      const int m = static_cast<int>(p.size());
      bound = Rounding<T>::gamma(2 * m + 12) * terms +
              Vec3<T>::Constant(Rounding<T>::underflow(T(2 * (m - 2) + 4)));
    }
    decide_normal_zero(out, ns, bound, inputs_relative, 2 * k,
                       [&] { return exact_polygon_normal(exact_points).n; });
    if (out.zero) return out;  // the exact normal: 0
    for (int i = 0; i < 3; ++i) out.n(i) = scaled_by(ns(i), 2 * k, out.underflow);
    return out;
  }
}

// A value the exact fallback produced (its nearest T): said, since no rounding of the
// computation is in it and the ill-conditioning warnings do not apply to it.
template <typename T>
void report_exact_value(NumericOut<T>& out, const Said& what) {
  out.note(say(kNumericComputedExactly, what));
}

template <typename T>
void report_normal(NumericOut<T>& out, const NormalPair<T>& n) {
  if (n.underflow) out.underflow();
  out.vector("normal", n.n);
  if (n.exact_zero_test) out.exact_decision(say(kNumericWhetherNormalIsZero));
  if (n.exact_value) report_exact_value(out, say(kNumericTheNormal));
  if (n.zero) {
    out.null("unit_normal");
  } else {
    out.vector("unit_normal", n.unit);
  }
}

// Runs a prepared solver once and returns its answers.
NumericResult run_numeric(std::unique_ptr<NumericSolver> solver);

}  // namespace frustum
