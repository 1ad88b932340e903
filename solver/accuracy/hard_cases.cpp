#include "solver/accuracy/hard_cases.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <limits>

#include "solver/geometry/facing.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/rng.hpp"
#include "solver/viewing/projection.hpp"

namespace frustum::bench {

namespace {

constexpr long double kHalfPi = 1.570796326794896619231321691639751442L;

template <typename T>
Vec3<T> rounded(const Vec3<Exact>& v) {
  return Vec3<T>(from_exact<T>(v(0)), from_exact<T>(v(1)), from_exact<T>(v(2)));
}

// Angle between a computed vector and the exact direction (π/2 for a zero or non-finite vector).
template <typename T>
double angle_to(const Vec3<T>& v, const Eigen::Matrix<long double, 3, 1>& exact_unit) {
  Eigen::Matrix<long double, 3, 1> x(v(0), v(1), v(2));
  if (!x.allFinite() || x.cwiseAbs().maxCoeff() == 0) return static_cast<double>(kHalfPi);
  x /= x.cwiseAbs().maxCoeff();
  return static_cast<double>(std::atan2(x.cross(exact_unit).norm(), x.dot(exact_unit)));
}

template <typename T>
NormalMethods methods_in(const std::string& id, Precision p, const Polygon3<Exact>& points,
                         const Eigen::Matrix<long double, 3, 1>& exact_unit) {
  Polygon3<T> q;
  for (const Vec3<Exact>& v : points) q.push_back(rounded<T>(v));
  return {id, p, angle_to(edge_pair_normal(q, 0), exact_unit),
          angle_to(best_edge_pair_normal(q), exact_unit), angle_to(newell_normal(q), exact_unit)};
}

template <typename T>
double elapsed_ns(std::chrono::steady_clock::time_point start) {
  return static_cast<double>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start)
          .count());
}

template <typename T>
FacingStudy facing_study_in(Precision p, int cases, std::uint64_t seed) {
  FacingStudy s{p, cases};
  Rng rng(seed);
  // Coordinates with b bits, so that p₀ + s·e₁ + t·e₂ (s, t eighths) is exact in T: the eye
  // starts exactly in the plane and is then moved by k = 0..3 units in the last place.
  const int bits = std::numeric_limits<T>::digits - 6;
  const auto coordinate = [&] {
    return Exact(GiNaC::numeric(static_cast<long>(rng.integer(-(1LL << bits), 1LL << bits)))) /
           GiNaC::pow(2, bits);
  };
  std::vector<Polygon3<T>> polys;
  std::vector<Vec3<T>> eyes, far_eyes;
  std::vector<int> exact_signs;
  std::vector<Polygon3<Exact>>
      exact_polys;  // the inputs' exact values (those of the T coordinates)
  std::vector<Vec3<Exact>> exact_eyes, exact_far_eyes;
  for (int c = 0; c < cases; ++c) {
    Polygon3<Exact> poly;
    for (int i = 0; i < 3; ++i)
      poly.push_back(Vec3<Exact>(coordinate(), coordinate(), coordinate()));
    const Exact a = Exact(static_cast<long>(rng.integer(-8, 16))) / 8,
                b = Exact(static_cast<long>(rng.integer(-8, 16))) / 8;
    const Vec3<Exact> on_plane = poly[0] + a * (poly[1] - poly[0]) + b * (poly[2] - poly[0]);
    Polygon3<T> pt;
    for (const Vec3<Exact>& v : poly) pt.push_back(rounded<T>(v));
    Vec3<T> eye = rounded<T>(on_plane);
    const int axis = static_cast<int>(rng.integer(0, 2)),
              steps = static_cast<int>(rng.integer(0, 3));
    const T toward =
        rng.chance(1, 2) ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
    for (int k = 0; k < steps; ++k) eye(axis) = std::nextafter(eye(axis), toward);
    Polygon3<Exact> pe;
    for (const Vec3<T>& v : pt)
      pe.push_back(Vec3<Exact>(exact_of(v(0)), exact_of(v(1)), exact_of(v(2))));
    const Vec3<Exact> ee(exact_of(eye(0)), exact_of(eye(1)), exact_of(eye(2)));
    exact_signs.push_back(exact_sign((ee - pe[0]).dot(newell_normal(pe))));
    polys.push_back(pt);
    eyes.push_back(eye);
    far_eyes.push_back(Vec3<T>(T(3), T(-2), T(5)));
    exact_polys.push_back(pe);
    exact_eyes.push_back(ee);
    exact_far_eyes.push_back(Vec3<Exact>(3, -2, 5));
  }
  for (int c = 0; c < cases; ++c) {
    const auto k = static_cast<std::size_t>(c);
    const Facing<T> f = facing(polys[k], eyes[k], exact_polys[k], exact_eyes[k], true);
    s.naive_wrong += f.naive_sign != exact_signs[static_cast<std::size_t>(c)] ? 1 : 0;
    s.adaptive_wrong += f.sign != exact_signs[static_cast<std::size_t>(c)] ? 1 : 0;
    s.exact_fallbacks += f.used_exact ? 1 : 0;
  }
  // Timings: the naive sign, and the adaptive predicate, on these cases and on easy ones.
  const auto time = [&](const std::vector<Vec3<T>>& e, const std::vector<Vec3<Exact>>& ee,
                        bool adaptive) {
    const auto start = std::chrono::steady_clock::now();
    long passes = 0;
    long checksum = 0;
    do {
      for (std::size_t c = 0; c < polys.size(); ++c) {
        if (adaptive) {
          checksum += facing(polys[c], e[c], exact_polys[c], ee[c], true).sign;
        } else {
          const Vec3<T> n = newell_normal(polys[c]);
          checksum += scalar_sign(T((e[c] - polys[c][0]).dot(n)));
        }
      }
      ++passes;
    } while (elapsed_ns<T>(start) < 2e7);
    const double ns =
        elapsed_ns<T>(start) / (static_cast<double>(passes) * static_cast<double>(polys.size()));
    return checksum == std::numeric_limits<long>::min() ? 0.0 : ns;  // keeps the loop observable
  };
  s.naive_ns = time(eyes, exact_eyes, false);
  s.adaptive_ns = time(eyes, exact_eyes, true);
  s.naive_ns_generic = time(far_eyes, exact_far_eyes, false);
  s.adaptive_ns_generic = time(far_eyes, exact_far_eyes, true);
  return s;
}

// Stored depth of a surface at eye distance D in float, and whether larger means nearer.
float stored_depth(DepthMapping m, float near, float far, float distance) {
  const Volume<float> v{-1, 1, -1, 1, near, far};
  if (m == DepthMapping::OpenGL) {
    const MatX<float> p = frustum_matrix(v, Api::OpenGL);
    const float z = -distance;
    const float ndc = (p(2, 2) * z + p(2, 3)) / (-z);
    return ndc * 0.5f + 0.5f;
  }
  if (m == DepthMapping::DirectX) {
    const MatX<float> p = frustum_matrix(v, Api::DirectX);
    return (p(2, 2) * distance + p(2, 3)) / distance;
  }
  // Reversed-Z: DirectX's [0, 1] matrix with near and far exchanged (near → 1, far → 0).
  const float a = near / (near - far), b = far * near / (far - near);
  return (a * distance + b) / distance;
}

}  // namespace

std::vector<NormalMethods> normal_methods(const ProblemSet& set) {
  std::vector<NormalMethods> out;
  for (const ProblemSpec& spec : set.problems) {
    if (spec.error || spec.kind != "normal" || !spec.given_node["points"]) continue;
    GivenReader reader(spec.given_node, set.file, spec.field + ".given", {});
    const Polygon3<Exact> points = reader.points("points", 3);
    // The exact unit normal, converted last: n itself may be beyond every format (1e-620).
    const Vec3<Exact> n = newell_normal(points);
    const Exact length = GiNaC::sqrt(n.dot(n));
    Eigen::Matrix<long double, 3, 1> unit;
    for (int i = 0; i < 3; ++i) unit(i) = to_long_double(canonical(n(i) / length));
    out.push_back(methods_in<float>(spec.id, Precision::Float, points, unit));
    out.push_back(methods_in<double>(spec.id, Precision::Double, points, unit));
    out.push_back(methods_in<long double>(spec.id, Precision::LongDouble, points, unit));
  }
  return out;
}

FacingStudy facing_study(Precision p, int cases, std::uint64_t seed) {
  switch (p) {
    case Precision::Float:
      return facing_study_in<float>(p, cases, seed);
    case Precision::LongDouble:
      return facing_study_in<long double>(p, cases, seed);
    default:
      return facing_study_in<double>(Precision::Double, cases, seed);
  }
}

std::string to_string(DepthMapping m) {
  return m == DepthMapping::OpenGL    ? "OpenGL [−1, 1] → (z + 1)/2"
         : m == DepthMapping::DirectX ? "DirectX [0, 1]"
                                      : "reversed-Z [0, 1] (near → 1)";
}

int depth_flips(DepthMapping m, double far_over_near, double relative_gap, int pixels) {
  const float near = 1.0f, far = static_cast<float>(far_over_near);
  int flips = 0;
  for (int i = 0; i < pixels; ++i) {
    const double t = pixels > 1 ? static_cast<double>(i) / (pixels - 1) : 0.0;
    const double d = 2.0 * std::pow(far_over_near / 4.0, t);  // 2·near … far/2
    const float d1 = static_cast<float>(d), d2 = static_cast<float>(d * (1 + relative_gap));
    const float z1 = stored_depth(m, near, far, d1), z2 = stored_depth(m, near, far, d2);
    const bool separated = m == DepthMapping::ReversedZ ? z2 < z1 : z2 > z1;
    flips += separated ? 0 : 1;
  }
  return flips;
}

double smallest_separable_gap(DepthMapping m, double far_over_near, int pixels) {
  double smallest = 1.0;
  for (int k = 0; k <= 80; ++k) {
    const double gap = std::pow(10.0, -k / 8.0);
    if (depth_flips(m, far_over_near, gap, pixels) > 0) break;
    smallest = gap;
  }
  return smallest;
}

std::string hard_case_report(const ProblemSet& hard, int facing_cases, std::uint64_t seed) {
  std::string out =
      "### Normals of near-degenerate polygons (angle to the exact normal, radians)\n\n"
      "| problem | backend | naive e₀ × e₁ | best edge pair | Newell |\n| --- | --- | ---: | ---: "
      "| ---: |\n";
  const auto angle = [](double a) {
    return a >= 1.5707 ? std::string("zero vector") : fmt::format("{:.1e}", a);
  };
  for (const NormalMethods& m : normal_methods(hard))
    out += fmt::format("| {} | {} | {} | {} | {} |\n", m.id, to_string(m.precision), angle(m.naive),
                       angle(m.best_pair), angle(m.newell));
  out += fmt::format(
      "\n### Back-face signs with the eye 0–3 units in the last place from the plane ({} cases)\n\n"
      "| backend | naive sign wrong | adaptive sign wrong | exact fallbacks | naive ns | adaptive "
      "ns | "
      "naive ns (eye off the plane) | adaptive ns (eye off the plane) |\n"
      "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n",
      facing_cases);
  for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
    const FacingStudy s = facing_study(p, facing_cases, seed);
    out += fmt::format("| {} | {} ({:.1f}%) | {} | {} | {:.0f} | {:.0f} | {:.0f} | {:.0f} |\n",
                       to_string(p), s.naive_wrong, 100.0 * s.naive_wrong / s.cases,
                       s.adaptive_wrong, s.exact_fallbacks, s.naive_ns, s.adaptive_ns,
                       s.naive_ns_generic, s.adaptive_ns_generic);
  }
  out +=
      "\n### Depth precision: float depth buffer, two parallel planes, 1000 pixels from 2·near to "
      "far/2\n\n"
      "| mapping | far/near | flips at gap 1e-2 | flips at gap 1e-3 | flips at gap 1e-4 | flips at "
      "gap 1e-5 | "
      "smallest separable relative gap |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (DepthMapping m : {DepthMapping::OpenGL, DepthMapping::DirectX, DepthMapping::ReversedZ})
    for (double ratio : {1e3, 1e4, 1e5, 1e6})
      out += fmt::format("| {} | {:.0e} | {} | {} | {} | {} | {:.1e} |\n", to_string(m), ratio,
                         depth_flips(m, ratio, 1e-2), depth_flips(m, ratio, 1e-3),
                         depth_flips(m, ratio, 1e-4), depth_flips(m, ratio, 1e-5),
                         smallest_separable_gap(m, ratio));
  return out;
}

}  // namespace frustum::bench
