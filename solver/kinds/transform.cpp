// Composite transforms in 2D and 3D homogeneous coordinates (seeds 002, 004): steps applied
// in the listed order, so the composite of A₁, A₂, A₃ is M = A₃·A₂·A₁ and P′ = M·P.
#include <fmt/format.h>

#include <algorithm>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/shared/transform_steps.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kArray{"array", "配列", "массив"};

constexpr Phrase kTransformAPoint{"Transform a point", "点を変換", "Преобразование точки"};

constexpr Phrase kIllConditionedMatrix{"Ill-conditioned matrix", "条件の悪い行列",
                                       "Плохо обусловленная матрица"};
constexpr Phrase kTheInverseCondition{"the inverse (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)",
                                      "逆行列 (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)",
                                      "обратная матрица (κ∞(M) = ‖M‖∞‖M⁻¹‖∞)"};
constexpr Phrase kInverseStepByStep{"inverse = A₁⁻¹·…·Aₙ⁻¹.", "逆行列 = A₁⁻¹·…·Aₙ⁻¹.",
                                    "обратная матрица = A₁⁻¹·…·Aₙ⁻¹."};
constexpr Phrase kInverseByLu{
    "inverse by LU with partial pivoting.", "逆行列は部分ピボット選択付き LU 分解で求めた.",
    "обратная матрица — LU-разложением с частичным выбором ведущего элемента."};
constexpr Phrase kArrayByColumn{"The matrix as an array, column by column",
                                "行列を配列に: 列ごとに", "Матрица как массив: по столбцам"};
constexpr Phrase kArrayByRow{"The matrix as an array, row by row", "行列を配列に: 行ごとに",
                             "Матрица как массив: по строкам"};
constexpr Phrase kColumnsInPieces3d{
    "Each column of M lies in one piece: m0–m2 is the image of the x axis, m4–m6 that of the y "
    "axis, m8–m10 that of the z axis, and m12–m14 the translation (where the origin goes).",
    "M の各列が連続して並ぶ: m0–m2 は x 軸の像, m4–m6 は y 軸の像, m8–m10 は z 軸の像, m12–m14 "
    "は平行移動 (原点の移る先) である.",
    "Каждый столбец M лежит подряд: m0–m2 — образ оси X, m4–m6 — оси Y, m8–m10 — оси Z, m12–m14 — "
    "перенос (куда переходит начало координат)."};
constexpr Phrase kColumnsInPieces2d{
    "Each column of M lies in one piece: m0–m1 is the image of the x axis, m3–m4 that of the y "
    "axis, and m6–m7 the translation (where the origin goes).",
    "M の各列が連続して並ぶ: m0–m1 は x 軸の像, m3–m4 は y 軸の像, m6–m7 は平行移動 "
    "(原点の移る先) である.",
    "Каждый столбец M лежит подряд: m0–m1 — образ оси X, m3–m4 — оси Y, m6–m7 — перенос (куда "
    "переходит начало координат)."};
constexpr Phrase kComposite{"Composite (first step applied first)",
                            "合成変換 (最初のステップを最初に適用)",
                            "Композиция (первый шаг применяется первым)"};
constexpr Phrase kNoInverse{"No inverse", "逆行列なし", "Обратной матрицы нет"};
constexpr Phrase kFlattensSpace{
    "det M = 0: the transform flattens space and cannot be undone.",
    "det M = 0: この変換は空間を押しつぶすので, 元に戻せない.",
    "det M = 0: преобразование сплющивает пространство, и его нельзя обратить."};
constexpr Phrase kInverse{"Inverse", "逆行列", "Обратная матрица"};
constexpr Phrase kRotationUsesDegreesAsRadians{
    "Your rotation uses the angle's number of degrees as radians (cos {0} instead of cos {1}).",
    "回転で角度の度数をラジアンとして使っています (cos {1} ではなく cos {0}).",
    "В повороте число градусов взято как радианы (cos {0} вместо cos {1})."};
constexpr Phrase kEachStepUndone{
    "Each step is undone on its own (a translation by its negative, a scaling by its reciprocal, "
    "a rotation by its transpose), in reverse order.",
    "各ステップを個別に元に戻す (平行移動は符号を反転, 拡大縮小は逆数, 回転は転置) — 逆の順序で.",
    "Каждый шаг обращается отдельно (перенос — противоположным, масштабирование — обратными "
    "величинами, поворот — транспонированием), в обратном порядке."};

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
      for (const MatX<T>& s : in.steps) o.m = then_apply(o.m, s);
      for (const std::vector<T>& q : in.points) o.moved.push_back(transform_point(o.m, q));
      if (in.invertible) {
        if constexpr (kIsExact<T>) {
          // M⁻¹ = A₁⁻¹·…·Aₙ⁻¹, each step undone on its own.
          o.inverse = MatX<T>::Identity(in.size, in.size);
          for (const MatX<T>& s : in.inverses) o.inverse = then_undo(o.inverse, s);
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
          warn_condition(out, p, kappa, say(kIllConditionedMatrix), say(kTheInverseCondition));
        }
        out.note(say(kIsExact<T> ? kInverseStepByStep : kInverseByLu));
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

// The matrix as one array m0, m1, …, m(n²−1): column by column (OpenGL's layout: glLoadMatrixf
// and glUniformMatrix4fv without transposing read it so) or row by row; the step shows which
// entry of the matrix each m_k is, as on paper.
Value array_with_steps(const MatX<Exact>& m, bool column_major, Derivation* steps) {
  const auto n = static_cast<std::size_t>(m.rows());
  std::vector<Exact> array;
  std::vector<MathText> names(n * n);
  for (std::size_t k = 0; k < n * n; ++k) {
    const std::size_t i = column_major ? k % n : k / n, j = column_major ? k / n : k % n;
    array.push_back(m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)));
    names[i * n + j] = tex(fmt::format("m_{{{}}}", k));
  }
  if (steps) {
    Step& step =
        steps
            ->add(say(column_major ? kArrayByColumn : kArrayByRow),
                  math("M = ") + matrix_of(names, n), {},
                  tex(fmt::format("(m_{{0}}, \\ldots, m_{{{}}}) = ", n * n - 1)) + vec(array))
            .yields("array");
    if (column_major) step.note = say(n == 4 ? kColumnsInPieces3d : kColumnsInPieces2d);
  }
  return Value::vector(array);
}

struct Transform {
  static constexpr const char* kName = "transform";
  static constexpr Phrase kSummary{"the composite of translations, scalings, rotations and shears",
                                   "平行移動, 拡大縮小, 回転, せん断の合成",
                                   "композиция переносов, масштабирований, поворотов и сдвигов"};
  struct Given {
    int dim = 3;
    std::vector<TransformStep> steps;
    std::vector<std::vector<Exact>> points;
    Api api = Api::OpenGL;  // DirectX prints every matrix in row-vector form (the transpose)
    // `array`: the matrix as the 16 (2-D: 9) numbers of an array, m0, m1, … taken column by
    // column (OpenGL's layout, glLoadMatrixf) or row by row.
    std::optional<bool> column_major;
  };
  static std::vector<std::string> given_fields() { return {"dim", "steps", "points", "array"}; }
  // Error carried forward: the points moved by the student's own matrix, and its inverse.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const auto n = static_cast<std::size_t>(g.dim + 1);
    if (auto p = carried_points(student, g.points, n, g.api)) out.set("points", std::move(*p));
    if (auto inverse = carried_inverse(student, "matrix", n))
      out.set("inverse", std::move(*inverse));
    // The array of the student's own matrix, in the asked order.
    if (const auto m = g.column_major ? carried(student, "matrix", n * n) : std::nullopt) {
      std::vector<Exact> array;
      for (std::size_t k = 0; k < n * n; ++k)
        array.push_back(*g.column_major ? (*m)[(k % n) * n + k / n] : (*m)[k]);
      out.set("array", Value::vector(array));
    }
    return out;
  }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "matrix", .kind = AnswerKind::Transform, .symbols = {"M"}},
            {.name = "points",
             .kind = AnswerKind::Matrix,
             .depends_on = {"matrix"},
             .needs_given = "points",
             .point_rows = true,
             .label = say(words::kPoints)},
            {.name = "inverse",
             .kind = AnswerKind::Transform,
             .depends_on = {"matrix"},
             .symbols = {"M⁻¹"}},
            {.name = "array",
             .kind = AnswerKind::Vector,
             .depends_on = {"matrix"},
             .needs_given = "array",
             .label = say(kArray)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.api = c.api;
    g.dim = r.has("dim") ? static_cast<int>(to_double(r.number("dim"))) : 3;
    if (g.dim != 2 && g.dim != 3) r.fail("dim", "must be 2 or 3");
    g.steps = read_transform_steps(r, "steps", g.dim, c);
    if (r.has("array"))
      g.column_major = r.word("array", {"column_major", "row_major"}) == "column_major";
    if (r.has("points")) {
      const std::size_t count = r.list_size("points");
      for (std::size_t i = 0; i < count; ++i) {
        // Each point is a list of dim numbers; reuse the reader on a one-field view.
        g.points.push_back(r.numbers_at("points", i, static_cast<std::size_t>(g.dim)));
      }
    }
    return g;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    std::vector<Misconception> out;
    const auto product = [&](const std::vector<MatX<Exact>>& steps, bool reversed) {
      MatX<Exact> m = MatX<Exact>::Identity(g.dim + 1, g.dim + 1);
      // The wrong order multiplies on the other side.
      for (const MatX<Exact>& s : steps)
        m = canonical(reversed ? then_apply(s, m) : then_apply(m, s));
      return m;
    };
    // The answers a mistake leads to: its matrix, the points moved by it and its inverse (the
    // steps' inverses undone in the opposite order; none when a step is singular).
    const auto composite = [&](const std::vector<MatX<Exact>>& steps,
                               std::vector<MatX<Exact>> inverses, bool reversed) {
      const MatX<Exact> m = product(steps, reversed);
      Answers a;
      // In the problem's own convention: DirectX students write the row-vector form.
      a.set("matrix", matrix_value(paper_form(m, g.api)));
      if (!g.points.empty())
        a.set("points", transform_points_with_steps(m, g.points, {}, "P", nullptr, g.api));
      const bool singular = std::any_of(inverses.begin(), inverses.end(),
                                        [](const MatX<Exact>& i) { return i.size() == 0; });
      if (!singular) {
        std::reverse(inverses.begin(), inverses.end());
        a.set("inverse", matrix_value(paper_form(product(inverses, reversed), g.api)));
      }
      return a;
    };
    std::vector<MatX<Exact>> matrices, inverses;
    for (const TransformStep& s : g.steps) {
      matrices.push_back(s.matrix);
      inverses.push_back(s.inverse);
    }
    if (g.steps.size() >= 2)
      out.push_back({say(kCompositionInTheWrongOrder), wrong_order_feedback(g.api), say(kComposite),
                     composite(matrices, inverses, true)});
    // Degrees taken as radians: every rotation by the angle's number of degrees, in radians
    // (undone by the rotation by minus that many radians).
    bool rotates = false;
    std::string degrees;  // the first rotation's angle in degrees, as the feedback quotes it
    std::vector<MatX<Exact>> as_radians, as_radians_undone;
    for (const TransformStep& s : g.steps) {
      rotates = rotates || s.angle.has_value();
      const bool turned = s.angle && s.rotation;
      const Exact radians = turned ? canonical(*s.angle * 180 / GiNaC::Pi) : Exact(0);
      if (s.angle && degrees.empty())
        degrees = format_exact(canonical(*s.angle * 180 / GiNaC::Pi), MathStyle::Unicode);
      as_radians.push_back(turned ? s.rotation(radians) : s.matrix);
      as_radians_undone.push_back(turned ? s.rotation(canonical(-radians)) : s.inverse);
    }
    if (rotates)
      out.push_back({say(kDegreesTakenAsRadians),
                     say(kRotationUsesDegreesAsRadians, degrees, degrees + "°"), say(kComposite),
                     composite(as_radians, as_radians_undone, false)});
    return out;
  }

  // The numeric path: the steps' matrices rounded to the backend, composed and inverted there.
  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    std::vector<MatX<Exact>> matrices, inverses;
    bool singular = false;
    for (const TransformStep& s : g.steps) {
      matrices.push_back(s.matrix);
      inverses.push_back(s.inverse);
      singular = singular || s.inverse.size() == 0;
    }
    return transform_numeric(g.dim, matrices, inverses, !singular, g.points, g.api, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const int size = g.dim + 1;
    const bool rows = g.api == Api::DirectX;
    const MatX<Exact> m = compose_with_steps(g.steps, g.dim, g.api, "M", kComposite, steps);
    Answers out;
    out.set("matrix", matrix_value(paper_form(m, g.api)));
    if (steps) steps->yields("matrix");
    if (g.column_major)
      out.set("array", array_with_steps(paper_form(m, g.api), *g.column_major, steps));
    out.set("points",
            transform_points_with_steps(m, g.points, say(kTransformAPoint), "P", steps, g.api));
    // det M is the product of the steps' determinants (rotations and translations have 1).
    Exact det = 1;
    for (const TransformStep& s : g.steps) det *= s.det;
    det = canonical(det);
    if (det.is_zero()) {
      out.set("inverse", Value::null());
      if (steps) steps->warn(say(kNoInverse), say(kFlattensSpace));
    } else {
      // M⁻¹ = A₁⁻¹·A₂⁻¹·…·Aₙ⁻¹.
      MatX<Exact> inv = MatX<Exact>::Identity(size, size);
      for (const TransformStep& s : g.steps) inv = canonical(then_undo(inv, s.inverse));
      out.set("inverse", matrix_value(paper_form(inv, g.api)));
      if (steps) {
        std::string order;  // A_1^{-1}\,A_2^{-1}…, read as A₁⁻¹·A₂⁻¹·…
        for (std::size_t k = 1; k <= g.steps.size(); ++k) {
          const std::size_t i = rows ? g.steps.size() + 1 - k : k;
          order += fmt::format("{}A_{{{}}}^{{-1}}", k == 1 ? "" : "\\,", i);
        }
        steps
            ->add(say(kInverse), tex("M^{-1} = " + order + "\\;(M\\,M^{-1} = I)"), {},
                  tex("M^{-1} = ") + matrix_text(paper_form(inv, g.api)))
            .yields("inverse")
            .note = say(kEachStepUndone);
      }
    }
    return out;
  }
  // Default generator: 2 or 3 steps in 2D or 3D (translate, scale, rotate, now and then a
  // shear) and one or two integer points; nice: right angles and integer factors only; hard:
  // a 3D rotation about an oblique axis and a fractional scale.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const int dim = rng.chance(1, 2) ? 2 : 3;
    const std::vector<std::int64_t> angles =
        o.nice ? std::vector<std::int64_t>{90, 180, -90}
               : std::vector<std::int64_t>{30, 45, 60, 90, 120, 135, 150, -30, -45, -60};
    YAML::Node steps(YAML::NodeType::Sequence);
    const auto count = rng.integer(2, 3);
    for (std::int64_t i = 0; i < count; ++i) {
      YAML::Node s;
      const auto which = rng.below(o.hard ? 5 : 4);
      std::vector<std::int64_t> v(static_cast<std::size_t>(dim));
      if (which == 0) {
        do {
          for (auto& x : v) x = rng.integer(-5, 5);
        } while (std::all_of(v.begin(), v.end(), [](std::int64_t x) { return x == 0; }));
        s["translate"] = gen_list(v);
      } else if (which == 1) {
        if (o.hard) {
          s["scale"] = gen_fraction(1, rng.integer(2, 3));
        } else {
          for (auto& x : v) x = rng.pick(std::vector<std::int64_t>{-1, 2, 2, 3});
          s["scale"] = gen_list(v);
        }
      } else if (which == 2 || which == 4) {
        const std::int64_t a = rng.pick(angles);
        if (dim == 2) {
          s["rotate"] = gen_angle(a, o.conventions);
        } else if (which == 4) {
          YAML::Node r;
          r["axis"] = gen_list(
              rng.pick(std::vector<std::vector<std::int64_t>>{{1, 1, 1}, {1, 2, 2}, {0, 1, 1}}));
          r["angle"] = gen_angle(a, o.conventions);
          s["rotate"] = r;
        } else {
          s[rng.pick(std::vector<std::string>{"rotate_x", "rotate_y", "rotate_z"})] =
              gen_angle(a, o.conventions);
        }
      } else if (dim == 2) {
        s["shear"] = gen_list({rng.nonzero(-2, 2), 0});
      } else {
        YAML::Node h;
        h[rng.pick(std::vector<std::string>{"xy", "xz", "yz"})] = gen_number(rng.nonzero(-2, 2));
        s["shear"] = h;
      }
      steps.push_back(s);
    }
    YAML::Node points(YAML::NodeType::Sequence);
    const auto n = rng.integer(1, 2);
    for (std::int64_t i = 0; i < n; ++i) {
      std::vector<std::int64_t> p(static_cast<std::size_t>(dim));
      for (auto& x : p) x = rng.integer(-3, 3);
      points.push_back(gen_list(p));
    }
    points.SetStyle(YAML::EmitterStyle::Flow);
    YAML::Node g;
    g["dim"] = gen_number(dim);
    g["steps"] = steps;
    g["points"] = points;
    return g;
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  using namespace accuracy;
  const Point3 axis = point(rng, -3, 3);
  if (axis.d().norm() < 0.5) return std::nullopt;
  return fmt::format(
      "{{dim: 3, steps: [{{translate: {}}}, {{rotate_z: {}}}, {{scale: [{}, {}, {}]}}, "
      "{{rotate: {{axis: {}, angle: {}}}}}], points: [{}, {}]}}",
      point(rng, -9, 9).yaml(), rng.integer(5, 85), decimal(rng, 1, 3), decimal(rng, 1, 3),
      decimal(rng, 1, 3), axis.yaml(), rng.integer(5, 85), point(rng, -9, 9).yaml(),
      point(rng, -9, 9).yaml());
}

}  // namespace

KindInfo transform_kind() {
  KindInfo k = make_kind<Transform>();
  k.order = 60;
  k.doc_given =
      "`dim` (2/3), `steps` (`translate`, `scale`, `rotate_x/y/z`, `rotate` (2D angle or 3D "
      "{`axis`, `angle`}), `shear`), `points`, `array` (`column_major`: OpenGL's layout, or "
      "`row_major`)";
  k.doc_answers =
      "`matrix` (first step applied first: M = A₃A₂A₁), `points`, `inverse`, `array` (with "
      "`array: column_major` or `row_major`: the matrix's entries m0, m1, … in that order)";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
