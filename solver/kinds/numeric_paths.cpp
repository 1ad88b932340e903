#include "solver/kinds/numeric_paths.hpp"

#include "solver/geometry/facing.hpp"
#include "solver/geometry/plane_depth.hpp"
#include "solver/numeric/condition.hpp"

#include <fmt/format.h>

#include <cmath>

namespace frustum {

namespace {

template <typename T, int N>
Eigen::Matrix<T, N, 1> conv(const Eigen::Matrix<Exact, N, 1>& v) {
  Eigen::Matrix<T, N, 1> out;
  for (int i = 0; i < N; ++i) out(i) = from_exact<T>(v(i));
  return out;
}

template <typename T>
Polygon3<T> conv(const Polygon3<Exact>& p) {
  Polygon3<T> out;
  for (const Vec3<Exact>& v : p) out.push_back(conv<T>(v));
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

template <typename T>
T scaled_by(const T& v, int k) {
  if constexpr (kIsExact<T>)
    return v;
  else
    return std::ldexp(v, k);
}

// The warning a numeric path gives when its answer's condition is poor.
template <typename T>
void warn_condition(NumericOut<T>& out, Precision p, double kappa, const std::string& title,
                    const std::string& what) {
  if (!(kappa > kIllConditioned) || p == Precision::Exact) return;
  out.warn(title, fmt::format("{} is ill-conditioned ({}): {}; solve with --precision exact for "
                              "the exact value.",
                              what, std::isfinite(kappa) ? fmt::format("κ ≈ {:.1e}", kappa) : "κ = ∞",
                              digits_sentence(kappa, p)));
}

// A polygon's normal in T: e₀ × e₁ for a triangle (seed 003), Newell's Σ dᵢ × dᵢ₊₁ (dᵢ = pᵢ − p₀)
// otherwise. In floating point the offsets are first scaled by a power of two (exact) so that
// neither the products nor ‖n‖ overflow or underflow for huge, tiny or subnormal coordinates;
// the normal is scaled back (it may then overflow; the unit normal never does).
template <typename T>
struct NormalPair {
  Vec3<T> n;
  Vec3<T> unit;
  bool zero = false;
};

template <typename T>
NormalPair<T> polygon_normal(const Polygon3<T>& p) {
  NormalPair<T> out;
  const bool triangle = p.size() == 3;
  if constexpr (kIsExact<T>) {
    out.n = triangle ? edge_pair_normal(p, 0) : newell_normal(p);
    out.zero = scalar_sign(T(out.n.dot(out.n))) == 0;
    if (!out.zero) out.unit = out.n / stable_norm(out.n);
    return out;
  } else {
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
    out.zero = ns.cwiseAbs().maxCoeff() == T(0);
    if (!out.zero) out.unit = ns / stable_norm(ns);
    for (int i = 0; i < 3; ++i) out.n(i) = std::ldexp(ns(i), 2 * k);
    return out;
  }
}

template <typename T>
void report_normal(NumericOut<T>& out, const NormalPair<T>& n) {
  out.vector("normal", n.n);
  if (n.zero) {
    out.null("unit_normal");
    out.warn("Zero normal in this precision",
             "the normal computed in this backend is the zero vector (cancellation or underflow): "
             "the polygon is degenerate at this precision.");
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
    };
    struct Out {
      T dot{}, area{}, sin{}, cos{}, angle{};
      Vec3<T> cross, unit;
      bool parallel = false;
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
      const Vec3<T> cross = a.cross(b);
      const T area = stable_norm(cross), la = stable_norm(a), lb = stable_norm(b);
      o.dot = scaled_by(dot, ka + kb);
      for (int i = 0; i < 3; ++i) o.cross(i) = scaled_by(cross(i), ka + kb);
      o.area = scaled_by(area, ka + kb);
      o.sin = area / la / lb;
      o.cos = dot / la / lb;
      // θ = atan2(‖a × b‖, a·b): accurate at every angle, unlike arccos(cos θ) near 0 and π.
      o.angle = scalar_angle(area, dot);
      if (in.degrees) o.angle = o.angle * T(180) / scalar_pi(o.angle);
      o.parallel = scalar_sign(area) == 0;
      if (!o.parallel) o.unit = cross / area;
      return o;
    };
    auto report = [p](const In&, const Out& o) {
      NumericOut<T> out(p);
      out.scalar("dot", o.dot);
      out.vector("cross", o.cross);
      out.scalar("area", o.area);
      out.scalar("sin", o.sin);
      out.scalar("cos", o.cos);
      out.scalar("angle", o.angle);
      if (o.parallel)
        out.null("unit_normal");
      else
        out.vector("unit_normal", o.unit);
      out.note("angle = atan2(‖a × b‖, a·b)");
      return out.take();
    };
    return prepare(In{conv<T>(a), conv<T>(b), unit == AngleUnit::Degrees}, core, report);
  });
}

std::unique_ptr<NumericSolver> normal_numeric(const Polygon3<Exact>& points,
                                              const std::optional<CrossOrder>& order, Precision p) {
  const double kappa = normal_condition(doubles(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      std::optional<std::array<int, 4>> order;  // first = X₀→Y₀, second = X₁→Y₁ (vertex indices)
    };
    auto core = [](const In& in) {
      if (!in.order) return polygon_normal(in.points);
      const auto& o = *in.order;
      NormalPair<T> r;
      r.n = Vec3<T>(in.points[o[1]] - in.points[o[0]]).cross(Vec3<T>(in.points[o[3]] - in.points[o[2]]));
      r.zero = scalar_sign(T(r.n.dot(r.n))) == 0;
      if (!r.zero) r.unit = r.n / stable_norm(r.n);
      return r;
    };
    auto report = [p, kappa](const In&, const NormalPair<T>& n) {
      NumericOut<T> out(p);
      report_normal(out, n);
      warn_condition(out, p, kappa, "Ill-conditioned normal", "the normal's direction");
      return out.take();
    };
    In in{conv<T>(points), std::nullopt};
    if (order)
      in.order = std::array<int, 4>{order->first[0] - 'A', order->first[1] - 'A',
                                    order->second[0] - 'A', order->second[1] - 'A'};
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> plane_numeric(const Polygon3<Exact>& points, const Vec3<Exact>& point,
                                             const Vec3<Exact>& normal, Precision p) {
  const double kappa = points.empty() ? 1.0 : normal_condition(doubles(points));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      Vec3<T> point, normal;
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
      o.n = polygon_normal(in.points);
      o.d = o.n.n.dot(in.points[0]);
      // dist = |n̂·p₀|, the same as |d|/‖n‖ without squaring ‖n‖.
      if (!o.n.zero) o.distance = scalar_abs(T(o.n.unit.dot(in.points[0])));
      return o;
    };
    auto report = [p, kappa](const In&, const Out& o) {
      NumericOut<T> out(p);
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
    return prepare(In{conv<T>(points), conv<T>(point), conv<T>(normal)}, core, report);
  });
}

std::unique_ptr<NumericSolver> depth_at_pixel_numeric(const std::array<Vec3<Exact>, 3>& triangle,
                                                      const Vec2<Exact>& pixel,
                                                      const CrossOrder& order, Precision p) {
  const DepthCondition cond = depth_condition(to_double(triangle[0]), to_double(triangle[1]),
                                              to_double(triangle[2]), to_double(pixel));
  // Fall back to the barycentric form when the plane method would keep fewer than half of the
  // backend's digits (the exact backend never needs to).
  const bool fallback = p != Precision::Exact &&
                        trusted_digits(cond.kappa_z, p) < decimal_digits(p) / 2;
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      std::array<Vec3<T>, 3> t;
      Vec2<T> pixel;
      std::array<int, 4> order;
      bool barycentric;
    };
    auto core = [](const In& in) {
      const Vec3<T> first = in.t[in.order[1]] - in.t[in.order[0]];
      const Vec3<T> second = in.t[in.order[3]] - in.t[in.order[2]];
      return plane_depth(in.t, first, second, in.pixel, in.barycentric);
    };
    auto report = [p, cond](const In&, const PlaneDepth<T>& r) {
      NumericOut<T> out(p);
      out.vector("normal", r.normal);
      out.vector("unit_normal", r.unit_normal);
      out.vector("plane", std::vector<T>{r.unit_normal(0), r.unit_normal(1), r.unit_normal(2), r.d});
      out.scalar("z", r.z);
      out.boolean("inside", r.inside);
      out.note(r.barycentric ? "z by barycentric interpolation (stable fallback)"
                             : "z = (d − a·xₛ − b·yₛ)/c (the plane method)");
      if (r.barycentric)
        out.warn("Nearly edge-on triangle: barycentric fallback",
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
    return prepare(In{{conv<T>(triangle[0]), conv<T>(triangle[1]), conv<T>(triangle[2])},
                      conv<T>(pixel), o, fallback},
                   core, report);
  });
}

std::unique_ptr<NumericSolver> backface_numeric(const Polygon3<Exact>& points, const Vec3<Exact>& eye,
                                                Precision p) {
  const double kappa = facing_condition(doubles(points), to_double(eye));
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Polygon3<T> points;
      Vec3<T> eye;
    };
    auto core = [](const In& in) { return facing(in.points, in.eye); };
    auto report = [p, kappa](const In&, const Facing<T>& f) {
      NumericOut<T> out(p);
      out.vector("normal", f.normal);
      out.vector("view", f.view);
      out.scalar("df", f.df);
      out.word("facing", f.sign > 0 ? "front" : f.sign < 0 ? "back" : "edge_on");
      warn_condition(out, p, kappa, "Eye nearly in the polygon's plane", "D_f");
      if (f.used_exact)
        out.warn("Sign decided exactly",
                 fmt::format("|D_f| is below its rounding-error bound, so the computed sign ({}) "
                             "could be wrong; the facing comes from the exact sign of D_f for the "
                             "inputs as rounded to {}.",
                             f.naive_sign, to_string(p)));
      out.note("facing: adaptive predicate (error-bounded filter, exact fallback)");
      return out.take();
    };
    return prepare(In{conv<T>(points), conv<T>(eye)}, core, report);
  });
}

std::unique_ptr<NumericSolver> project_point_numeric(
    const Vec3<Exact>& point, const std::optional<std::array<Vec3<Exact>, 3>>& camera,
    const ProjectionSpec& projection, const Exact& width, const Exact& height, Api api, Precision p) {
  return with_scalar(p, [&]<typename T>() -> std::unique_ptr<NumericSolver> {
    struct In {
      Vec3<T> point;
      std::optional<std::array<Vec3<T>, 3>> camera;
      ProjectionSpec::Type type;
      Volume<T> volume;
      std::optional<T> fovy, aspect;
      T width, height;
      Api api;
    };
    struct Out {
      Vec4<T> clip;
      Vec3<T> ndc, window;
      Vec4<T> row3, homogeneous;  // M's last row and the point, for the condition of w
      int w_sign = 0;
      bool inside = false;
    };
    auto core = [](const In& in) {
      Out o;
      MatX<T> m;
      if (in.type == ProjectionSpec::Type::Ortho) {
        m = ortho_matrix(in.volume, in.api);
      } else {
        const Volume<T> v = in.fovy ? perspective_volume(*in.fovy, *in.aspect, in.volume.near, in.volume.far)
                                    : in.volume;
        m = frustum_matrix(v, in.api);
      }
      if (in.camera) m = MatX<T>(m * look_at((*in.camera)[0], (*in.camera)[1], (*in.camera)[2], in.api));
      o.homogeneous = Vec4<T>(in.point(0), in.point(1), in.point(2), T(1));
      o.clip = m * o.homogeneous;
      o.row3 = m.row(3).transpose();
      const T& w = o.clip(3);
      o.w_sign = scalar_sign(w);
      o.inside = o.w_sign > 0;
      for (int i = 0; i < 3 && o.inside; ++i) {
        const T low = (i == 2 && in.api == Api::DirectX) ? T(0) : T(-w);
        o.inside = scalar_sign(T(o.clip(i) - low)) >= 0 && scalar_sign(T(w - o.clip(i))) >= 0;
      }
      if (o.w_sign > 0) {
        o.ndc = o.clip.template head<3>() / w;
        o.window = viewport(o.ndc, in.width, in.height, in.api);
      }
      return o;
    };
    auto report = [p](const In&, const Out& o) {
      NumericOut<T> out(p);
      out.vector("clip", o.clip);
      if (o.w_sign > 0) {
        out.vector("ndc", o.ndc);
        out.vector("window", o.window);
      } else {
        out.null("ndc");
        out.null("window");
        out.warn(o.w_sign == 0 ? "The point is in the eye's plane" : "The point is behind the eye",
                 "w_c ≤ 0 as computed: no NDC or window position.");
      }
      out.boolean("inside", o.inside);
      Eigen::Vector4d row, h;
      for (int i = 0; i < 4; ++i) {
        row(i) = static_cast<double>(to_long_double(o.row3(i)));
        h(i) = static_cast<double>(to_long_double(o.homogeneous(i)));
      }
      warn_condition(out, p, w_condition(row, h), "Point close to the eye's plane", "w_c (and the NDC divided by it)");
      return out.take();
    };
    In in{conv<T>(point), std::nullopt, projection.type, {}, std::nullopt, std::nullopt,
          from_exact<T>(width), from_exact<T>(height), api};
    const Volume<Exact>& v = projection.volume;
    in.volume = {from_exact<T>(v.left), from_exact<T>(v.right), from_exact<T>(v.bottom),
                 from_exact<T>(v.top), from_exact<T>(v.near), from_exact<T>(v.far)};
    if (projection.fovy && projection.aspect) {
      in.fovy = from_exact<T>(*projection.fovy);
      in.aspect = from_exact<T>(*projection.aspect);
    }
    if (camera) in.camera = std::array<Vec3<T>, 3>{conv<T>((*camera)[0]), conv<T>((*camera)[1]), conv<T>((*camera)[2])};
    return prepare(std::move(in), core, report);
  });
}

std::unique_ptr<NumericSolver> transform_numeric(int dim, const std::vector<MatX<Exact>>& steps,
                                                 const std::vector<MatX<Exact>>& inverses,
                                                 bool invertible,
                                                 const std::vector<std::vector<Exact>>& points,
                                                 Precision p) {
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
    auto report = [p](const In&, const Out& o) {
      NumericOut<T> out(p);
      out.matrix("matrix", o.m);
      if (o.moved.empty())
        out.null("points");
      else
        out.rows("points", o.moved);
      if (o.inverse.size() == 0) {
        out.null("inverse");
      } else {
        out.matrix("inverse", o.inverse);
        if constexpr (!kIsExact<T>) {
          const double kappa = static_cast<double>(o.m.cwiseAbs().rowwise().sum().maxCoeff() *
                                                   o.inverse.cwiseAbs().rowwise().sum().maxCoeff());
          warn_condition(out, p, kappa, "Ill-conditioned matrix", "the inverse (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)");
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
    return prepare(In{conv<T>(ndc), from_exact<T>(width), from_exact<T>(height), api}, core, report);
  });
}

}  // namespace frustum
