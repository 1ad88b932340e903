// A point through the pipeline (seed 004: v′ = (P·V·M)·v, then divide by w, then the
// viewport): clip coordinates, NDC, window coordinates with depth in [0, 1], and whether it
// lies inside the view volume. The model matrix M (optional `model`: transform steps, first
// applied first, M = M_parent·M_object) places the point, the camera's V views it. A point at
// or behind the eye (w ≤ 0) is reported as such and never divided.
#include <fmt/format.h>

#include <algorithm>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/numeric/ranged.hpp"
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
constexpr Phrase kClipCoords{"clip", "クリップ座標", "координаты отсечения"};
constexpr Phrase kNdc{"ndc", "正規化デバイス座標", "нормализованные координаты"};

constexpr Phrase kPointInEyePlane{"The point is in the eye's plane", "点は視点を通る平面上にある",
                                  "Точка в плоскости глаза"};
constexpr Phrase kPointBehindEye{"The point is behind the eye", "点は視点の後ろにある",
                                 "Точка позади глаза"};
constexpr Phrase kNoNdcOrWindowPosition{"w_c ≤ 0: no NDC or window position.",
                                        "w_c ≤ 0: NDC もウィンドウ上の位置もない.",
                                        "w_c ≤ 0: нет ни NDC, ни положения в окне."};
constexpr Phrase kWcPositiveAndInside{"w_c > 0 and inside", "w_c > 0 と内側かどうか",
                                      "w_c > 0 и «внутри»"};
constexpr Phrase kPointCloseToEyePlane{"Point close to the eye's plane", "点が視点を通る平面に近い",
                                       "Точка близко к плоскости глаза"};
constexpr Phrase kWcAndNdcDividedByIt{"w_c (and the NDC divided by it)",
                                      "w_c (と, それで割った NDC)",
                                      "w_c (и NDC, делённые на него)"};
constexpr Phrase kModelMatrix{"Model matrix (first step applied first)",
                              "モデル変換行列 (最初のステップを最初に適用)",
                              "Матрица модели (первый шаг применяется первым)"};
constexpr Phrase kWcAndNdcIllConditioned{
    "w_c, and the NDC divided by it, is ill-conditioned ({0}).",
    "w_c と, それで割った NDC は条件が悪い ({0}).",
    "w_c и NDC, делённые на него, плохо обусловлены ({0})."};
constexpr Phrase kModelToWorld{"Model to world coordinates", "モデル座標からワールド座標へ",
                               "Из локальных координат в мировые"};
constexpr Phrase kModelToView{"Model to view coordinates", "モデル座標から視点座標へ",
                              "Из локальных координат в координаты вида"};
constexpr Phrase kWorldToView{"World to view coordinates", "ワールド座標から視点座標へ",
                              "Из мировых координат в координаты вида"};
constexpr Phrase kReadInRightHanded{
    "Read in right-handed coordinates (gluLookAt and the right-handed projection on the same "
    "numbers), the chain is P_right·diag(−1, 1, 1, 1)·V_right instead: the view coordinates' x "
    "changes sign between V and P, so for a view volume symmetric in x (l = −r) the picture is "
    "mirrored left to right.",
    "右手系で読むと (同じ数値に gluLookAt と右手系の投影を使うと), 連鎖は代わりに P_right·diag(−1, "
    "1, 1, 1)·V_right になる: V と P の間で視点座標の x の符号が変わるので, x について対称な視体積 "
    "(l = −r) では画像が左右反転する.",
    "В правой системе координат (gluLookAt и проекция правой системы на тех же числах) цепочка "
    "вместо этого равна P_right·diag(−1, 1, 1, 1)·V_right: координата x вида меняет знак между V и "
    "P, поэтому для видимого объёма, симметричного по x (l = −r), изображение зеркально отражается "
    "слева направо."};
constexpr Phrase kClipCoordinates{"Clip coordinates", "クリップ座標", "Координаты отсечения"};
constexpr Phrase kWholeChainAtOnce{"The whole chain at once", "変換の合成を一度に",
                                   "Вся цепочка сразу"};
constexpr Phrase kProductComputedOnce{
    "The product of the matrices is computed once and applies to every vertex of the object; it "
    "gives the same clip coordinates as the steps one by one.",
    "行列の積は一度だけ計算すれば物体のすべての頂点に使える. "
    "一段ずつ変換した場合と同じクリップ座標になる.",
    "Произведение матриц вычисляется один раз и применяется ко всем вершинам объекта; оно даёт те "
    "же координаты отсечения, что и пошаговое преобразование."};
constexpr Phrase kDepthPrecision{"Depth precision", "奥行きの精度", "Точность глубины"};
constexpr Phrase kFarNearDepthBuffer{
    "far/near = {0}: a float depth buffer in [0, 1] separates surfaces at this distance only when "
    "they are more than Δz ≈ {1} apart (Δz ≈ 2⁻²⁴(f − n)z²/(f·n); a reversed-Z depth buffer keeps "
    "far more).",
    "far/near = {0}: [0, 1] の float の奥行きバッファがこの距離で面を区別できるのは, 面が Δz ≈ {1} "
    "より離れているときだけ (Δz ≈ 2⁻²⁴(f − n)z²/(f·n). 逆 Z "
    "の奥行きバッファならはるかに多くの精度が残る).",
    "far/near = {0}: float-буфер глубины в [0, 1] различает поверхности на этом расстоянии, только "
    "если они отстоят больше чем на Δz ≈ {1} (Δz ≈ 2⁻²⁴(f − n)z²/(f·n); обратный Z-буфер сохраняет "
    "гораздо больше)."};
constexpr Phrase kWcZeroCannotDivide{
    "w_c = 0: dividing by w would send the point to infinity or mirror it in front of the eye, so "
    "it has no NDC or window position; clipping removes it before the divide.",
    "w_c = 0: w で割ると点は無限遠に飛ぶか視点の前に鏡映されるので, "
    "正規化座標もウィンドウ上の位置もない. 除算の前にクリッピングで除かれる.",
    "w_c = 0: деление на w отправило бы точку в бесконечность или отразило бы её перед глазом, "
    "поэтому у неё нет положения в NDC и в окне; отсечение удаляет её до деления."};
constexpr Phrase kWcNegativeCannotDivide{
    "w_c < 0: dividing by w would send the point to infinity or mirror it in front of the eye, so "
    "it has no NDC or window position; clipping removes it before the divide.",
    "w_c < 0: w で割ると点は無限遠に飛ぶか視点の前に鏡映されるので, "
    "正規化座標もウィンドウ上の位置もない. 除算の前にクリッピングで除かれる.",
    "w_c < 0: деление на w отправило бы точку в бесконечность или отразило бы её перед глазом, "
    "поэтому у неё нет положения в NDC и в окне; отсечение удаляет её до деления."};
constexpr Phrase kPerspectiveDivide{"Perspective divide", "透視除算", "Перспективное деление"};
constexpr Phrase kInsideViewVolume{"Inside the view volume?", "視体積の内側か?",
                                   "Внутри видимого объёма?"};
constexpr Phrase kYesPointVisible{"yes: the point is visible", "はい: 点は見える",
                                  "да: точка видна"};
constexpr Phrase kNoClippingRemovesIt{"no: clipping removes it", "いいえ: クリッピングで除かれる",
                                      "нет: отсечение удаляет её"};
constexpr Phrase kMissingPerspectiveDivide{"missing perspective divide",
                                           "透視除算 (w による除算) の忘れ",
                                           "пропущено перспективное деление"};
constexpr Phrase kSkippedDivideByW{"You skipped the divide by w: NDC = (x_c, y_c, z_c) / w_c.",
                                   "w による除算が抜けています. NDC = (x_c, y_c, z_c) / w_c です.",
                                   "Вы пропустили деление на w: NDC = (x_c, y_c, z_c) / w_c."};

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

// The seven signs of volume_tests computed exactly (the exact backend, the exact fallback of
// the floating ones, and the exact solve).
std::array<int, 7> exact_volume_signs(const Vec4<Exact>& clip, Api api) {
  const std::array<Exact, 7> t = volume_tests(clip, api);
  std::array<int, 7> sign{};
  for (int k = 0; k < 7; ++k) sign[k] = exact_sign(t[k]);
  return sign;
}

// Inside the view volume from the seven signs: w > 0 and every plane test ≥ 0.
bool inside_volume(const std::array<int, 7>& sign) {
  bool inside = sign[0] > 0;
  for (int k = 1; k < 7; ++k) inside = inside && sign[k] >= 0;
  return inside;
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
        sign = exact_volume_signs(o.clip, in.given.api);
      } else {
        const std::array<Ranged<T>, 7> t =
            volume_tests(clip_of(clip_from_world(in.ranged), in.ranged.point), in.given.api);
        std::optional<std::array<int, 7>> exact;
        for (int k = 0; k < 7; ++k) {
          const SignDecision d = decide_sign(t[k], [&] {
            if (!exact)
              exact = exact_volume_signs(clip_of(clip_from_world(in.exact), in.exact.point),
                                         in.given.api);
            return (*exact)[k];
          });
          sign[k] = d.sign;
          o.exact_decided = o.exact_decided || d.exact;
        }
      }
      o.w_sign = sign[0];
      o.inside = inside_volume(sign);
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
        out.warn(o.w_sign == 0 ? say(kPointInEyePlane) : say(kPointBehindEye),
                 say(kNoNdcOrWindowPosition));
      }
      out.boolean("inside", o.inside);
      if (o.exact_decided) out.exact_decision(say(kWcPositiveAndInside));
      Eigen::Vector4d row, h;
      for (int i = 0; i < 4; ++i) {
        row(i) = static_cast<double>(to_long_double(o.row3(i)));
        h(i) = static_cast<double>(to_long_double(o.homogeneous(i)));
      }
      warn_condition(out, p, w_condition(row, h), say(kPointCloseToEyePlane),
                     say(kWcAndNdcDividedByIt));
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

struct ProjectPoint {
  static constexpr const char* kName = "project_point";
  static constexpr Phrase kSummary{"a point's clip, NDC and window coordinates",
                                   "点のクリップ座標, NDC とウィンドウ座標",
                                   "координаты точки в пространстве отсечения, в NDC и в окне"};
  struct Given {
    Vec3<Exact> point;
    std::vector<TransformStep> model;                  // empty: the point is in world coordinates
    std::optional<std::array<Vec3<Exact>, 3>> camera;  // eye, center, up
    ProjectionSpec projection;
    Exact width, height;
    Api api;
    bool left_handed = false;  // a left-handed course under column vectors (camera and projection)
  };
  static std::vector<std::string> given_fields() {
    return {"point", "model", "camera", "perspective", "frustum", "ortho", "viewport"};
  }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "clip", .kind = AnswerKind::Point, .label = say(kClipCoords)},
            {.name = "ndc", .kind = AnswerKind::Vector, .depends_on = {"clip"}, .label = say(kNdc)},
            {.name = "window",
             .kind = AnswerKind::Vector,
             .depends_on = {"ndc"},
             .label = say(words::kWindowCoordinates)},
            {.name = "inside",
             .kind = AnswerKind::Bool,
             .depends_on = {"ndc"},
             .words = {"inside", "outside"},
             .label = say(words::kInsideQuestion)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.point = r.vector<3>("point");
    if (r.has("model")) g.model = read_transform_steps(r, "model", 3, c);
    if (r.has("camera")) {
      GivenReader cam = r.child("camera", {"eye", "center", "up"});
      g.camera = {cam.vector<3>("eye"), cam.vector<3>("center"), cam.vector<3>("up")};
      cam.finish();
    }
    g.projection = read_projection(r, c);
    GivenReader vp = r.child("viewport", {"width", "height"});
    g.width = vp.number("width");
    g.height = vp.number("height");
    if (exact_sign(g.width) <= 0) vp.fail("width", "must be positive");
    if (exact_sign(g.height) <= 0) vp.fail("height", "must be positive");
    vp.finish();
    g.api = c.api;
    g.left_handed = left_handed_columns(c);
    return g;
  }

  // Error carried forward: NDC by dividing the student's clip coordinates, the window and
  // inside from their NDC.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    std::optional<Vec3<Exact>> ndc;
    if (const auto c = carried(student, "clip", 4); c && exact_sign((*c)[3]) > 0) {
      ndc = Vec3<Exact>(canonical((*c)[0] / (*c)[3]), canonical((*c)[1] / (*c)[3]),
                        canonical((*c)[2] / (*c)[3]));
      out.set("ndc", Value::vector(*ndc));
    } else if (c) {
      out.set("inside", Value::boolean(false));  // w ≤ 0: behind the eye
    }
    if (const Value* n = student.find("ndc"); n && n->exact.size() == 3)
      ndc = Vec3<Exact>(n->exact[0], n->exact[1], n->exact[2]);
    if (ndc) {
      const Vec3<Exact> w = viewport(*ndc, g.width, g.height, g.api);
      out.set("window",
              Value::vector(Vec3<Exact>(canonical(w(0)), canonical(w(1)), canonical(w(2)))));
      out.set("inside", Value::boolean(ndc_inside(*ndc, g.api)));
    }
    return out;
  }

  static AnswerScales scales(const Given& g, const Answers&) {
    return {{"ndc", ndc_scale(g.api)}, {"window", window_scale(g.width, g.height)}};
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    std::vector<Misconception> out;
    auto variant = [&](const Said& name, const Said& feedback, const Said& step, Given changed) {
      try {
        out.push_back({name, feedback, step, solve(changed, nullptr)});
      } catch (const std::exception&) {
        // A mistake that leads nowhere (a degenerate volume) cannot be matched.
      }
    };
    // Missing perspective divide: the clip coordinates taken as NDC.
    try {
      const Answers right = solve(g, nullptr);
      const Value* clip = right.find("clip");
      if (clip && clip->exact.size() == 4) {
        Answers nodiv;
        const Vec3<Exact> c(clip->exact[0], clip->exact[1], clip->exact[2]);
        nodiv.set("ndc", Value::vector(c));
        const Vec3<Exact> w = viewport(c, g.width, g.height, g.api);
        nodiv.set("window",
                  Value::vector(Vec3<Exact>(canonical(w(0)), canonical(w(1)), canonical(w(2)))));
        nodiv.set("inside", Value::boolean(ndc_inside(c, g.api)));
        out.push_back({say(kMissingPerspectiveDivide), say(kSkippedDivideByW),
                       say(kPerspectiveDivide), nodiv});
      }
    } catch (const std::exception&) {
    }
    // The model's steps multiplied in the order they are applied (the transform kind's mistake).
    if (g.model.size() >= 2) {
      Given changed = g;
      std::reverse(changed.model.begin(), changed.model.end());
      variant(say(kCompositionInTheWrongOrder), wrong_order_feedback(g.api), say(kModelMatrix),
              changed);
    }
    for (const ProjectionMistake& m : projection_mistakes(g.projection)) {
      Given changed = g;
      changed.projection = m.projection;
      variant(m.name, m.feedback, m.step.empty() ? say(kClipCoordinates) : m.step, changed);
    }
    return out;
  }

  // Seed 004's v′ = (P·V·M)·v: the three matrices multiplied first, the same clip point.
  static void chain_step(Derivation* steps, const Given& g, const MatX<Exact>& pvm,
                         const std::vector<Exact>& clip) {
    const bool rows = g.api == Api::DirectX;
    // The factors joined by \, (read as P·V·M).
    std::string product = g.camera ? "P\\,V" : "P";
    if (!g.model.empty()) product += "\\,M";
    if (rows)  // row vectors: v′ = v·(M·V·P)
      product = g.model.empty() ? "V\\,P" : (g.camera ? "M\\,V\\,P" : "M\\,P");
    steps
        ->add(say(kWholeChainAtOnce),
              rows ? tex("\\mathbf{v}' = \\mathbf{v}\\,(" + product + ")")
                   : tex("\\mathbf{v}' = (" + product + ")\\,\\mathbf{v}"),
              tex(product + " = ") + matrix_text(paper_form(pvm, g.api)),
              tex("\\mathbf{v}' = ") + vec(clip, true))
        .note = say(kProductComputedOnce);
  }

  static std::unique_ptr<NumericSolver> solve_numeric(const Given& g, Precision p) {
    return project_point_numeric(g.point, model_matrix(g.model), g.camera, g.projection, g.width,
                                 g.height, g.api, p);
  }

  // M = Aₙ·…·A₁ of the model's steps (column form), or nothing without a model.
  static std::optional<MatX<Exact>> model_matrix(const std::vector<TransformStep>& model) {
    if (model.empty()) return std::nullopt;
    return compose_with_steps(model, 3, Api::OpenGL, "M", kModelMatrix, nullptr);
  }

  static Vec3<Exact> moved(const MatX<Exact>& m, const Vec3<Exact>& p) {
    const std::vector<Exact> v = transform_point(m, std::vector<Exact>{p(0), p(1), p(2)});
    return Vec3<Exact>(canonical(v[0]), canonical(v[1]), canonical(v[2]));
  }

  static Answers solve(const Given& g, Derivation* steps) {
    Vec3<Exact> p = g.point;
    const bool rows = g.api == Api::DirectX;
    MatX<Exact> model = MatX<Exact>::Identity(4, 4), view = MatX<Exact>::Identity(4, 4);
    if (!g.model.empty()) {
      // Seed 004: the model matrix places the object (M = M_parent·M_object).
      model = compose_with_steps(g.model, 3, g.api, "M", kModelMatrix, steps);
      p = moved(model, p);
      if (steps) {
        const std::string to = g.camera ? "world" : "view";
        steps->add(g.camera ? say(kModelToWorld) : say(kModelToView),
                   tex("\\mathbf{p}_{\\text{" + to +
                       "}} = " + (rows ? "\\mathbf{v}\\,M" : "M\\,\\mathbf{v}")),
                   tex("\\mathbf{v} = ") + vec(g.point),
                   tex("\\mathbf{p}_{\\text{" + to + "}} = ") + vec(p, true));
      }
    }
    if (g.camera) {
      const auto& [eye, center, up] = *g.camera;
      view = look_at_with_steps(eye, center, up, g.api, "camera.", steps, g.left_handed);
      p = moved(view, p);
      if (steps)
        steps->add(say(kWorldToView),
                   tex("\\mathbf{p}_{\\text{view}} = V\\,\\mathbf{p}_{\\text{world}}"), {},
                   tex("\\mathbf{p}_{\\text{view}} = ") + vec(p, true));
    }
    // The lecture's names: P projects, V views, M places (v′ = (P·V·M)·v).
    const MatX<Exact> m = projection_with_steps(g.projection, g.api, steps, "P");
    if (steps && g.left_handed && g.camera)
      steps->note(say(kRightHandedReading), say(kReadInRightHanded));
    Eigen::Matrix<Exact, Eigen::Dynamic, 1> h(4);
    h << p(0), p(1), p(2), Exact(1);
    Eigen::Matrix<Exact, Eigen::Dynamic, 1> clip = m * h;
    for (int i = 0; i < 4; ++i) clip(i) = canonical(clip(i));
    Answers out;
    const std::vector<Exact> clip_v(clip.data(), clip.data() + 4);
    out.set("clip", Value::vector(clip_v));
    if (steps) {
      steps->add(say(kClipCoordinates),
                 g.api == Api::DirectX
                     ? tex("(x_c, y_c, z_c, w_c) = (x, y, z, 1)\\,P")
                     : tex("(x_c, y_c, z_c, w_c)^{\\mathsf{T}} = P\\,(x, y, z, 1)^{\\mathsf{T}}"),
                 math("p = ") + vec(std::vector<Exact>{p(0), p(1), p(2), 1}),
                 math("(x_c, y_c, z_c, w_c) = ") + vec(clip_v, true));
      if (!g.model.empty() || g.camera)
        chain_step(steps, g, canonical(MatX<Exact>(m * view * model)), clip_v);
      steps->yields("clip");
    }
    const Exact& w = clip(3);
    // The decisions by the formulas the numeric path uses: the seven signs of w and of the
    // plane tests −w ≤ x, y ≤ w, −w ≤ z ≤ w (DirectX: 0 ≤ z ≤ w), here computed exactly.
    const std::array<int, 7> sign =
        exact_volume_signs(Vec4<Exact>(clip(0), clip(1), clip(2), clip(3)), g.api);
    const int w_sign = sign[0];
    if (steps && w_sign > 0) {
      // How far the point is from the eye's plane, relative to the terms of w.
      Eigen::Vector4d row, ph;
      for (int j = 0; j < 4; ++j) row(j) = to_double(m(3, j));
      ph << to_double(p(0)), to_double(p(1)), to_double(p(2)), 1.0;
      warn_condition(steps, w_condition(row, ph), say(kPointCloseToEyePlane),
                     kWcAndNdcIllConditioned);
      const double n = to_double(g.projection.volume.near), f = to_double(g.projection.volume.far);
      if (g.projection.type != ProjectionSpec::Type::Ortho && f / n >= kDepthRatioNote)
        steps->note(say(kDepthPrecision),
                    say(kFarNearDepthBuffer, fmt::format("{:.0e}", f / n),
                        format_approx(float_depth_resolution(n, f, to_double(w)))));
    }
    // Inside the view volume: w > 0 and every plane test ≥ 0.
    const bool inside = inside_volume(sign);
    if (w_sign <= 0) {
      out.set("ndc", Value::null());
      out.set("window", Value::null());
      if (steps)
        steps->warn(w_sign == 0 ? say(kPointInEyePlane) : say(kPointBehindEye),
                    w_sign == 0 ? say(kWcZeroCannotDivide) : say(kWcNegativeCannotDivide));
    } else {
      const Vec3<Exact> ndc(canonical(clip(0) / w), canonical(clip(1) / w), canonical(clip(2) / w));
      out.set("ndc", Value::vector(ndc));
      const Vec3<Exact> win = viewport(ndc, g.width, g.height, g.api);
      const Vec3<Exact> window(canonical(win(0)), canonical(win(1)), canonical(win(2)));
      out.set("window", Value::vector(window));
      if (steps) {
        steps
            ->add(say(kPerspectiveDivide), tex("\\text{ndc} = \\frac{(x_c, y_c, z_c)}{w_c}"), {},
                  tex("\\text{ndc} = ") + vec(ndc, true))
            .yields("ndc");
        viewport_step(steps, g.api, g.width, g.height, window);
      }
    }
    out.set("inside", Value::boolean(inside));
    if (steps)
      steps
          ->add(say(kInsideViewVolume),
                g.api == Api::DirectX
                    ? tex("-w_c \\le x_c, y_c \\le w_c,\\; 0 \\le z_c \\le w_c,\\; w_c > 0")
                    : tex("-w_c \\le x_c, y_c, z_c \\le w_c,\\; w_c > 0"),
                {}, word(inside ? say(kYesPointVisible) : say(kNoClippingRemovesIt)))
          .yields("inside");
    return out;
  }
  // Default generator: perspective (fovy 45°/60°/90°, aspect of the viewport) or a symmetric
  // frustum, and a point in front of the eye between near and far (hard: between the eye and
  // the near plane), in view coordinates or, one time in three, in world coordinates seen by
  // camera {eye: (0, 0, k), center: 0, up: y}, half of those in an object's coordinates with a
  // model matrix (rotate_y by a right angle, then translate); nice: fovy 90°.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const auto [w, h] = rng.pick(std::vector<std::pair<std::int64_t, std::int64_t>>{
        {200, 200}, {400, 300}, {640, 480}, {800, 600}});
    const std::int64_t near = rng.integer(1, 3);
    const std::int64_t far = near + rng.integer(20, 100);
    YAML::Node g, p, vp;
    const bool frustum = !o.nice && rng.chance(1, 4);
    if (frustum) {
      const std::int64_t half = rng.integer(1, 2);
      p["left"] = gen_number(-half);
      p["right"] = gen_number(half);
      p["bottom"] = gen_number(-half);
      p["top"] = gen_number(half);
    } else {
      p["fovy"] =
          gen_angle(o.nice ? 90 : rng.pick(std::vector<std::int64_t>{45, 60, 90}), o.conventions);
      p["aspect"] = gen_fraction(w, h);
    }
    p["near"] = gen_number(near);
    p["far"] = gen_number(far);
    const Exact depth = o.hard ? Exact(GiNaC::numeric(near, rng.integer(2, 10)))
                               : Exact(rng.integer(near + 1, far - 1));
    const Exact x = depth * GiNaC::numeric(rng.integer(-2, 2), 4),
                y = depth * GiNaC::numeric(rng.integer(-2, 2), 4);
    const int toward =
        o.conventions.api == Api::DirectX || left_handed_columns(o.conventions) ? 1 : -1;
    if (!o.hard && rng.chance(1, 3)) {
      const std::int64_t k = rng.integer(2, 10);
      YAML::Node cam;
      cam["eye"] = gen_list({0, 0, k});
      cam["center"] = gen_list({0, 0, 0});
      cam["up"] = gen_list({0, 1, 0});
      const std::vector<Exact> world{x, y, Exact(k) - depth};
      if (rng.chance(1, 2)) {
        // Seed 004's chain: the point in its object's coordinates, placed by M = T·R_y(θ), so
        // v = R_y(θ)ᵀ·(world − t) lands where the camera sees it.
        const std::int64_t angle = rng.pick(std::vector<std::int64_t>{90, 180, -90});
        const std::vector<Exact> t{Exact(rng.integer(-3, 3)), Exact(0), Exact(rng.integer(-3, 3))};
        const MatX<Exact> r = rotate_axis_index(1, Exact(GiNaC::numeric(angle, 180) * GiNaC::Pi));
        std::vector<Exact> v(3);
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) v[i] += r(j, i) * (world[j] - t[j]);
        for (Exact& e : v) e = canonical(e);
        YAML::Node rotate, translate;
        rotate["rotate_y"] = gen_angle(angle, o.conventions);
        translate["translate"] = gen_list(t);
        YAML::Node model(YAML::NodeType::Sequence);
        model.push_back(rotate);
        model.push_back(translate);
        g["point"] = gen_list(v);
        g["model"] = model;
      } else {
        g["point"] = gen_list(world);
      }
      g["camera"] = cam;
    } else {
      g["point"] = gen_list(std::vector<Exact>{x, y, toward * depth});
    }
    g[frustum ? "frustum" : "perspective"] = p;
    vp["width"] = gen_number(w);
    vp["height"] = gen_number(h);
    g["viewport"] = vp;
    return g;
  }

  static std::string ill_conditioned(const Given&, const Answers& a) {
    const Value* clip = a.find("clip");
    return clip && clip->numbers.size() == 4 && clip->numbers[3] <= 0
               ? "the point is behind the eye"
               : "";
  }
};

// The accuracy bench's draw (KindInfo::accuracy_given).
std::optional<std::string> accuracy_given(Rng& rng) {
  using namespace accuracy;
  const std::string projection = fmt::format(
      "perspective: {{fovy: {}, aspect: {}, near: {}, far: {}}}, viewport: {{width: 640, "
      "height: 480}}",
      rng.integer(30, 90), rng.chance(1, 2) ? "1" : "\"4/3\"", decimal(rng, 1, 2),
      rng.integer(50, 200));
  if (rng.chance(1, 3)) {
    const Point3 eye = {decimal(rng, -5, 5), decimal(rng, -5, 5), decimal(rng, 10, 20)};
    return "{point: " + point(rng, -3, 3).yaml() + ", camera: {eye: " + eye.yaml() +
           ", center: [0, 0, 0], up: [0, 1, 0]}, " + projection + "}";
  }
  const Point3 p = {decimal(rng, -5, 5), decimal(rng, -5, 5), decimal(rng, -40, -3)};
  return "{point: " + p.yaml() + ", " + projection + "}";
}

}  // namespace

KindInfo project_point_kind() {
  KindInfo k = make_kind<ProjectPoint>();
  k.order = 90;
  k.doc_given =
      "`point` (view, or world with `camera` {eye, center, up}, or the object's own with `model`: "
      "transform steps, first applied first, M = M_parent·M_object), a projection, `viewport` "
      "{`width`, `height`}";
  k.doc_answers = "`clip`, `ndc`, `window`, `inside`";
  k.accuracy_given = accuracy_given;
  return k;
}

}  // namespace frustum
