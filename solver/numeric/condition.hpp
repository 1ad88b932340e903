// Condition estimates: how much a rounding error in the inputs or the arithmetic can grow in
// an answer. A relative error of u in the data becomes about κ·u in the answer, so a backend
// with D decimal digits keeps about D − log10 κ of them. Estimates are computed in double on
// the (double-rounded) data: they warn, they never decide.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "solver/numeric/precision.hpp"

namespace frustum {

// Above this κ a derivation warns (more than 4 of the backend's digits are lost).
inline constexpr double kIllConditioned = 1e4;

// Digits of an answer with condition κ that a backend can be trusted with, at least 0
// (infinite for the exact backend).
double trusted_digits(double kappa, Precision p);

// "κ ≈ 3.2e+09: float keeps no digit, double about 6.5 of its 15.9, long double about 9.8 of
// its 19.3; the exact value is unaffected" — for the exact derivation; or, with a backend,
// only its own line.
std::string digits_sentence(double kappa);
std::string digits_sentence(double kappa, Precision p);

// Polygon normal n = Σᵢ dᵢ × dᵢ₊₁ (dᵢ = pᵢ − p₀; a triangle's e₀ × e₁ is the one term): input
// errors of u·max‖pᵢ‖ in the dᵢ, and the rounding of each product, relative to ‖n‖.
// Computed on the points scaled by a power of two, so tiny and huge coordinates (whose products
// would under- or overflow in double) get the estimate of the same shape at scale 1; the same
// holds for depth_condition and facing_condition.
double normal_condition(const std::vector<Eigen::Vector3d>& points);

// D_f = v·n with v = eye − p₀ and n the polygon's normal: the permanent (every product taken
// with absolute values) plus the effect of rounding the inputs, over |D_f|. Infinite when D_f = 0.
// Computed on the inputs scaled by a power of two (κ does not change with the scale), so tiny
// and huge coordinates get a true estimate.
double facing_condition(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& eye);

// The same for one backend: products below its normal range are off by up to η absolutely
// (η its least subnormal), which relative to |D_f| costs digits no κ shows; they are added as
// an equivalent condition (absolute error / (u·|D_f|)). For the exact backend, κ alone.
double facing_condition(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& eye,
                        Precision p);

// "κ ≈ …: float keeps …, double …, long double …" with each backend's own condition.
std::string digits_sentence(double kappa, double kappa_float, double kappa_double,
                            double kappa_long_double);

// a × b and a · b of two vectors each rounded to a backend: the products' absolute values over
// the result, in the max norm in which an answer's error is measured — a × b's condition is
// also the area's, sin θ's and the angle's (θ = atan2(‖a × b‖, a·b) near 0 and π), a · b's is
// cos θ's. Each vector is scaled by a power of two first (κ does not change). Infinite when the
// result is 0.
double cross_condition(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
double dot_condition(const Eigen::Vector3d& a, const Eigen::Vector3d& b);

// The plane method's z at pixel (x, y) of triangle ABC: c = n_z is a 2×2 determinant of the
// projected edges (its condition κ_c is how close the triangle is to edge-on), and the
// correction (a·Δx + b·Δy)/c added to z_A inherits it.
struct DepthCondition {
  double kappa_c = 1;  // of c alone
  double kappa_z = 1;  // of z at the pixel, relative to the largest of |z| and the vertices' |zᵢ|
};
DepthCondition depth_condition(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c, const Eigen::Vector2d& pixel);

// w = M₃·p of a homogeneous point: Σⱼ |M₃ⱼ pⱼ| / |w| (infinite at w = 0); NDC inherit it.
double w_condition(const Eigen::Vector4d& row3, const Eigen::Vector4d& p);

// far/near from which a derivation notes the depth buffer's resolution.
inline constexpr double kDepthRatioNote = 1e3;

// Eye-space distance below which a float depth buffer in [0, 1] cannot separate two surfaces at
// eye distance z (standard mapping, depth = f(z − n)/((f − n)z)): Δz ≈ 2⁻²⁴ (f − n) z² / (f n).
double float_depth_resolution(double near, double far, double z);

}  // namespace frustum
