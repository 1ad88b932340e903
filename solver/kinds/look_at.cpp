// The view matrix of gluLookAt / Processing's camera() (seed 000: camera(eye, center, up)),
// or DirectX's LookAtLH: rows are the camera's axes, the last column moves the eye to the
// origin.
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kAPointInViewCoordinates{"A point in view coordinates", "視点座標系での点",
                                          "Точка в координатах вида"};

constexpr Phrase kReversedLookAtBasis{"reversed look-at basis", "カメラ基底の向きの反転",
                                      "развёрнутый базис камеры"};
constexpr Phrase kZAwayFromSceneDirectX{
    "Your camera's z axis points away from the scene: DirectX's camera looks down +z, so z = "
    "(center − eye)/‖center − eye‖ and x = up × z.",
    "あなたのカメラの z 軸はシーンと反対を向いています. DirectX のカメラは +z 方向を見るので, z = "
    "(center − eye)/‖center − eye‖, x = up × z です.",
    "Ось z вашей камеры направлена от сцены: камера DirectX смотрит вдоль +z, поэтому z = (center "
    "− eye)/‖center − eye‖ и x = up × z."};
constexpr Phrase kZAwayFromSceneLeftHanded{
    "Your camera's z axis points away from the scene: in left-handed coordinates the camera looks "
    "down +z, so z = (center − eye)/‖center − eye‖ and x = up × z.",
    "あなたのカメラの z 軸はシーンと反対を向いています. 左手系の座標ではカメラは +z "
    "方向を見るので, z = (center − eye)/‖center − eye‖, x = up × z です.",
    "Ось z вашей камеры направлена от сцены: в левой системе координат камера смотрит вдоль +z, "
    "поэтому z = (center − eye)/‖center − eye‖ и x = up × z."};
constexpr Phrase kZAtTheScene{
    "Your camera's z axis points at the scene: the camera looks down −z, so z = (eye − "
    "center)/‖eye − center‖ and x = up × z.",
    "あなたのカメラの z 軸はシーンの方を向いています. カメラは −z 方向を見るので, z = (eye − "
    "center)/‖eye − center‖, x = up × z です.",
    "Ось z вашей камеры направлена на сцену: камера смотрит вдоль −z, поэтому z = (eye − "
    "center)/‖eye − center‖ и x = up × z."};

struct LookAt {
  static constexpr const char* kName = "look_at";
  static constexpr Phrase kSummary{"the view matrix of a camera at eye looking at center",
                                   "eye から center を見るカメラのビュー変換行列",
                                   "матрица вида камеры в точке eye, смотрящей на center"};
  static constexpr ConventionUse kUses{.api = true, .angles = false};
  struct Given {
    Vec3<Exact> eye, center, up;
    std::vector<Vec3<Exact>> points;
    Api api;
    bool left_handed = false;  // a left-handed course under column vectors: LookAtLH's basis
  };
  static std::vector<std::string> given_fields() { return {"eye", "center", "up", "points"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "matrix", .kind = AnswerKind::Transform, .label = say(words::kMatrix)},
            {.name = "points",
             .kind = AnswerKind::Matrix,
             .depends_on = {"matrix"},
             .needs_given = "points",
             .point_rows = true,
             .label = say(words::kPoints)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.vector<3>("eye"),    r.vector<3>("center"), r.vector<3>("up"), {}, c.api,
            left_handed_columns(c)};
    if (r.has("points")) g.points = r.points("points", 1);
    return g;
  }

  // Error carried forward: the points moved by the student's own matrix.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    std::vector<std::vector<Exact>> points;
    for (const Vec3<Exact>& p : g.points) points.push_back({p(0), p(1), p(2)});
    if (auto p = carried_points(student, points, 4, g.api)) out.set("points", std::move(*p));
    return out;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const MatX<Exact> m =
        look_at_with_steps(g.eye, g.center, g.up, g.api, "", steps, g.left_handed);
    Answers out;
    out.set("matrix", matrix_value(paper_form(m, g.api)));
    if (steps) steps->yields("matrix");
    std::vector<std::vector<Exact>> points;
    for (const Vec3<Exact>& p : g.points) points.push_back({p(0), p(1), p(2)});
    out.set("points", transform_points_with_steps(m, points, say(kAPointInViewCoordinates), "p",
                                                  steps, g.api));
    return out;
  }
  // The reversed basis: the camera's z axis along the view direction instead of against it (or
  // the other way round in DirectX), as if the camera looked from eye away from center: the
  // basis turns half a turn about up.
  static std::vector<Misconception> misconceptions(const Given& g) {
    Given reversed = g;
    reversed.center =
        Vec3<Exact>(canonical(2 * g.eye(0) - g.center(0)), canonical(2 * g.eye(1) - g.center(1)),
                    canonical(2 * g.eye(2) - g.center(2)));
    try {
      const bool plus_z = g.api == Api::DirectX || g.left_handed;
      return {{say(kReversedLookAtBasis),
               say(g.api == Api::DirectX ? kZAwayFromSceneDirectX
                   : g.left_handed       ? kZAwayFromSceneLeftHanded
                                         : kZAtTheScene),
               say(plus_z ? kCameraAxesLeftHanded : kCameraAxesRightHanded),
               solve(reversed, nullptr)}};
    } catch (const std::exception&) {
      return {};
    }
  }

  // Default generator: center in [−2, 2]³, eye a few units away, up (0, 1, 0), and points near
  // the center (in front of the camera); nice: the view direction in the xz-plane with an
  // integer length, so every entry is rational; hard: up nearly along the view direction.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const IVec3 center = gen_ivec3(rng, -2, 2);
    IVec3 d{};
    if (o.hard) {
      d = {rng.integer(-1, 1), 12, rng.nonzero(-1, 1)};
    } else if (o.nice) {
      const std::vector<IVec3> dirs = {{0, 0, 5},  {5, 0, 0},  {3, 0, 4},  {4, 0, 3},
                                       {-3, 0, 4}, {0, 0, -5}, {-4, 0, -3}};
      d = rng.pick(dirs);
    } else {
      do {
        d = gen_ivec3(rng, -6, 6);
      } while (idot(d, d) < 9 ||
               sine_between({double(d[0]), double(d[1]), double(d[2])}, {0, 1, 0}) < 0.3);
    }
    std::vector<IVec3> points;
    const auto n = rng.integer(1, 2);
    for (std::int64_t i = 0; i < n; ++i) points.push_back(iadd(center, gen_ivec3(rng, -1, 1)));
    YAML::Node g;
    g["eye"] = gen_list(to_list(iadd(center, d)));
    g["center"] = gen_list(to_list(center));
    g["up"] = gen_list({0, 1, 0});
    g["points"] = gen_points(points);
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    return sine_between(doubles(Vec3<Exact>(g.center - g.eye)), doubles(g.up)) < kMinSine
               ? "up is nearly parallel to the view direction"
               : "";
  }
};

}  // namespace

KindInfo look_at_kind() {
  KindInfo k = make_kind<LookAt>();
  k.order = 70;
  k.doc_given = "`eye`, `center`, `up`, optional `points`";
  k.doc_answers = "`matrix`, `points`";
  return k;
}

}  // namespace frustum
