#include "solver/steps/numeric_paths.hpp"

#include <fmt/format.h>

#include <cmath>

#include "solver/geometry/facing.hpp"
#include "solver/geometry/plane_depth.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/geometry/zero_vector.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/numeric/ranged.hpp"
#include "solver/steps/kind_steps.hpp"

namespace frustum {

namespace {

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

std::vector<Eigen::Vector3d> doubles(const Polygon3<Exact>& p) {
  std::vector<Eigen::Vector3d> out;
  for (const Vec3<Exact>& v : p) out.push_back(to_double(v));
  return out;
}

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
void warn_condition(NumericOut<T>& out, Precision p, double kappa, const std::string& title,
                    const std::string& what) {
  if (!(kappa > kIllConditioned) || p == Precision::Exact) return;
  out.warn(title,
           fmt::format("{} is ill-conditioned ({}): {}; solve with --precision exact for "
                       "the exact value.",
                       what, std::isfinite(kappa) ? fmt::format("κ ≈ {:.1e}", kappa) : "κ = ∞",
                       digits_sentence(kappa, p)));
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
  bool underflow = false;        // n scaled back fell below the normal range
};

// The exact normal of the formula polygon_normal uses (e₀ × e₁ = Newell's for a triangle).
inline NormalPair<Exact> exact_polygon_normal(const Polygon3<Exact>& p) {
  NormalPair<Exact> out;
  out.n = p.size() == 3 ? edge_pair_normal(p, 0) : newell_normal(p);
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
    Vec3<T> ns = triangle ? Vec3<T>(d[1].cross(d[2] - d[1])) : newell_normal(d);
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

template <typename T>
void report_normal(NumericOut<T>& out, const NormalPair<T>& n) {
  if (n.underflow) out.underflow();
  out.vector("normal", n.n);
  if (n.exact_zero_test) out.exact_decision("whether the normal is zero");
  if (n.zero) {
    out.null("unit_normal");
  } else {
    out.vector("unit_normal", n.unit);
  }
}

}  // namespace

NumericResult run_numeric(std::unique_ptr<NumericSolver> solver) {
  solver->run();
  return solver->result();
}

std::unique_ptr<NumericSolver> vectors_numeric(const Vec3<Exact>& a, const Vec3<Exact>& b,
                                               AngleUnit unit, Precision p) {
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Vec3<T> a, b;
      bool degrees;
      InputRange range;
      Vec3<Exact> exact_a, exact_b;  // for the exact parallel test
    };
    struct Out {
      T dot{}, area{}, sin{}, cos{}, angle{};
      Vec3<T> cross;
      NormalPair<T> unit;  // unit.zero: a and b are parallel (a × b = 0)
      bool underflow = false;
    };
    auto core = [](const In& in) {
      Out o;
      // Floating point: a and b scaled by powers of two first (exact), so that huge, tiny and
      // subnormal components keep their digits; sin, cos, the angle and the unit normal do not
      // depend on the scale, the products are scaled back (and may then overflow or underflow,
      // as their true values would).
      Vec3<T> a = in.a, b = in.b;
      int ka = 0, kb = 0;
      if constexpr (!kIsExact<T>) {
        ka = power_of_two_scale(a);
        kb = power_of_two_scale(b);
      }
      const T dot = a.dot(b);
      Vec3<T> cross = a.cross(b);
      // Parallel or not is a discrete answer (the unit normal exists or not): a × b's bound
      // (each scaled component one rounding from its exact value) or else exactly.
      Vec3<T> bound = Vec3<T>::Zero();
      if constexpr (!kIsExact<T>)
        bound = cross_error_bound(Vec3<T>(a.cwiseAbs()), Vec3<T>(b.cwiseAbs()), 1);
      decide_normal_zero(o.unit, cross, bound, in.range.relative(), ka + kb,
                         [&] { return Vec3<Exact>(in.exact_a.cross(in.exact_b)); });
      const T area = stable_norm(cross), la = stable_norm(a), lb = stable_norm(b);
      o.dot = scaled_by(dot, ka + kb, o.underflow);
      for (int i = 0; i < 3; ++i) o.cross(i) = scaled_by(cross(i), ka + kb, o.underflow);
      o.area = scaled_by(area, ka + kb, o.underflow);
      o.sin = area / la / lb;
      o.cos = dot / la / lb;
      // θ = atan2(‖a × b‖, a·b): accurate at every angle, unlike arccos(cos θ) near 0 and π.
      o.angle = scalar_angle(area, dot);
      if (in.degrees) o.angle = o.angle * T(180) / scalar_pi(o.angle);
      return o;
    };
    auto report = [p](const In& in, const Out& o) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      if (o.underflow) out.underflow();
      out.scalar("dot", o.dot);
      out.vector("cross", o.cross);
      out.scalar("area", o.area);
      out.scalar("sin", o.sin);
      out.scalar("cos", o.cos);
      out.scalar("angle", o.angle);
      if (o.unit.exact_zero_test) out.exact_decision("whether a and b are parallel");
      if (o.unit.zero)
        out.null("unit_normal");
      else
        out.vector("unit_normal", o.unit.unit);
      out.note("angle = atan2(‖a × b‖, a·b)");
      return out.take();
    };
    In in{{}, {}, unit == AngleUnit::Degrees, {}, a, b};
    in.a = conv<T>(a, &in.range);
    in.b = conv<T>(b, &in.range);
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> normal_numeric(const Polygon3<Exact>& points,
                                              const std::optional<CrossOrder>& order, Precision p) {
  const double kappa = normal_condition(doubles(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      std::optional<std::array<int, 4>> order;  // first = X₀→Y₀, second = X₁→Y₁ (vertex indices)
      InputRange range;
      Polygon3<Exact> exact_points;  // for the exact zero test and the refusal
      std::optional<CrossOrder> cross;
    };
    auto core = [](const In& in) {
      NormalPair<T> r;
      if (!in.order) {
        r = polygon_normal(in.points, in.exact_points, in.range.relative());
        // A degenerate polygon is refused, as the exact solve refuses it (the same words).
        if (r.zero) polygon_normal_with_steps(in.exact_points, "points", nullptr);
        return r;
      }
      const auto& o = *in.order;
      r.n = Vec3<T>(in.points[o[1]] - in.points[o[0]])
                .cross(Vec3<T>(in.points[o[3]] - in.points[o[2]]));
      Vec3<T> bound = Vec3<T>::Zero();
      if constexpr (!kIsExact<T>) {
        auto magnitude = [&](int i, int j) {
          return Vec3<T>(in.points[i].cwiseAbs() + in.points[j].cwiseAbs());
        };
        bound = cross_error_bound(magnitude(o[1], o[0]), magnitude(o[3], o[2]), 2);
      }
      const std::array<Vec3<Exact>, 3> abc{in.exact_points[0], in.exact_points[1],
                                           in.exact_points[2]};
      decide_normal_zero(r, r.n, bound, in.range.relative(), 0, [&] {
        return Vec3<Exact>(
            Vec3<Exact>(abc[o[1]] - abc[o[0]]).cross(Vec3<Exact>(abc[o[3]] - abc[o[2]])));
      });
      if (r.zero) cross_normal_with_steps(abc, *in.cross, "A", nullptr);
      return r;
    };
    auto report = [p, kappa](const In& in, const NormalPair<T>& n) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      report_normal(out, n);
      warn_condition(out, p, kappa, "Ill-conditioned normal", "the normal's direction");
      return out.take();
    };
    In in{{}, std::nullopt, {}, points, order};
    in.points = conv<T>(points, &in.range);
    if (order)
      in.order = std::array<int, 4>{order->first[0] - 'A', order->first[1] - 'A',
                                    order->second[0] - 'A', order->second[1] - 'A'};
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> plane_numeric(const Polygon3<Exact>& points,
                                             const Vec3<Exact>& point, const Vec3<Exact>& normal,
                                             Precision p) {
  const double kappa = points.empty() ? 1.0 : normal_condition(doubles(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      Vec3<T> point, normal;
      InputRange range;
      Polygon3<Exact> exact_points;  // for the exact zero test and the refusal
    };
    struct Out {
      NormalPair<T> n;
      T d{}, distance{};
    };
    auto core = [](const In& in) {
      Out o;
      if (in.points.empty()) {
        o.n.n = in.normal;
        o.n.unit = in.normal / stable_norm(in.normal);
        o.d = in.normal.dot(in.point);
        o.distance = scalar_abs(T(o.n.unit.dot(in.point)));
        return o;
      }
      o.n = polygon_normal(in.points, in.exact_points, in.range.relative());
      // A degenerate polygon is refused, as the exact solve refuses it (the same words).
      if (o.n.zero) polygon_normal_with_steps(in.exact_points, "points", nullptr);
      o.d = o.n.n.dot(in.points[0]);
      // dist = |n̂·p₀|, the same as |d|/‖n‖ without squaring ‖n‖.
      if (!o.n.zero) o.distance = scalar_abs(T(o.n.unit.dot(in.points[0])));
      return o;
    };
    auto report = [p, kappa](const In& in, const Out& o) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      report_normal(out, o.n);
      out.vector("plane", std::vector<T>{o.n.n(0), o.n.n(1), o.n.n(2), o.d});
      if (o.n.zero)
        out.null("distance");
      else
        out.scalar("distance", o.distance);
      warn_condition(out, p, kappa, "Ill-conditioned plane", "the plane's normal");
      out.note("plane = (n, n·p₀), not rescaled; distance = |n̂·p₀|");
      return out.take();
    };
    In in;
    in.exact_points = points;
    in.points = conv<T>(points, &in.range);
    in.point = conv<T>(point, &in.range);
    in.normal = conv<T>(normal, &in.range);
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> depth_at_pixel_numeric(const std::array<Vec3<Exact>, 3>& triangle,
                                                      const Vec2<Exact>& pixel,
                                                      const CrossOrder& order, Precision p) {
  const DepthCondition cond = depth_condition(to_double(triangle[0]), to_double(triangle[1]),
                                              to_double(triangle[2]), to_double(pixel));
  // Fall back to the barycentric form when the plane method would keep fewer than half of the
  // backend's digits (the exact backend never needs to).
  const bool fallback =
      p != Precision::Exact && trusted_digits(cond.kappa_z, p) < decimal_digits(p) / 2;
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      std::array<Vec3<T>, 3> t;
      Vec2<T> pixel;
      std::array<int, 4> order;
      bool barycentric;
      std::array<Vec3<Exact>, 3> exact_t;  // for the exact fallback of `inside` and of c = 0
      Vec2<Exact> exact_pixel;
      InputRange range;
      CrossOrder cross;
    };
    struct Out {
      PlaneDepth<T> depth;
      bool inside = false;
      bool inside_exact = false;  // the exact fallback decided some edge sign
    };
    auto core = [](const In& in) {
      Out o;
      // Edge-on (c = 0) is a discrete answer too: c = ±E(A, B, C) over x and y, decided like the
      // edge signs; such a triangle is refused, as the exact solve refuses it (the same words).
      const SignDecision c = edge_sign(
          in.t[0], in.t[1], Vec2<T>(in.t[2].x(), in.t[2].y()), in.exact_t[0], in.exact_t[1],
          Vec2<Exact>(in.exact_t[2].x(), in.exact_t[2].y()), in.range.relative());
      if (c.sign == 0) {
        cross_normal_with_steps(in.exact_t, in.cross, "triangle",
                                nullptr);  // refuses a collinear one
        refuse_edge_on_triangle("triangle");
      }
      const Vec3<T> first = in.t[in.order[1]] - in.t[in.order[0]];
      const Vec3<T> second = in.t[in.order[3]] - in.t[in.order[2]];
      o.depth = plane_depth(in.t, first, second, in.pixel, in.barycentric);
      // Inside the closed triangle: the three edge signs agree (0 = on an edge), each decided
      // by the filtered predicate.
      int s[3];
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const SignDecision d = edge_sign(in.t[k], in.t[j], in.pixel, in.exact_t[k], in.exact_t[j],
                                         in.exact_pixel, in.range.relative());
        s[k] = d.sign;
        o.inside_exact = o.inside_exact || d.exact;
      }
      o.inside = inside_closed_triangle(s[0], s[1], s[2]);
      return o;
    };
    auto report = [p, cond](const In& in, const Out& o) {
      const PlaneDepth<T>& r = o.depth;
      NumericOut<T> out(p);
      out.inputs(in.range);
      out.vector("normal", r.normal);
      out.vector("unit_normal", r.unit_normal);
      out.vector("plane",
                 std::vector<T>{r.unit_normal(0), r.unit_normal(1), r.unit_normal(2), r.d});
      out.scalar("z", r.z);
      out.boolean("inside", o.inside);
      out.note(r.barycentric ? "z by barycentric interpolation (stable fallback)"
                             : "z = (d − a·xₛ − b·yₛ)/c (the plane method)");
      if (o.inside_exact) out.exact_decision("inside");
      if (r.barycentric)
        out.warn(
            "Nearly edge-on triangle: barycentric fallback",
            fmt::format("c ≈ 0 (κ_c ≈ {:.1e}); the plane method would keep {:.1f} digits of z, "
                        "so z = Σ λᵢ zᵢ with λᵢ from the edge functions at the pixel is used: for "
                        "a pixel inside the triangle it stays within the vertices' depths.",
                        cond.kappa_c, trusted_digits(cond.kappa_z, p)));
      else
        warn_condition(out, p, cond.kappa_z, "Nearly edge-on triangle", "z at this pixel");
      return out.take();
    };
    const std::array<int, 4> o{order.first[0] - 'A', order.first[1] - 'A', order.second[0] - 'A',
                               order.second[1] - 'A'};
    In in{{}, {}, o, fallback, triangle, pixel, {}, order};
    for (int k = 0; k < 3; ++k) in.t[k] = conv<T>(triangle[k], &in.range);
    in.pixel = conv<T>(pixel, &in.range);
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> backface_numeric(const Polygon3<Exact>& points,
                                                const Vec3<Exact>& eye, Precision p) {
  const double kappa = facing_condition(doubles(points), to_double(eye), p);
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      Vec3<T> eye;
      T fast_bound{};  // the filter's bound, computed once with the inputs (beside them: one cache
                       // line)
      Polygon3<Exact> exact_points;  // for the exact fallback of the facing
      Vec3<Exact> exact_eye;
      InputRange range;
    };
    auto core = [](const In& in) {
      if constexpr (kIsExact<T>)
        return facing(in.points, in.eye, in.exact_points, in.exact_eye, true, T(0));
      else {
        const Facing<T> f = facing(in.points, in.eye, in.exact_points, in.exact_eye,
                                   in.range.relative(), in.fast_bound);
        // D_f exactly 0 may mean a degenerate polygon, which is refused as the exact solve
        // refuses it (the same words); checked only after an exact decision.
        if (f.used_exact && f.sign == 0)
          polygon_normal_with_steps(in.exact_points, "points", nullptr);
        return f;
      }
    };
    auto report = [p, kappa](const In& in, const Facing<T>& f) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      out.vector("normal", f.normal);
      out.vector("view", f.view);
      out.scalar("df", f.df);
      out.word("facing", facing_word(f.sign));
      warn_condition(out, p, kappa, "Eye nearly in the polygon's plane", "D_f");
      out.note(
          "facing: the sign of D_f, proven by its rounding-error bound or else computed exactly");
      if (f.used_exact) out.exact_decision("facing");
      return out.take();
    };
    In in{{}, {}, {}, points, eye, {}};
    in.points = conv<T>(points, &in.range);
    in.eye = conv<T>(eye, &in.range);
    if constexpr (!kIsExact<T>) in.fast_bound = facing_error_bound_fast(in.points, in.eye);
    return prepare(std::move(in), core, report);
  });
}

// The inputs of project_point in scalar S (T, Ranged<T> for the decisions, Exact for their
// fallback), and clip = P·V·M·p from them: one formula for all three.
template <typename S>
struct ProjectionInputs {
  Vec3<S> point;
  std::optional<MatX<S>> model;
  std::optional<std::array<Vec3<S>, 3>> camera;
  ProjectionSpec::Type type = ProjectionSpec::Type::Perspective;
  Volume<S> volume;
  std::optional<S> fovy, aspect;
  Api api = Api::OpenGL;
  bool left_handed = false;  // ProjectionSpec::left_handed: LookAtLH's basis, third column negated
};

// The exact inputs converted one by one by f (to T, to Ranged<T>).
template <typename F>
auto map_inputs(const ProjectionInputs<Exact>& in, F f) {
  using R = decltype(f(std::declval<Exact>()));
  auto vec = [&](const Vec3<Exact>& v) { return Vec3<R>(f(v(0)), f(v(1)), f(v(2))); };
  ProjectionInputs<R> out;
  out.point = vec(in.point);
  if (in.model) out.model = in.model->unaryExpr([&](const Exact& e) { return f(e); }).eval();
  if (in.camera)
    out.camera =
        std::array<Vec3<R>, 3>{vec((*in.camera)[0]), vec((*in.camera)[1]), vec((*in.camera)[2])};
  out.type = in.type;
  const Volume<Exact>& v = in.volume;
  out.volume = {f(v.left), f(v.right), f(v.bottom), f(v.top), f(v.near), f(v.far)};
  if (in.fovy) out.fovy = f(*in.fovy);
  if (in.aspect) out.aspect = f(*in.aspect);
  out.api = in.api;
  out.left_handed = in.left_handed;
  return out;
}

template <typename S>
MatX<S> clip_from_world(const ProjectionInputs<S>& in) {
  MatX<S> m;
  if (in.type == ProjectionSpec::Type::Ortho) {
    m = ortho_matrix(in.volume, in.api);
  } else {
    const Volume<S> v =
        in.fovy ? perspective_volume(*in.fovy, *in.aspect, in.volume.near, in.volume.far)
                : in.volume;
    m = frustum_matrix(v, in.api);
  }
  if (in.left_handed)
    for (int i = 0; i < 4; ++i) m(i, 2) = -m(i, 2);
  const Api basis = in.left_handed ? Api::DirectX : in.api;
  if (in.camera) m = MatX<S>(m * look_at((*in.camera)[0], (*in.camera)[1], (*in.camera)[2], basis));
  if (in.model) m = MatX<S>(m * *in.model);
  return m;
}

template <typename S>
Vec4<S> clip_of(const MatX<S>& m, const Vec3<S>& point) {
  return Vec4<S>(m * Vec4<S>(point(0), point(1), point(2), S(1)));
}

// The seven signs that decide where a clip point lies: w, then wᵢ ± xᵢ for the six planes
// −w ≤ x, y ≤ w, −w ≤ z ≤ w (DirectX: 0 ≤ z ≤ w, so z itself).
template <typename S>
std::array<S, 7> volume_tests(const Vec4<S>& c, Api api) {
  const S& w = c(3);
  return {w,           S(c(0) + w), S(w - c(0)),
          S(c(1) + w), S(w - c(1)), api == Api::DirectX ? c(2) : S(c(2) + w),
          S(w - c(2))};
}

std::unique_ptr<NumericSolver> project_point_numeric(
    const Vec3<Exact>& point, const std::optional<MatX<Exact>>& model,
    const std::optional<std::array<Vec3<Exact>, 3>>& camera, const ProjectionSpec& projection,
    const Exact& width, const Exact& height, Api api, Precision p) {
  ProjectionInputs<Exact> exact;
  exact.point = point;
  exact.model = model;
  exact.camera = camera;
  exact.type = projection.type;
  exact.volume = projection.volume;
  if (projection.fovy && projection.aspect &&
      !projection.fovx) {  // fovx: the volume already holds it
    exact.fovy = *projection.fovy;
    exact.aspect = *projection.aspect;
  }
  exact.api = api;
  exact.left_handed = projection.left_handed;
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      ProjectionInputs<T> given;
      // The same inputs with their rounding error (unused by the exact backend).
      ProjectionInputs<std::conditional_t<kIsExact<T>, T, Ranged<T>>> ranged;
      ProjectionInputs<Exact> exact;  // for the exact fallback of the decisions
      T width, height;
      InputRange range;
    };
    struct Out {
      Vec4<T> clip;
      Vec3<T> ndc, window;
      Vec4<T> row3, homogeneous;  // M's last row and the point, for the condition of w
      int w_sign = 0;
      bool inside = false;
      bool exact_decided = false;
    };
    auto core = [](const In& in) {
      Out o;
      const MatX<T> m = clip_from_world(in.given);
      o.homogeneous = Vec4<T>(in.given.point(0), in.given.point(1), in.given.point(2), T(1));
      o.clip = clip_of(m, in.given.point);
      o.row3 = m.row(3).transpose();
      // The decisions: each sign proven on the ranged clip point, or computed exactly.
      std::array<int, 7> sign{};
      if constexpr (kIsExact<T>) {
        const std::array<T, 7> t = volume_tests(o.clip, in.given.api);
        for (int k = 0; k < 7; ++k) sign[k] = exact_sign(t[k]);
      } else {
        const std::array<Ranged<T>, 7> t =
            volume_tests(clip_of(clip_from_world(in.ranged), in.ranged.point), in.given.api);
        std::optional<std::array<Exact, 7>> exact;
        for (int k = 0; k < 7; ++k) {
          const SignDecision d = decide_sign(t[k], [&] {
            if (!exact)
              exact =
                  volume_tests(clip_of(clip_from_world(in.exact), in.exact.point), in.given.api);
            return exact_sign((*exact)[k]);
          });
          sign[k] = d.sign;
          o.exact_decided = o.exact_decided || d.exact;
        }
      }
      o.w_sign = sign[0];
      o.inside = o.w_sign > 0;
      for (int k = 1; k < 7; ++k) o.inside = o.inside && sign[k] >= 0;
      if (o.w_sign > 0) {
        o.ndc = o.clip.template head<3>() / o.clip(3);
        o.window = viewport(o.ndc, in.width, in.height, in.given.api);
      }
      return o;
    };
    auto report = [p](const In& in, const Out& o) {
      NumericOut<T> out(p);
      out.inputs(in.range);
      out.vector("clip", o.clip);
      if (o.w_sign > 0) {
        out.vector("ndc", o.ndc);
        out.vector("window", o.window);
      } else {
        out.null("ndc");
        out.null("window");
        out.warn(o.w_sign == 0 ? "The point is in the eye's plane" : "The point is behind the eye",
                 "w_c ≤ 0: no NDC or window position.");
      }
      out.boolean("inside", o.inside);
      if (o.exact_decided) out.exact_decision("w_c > 0 and inside");
      Eigen::Vector4d row, h;
      for (int i = 0; i < 4; ++i) {
        row(i) = static_cast<double>(to_long_double(o.row3(i)));
        h(i) = static_cast<double>(to_long_double(o.homogeneous(i)));
      }
      warn_condition(out, p, w_condition(row, h), "Point close to the eye's plane",
                     "w_c (and the NDC divided by it)");
      return out.take();
    };
    In in{{}, {}, exact, from_exact<T>(width), from_exact<T>(height), {}};
    in.given = map_inputs(exact, [&](const Exact& e) { return conv<T>(e, &in.range); });
    if constexpr (!kIsExact<T>)
      in.ranged =
          map_inputs(exact, [](const Exact& e) { return Ranged<T>::input(from_exact<T>(e)); });
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> transform_numeric(int dim, const std::vector<MatX<Exact>>& steps,
                                                 const std::vector<MatX<Exact>>& inverses,
                                                 bool invertible,
                                                 const std::vector<std::vector<Exact>>& points,
                                                 Api api, Precision p) {
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      int size;
      bool invertible;
      std::vector<MatX<T>> steps, inverses;
      std::vector<std::vector<T>> points;
    };
    struct Out {
      MatX<T> m, inverse;
      std::vector<std::vector<T>> moved;
    };
    auto core = [](const In& in) {
      Out o;
      o.m = MatX<T>::Identity(in.size, in.size);
      for (const MatX<T>& s : in.steps) o.m = MatX<T>(s * o.m);
      for (const std::vector<T>& q : in.points) o.moved.push_back(transform_point(o.m, q));
      if (in.invertible) {
        if constexpr (kIsExact<T>) {
          // M⁻¹ = A₁⁻¹·…·Aₙ⁻¹, each step undone on its own.
          o.inverse = MatX<T>::Identity(in.size, in.size);
          for (const MatX<T>& s : in.inverses) o.inverse = MatX<T>(o.inverse * s);
        } else {
          o.inverse = o.m.partialPivLu().inverse();
        }
      }
      return o;
    };
    auto report = [p, api](const In&, const Out& o) {
      NumericOut<T> out(p);
      out.matrix("matrix", paper_form(o.m, api));
      if (o.moved.empty())
        out.null("points");
      else
        out.rows("points", o.moved);
      if (o.inverse.size() == 0) {
        out.null("inverse");
      } else {
        out.matrix("inverse", paper_form(o.inverse, api));
        if constexpr (!kIsExact<T>) {
          const double kappa = static_cast<double>(o.m.cwiseAbs().rowwise().sum().maxCoeff() *
                                                   o.inverse.cwiseAbs().rowwise().sum().maxCoeff());
          warn_condition(out, p, kappa, "Ill-conditioned matrix",
                         "the inverse (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)");
        }
        out.note(kIsExact<T> ? "inverse = A₁⁻¹·…·Aₙ⁻¹" : "inverse by LU with partial pivoting");
      }
      return out.take();
    };
    In in{dim + 1, invertible, {}, {}, {}};
    for (const MatX<Exact>& s : steps) in.steps.push_back(conv<T>(s));
    for (const MatX<Exact>& s : inverses) in.inverses.push_back(conv<T>(s));
    for (const std::vector<Exact>& q : points) {
      std::vector<T> v;
      for (const Exact& x : q) v.push_back(from_exact<T>(x));
      in.points.push_back(v);
    }
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> viewport_numeric(const Vec3<Exact>& ndc, const Exact& width,
                                                const Exact& height, Api api, Precision p) {
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Vec3<T> ndc;
      T width, height;
      Api api;
    };
    auto core = [](const In& in) { return viewport(in.ndc, in.width, in.height, in.api); };
    auto report = [p](const In&, const Vec3<T>& w) {
      NumericOut<T> out(p);
      out.vector("window", w);
      return out.take();
    };
    return prepare(In{conv<T>(ndc), from_exact<T>(width), from_exact<T>(height), api}, core,
                   report);
  });
}

}  // namespace frustum
