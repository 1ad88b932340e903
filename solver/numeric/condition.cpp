#include "solver/numeric/condition.hpp"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

namespace frustum {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// |a| ⊗ |b|: the cross product's terms with absolute values, componentwise.
Eigen::Vector3d abs_cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d x = a.cwiseAbs(), y = b.cwiseAbs();
  return {x.y() * y.z() + x.z() * y.y(), x.z() * y.x() + x.x() * y.z(),
          x.x() * y.y() + x.y() * y.x()};
}

// The exponent k that puts the largest |coordinate| in [1, 2)·2ᵏ (0 when all are 0 or one is
// not finite). κ is the same for the points scaled by 2⁻ᵏ (exactly), whose products neither
// underflow nor overflow in double: an estimate true for tiny and huge coordinates alike.
int largest_exponent(const std::vector<Eigen::Vector3d>& points, double also = 0) {
  double largest = std::abs(also);
  for (const Eigen::Vector3d& q : points) largest = std::max(largest, q.cwiseAbs().maxCoeff());
  return largest > 0 && std::isfinite(largest) ? std::ilogb(largest) : 0;
}

template <int N>
Eigen::Matrix<double, N, 1> scaled(const Eigen::Matrix<double, N, 1>& q, int k) {
  Eigen::Matrix<double, N, 1> out;
  for (int i = 0; i < N; ++i) out(i) = std::ldexp(q(i), -k);
  return out;
}

double ratio(double num, double den) {
  if (num == 0) return 1.0;
  if (den == 0) return kInfinity;
  return std::max(1.0, num / den);
}

}  // namespace

double trusted_digits(double kappa, Precision p) {
  if (p == Precision::Exact) return kInfinity;
  return std::clamp(decimal_digits(p) - std::log10(std::max(1.0, kappa)), 0.0, decimal_digits(p));
}

std::string digits_sentence(double kappa, Precision p) {
  const double d = trusted_digits(kappa, p);
  if (p == Precision::Exact) return "the exact backend keeps every digit";
  if (d < 0.5) return fmt::format("{} keeps no correct digit", to_string(p));
  return fmt::format("{} keeps about {:.1f} of its {:.1f} digits", to_string(p), d,
                     decimal_digits(p));
}

std::string digits_sentence(double kappa) { return digits_sentence(kappa, kappa, kappa, kappa); }

std::string digits_sentence(double kappa, double kappa_float, double kappa_double,
                            double kappa_long_double) {
  const std::string k = std::isfinite(kappa) ? fmt::format("κ ≈ {:.1e}", kappa) : "κ = ∞";
  return fmt::format("{}: {}, {}, {}; the exact value shown is unaffected", k,
                     digits_sentence(kappa_float, Precision::Float),
                     digits_sentence(kappa_double, Precision::Double),
                     digits_sentence(kappa_long_double, Precision::LongDouble));
}

double normal_condition(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 3) return kInfinity;
  const int k = largest_exponent(points);
  std::vector<Eigen::Vector3d> p;
  for (const Eigen::Vector3d& q : points) p.push_back(scaled(q, k));
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), terms = Eigen::Vector3d::Zero();
  double scale = 0, sum_d = 0;
  for (const Eigen::Vector3d& q : p) scale = std::max(scale, q.cwiseAbs().maxCoeff());
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Eigen::Vector3d d0 = p[i] - p[0], d1 = p[i + 1] - p[0];
    n += d0.cross(d1);
    terms += abs_cross(d0, d1);
    sum_d += d0.cwiseAbs().maxCoeff() + d1.cwiseAbs().maxCoeff();
  }
  const double len = n.cwiseAbs().maxCoeff();
  // Input rounding: each dᵢ is off by up to 2u·max‖p‖ and meets the other edges' lengths.
  return ratio(2 * scale * sum_d + terms.maxCoeff(), len);
}

// Each input component is off by u relative (2u in a product of two), each product is rounded
// (u) and each sum or difference too: 3u times the products' absolute values, over u·|result|.
double cross_condition(const Eigen::Vector3d& a_in, const Eigen::Vector3d& b_in) {
  const Eigen::Vector3d a = scaled(a_in, largest_exponent({a_in})),
                        b = scaled(b_in, largest_exponent({b_in}));
  return ratio(3 * abs_cross(a, b).maxCoeff(), a.cross(b).cwiseAbs().maxCoeff());
}

double dot_condition(const Eigen::Vector3d& a_in, const Eigen::Vector3d& b_in) {
  const Eigen::Vector3d a = scaled(a_in, largest_exponent({a_in})),
                        b = scaled(b_in, largest_exponent({b_in}));
  return ratio(4 * a.cwiseAbs().dot(b.cwiseAbs()), std::abs(a.dot(b)));
}

double facing_condition(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& eye) {
  return facing_condition(points, eye, Precision::Exact);
}

double facing_condition(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& eye_in,
                        Precision precision) {
  if (points.size() < 3) return kInfinity;
  // Scaled by 2⁻ᵏ so the largest coordinate is about 1 (largest_exponent).
  if (!std::isfinite(eye_in.cwiseAbs().maxCoeff())) return kInfinity;
  for (const Eigen::Vector3d& q : points)
    if (!std::isfinite(q.cwiseAbs().maxCoeff())) return kInfinity;
  const int k = largest_exponent(points, eye_in.cwiseAbs().maxCoeff());
  std::vector<Eigen::Vector3d> p;
  for (const Eigen::Vector3d& q : points) p.push_back(scaled(q, k));
  const Eigen::Vector3d eye = scaled(eye_in, k);
  Eigen::Vector3d n = Eigen::Vector3d::Zero(), terms = Eigen::Vector3d::Zero();
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    n += (p[i] - p[0]).cross(p[i + 1] - p[0]);
    terms += abs_cross(p[i] - p[0], p[i + 1] - p[0]);
  }
  const Eigen::Vector3d v = eye - p[0];
  // Input rounding: eye and p₀ move by u·S (S the largest coordinate), which moves D_f by
  // about 2S‖n‖₁; the polygon's vertices move n by about 2S·Σ‖dᵢ‖, seen through v.
  double scale = eye.cwiseAbs().maxCoeff(), edges = 0;
  for (const Eigen::Vector3d& q : p) {
    scale = std::max(scale, q.cwiseAbs().maxCoeff());
    edges += (q - p[0]).cwiseAbs().maxCoeff();
  }
  const double input = 2 * scale * (n.cwiseAbs().sum() + v.cwiseAbs().maxCoeff() * edges);
  const double df = std::abs(v.dot(n));
  const double kappa = ratio(v.cwiseAbs().dot(terms) + input, df);
  if (precision == Precision::Exact || !std::isfinite(kappa)) return kappa;
  // Underflow, in log₂ (the unscaled magnitudes may be outside double's range): each of the
  // 2(m − 2) products per component of n is off by η/2 and meets |v| = |v_s|·2ᵏ; the dot
  // product's three by η; |D_f| = |D_s|·2³ᵏ.
  // log₂ η = min_exponent − digits (η = 2^(emin − p + 1), emin = min_exponent − 1).
  const auto log2_eta = [](auto x) {
    using L = std::numeric_limits<decltype(x)>;
    return double(L::min_exponent - L::digits);
  };
  const double log_eta = precision == Precision::Float    ? log2_eta(0.0f)
                         : precision == Precision::Double ? log2_eta(0.0)
                                                          : log2_eta(0.0L);
  const double through_v = std::log2(double(p.size() - 2) * v.cwiseAbs().sum() + 1e-300) + k;
  const double absolute = log_eta + std::max(through_v, std::log2(3.0)) + 1;
  const double underflow =
      absolute - (std::log2(df) + 3.0 * k) - std::log2(unit_roundoff(precision));
  if (underflow > 1023) return kInfinity;
  return kappa + std::exp2(underflow);
}

DepthCondition depth_condition(const Eigen::Vector3d& a_in, const Eigen::Vector3d& b_in,
                               const Eigen::Vector3d& c_in, const Eigen::Vector2d& pixel_in) {
  DepthCondition out;
  // Scaled by 2⁻ᵏ (largest_exponent): every term of both κ has the same degree in the scale.
  const int k = largest_exponent({a_in, b_in, c_in}, pixel_in.cwiseAbs().maxCoeff());
  const Eigen::Vector3d a = scaled(a_in, k), b = scaled(b_in, k), c = scaled(c_in, k);
  const Eigen::Vector2d pixel = scaled(pixel_in, k);
  const Eigen::Vector3d u = b - a, v = c - a;
  const Eigen::Vector3d n = u.cross(v), terms = abs_cross(u, v);
  // Input rounding in the projected edges, as for a normal.
  const double scale =
      std::max({a.head<2>().cwiseAbs().maxCoeff(), b.head<2>().cwiseAbs().maxCoeff(),
                c.head<2>().cwiseAbs().maxCoeff()});
  const double edges = u.head<2>().cwiseAbs().maxCoeff() + v.head<2>().cwiseAbs().maxCoeff();
  out.kappa_c = ratio(terms.z() + 2 * scale * edges, std::abs(n.z()));
  if (!std::isfinite(out.kappa_c)) {
    out.kappa_z = kInfinity;
    return out;
  }
  const double dx = pixel.x() - a.x(), dy = pixel.y() - a.y();
  const double correction = (std::abs(n.x() * dx) + std::abs(n.y() * dy)) / std::abs(n.z());
  const double z = a.z() - (n.x() * dx + n.y() * dy) / n.z();
  // Relative to the triangle's depths (what a z-buffer compares), not to z alone, which may be 0.
  const double depth_scale =
      std::max({std::abs(z), std::abs(a.z()), std::abs(b.z()), std::abs(c.z())});
  out.kappa_z = ratio(std::abs(a.z()) + correction * (1 + out.kappa_c), depth_scale);
  return out;
}

double w_condition(const Eigen::Vector4d& row3, const Eigen::Vector4d& p) {
  return ratio(row3.cwiseAbs().dot(p.cwiseAbs()), std::abs(row3.dot(p)));
}

double float_depth_resolution(double near, double far, double z) {
  return std::ldexp(1.0, -24) * (far - near) * z * z / (far * near);
}

}  // namespace frustum
