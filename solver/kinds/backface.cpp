// seed 003: back-face test. D_f = (p_eye − p_i)·n; D_f > 0 front, D_f < 0 back, 0 edge-on.
// p0 = (1,0,0), p1 = (1,1,1), p2 = (0,1,2), eye = (0,1,0) → n = (1, −1, 1), v = (−1, 1, 0),
// D_f = −2: back. The sign is decided exactly, never against a float epsilon.
#include <fmt/format.h>

#include <array>
#include <cmath>

#include "solver/derivation/vocabulary.hpp"
#include "solver/geometry/facing.hpp"
#include "solver/geometry/predicates.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/accuracy_draws.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/digits_said.hpp"
#include "solver/shared/numeric_path_common.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kFacing{"facing", "表裏", "ориентация"};

constexpr Phrase kFacingNote{
    "facing: the sign of D_f, proven by its rounding-error bound or else computed exactly.",
    "表裏: D_f の符号. 丸め誤差の上界で確かめ, 確かめられなければ厳密に計算する.",
    "ориентация: знак D_f, доказанный оценкой ошибки округления или иначе вычисленный точно."};
constexpr Phrase kDirectXWinding{
    "In DirectX's left-handed coordinates the same formula n = e₀ × e₁ points to the side from "
    "which the vertices appear clockwise — Direct3D's default front face (FrontCounterClockwise = "
    "false).",
    "DirectX の左手系では同じ式 n = e₀ × e₁ が, 頂点が時計回りに見える側を向く — Direct3D "
    "の既定の表面 (FrontCounterClockwise = false).",
    "В левой системе DirectX та же формула n = e₀ × e₁ указывает в сторону, откуда вершины видны "
    "по часовой стрелке, — лицевая грань Direct3D по умолчанию (FrontCounterClockwise = false)."};
constexpr Phrase kViewVector{"View vector from p₀ to the eye", "p₀ から視点への視線ベクトル",
                             "Вектор взгляда от p₀ к глазу"};
constexpr Phrase kDiscriminant{"Discriminant", "判別式", "Признак лицевой грани"};
constexpr Phrase kEyeNearlyInPlane{"Eye nearly in the polygon's plane",
                                   "視点がほぼ多角形の平面上にある",
                                   "Глаз почти в плоскости многоугольника"};
constexpr Phrase kDfIllConditioned{
    "D_f (its sign, front or back, is decided exactly here; a floating-point sign needs an "
    "error-bounded filter with an exact fallback) is ill-conditioned ({0}).",
    "D_f (その符号, つまり表か裏かはここでは厳密に判定する. "
    "浮動小数点での符号には誤差限界付きのフィルタと厳密計算による代替が必要) は条件が悪い ({0}).",
    "D_f (его знак — лицевая или обратная — здесь определяется точно; знаку в плавающей точке "
    "нужен фильтр с оценкой погрешности и точный запасной путь) плохо обусловлен ({0})."};
constexpr Phrase kFrontOrBack{"Front or back", "表か裏か", "Лицевая или обратная"};
constexpr Phrase kDfPositive{
    "D_f > 0: v and n make an acute angle, so the eye sees the front.",
    "D_f > 0: v と n のなす角は鋭角なので, 視点からは表が見える.",
    "D_f > 0: v и n образуют острый угол, поэтому глаз видит лицевую сторону."};
constexpr Phrase kDfNegative{
    "D_f < 0: v and n make an obtuse angle, so the eye sees the back.",
    "D_f < 0: v と n のなす角は鈍角なので, 視点からは裏が見える.",
    "D_f < 0: v и n образуют тупой угол, поэтому глаз видит обратную сторону."};
constexpr Phrase kDfZero{
    "D_f = 0 exactly: the eye lies in the polygon's plane, which it sees edge-on.",
    "D_f = 0 (厳密): 視点は多角形の平面上にあり, 多角形を真横から見る.",
    "D_f = 0 точно: глаз лежит в плоскости многоугольника и видит его с ребра."};
constexpr Phrase kMirrorImage{
    "Read in right-handed coordinates the same numbers describe the mirror image: its normal e₀ × "
    "e₁ is −n, D_f changes sign, and the eye would see the other side.",
    "右手系で読むと同じ数値は鏡像を表す: その法線 e₀ × e₁ は −n で, D_f の符号が変わり, "
    "視点からは反対側が見える.",
    "Прочитанные в правой системе, те же числа описывают зеркальный образ: его нормаль e₀ × e₁ "
    "равна −n, D_f меняет знак, и глаз увидел бы другую сторону."};
constexpr Phrase kHandednessDecides{"The handedness decides the answer.",
                                    "答えは座標系の右手・左手で決まる.",
                                    "Ответ зависит от ориентации системы координат."};

constexpr Phrase kViewVectorFromAnyVertex{
    "the view vector from {0}: any vertex of the face gives the same D_f",
    "{0} からの視線ベクトル: 面のどの頂点から取っても D_f は同じです",
    "вектор взгляда от {0}: любая вершина грани даёт то же D_f"};
constexpr Phrase kViewVectorReversed{"view vector reversed", "視線ベクトルの向きが逆",
                                     "вектор взгляда развёрнут"};
constexpr Phrase kViewVectorPointsToPolygon{
    "Your view vector points from the eye to the polygon: v = p_eye − pᵢ points from the polygon "
    "to the eye, and that flips the sign of D_f.",
    "あなたの視線ベクトルは視点から多角形へ向いています. v = p_eye − pᵢ "
    "は多角形から視点へ向くベクトルで, 向きが逆だと D_f の符号が反転します.",
    "Ваш вектор взгляда направлен от глаза к многоугольнику: v = p_eye − pᵢ направлен от "
    "многоугольника к глазу, и это меняет знак D_f."};

std::unique_ptr<NumericSolver> backface_numeric(const Polygon3<Exact>& points,
                                                const Vec3<Exact>& eye, Precision p) {
  const double kappa = facing_condition(double_points(points), to_double(eye), p);
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
      warn_condition(out, p, kappa, say(kEyeNearlyInPlane), Said::verbatim("D_f"));
      out.note(say(kFacingNote));
      if (f.used_exact) out.exact_decision(say(kFacing));
      return out.take();
    };
    In in{{}, {}, {}, points, eye, {}};
    in.points = conv<T>(points, &in.range);
    in.eye = conv<T>(eye, &in.range);
    if constexpr (!kIsExact<T>) in.fast_bound = facing_error_bound_fast(in.points, in.eye);
    return prepare(std::move(in), core, report);
  });
}

// "₂" for 2: a vertex's index as the derivation writes it (p₂).
std::string subscript(std::size_t i) {
  std::string out;
  for (const char c : std::to_string(i)) out += std::string("₀₁₂₃₄₅₆₇₈₉").substr((c - '0') * 3, 3);
  return out;
}

struct Backface {
  static constexpr const char* kName = "backface";
  static constexpr Phrase kSummary{
      "is a polygon front- or back-facing from the eye", "多角形は視点から見て表か裏か",
      "какой стороной, лицевой или нелицевой, многоугольник обращён к глазу"};
  static constexpr ConventionUse kUses{.api = false, .angles = false, .handedness = true};
  struct Given {
    Polygon3<Exact> points;
    Vec3<Exact> eye;
    Api api;
    bool left_handed = false;  // a left-handed course under OpenGL's winding: n = e₁ × e₀
  };
  static std::vector<std::string> given_fields() { return {"points", "eye"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "normal", .kind = AnswerKind::Direction, .symbols = {"n"}},
            {.name = "view", .kind = AnswerKind::Vector, .symbols = {"v"}},
            {.name = "df",
             .kind = AnswerKind::Scalar,
             .depends_on = {"normal", "view"},
             .symbols = {"D_f"}},
            {.name = "facing",
             .kind = AnswerKind::Category,
             .depends_on = {"df"},
             .words = {"front", "back", "edge_on"},
             .label = say(kFacing)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    return {r.points("points", 3), r.vector<3>("eye"), c.api, left_handed_columns(c)};
  }

  static std::string facing_of(const Exact& df) { return facing_word(exact_sign(df)); }

  // Error carried forward: D_f from the student's normal and view vector, facing from D_f.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    Vec3<Exact> n = polygon_normal_with_steps(g.points, "points", nullptr, g.left_handed);
    Vec3<Exact> v = g.eye - g.points[0];
    const auto sn = carried(student, "normal", 3);
    const auto sv = carried(student, "view", 3);
    if (sn) n = Vec3<Exact>((*sn)[0], (*sn)[1], (*sn)[2]);
    if (sv) v = Vec3<Exact>((*sv)[0], (*sv)[1], (*sv)[2]);
    Exact df = canonical(v.dot(n));
    if (sn || sv) out.set("df", Value::scalar(df));
    if (const Value* d = student.find("df"); d && d->exact.size() == 1) df = d->exact[0];
    out.set("facing", Value::category(facing_of(df)));
    return out;
  }

  // The lecture's view vector runs from a vertex of the face to the eye, any vertex: the face is
  // planar, so every one gives the same D_f = v·n (the key takes p₀).
  static std::vector<AlsoRight> also_right(const Given& g) {
    std::vector<AlsoRight> out;
    for (std::size_t i = 1; i < g.points.size(); ++i)
      out.push_back({"view", Value::vector(Vec3<Exact>(g.eye - g.points[i])),
                     say(kViewVectorFromAnyVertex, "p" + subscript(i))});
    return out;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    const Vec3<Exact> n = polygon_normal_with_steps(g.points, "points", nullptr, g.left_handed);
    const Vec3<Exact> v = g.eye - g.points[0];
    const Exact df = canonical(v.dot(n));
    // Each mistake with everything it changes downstream, so that it is named only where the
    // student's other answers show it (a reversed D_f beside a correct view vector is not a
    // reversed view vector).
    Answers reversed_n;
    reversed_n.set("normal", Value::vector(Vec3<Exact>(-n)));
    reversed_n.set("df", Value::scalar(-df));
    reversed_n.set("facing", Value::category(facing_of(-df)));
    Answers reversed_v;
    reversed_v.set("view", Value::vector(Vec3<Exact>(-v)));
    reversed_v.set("df", Value::scalar(-df));
    reversed_v.set("facing", Value::category(facing_of(-df)));
    // The reversed cross product as the normal's helper says it for a triangle (e₀ × e₁ of the
    // first three vertices, whatever their number), with its consequences here.
    std::vector<Misconception> out;
    if (auto m = reversed_normal_mistake(n, 3, g.left_handed, std::nullopt)) {
      m->answers = reversed_n;
      out.push_back(std::move(*m));
    }
    out.push_back(
        {say(kViewVectorReversed), say(kViewVectorPointsToPolygon), say(kViewVector), reversed_v});
    // Reversed from any other vertex: the same mistake.
    for (std::size_t i = 1; i < g.points.size(); ++i) {
      Misconception m = out.back();
      m.answers.set("view", Value::vector(Vec3<Exact>(g.points[i] - g.eye)));
      out.push_back(std::move(m));
    }
    return out;
  }

  // Grading scales (docs/grading.md §2): D_f = v·n has terms of size max|vᵢ|·max|nᵢ| and its
  // sign is the whole point of the question.
  static AnswerScales scales(const Given&, const Answers& key) {
    return {{"df", uniform_scale(1, largest(key.find("view")) * largest(key.find("normal")), {0})}};
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return backface_numeric(g.left_handed ? reversed_winding(g.points) : g.points, g.eye, p);
  }

  static Answers solve(const Given& g, Derivation* steps) {
    if (steps && g.api == Api::DirectX) steps->note(say(kWindingLeftHanded), say(kDirectXWinding));
    const Vec3<Exact> n = polygon_normal_with_steps(g.points, "points", steps, g.left_handed);
    if (steps) steps->yields("normal");
    Answers out;
    out.set("normal", Value::vector(n));
    // D_f and its sign by the template the numeric path uses (the winding it reads: the
    // left-handed front normal e₁ × e₀ is the normal of the reversed polygon); the steps show them.
    const Polygon3<Exact> wound = g.left_handed ? reversed_winding(g.points) : g.points;
    const Facing<Exact> f = facing(wound, g.eye, wound, g.eye, true);
    const Vec3<Exact>& v = f.view;
    out.set("view", Value::vector(v));
    if (steps)
      steps
          ->add(say(kViewVector), tex("\\mathbf{v} = \\mathbf{p}_{\\text{eye}} - \\mathbf{p}_0"),
                tex("\\mathbf{v} = ") + vec(g.eye) + tex(" - ") + vec(g.points[0]),
                tex("\\mathbf{v} = ") + vec(v))
          .yields("view");
    const Exact df = canonical(f.df);
    out.set("df", Value::scalar(df));
    if (steps) {
      steps
          ->add(say(kDiscriminant), tex("D_f = \\mathbf{v}\\cdot\\mathbf{n}"),
                math("D_f = ") + vec(v) + tex("\\cdot") + vec(n), math("D_f = ") + exact(df, true))
          .yields("df");
      std::vector<Eigen::Vector3d> pts;
      for (const Vec3<Exact>& q : g.points) pts.push_back(to_double(q));
      // Each backend's own condition: products below its normal range cost it digits too.
      const Eigen::Vector3d eye = to_double(g.eye);
      const double kf = facing_condition(pts, eye, Precision::Float);
      if (!df.is_zero() && kf > kIllConditioned)
        steps->warn(
            say(kEyeNearlyInPlane),
            say(kDfIllConditioned, digits_said(facing_condition(pts, eye), kf,
                                               facing_condition(pts, eye, Precision::Double),
                                               facing_condition(pts, eye, Precision::LongDouble))));
    }
    const int sign = f.sign;
    const std::string side = facing_word(sign);
    out.set("facing", Value::category(side));
    if (steps) {
      const Phrase& why = sign > 0 ? kDfPositive : sign < 0 ? kDfNegative : kDfZero;
      const Phrase& seen = sign > 0 ? words::kFront : sign < 0 ? words::kBack : words::kEdgeOnKey;
      steps->add(say(kFrontOrBack), {}, {}, word(seen)).yields("facing").note = say(why);
      if (g.left_handed && sign != 0)
        steps->note(say(kRightHandedReading), say(kMirrorImage) + say(kHandednessDecides));
    }
    return out;
  }
  // Default generator: an integer triangle and an eye in [−8, 8]³ well off its plane; hard:
  // the eye exactly in the plane (edge-on, D_f = 0). D_f is an integer for integer input.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::array<IVec3, 3> t =
        gen_triangle(rng, GenerateOptions{o.nice, false, o.conventions}, -5, 5);
    const IVec3 eye = o.hard ? iadd(t[0], iadd(iscale(rng.integer(-2, 2), isub(t[1], t[0])),
                                               iscale(rng.integer(-2, 2), isub(t[2], t[0]))))
                             : gen_ivec3(rng, -8, 8);
    YAML::Node g;
    g["points"] = gen_points({t[0], t[1], t[2]});
    g["eye"] = gen_list(to_list(eye));
    return g;
  }

  static std::string ill_conditioned(const Given& g, const Answers& a) {
    if (triangle_shape(doubles(g.points)) < kMinTriangleShape)
      return "the polygon is nearly degenerate";
    const Value* n = a.find("normal");
    const Value* v = a.find("view");
    if (n && v) {
      const double s = sine_between(n->numbers, v->numbers);
      // |cos| < kMinSine, or a zero vector (sine_between gives 0): the eye grazes the plane.
      if (s == 0 || 1 - s * s < kMinSine * kMinSine)
        return "the eye is nearly in the polygon's plane";
    }
    return "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  using namespace accuracy;
  const auto t = well_conditioned_triangle(rng);
  if (!t) return std::nullopt;
  const Point3 eye = point(rng, -20, 20);
  if (facing_condition({(*t)[0].d(), (*t)[1].d(), (*t)[2].d()}, eye.d()) < kWellConditioned)
    return "{points: " + triangle_yaml(*t) + ", eye: " + eye.yaml() + "}";
  return std::nullopt;
}

}  // namespace

KindInfo backface_kind() {
  KindInfo k = make_kind<Backface>();
  k.order = 50;
  k.doc_given = "`points`, `eye`";
  k.doc_answers = "`normal`, `view` (p_eye − p₀), `df`, `facing` (`front`/`back`/`edge_on`)";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
