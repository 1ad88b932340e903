// seed 000 exercise 2: the projection plane of a window of width × height pixels seen with a
// vertical field of view fov lies at distance (height/2) / tan(fov/2) from the eye
// (Processing's default camera z); a point P in view coordinates projects to
// P′ = P · (s / z_P) on it. Window 200×200, fov 60°: s = −100√3, and P(0, 100, −300) ↦
// P′ = (0, 100√3/3, −100√3).
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kDistanceOfProjectionPlane{"Distance of the projection plane", "投影面までの距離",
                                            "Расстояние до плоскости проекции"};
constexpr Phrase kPlaneFillsFieldOfView{
    "The plane on which the window's height exactly fills the vertical field of view; Processing "
    "puts its default camera at this distance.",
    "ウィンドウの高さがちょうど垂直方向の画角を満たす平面. Processing "
    "は既定のカメラをこの距離に置く.",
    "Плоскость, на которой высота окна в точности заполняет вертикальный угол обзора; Processing "
    "ставит камеру по умолчанию на этом расстоянии."};
constexpr Phrase kEyeSpaceLooksDownMinusZ{
    "Eye space looks down −z, so the plane is at negative z.",
    "視点座標系は −z 方向を見るので, この平面は負の z にある.",
    "Пространство вида смотрит вдоль −z, поэтому плоскость лежит при отрицательном z."};
constexpr Phrase kDirectXLooksDownPlusZ{"DirectX's eye space looks down +z.",
                                        "DirectX の視点座標系は +z 方向を見る.",
                                        "В DirectX пространство вида смотрит вдоль +z."};
constexpr Phrase kLeftHandedPlaneAtPositiveZ{
    "The course's left-handed eye space looks down +z, so the plane is at positive z.",
    "この講義の左手系の視点座標系は +z 方向を見るので, この平面は正の z にある.",
    "В левой системе координат курса пространство вида смотрит вдоль +z, поэтому плоскость лежит "
    "при положительном z."};
constexpr Phrase kReadRightHandedPlane{
    "Read right-handed (looking down −z), the same picture has the plane at z = −s and every "
    "point's z negated: x′ and y′ are the same in both readings.",
    "右手系 (−z 方向を見る) で読むと, 同じ像で平面は z = −s にあり, 各点の z の符号が反転する: x′ "
    "と y′ はどちらで読んでも同じである.",
    "В правой системе (взгляд вдоль −z) та же картина даёт плоскость z = −s и противоположный знак "
    "z у каждой точки: x′ и y′ в обоих прочтениях одинаковы."};

// +1 when eye space looks down +z (left-handed: DirectX, or a course that declares it), else −1.
int looking_down(const Conventions& c) { return handedness_of(c) == Handedness::Left ? 1 : -1; }

struct ProjectionPlane {
  static constexpr const char* kName = "projection_plane";
  static constexpr Phrase kSummary{"where the projection plane lies and where a point lands on it",
                                   "投影面の位置と, その上に点が写る位置",
                                   "где лежит плоскость проекции и куда на неё попадает точка"};
  struct Given {
    Exact width, height, fov;
    Vec3<Exact> point;
    Conventions conventions;
  };
  static std::vector<std::string> given_fields() { return {"window", "fov", "point"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "plane_z", .kind = AnswerKind::Scalar, .symbols = {"s"}},
            {.name = "projected",
             .kind = AnswerKind::Vector,
             .depends_on = {"plane_z"},
             .symbols = {"P′"}}};
  }

  // Error carried forward: the point projected onto the student's own plane z = s (similar
  // triangles, P′ = P · s / z_P), when the point can be projected at all.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const auto s = carried(student, "plane_z", 1);
    if (!s || exact_sign(g.point(2)) == 0) return out;
    const Exact k = canonical((*s)[0] / g.point(2));
    out.set("projected", Value::vector(Vec3<Exact>(canonical(g.point(0) * k),
                                                   canonical(g.point(1) * k), (*s)[0])));
    return out;
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    const std::vector<Exact> window = r.numbers("window", 2);
    g.width = window[0];
    g.height = window[1];
    if (exact_sign(g.width) <= 0 || exact_sign(g.height) <= 0)
      r.fail("window", "width and height must be positive");
    g.fov = read_angle(r, "fov", c.angles);
    if (exact_sign(g.fov) <= 0 || exact_sign(g.fov - GiNaC::Pi) >= 0)
      r.fail("fov", "must be between 0° and 180° (exclusive)");
    g.point = r.vector<3>("point");
    g.conventions = c;
    return g;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    // OpenGL and Processing eye space looks down −z; DirectX, and a left-handed course under
    // OpenGL's or Processing's matrices, look down +z.
    const int toward = looking_down(g.conventions);
    const Exact half = g.fov / 2;
    const Exact s = canonical(toward * (g.height / 2) * GiNaC::cos(half) / GiNaC::sin(half));
    Answers out;
    out.set("plane_z", Value::scalar(s));
    if (steps)
      steps
          ->add(say(kDistanceOfProjectionPlane),
                tex(std::string(toward < 0 ? "s = -" : "s = ") +
                    "\\frac{\\text{height}/2}{\\tan(\\text{fov}/2)}"),
                tex("\\text{height} = ") + exact(g.height) + tex(",\\; \\text{fov} = ") +
                    angle_text(g.fov, g.conventions.angles),
                math("s = ") + exact(s, true))
          .yields("plane_z")
          .note = say(kPlaneFillsFieldOfView) +
                  (toward < 0 ? say(kEyeSpaceLooksDownMinusZ)
                   : g.conventions.api == Api::DirectX
                       ? say(kDirectXLooksDownPlusZ)
                       : say(kLeftHandedPlaneAtPositiveZ) + say(kReadRightHandedPlane));
    const int z_sign = exact_sign(g.point(2));
    if (z_sign != toward)
      throw DomainError(
          "point", z_sign == 0 ? "the point is in the eye's plane (z = 0): it has no projection"
                               : "the point is behind the eye: it has no projection");
    // Similar triangles: x′ : s = x : z (seed 000: x_n = x · n / (−z)).
    const Exact k = canonical(s / g.point(2));
    const Vec3<Exact> p(canonical(g.point(0) * k), canonical(g.point(1) * k), s);
    out.set("projected", Value::vector(p));
    if (steps)
      steps
          ->add(say(kSimilarTriangles), tex("P' = P \\cdot \\frac{s}{z_P}"),
                tex("P' = ") + vec(g.point) + tex(" \\cdot ") + frac(exact(s), exact(g.point(2))),
                tex("P' = ") + vec(p, true))
          .yields("projected");
    return out;
  }
  // Default generator: a window of 200×200, 400×300 or 640×480 pixels, fov 30°…90° (nice: 60°
  // or 90°; hard: 150°), and a point 100…400 in front of the eye.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const auto [w, h] = rng.pick(
        std::vector<std::pair<std::int64_t, std::int64_t>>{{200, 200}, {400, 300}, {640, 480}});
    const std::int64_t fov = o.hard ? 150
                                    : rng.pick(o.nice ? std::vector<std::int64_t>{60, 90}
                                                      : std::vector<std::int64_t>{30, 45, 60, 90});
    const int toward = looking_down(o.conventions);
    YAML::Node g;
    g["window"] = gen_list({w, h});
    g["fov"] = gen_angle(fov, o.conventions);
    g["point"] = gen_list(
        {10 * rng.integer(-10, 10), 10 * rng.integer(-10, 10), toward * 10 * rng.integer(10, 40)});
    return g;
  }
};

}  // namespace

KindInfo projection_plane_kind() {
  KindInfo k = make_kind<ProjectionPlane>();
  k.order = 100;
  k.doc_given = "`window` [w, h], `fov`, `point`";
  k.doc_answers = "`plane_z`, `projected`";
  return k;
}

}  // namespace frustum
