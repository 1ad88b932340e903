// seed 003 (review of dot and cross products): a = (2,0,1), b = (1,2,0) →
// a × b = (−2, 1, 4), S = √21, sin θ = √21/5, n = (−2, 1, 4)/√21.
#include "solver/geometry/zero_vector.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kWhetherAAndBAreParallel{"whether a and b are parallel", "a と b が平行かどうか",
                                          "параллельны ли a и b"};

constexpr Phrase kIllConditionedCrossProduct{"Ill-conditioned cross product", "条件の悪い外積",
                                             "Плохо обусловленное векторное произведение"};
constexpr Phrase kABAndWithItThe{"a × b (and with it the area, sin θ and the angle)",
                                 "a × b (と, それに従う面積, sin θ, 角度)",
                                 "a × b (а с ним площадь, sin θ и угол)"};
constexpr Phrase kIllConditionedDotProduct{"Ill-conditioned dot product", "条件の悪い内積",
                                           "Плохо обусловленное скалярное произведение"};
constexpr Phrase kABAndWithItCos{"a · b (and with it cos θ)", "a · b (と, それに従う cos θ)",
                                 "a · b (а с ним cos θ)"};

constexpr Phrase kAngleNote{"angle = atan2(‖a × b‖, a·b).", "角度 = atan2(‖a × b‖, a·b).",
                            "угол = atan2(‖a × b‖, a·b)."};
constexpr Phrase kDotProduct{"Dot product", "内積", "Скалярное произведение"};
constexpr Phrase kCrossProduct{"Cross product", "外積", "Векторное произведение"};
constexpr Phrase kAreaOfParallelogram{"Area of the parallelogram", "平行四辺形の面積",
                                      "Площадь параллелограмма"};
constexpr Phrase kSineOfAngle{"Sine of the angle", "角度の正弦", "Синус угла"};
constexpr Phrase kCosineOfAngle{"Cosine of the angle", "角度の余弦", "Косинус угла"};
constexpr Phrase kAngle{"Angle", "角度", "Угол"};
constexpr Phrase kNoPlane{"No plane", "平面なし", "Плоскости нет"};
constexpr Phrase kParallelNoPlane{
    "a and b are parallel (a × b = 0): the points 0, a, b are collinear and span no plane, so "
    "there is no unit normal.",
    "a と b は平行 (a × b = 0): 点 0, a, b は一直線上にあって平面を張らないので, 単位法線はない.",
    "a и b параллельны (a × b = 0): точки 0, a, b лежат на одной прямой и не задают плоскость, "
    "поэтому единичной нормали нет."};
constexpr Phrase kUnitNormalOfPlane{"Unit normal of the plane through 0, a, b",
                                    "0, a, b を通る平面の単位法線",
                                    "Единичная нормаль плоскости через 0, a, b"};
constexpr Phrase kAntiCommutative{
    "You computed b × a = −(a × b): the cross product is anti-commutative.",
    "b × a = −(a × b) を計算しています. 外積は反可換です.",
    "Вы вычислили b × a = −(a × b): векторное произведение антикоммутативно."};
constexpr Phrase kTriangleInsteadOfParallelogram{"triangle instead of parallelogram",
                                                 "平行四辺形ではなく三角形",
                                                 "треугольник вместо параллелограмма"};
constexpr Phrase kHalfTheArea{
    "That is half the area: ‖a × b‖ is the parallelogram's area, the triangle's is half of it.",
    "それは面積の半分です. ‖a × b‖ は平行四辺形の面積で, 三角形の面積はその半分です.",
    "Это половина площади: ‖a × b‖ — площадь параллелограмма, а треугольника — её половина."};
constexpr Phrase kRadiansInsteadOfDegrees{"radians instead of degrees", "度ではなくラジアン",
                                          "радианы вместо градусов"};
constexpr Phrase kDegreesInsteadOfRadians{"degrees instead of radians", "ラジアンの代わりに度",
                                          "градусы вместо радиан"};
constexpr Phrase kAngleInRadians{"Your angle is in radians; the problem asks for degrees.",
                                 "角度がラジアンになっています. 問題は度で求めています.",
                                 "Ваш угол в радианах; в задаче нужны градусы."};
constexpr Phrase kAngleInDegrees{"Your angle is in degrees; the problem asks for radians.",
                                 "角度が度になっています. 問題はラジアンで求めています.",
                                 "Ваш угол в градусах; в задаче нужны радианы."};
constexpr Phrase kCosForSin{"cos for sin", "sin の代わりに cos", "cos вместо sin"};
constexpr Phrase kThatIsCos{"That is cos θ = a·b/(‖a‖‖b‖); sin θ uses ‖a × b‖.",
                            "それは cos θ = a·b/(‖a‖‖b‖) です. sin θ には ‖a × b‖ を使います.",
                            "Это cos θ = a·b/(‖a‖‖b‖); для sin θ нужно ‖a × b‖."};

// The measures of a and b from their products, in any scalar: the parallelogram's area
// ‖a × b‖, the lengths, sin θ = ‖a × b‖/(‖a‖‖b‖) and cos θ = a·b/(‖a‖‖b‖). The exact solve and
// the numeric path (on a and b scaled by powers of two, which sin and cos do not see) both use
// it. a and b must not be zero.
template <typename T>
struct VectorMeasures {
  T area{}, length_a{}, length_b{}, sin{}, cos{};
};

template <typename T>
VectorMeasures<T> vector_measures(const Vec3<T>& a, const Vec3<T>& b, const T& dot,
                                  const Vec3<T>& cross) {
  VectorMeasures<T> m;
  m.area = stable_norm(cross);
  m.length_a = stable_norm(a);
  m.length_b = stable_norm(b);
  m.sin = m.area / m.length_a / m.length_b;
  m.cos = dot / m.length_a / m.length_b;
  return m;
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
      const VectorMeasures<T> m = vector_measures<T>(a, b, dot, cross);
      o.dot = scaled_by(dot, ka + kb, o.underflow);
      for (int i = 0; i < 3; ++i) o.cross(i) = scaled_by(cross(i), ka + kb, o.underflow);
      o.area = scaled_by(m.area, ka + kb, o.underflow);
      o.sin = m.sin;
      o.cos = m.cos;
      // θ = atan2(‖a × b‖, a·b): accurate at every angle, unlike arccos(cos θ) near 0 and π
      // (the exact solve writes arccos(cos θ): exact, it has no rounding to avoid).
      o.angle = scalar_angle(m.area, dot);
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
      if (o.unit.exact_zero_test) out.exact_decision(say(kWhetherAAndBAreParallel));
      if (o.unit.zero)
        out.null("unit_normal");
      else
        out.vector("unit_normal", o.unit.unit);
      out.note(say(kAngleNote));
      // Nearly parallel vectors cancel in a × b, nearly perpendicular ones in a · b. An exact 0
      // is decided exactly (parallel) or exact in every backend's products of the inputs.
      const Eigen::Vector3d da = to_double(in.exact_a), db = to_double(in.exact_b);
      if (o.unit.exact_value) report_exact_value(out, Said::verbatim("a × b"));
      if (!o.unit.zero && !o.unit.exact_value)
        warn_condition(out, p, cross_condition(da, db), say(kIllConditionedCrossProduct),
                       say(kABAndWithItThe));
      if (!canonical(Exact(in.exact_a.dot(in.exact_b))).is_zero())
        warn_condition(out, p, dot_condition(da, db), say(kIllConditionedDotProduct),
                       say(kABAndWithItCos));
      return out.take();
    };
    In in{{}, {}, unit == AngleUnit::Degrees, {}, a, b};
    in.a = conv<T>(a, &in.range);
    in.b = conv<T>(b, &in.range);
    return prepare(std::move(in), core, report);
  });
}

struct Vectors {
  static constexpr const char* kName = "vectors";
  static constexpr Phrase kSummary{
      "dot and cross products of two vectors, the parallelogram's area, sin, cos and the angle",
      "2 つのベクトルの内積と外積, 平行四辺形の面積, sin, cos となす角",
      "скалярное и векторное произведения двух векторов, площадь параллелограмма, sin, cos и угол"};
  static constexpr ConventionUse kUses{.api = false, .angles = true};
  struct Given {
    Vec3<Exact> a, b;
    AngleUnit angles;
  };
  static std::vector<std::string> given_fields() { return {"a", "b"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "dot", .kind = AnswerKind::Scalar, .symbols = {"a·b", "a.b", "a*b"}},
            {.name = "cross", .kind = AnswerKind::Vector, .symbols = {"a × b", "a x b"}},
            {.name = "area", .kind = AnswerKind::Scalar, .depends_on = {"cross"}, .symbols = {"S"}},
            {.name = "sin",
             .kind = AnswerKind::Scalar,
             .depends_on = {"area"},
             .symbols = {"sin θ", "sin(θ)", "sin theta", "sin(theta)"}},
            {.name = "cos",
             .kind = AnswerKind::Scalar,
             .depends_on = {"dot"},
             .symbols = {"cos θ", "cos(θ)", "cos theta", "cos(theta)"}},
            {.name = "angle",
             .kind = AnswerKind::Angle,
             .depends_on = {"cos"},
             .symbols = {"θ", "theta"}},
            {.name = "unit_normal",
             .kind = AnswerKind::UnitVector,
             .depends_on = {"cross"},
             .symbols = {"n", "n̂"}}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    return {r.vector<3>("a"), r.vector<3>("b"), c.angles};
  }

  // Error carried forward: area, sin and the unit normal from the student's cross product;
  // cos from their dot product.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const Exact la = canonical(norm(g.a)), lb = canonical(norm(g.b));
    Exact area = canonical(norm(Vec3<Exact>(g.a.cross(g.b))));
    if (const auto c = carried(student, "cross", 3)) {
      const Vec3<Exact> v((*c)[0], (*c)[1], (*c)[2]);
      area = canonical(norm(v));
      out.set("area", Value::scalar(area));
      out.set("unit_normal", Value::vector(unit(v)));
    }
    if (const Value* a = student.find("area"); a && a->exact.size() == 1) area = a->exact[0];
    out.set("sin", Value::scalar(canonical(area / (la * lb))));
    std::optional<Exact> cos;
    if (const Value* d = student.find("dot"); d && d->exact.size() == 1) {
      cos = canonical(d->exact[0] / (la * lb));
      out.set("cos", Value::scalar(*cos));
    }
    if (const Value* c = student.find("cos"); c && c->exact.size() == 1) cos = c->exact[0];
    // The angle of the student's own cos, in the set's unit (a cos beyond ±1 has none).
    if (cos && exact_sign(canonical(*cos - 1)) <= 0 && exact_sign(canonical(*cos + 1)) >= 0) {
      const Exact rad = canonical(exact_acos(*cos));
      out.set(
          "angle",
          Value::scalar(g.angles == AngleUnit::Degrees ? canonical(rad * 180 / GiNaC::Pi) : rad));
    }
    return out;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    const Vec3<Exact> ba = g.b.cross(g.a);
    Answers reversed;
    reversed.set("cross", Value::vector(ba));
    if (!canonical(ba.dot(ba)).is_zero()) reversed.set("unit_normal", Value::vector(unit(ba)));
    const Exact area = canonical(norm(Vec3<Exact>(g.a.cross(g.b))));
    Answers triangle;
    triangle.set("area", Value::scalar(canonical(area / 2)));
    const Exact cos = canonical(g.a.dot(g.b) / (norm(g.a) * norm(g.b)));
    // The angle in the other unit than the set's (degrees ↔ radians).
    const bool degrees = g.angles == AngleUnit::Degrees;
    Answers other_unit;
    const Exact rad = canonical(exact_acos(cos));
    other_unit.set("angle", Value::scalar(degrees ? rad : canonical(rad * 180 / GiNaC::Pi)));
    Answers swapped;
    swapped.set("sin", Value::scalar(cos));
    return {{say(kind_words::kReversedCrossProduct), say(kAntiCommutative), say(kCrossProduct),
             reversed},
            {say(kTriangleInsteadOfParallelogram), say(kHalfTheArea), say(kAreaOfParallelogram),
             triangle},
            {say(degrees ? kRadiansInsteadOfDegrees : kDegreesInsteadOfRadians),
             say(degrees ? kAngleInRadians : kAngleInDegrees), say(kAngle), other_unit},
            {say(kCosForSin), say(kThatIsCos), say(kSineOfAngle), swapped}};
  }

  // Grading scales (docs/grading.md §2): every product's terms are of size max|aᵢ|·max|bᵢ|;
  // dot and cos carry a sign (acute or obtuse), which a wrong answer never gets for free.
  static AnswerScales scales(const Given& g, const Answers& key) {
    const double ab = largest(doubles(g.a)) * largest(doubles(g.b));
    const double degree = g.angles == AngleUnit::Degrees ? 1.0 : 3.141592653589793 / 180;
    return {{"dot", uniform_scale(1, ab, {0})},
            {"cross", uniform_scale(3, ab)},
            {"area", uniform_scale(1, ab)},
            {"sin", uniform_scale(1, 1)},
            {"cos", uniform_scale(1, 1, {0})},
            {"angle", uniform_scale(1, std::max(degree, largest(key.find("angle"))))},
            {"unit_normal", uniform_scale(3, 1)}};
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return vectors_numeric(g.a, g.b, g.angles, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const Vec3<Exact>& a = g.a;
    const Vec3<Exact>& b = g.b;
    if (is_zero_vector(a)) throw DomainError("a", "a is the zero vector: no angle or normal");
    if (is_zero_vector(b)) throw DomainError("b", "b is the zero vector: no angle or normal");
    Answers out;
    // Dot product: a·b = a_x b_x + a_y b_y + a_z b_z.
    const Exact dot = canonical(a.dot(b));
    out.set("dot", Value::scalar(dot));
    if (steps)
      steps
          ->add(say(kDotProduct),
                tex("\\mathbf{a}\\cdot\\mathbf{b} = a_x\\,b_x + a_y\\,b_y + a_z\\,b_z"),
                tex("\\mathbf{a}\\cdot\\mathbf{b} = ") + vec(a) + tex("\\cdot") + vec(b),
                tex("\\mathbf{a}\\cdot\\mathbf{b} = ") + exact(dot))
          .yields("dot");
    // Cross product by the determinant rule.
    Vec3<Exact> cross = a.cross(b);
    for (int i = 0; i < 3; ++i) cross(i) = canonical(cross(i));
    out.set("cross", Value::vector(cross));
    if (steps)
      steps
          ->add(say(kCrossProduct),
                tex("\\mathbf{a}\\times\\mathbf{b} = (a_y\\,b_z - a_z\\,b_y,\\; "
                    "a_z\\,b_x - a_x\\,b_z,\\; a_x\\,b_y - a_y\\,b_x)"),
                tex("\\mathbf{a}\\times\\mathbf{b} = ") + vec(a) + tex(" \\times ") + vec(b),
                tex("\\mathbf{a}\\times\\mathbf{b} = ") + vec(cross))
          .yields("cross");
    // The measures by the template the numeric path uses; the steps show them.
    const VectorMeasures<Exact> m = vector_measures<Exact>(a, b, dot, cross);
    const Exact len_a = canonical(m.length_a), len_b = canonical(m.length_b);
    const Exact area = canonical(m.area);
    out.set("area", Value::scalar(area));
    if (steps)
      steps
          ->add(say(kAreaOfParallelogram), tex("S = \\lVert \\mathbf{a}\\times\\mathbf{b} \\rVert"),
                {}, math("S = ") + exact(area, true))
          .yields("area");
    const Exact sin = canonical(m.sin);
    out.set("sin", Value::scalar(sin));
    if (steps)
      steps
          ->add(say(kSineOfAngle),
                tex("\\sin\\theta = \\frac{\\lVert \\mathbf{a}\\times\\mathbf{b} "
                    "\\rVert}{\\lVert\\mathbf{a}\\rVert \\lVert\\mathbf{b}\\rVert}"),
                tex("\\sin\\theta = ") +
                    frac(exact(area), exact(len_a) + tex(" \\cdot ") + exact(len_b)),
                tex("\\sin\\theta = ") + exact(sin, true))
          .yields("sin");
    const Exact cos = canonical(m.cos);
    out.set("cos", Value::scalar(cos));
    if (steps)
      steps
          ->add(say(kCosineOfAngle),
                tex("\\cos\\theta = \\frac{\\mathbf{a}\\cdot\\mathbf{b}}{\\lVert\\mathbf{a}\\rVert "
                    "\\lVert\\mathbf{b}\\rVert}"),
                tex("\\cos\\theta = ") +
                    frac(exact(dot), exact(len_a) + tex(" \\cdot ") + exact(len_b)),
                tex("\\cos\\theta = ") + exact(cos, true))
          .yields("cos");
    const Exact radians = canonical(exact_acos(cos));
    const Exact angle =
        g.angles == AngleUnit::Degrees ? canonical(radians * 180 / GiNaC::Pi) : radians;
    out.set("angle", Value::scalar(angle));
    if (steps)
      steps
          ->add(say(kAngle), tex("\\theta = \\arccos(\\cos\\theta)"), {},
                tex("\\theta = ") + exact(angle, true) +
                    tex(g.angles == AngleUnit::Degrees ? "{}^\\circ" : "\\,\\text{rad}"))
          .yields("angle");
    if (area.is_zero()) {
      out.set("unit_normal", Value::null());
      if (steps) steps->warn(say(kNoPlane), say(kParallelNoPlane));
    } else {
      const Vec3<Exact> n = unit(cross);
      out.set("unit_normal", Value::vector(n));
      if (steps)
        steps
            ->add(say(kUnitNormalOfPlane),
                  tex("\\mathbf{n} = \\frac{\\mathbf{a}\\times\\mathbf{b}}{\\lVert "
                      "\\mathbf{a}\\times\\mathbf{b} \\rVert}"),
                  tex("\\mathbf{n} = ") + frac(vec(cross), exact(area)),
                  tex("\\mathbf{n} = ") + vec(n, true))
            .yields("unit_normal");
    }
    return out;
  }
  // Default generator: integer vectors in [−4, 4]³; nice: an angle of 0°, 30°, 45°, 60°, 90°,
  // 120°, 135°, 150° or 180° (4(a·b)² = k‖a‖²‖b‖², k = 0…4); hard: nearly parallel.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    IVec3 a{}, b{};
    for (int attempt = 0; attempt < 2000; ++attempt) {
      a = gen_ivec3(rng, -4, 4);
      b = o.hard ? iadd(iscale(rng.nonzero(-2, 2), a), gen_ivec3(rng, -1, 1))
                 : gen_ivec3(rng, -4, 4);
      const std::int64_t aa = idot(a, a), bb = idot(b, b), ab = idot(a, b);
      if (aa == 0 || bb == 0) continue;
      if (!o.hard && sine_between({double(a[0]), double(a[1]), double(a[2])},
                                  {double(b[0]), double(b[1]), double(b[2])}) < kMinSine)
        continue;
      if (!o.nice) break;
      const std::int64_t k4 = 4 * ab * ab;
      if (k4 == 0 || k4 == aa * bb || k4 == 2 * aa * bb || k4 == 3 * aa * bb) break;
    }
    YAML::Node g;
    g["a"] = gen_list(to_list(a));
    g["b"] = gen_list(to_list(b));
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    return sine_between(doubles(g.a), doubles(g.b)) < kMinSine ? "a and b are nearly parallel" : "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  using namespace accuracy;
  const Point3 a = point(rng, -9, 9), b = point(rng, -9, 9);
  const Eigen::Vector3d x = a.d(), y = b.d();
  const double s = x.cross(y).norm() / (x.norm() * y.norm()), c = x.dot(y) / (x.norm() * y.norm());
  if (x.norm() > 1 && y.norm() > 1 && s > 0.2 && std::abs(c) > 0.1)
    return "{a: " + a.yaml() + ", b: " + b.yaml() + "}";
  return std::nullopt;
}

}  // namespace

KindInfo vectors_kind() {
  KindInfo k = make_kind<Vectors>();
  k.order = 10;
  k.doc_given = "`a`, `b`";
  k.doc_answers =
      "`dot`, `cross`, `area`, `sin`, `cos`, `angle` (in the set's angle unit), `unit_normal`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
