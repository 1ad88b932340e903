// seed 002 (Foley et al.'s normalized view volume): the eye looks down +z at a projection
// plane at distance d with half-extents a, b; clipping planes z_min, z_max. First
// S(d/(a·z_max), d/(b·z_max), 1/z_max) puts the back plane at z = 1 with x, y ∈ [−1, 1]; then
// P(z̃_min), z̃_min = z_min/z_max, maps z̃_min → 0 and 1 → 1 after the divide by W′ = z.
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kScaleMatrix{"scale_matrix", "拡大縮小行列", "матрица масштабирования"};
constexpr Phrase kPerspectiveMatrix{"perspective_matrix", "透視変換行列", "матрица перспективы"};
constexpr Phrase kPoint{"point", "点", "точка"};

constexpr Phrase kViewVolumeAndWhereItGoes{
    "The view volume and where it goes", "視体積とその行き先", "Видимый объём и куда он переходит"};
constexpr Phrase kEyeLooksDownPlusZVolume{
    "The eye looks down +z: the view volume runs from z = z_min to z = z_max, with half-widths a "
    "(in x) and b (in y) at distance d. S and P map it to 0 ≤ z ≤ 1 with near → 0 and far → 1, and "
    "x, y to [−1, 1] (OpenGL's NDC cube instead sends near to −1).",
    "視点は +z 方向を見る: 視体積は z = z_min から z = z_max まで, 距離 d での半幅は a (x 方向) と "
    "b (y 方向). S と P はこれを 0 ≤ z ≤ 1 (前方クリッピング面 → 0, 後方クリッピング面 → 1), x, y "
    "を [−1, 1] に写す (OpenGL の正規化視体積の立方体では前方は −1 に行く).",
    "Глаз смотрит вдоль +z: видимый объём простирается от z = z_min до z = z_max, с полуширинами a "
    "(по x) и b (по y) на расстоянии d. S и P переводят его в 0 ≤ z ≤ 1 (ближняя плоскость → 0, "
    "дальняя → 1), а x, y — в [−1, 1] (куб NDC в OpenGL переводит ближнюю плоскость в −1)."};
constexpr Phrase kNormalizeTheViewVolume{"① Normalize the view volume", "① 視体積の正規化",
                                         "① Нормализация видимого объёма"};
constexpr Phrase kBackPlaneMovesToZ1{
    "The back clipping plane moves to z = 1, where x and y span [−1, 1].",
    "後方クリッピング面は z = 1 に移り, そこで x と y は [−1, 1] に広がる.",
    "Дальняя плоскость отсечения переходит в z = 1, где x и y пробегают [−1, 1]."};
constexpr Phrase kPerspectiveOfNormalizedVolume{"② Perspective of the normalized volume",
                                                "② 正規化視体積の透視変換",
                                                "② Перспектива нормализованного объёма"};
constexpr Phrase kProjectiveNotAffine{
    "X′ and Y′ are unchanged and W′ = z: the matrix is projective, not affine.",
    "X′ と Y′ は変わらず W′ = z: この行列はアフィンではなく射影変換である.",
    "X′ и Y′ не меняются, а W′ = z: матрица проективная, не аффинная."};
constexpr Phrase kPointThroughBoth{"A point through both, then the divide by W′",
                                   "両方を通る点と W′ による除算",
                                   "Точка через оба преобразования, затем деление на W′"};

struct ViewVolume {
  static constexpr const char* kName = "view_volume";
  static constexpr Phrase kSummary{
      "the normalized perspective view volume of Foley et al.",
      "フォーリーらの正規化視体積 (透視投影)",
      "нормированный видимый объём перспективной проекции по Фоли и др."};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    Exact d, a, b, z_min, z_max;
    Vec3<Exact> point;
    Api api = Api::OpenGL;  // DirectX prints S and P in row-vector form (transposed)
  };
  static std::vector<std::string> given_fields() {
    return {"d", "a", "b", "z_min", "z_max", "point"};
  }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "scale_matrix", .kind = AnswerKind::Transform, .label = say(kScaleMatrix)},
            {.name = "perspective_matrix",
             .kind = AnswerKind::Transform,
             .label = say(kPerspectiveMatrix)},
            {.name = "point",
             .kind = AnswerKind::Vector,
             .depends_on = {"scale_matrix", "perspective_matrix"},
             .label = say(kPoint)}};
  }

  // Error carried forward: the point through the student's own matrices (P·S·p, then the divide
  // by W′), when both are written and the point does not go to infinity under them.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const auto s = carried(student, "scale_matrix", 16);
    const auto p = carried(student, "perspective_matrix", 16);
    if (!s || !p) return out;
    const auto column_form = [&](const std::vector<Exact>& m) {
      MatX<Exact> written(4, 4);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) written(i, j) = m[static_cast<std::size_t>(i * 4 + j)];
      return paper_form(written, g.api);
    };
    try {
      const std::vector<Exact> h =
          transform_point(MatX<Exact>(column_form(*p) * column_form(*s)),
                          std::vector<Exact>{g.point(0), g.point(1), g.point(2)});
      out.set("point",
              Value::vector(std::vector<Exact>{canonical(h[0]), canonical(h[1]), canonical(h[2])}));
    } catch (const std::exception&) {
      // W′ = 0 under the student's matrices: the point has no image to carry.
    }
    return out;
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g{r.number("d"), r.number("a"), r.number("b"), r.number("z_min"), r.number("z_max"), {},
            c.api};
    for (const char* k : {"d", "a", "b"})
      if (exact_sign(r.number(k)) <= 0) r.fail(k, "must be positive");
    if (exact_sign(g.z_min) <= 0)
      r.fail("z_min", "must be positive: the front clipping plane is in front of the eye");
    if (exact_sign(g.z_max - g.z_min) <= 0) r.fail("z_max", "must be greater than z_min");
    if (r.has("point"))
      g.point = r.vector<3>("point");
    else
      g.point = Vec3<Exact>(0, 0, g.z_max);
    return g;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const MatX<Exact> s = canonical(
        scale(std::vector<Exact>{g.d / (g.a * g.z_max), g.d / (g.b * g.z_max), 1 / g.z_max}));
    const Exact zt = canonical(g.z_min / g.z_max);
    MatX<Exact> p = MatX<Exact>::Identity(4, 4);
    p(2, 2) = canonical(1 / (1 - zt));
    p(2, 3) = canonical(-zt / (1 - zt));
    p(3, 2) = 1;
    p(3, 3) = 0;
    Answers out;
    // The volume's own coordinates, stated instead of an API's eye space: they differ from
    // OpenGL's (near → 0 here, −1 there), and a header saying otherwise would contradict step ②.
    if (steps) steps->note(say(kViewVolumeAndWhereItGoes), say(kEyeLooksDownPlusZVolume));
    out.set("scale_matrix", matrix_value(paper_form(s, g.api)));
    out.set("perspective_matrix", matrix_value(paper_form(p, g.api)));
    if (steps) {
      steps
          ->add(say(kNormalizeTheViewVolume),
                tex("S\\left(\\frac{d}{a\\,z_{\\max}}, \\frac{d}{b\\,z_{\\max}}, "
                    "\\frac{1}{z_{\\max}}\\right)"),
                {}, math("S = ") + matrix_text(paper_form(s, g.api)))
          .yields("scale_matrix")
          .note =
          say(kBackPlaneMovesToZ1) + (g.api == Api::DirectX ? multiply_note(g.api) : Said());
      steps
          ->add(say(kPerspectiveOfNormalizedVolume),
                g.api == Api::DirectX
                    ? tex("\\tilde{z}_{\\min} = \\frac{z_{\\min}}{z_{\\max}},\\; "
                          "P(\\tilde{z}_{\\min}) = \\begin{bmatrix} 1 & 0 & 0 & 0 \\\\ "
                          "0 & 1 & 0 & 0 \\\\ 0 & 0 & \\frac{1}{1 - \\tilde{z}_{\\min}} & 1 \\\\ "
                          "0 & 0 & -\\frac{\\tilde{z}_{\\min}}{1 - \\tilde{z}_{\\min}} & 0 "
                          "\\end{bmatrix}")
                    : tex("\\tilde{z}_{\\min} = \\frac{z_{\\min}}{z_{\\max}},\\; "
                          "P(\\tilde{z}_{\\min}) = \\begin{bmatrix} 1 & 0 & 0 & 0 \\\\ "
                          "0 & 1 & 0 & 0 \\\\ 0 & 0 & \\frac{1}{1 - \\tilde{z}_{\\min}} & "
                          "-\\frac{\\tilde{z}_{\\min}}{1 - \\tilde{z}_{\\min}} \\\\ "
                          "0 & 0 & 1 & 0 \\end{bmatrix}"),
                tex("\\tilde{z}_{\\min} = ") + exact(zt),
                math("P = ") + matrix_text(paper_form(p, g.api)))
          .yields("perspective_matrix")
          .note = say(kProjectiveNotAffine);
    }
    const std::vector<Exact> h =
        transform_point(MatX<Exact>(p * s), std::vector<Exact>{g.point(0), g.point(1), g.point(2)});
    const std::vector<Exact> q = {canonical(h[0]), canonical(h[1]), canonical(h[2])};
    out.set("point", Value::vector(q));
    if (steps)
      steps
          ->add(say(kPointThroughBoth),
                g.api == Api::DirectX
                    ? tex("(X', Y', Z', W') = \\mathbf{p}\\,S\\,P,\\; "
                          "\\mathbf{p}' = \\frac{(X', Y', Z')}{W'}")
                    : tex("(X', Y', Z', W')^{\\mathsf{T}} = P\\,S\\,\\mathbf{p},\\; "
                          "\\mathbf{p}' = \\frac{(X', Y', Z')}{W'}"),
                tex("\\mathbf{p} = ") + vec(g.point), tex("\\mathbf{p}' = ") + vec(q, true))
          .yields("point");
    return out;
  }
  // Default generator: d, a, b in 1…3, 1 ≤ z_min < z_max ≤ 105, and a point inside the view
  // volume (hard: on its corner edge z = z_max, x = a·z/d).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::int64_t d = rng.integer(1, 3), a = rng.integer(1, 3), b = rng.integer(1, 3);
    const std::int64_t z_min = rng.integer(1, 5), z_max = z_min + rng.integer(5, 100);
    const std::int64_t z = o.hard ? z_max : rng.integer(z_min, z_max);
    const Exact xmax = Exact(GiNaC::numeric(a * z, d)), ymax = Exact(GiNaC::numeric(b * z, d));
    YAML::Node g;
    g["d"] = gen_number(d);
    g["a"] = gen_number(a);
    g["b"] = gen_number(b);
    g["z_min"] = gen_number(z_min);
    g["z_max"] = gen_number(z_max);
    g["point"] =
        o.hard
            ? gen_list(std::vector<Exact>{xmax, ymax, Exact(z)})
            : gen_list(std::vector<Exact>{xmax * GiNaC::numeric(rng.integer(-4, 4), 4),
                                          ymax * GiNaC::numeric(rng.integer(-4, 4), 4), Exact(z)});
    return g;
  }

  static std::string ill_conditioned(const Given& g) {
    return exact_sign(g.point(2)) <= 0 ? "the point is behind the eye" : "";
  }
};

}  // namespace

KindInfo view_volume_kind() {
  KindInfo k = make_kind<ViewVolume>();
  k.order = 110;
  k.doc_given = "`d`, `a`, `b`, `z_min`, `z_max`, `point` (seed 002)";
  k.doc_answers = "`scale_matrix`, `perspective_matrix`, `point`";
  return k;
}

}  // namespace frustum
