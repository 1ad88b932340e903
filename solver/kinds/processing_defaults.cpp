// Processing's default camera and perspective for a sketch of width × height pixels: camera()
// and perspective() with no arguments. The camera sits at cameraZ = (height/2)/tan(30°) in
// front of the sketch's centre, looking at it with y as up; the perspective has fovy = 60°,
// aspect = width/height, near = cameraZ/10 and far = 10·cameraZ. The matrices are written in
// the set's conventions (the same camera and frustum in OpenGL's or DirectX's form).
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/viewing_parts.hpp"

namespace frustum {

namespace {

constexpr Phrase kDefaultCamera{"Processing's default camera", "Processing の既定のカメラ",
                                "Камера Processing по умолчанию"};
constexpr Phrase kDefaultFieldOfView{"Processing's default field of view",
                                     "Processing の既定の視野角",
                                     "Угол обзора Processing по умолчанию"};
constexpr Phrase kDefaultClippingPlanes{"Processing's default near and far planes",
                                        "Processing の既定の前方・後方クリップ面",
                                        "Ближняя и дальняя плоскости Processing по умолчанию"};
// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kViewMatrix{"view", "ビュー変換行列", "матрица вида"};
constexpr Phrase kProjectionMatrix{"projection", "投影行列", "матрица проекции"};
constexpr Phrase kFullAngleInTangent{"tan(fovy) for tan(fovy/2)", "tan(fovy/2) を tan(fovy) に",
                                     "tan(fovy) вместо tan(fovy/2)"};
constexpr Phrase kFullAngleInTangentFeedback{
    "The camera's distance uses half the field of view: half the sketch's height, height/2, is "
    "seen under fovy/2 = 30°, so cameraZ = (height/2)/tan(30°), not (height/2)/tan(60°).",
    "カメラの距離には視野角の半分を使います. スケッチの高さの半分 height/2 が fovy/2 = 30° "
    "に見えるので, cameraZ = (height/2)/tan(30°) で, (height/2)/tan(60°) ではありません.",
    "Расстояние камеры считается по половине угла обзора: половина высоты скетча, height/2, видна "
    "под углом fovy/2 = 30°, поэтому cameraZ = (height/2)/tan(30°), а не (height/2)/tan(60°)."};

struct ProcessingDefaults {
  static constexpr const char* kName = "processing_defaults";
  static constexpr Phrase kSummary{
      "Processing's default camera and perspective for a sketch of width × height pixels",
      "幅 × 高さ ピクセルのスケッチでの Processing の既定のカメラと透視投影",
      "камера и перспектива Processing по умолчанию для скетча ширины × высоты пикселей"};
  static constexpr ConventionUse kUses{.api = true, .angles = true};
  struct Given {
    Exact width, height;
    Api api;
    AngleUnit angles;
    bool left_handed = false;
    bool full_angle = false;  // the named mistake: tan(fovy) where tan(fovy/2) belongs
  };
  static std::vector<std::string> given_fields() { return {"width", "height"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "camera_z", .kind = AnswerKind::Scalar, .symbols = {"cameraZ", "z_cam"}},
            {.name = "eye", .kind = AnswerKind::Vector, .depends_on = {"camera_z"}},
            {.name = "view",
             .kind = AnswerKind::Transform,
             .depends_on = {"eye"},
             .label = say(kViewMatrix)},
            {.name = "fovy", .kind = AnswerKind::Angle},
            {.name = "near", .kind = AnswerKind::Scalar, .depends_on = {"camera_z"}},
            {.name = "far", .kind = AnswerKind::Scalar, .depends_on = {"camera_z"}},
            {.name = "projection",
             .kind = AnswerKind::Transform,
             .depends_on = {"fovy", "near", "far"},
             .label = say(kProjectionMatrix)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.number("width"), r.number("height"), c.api, c.angles, left_handed_columns(c)};
    if (exact_sign(g.width) <= 0) r.fail("width", "must be positive: the sketch's width in pixels");
    if (exact_sign(g.height) <= 0)
      r.fail("height", "must be positive: the sketch's height in pixels");
    return g;
  }

  // cameraZ = (height/2)/tan(fovy/2) with fovy = π/3 (the named mistake: tan(fovy)).
  static Exact camera_z(const Given& g) {
    return g.full_angle ? canonical(g.height / 2 / GiNaC::tan(GiNaC::Pi / 3))
                        : processing_camera_z(g.height);
  }
  static Vec3<Exact> eye_at(const Given& g, const Exact& z) {
    return {canonical(g.width / 2), canonical(g.height / 2), z};
  }
  static MatX<Exact> view_of(const Given& g, const Vec3<Exact>& eye, Derivation* steps) {
    const Vec3<Exact> center(canonical(g.width / 2), canonical(g.height / 2), Exact(0));
    return look_at_with_steps(eye, center, Vec3<Exact>(0, 1, 0), g.api, "", steps, g.left_handed);
  }
  static MatX<Exact> projection_of(const Given& g, const Exact& fovy, const Exact& near,
                                   const Exact& far, Derivation* steps) {
    ProjectionSpec p = perspective_projection(fovy, canonical(g.width / g.height), near, far);
    p.unit = g.angles;
    p.left_handed = g.left_handed;
    return projection_with_steps(p, g.api, steps, "P");
  }

  static Answers solve(const Given& g, Derivation* steps) {
    Answers out;
    const Exact z = camera_z(g);
    const Vec3<Exact> eye = eye_at(g, z);
    out.set("camera_z", Value::scalar(z));
    out.set("eye", Value::vector(eye));
    if (steps)
      steps
          ->add(say(kDefaultCamera),
                tex("\\text{cameraZ} = \\frac{\\text{height}/2}{\\tan(30^\\circ)},\\; "
                    "\\mathbf{eye} = (\\tfrac{\\text{width}}{2}, \\tfrac{\\text{height}}{2}, "
                    "\\text{cameraZ}),\\; \\mathbf{center} = (\\tfrac{\\text{width}}{2}, "
                    "\\tfrac{\\text{height}}{2}, 0),\\; \\mathbf{up} = (0, 1, 0)"),
                tex("\\text{width} = ") + exact(g.width) + tex(",\\; \\text{height} = ") +
                    exact(g.height),
                tex("\\text{cameraZ} = ") + exact(z, true) + tex(",\\; \\mathbf{eye} = ") +
                    vec(eye, true))
          .yields("camera_z")
          .yields("eye");
    out.set("view", matrix_value(paper_form(view_of(g, eye, steps), g.api)));
    if (steps) steps->yields("view");
    const Exact fovy = canonical(GiNaC::Pi / 3);
    out.set("fovy", Value::scalar(g.angles == AngleUnit::Degrees ? Exact(60) : fovy));
    if (steps)
      steps
          ->add(say(kDefaultFieldOfView), tex("\\text{fovy} = \\frac{\\pi}{3}"), {},
                tex("\\text{fovy} = ") + angle_text(fovy, g.angles))
          .yields("fovy");
    const Exact near = canonical(z / 10), far = canonical(z * 10);
    out.set("near", Value::scalar(near));
    out.set("far", Value::scalar(far));
    if (steps)
      steps
          ->add(say(kDefaultClippingPlanes),
                tex("\\text{near} = \\frac{\\text{cameraZ}}{10},\\; \\text{far} = "
                    "10\\,\\text{cameraZ}"),
                {},
                tex("\\text{near} = ") + exact(near, true) + tex(",\\; \\text{far} = ") +
                    exact(far, true))
          .yields("near")
          .yields("far");
    out.set("projection",
            matrix_value(paper_form(projection_of(g, fovy, near, far, steps), g.api)));
    if (steps) steps->yields("projection");
    return out;
  }

  // Error carried forward: the eye, near and far from the student's own cameraZ, the view
  // matrix from the student's own eye, the projection from the student's own fovy, near and far
  // (the key's where the student gave none).
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const Exact key_z = camera_z(g);
    Exact fovy = canonical(GiNaC::Pi / 3), near = canonical(key_z / 10),
          far = canonical(key_z * 10);
    bool own = false;
    if (const auto f = carried(student, "fovy", 1)) {
      fovy = g.angles == AngleUnit::Degrees ? canonical((*f)[0] * GiNaC::Pi / 180) : (*f)[0];
      own = true;
    }
    if (const auto n = carried(student, "near", 1)) {
      near = (*n)[0];
      own = true;
    }
    if (const auto f = carried(student, "far", 1)) {
      far = (*f)[0];
      own = true;
    }
    if (own) {
      try {
        if (exact_sign(near) > 0 && exact_sign(canonical(far - near)) != 0 &&
            exact_sign(fovy) > 0 && exact_sign(canonical(fovy - GiNaC::Pi)) < 0)
          out.set("projection",
                  matrix_value(paper_form(projection_of(g, fovy, near, far, nullptr), g.api)));
      } catch (const std::exception&) {
        // A frustum with no volume: nothing carried.
      }
    }
    if (const auto z = carried(student, "camera_z", 1)) {
      out.set("eye", Value::vector(eye_at(g, (*z)[0])));
      out.set("near", Value::scalar(canonical((*z)[0] / 10)));
      out.set("far", Value::scalar(canonical((*z)[0] * 10)));
    }
    if (const auto e = carried(student, "eye", 3)) {
      try {
        out.set("view", matrix_value(paper_form(
                            view_of(g, Vec3<Exact>((*e)[0], (*e)[1], (*e)[2]), nullptr), g.api)));
      } catch (const std::exception&) {
        // An eye at the centre (cameraZ 0) has no view matrix: nothing carried.
      }
    }
    return out;
  }

  static std::vector<Misconception> misconceptions(const Given& g) {
    Given full = g;
    full.full_angle = true;
    return {{say(kFullAngleInTangent), say(kFullAngleInTangentFeedback), say(kDefaultCamera),
             solve(full, nullptr)}};
  }

  // Default generator: a sketch size in common use; nice: a square sketch.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::vector<std::pair<std::int64_t, std::int64_t>> sizes =
        o.nice ? std::vector<std::pair<std::int64_t, std::int64_t>>{{100, 100},
                                                                    {200, 200},
                                                                    {400, 400},
                                                                    {600, 600}}
               : std::vector<std::pair<std::int64_t, std::int64_t>>{
                     {100, 100}, {640, 360}, {640, 480}, {800, 600}, {400, 300}, {1280, 720}};
    const auto [w, h] = rng.pick(sizes);
    YAML::Node g;
    g["width"] = gen_number(w);
    g["height"] = gen_number(h);
    return g;
  }
};

}  // namespace

KindInfo processing_defaults_kind() {
  KindInfo k = make_kind<ProcessingDefaults>();
  k.order = 85;  // after projection_matrix (80), before project_point (90)
  k.doc_given = "`width`, `height` (the sketch's size in pixels)";
  k.doc_answers =
      "`camera_z`, `eye` (camera() with no arguments), `view`, `fovy`, `near`, `far`, "
      "`projection` (perspective() with no arguments)";
  return k;
}

}  // namespace frustum
