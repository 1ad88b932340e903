// render: the colour and depth of a few queried pixels of a scene. Only what the
// question needs is modelled: every triangle goes through the geometry stages (cheap), but
// only triangles whose screen bounds hold a queried pixel centre are set up and tested, and
// no frame is allocated. The derivation is a z-buffer trace per pixel: the triangles that
// covered it, in drawing order, with their depths, and the winner.
#include "solver/kinds/render.hpp"

#include <fmt/format.h>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/raster/certified_trace.hpp"
#include "solver/raster/frame_work.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kColor{"color", "色", "цвет"};
constexpr Phrase kObject{"object", "物体", "объект"};

// The conventions and the geometry.
constexpr Phrase kConventionsAndModel{"Conventions and model", "規約とモデル",
                                      "Соглашения и модель"};
constexpr Phrase kPixelYDown{
    "Pixel (i, j) is counted in the y-down window (row 0 at the top) and has its centre at (i + ½, "
    "j + ½).",
    "画素 (i, j) は y が下向きのウィンドウで数え (0 行目が上), 中心は (i + ½, j + ½).",
    "Пиксель (i, j) отсчитывается в окне с осью y вниз (строка 0 сверху), его центр — в (i + ½, j "
    "+ ½)."};
constexpr Phrase kPixelYUp{
    "Pixel (i, j) is counted in the y-up window (row 0 at the bottom) and has its centre at (i + "
    "½, j + ½).",
    "画素 (i, j) は y が上向きのウィンドウで数え (0 行目が下), 中心は (i + ½, j + ½).",
    "Пиксель (i, j) отсчитывается в окне с осью y вверх (строка 0 снизу), его центр — в (i + ½, j "
    "+ ½)."};
constexpr Phrase kTrianglesClipped{
    "Triangles are clipped in homogeneous clip space, divided by w, mapped by the viewport, "
    "snapped to 1/256 pixel and covered under the top-left rule; depth is window z in [0, 1], "
    "interpolated as the plane through the snapped vertices (z/w is affine in screen space) and "
    "stored as a 32-bit float.",
    "三角形は同次クリップ空間でクリップし, w で割り, ビューポート変換で写し, 1/256 画素に丸め, "
    "左上規則で被覆を決める. 奥行きは [0, 1] のウィンドウ z で, 丸めた頂点を通る平面として補間し "
    "(z/w は画面空間でアフィン), 32 ビット float で格納する.",
    "Треугольники отсекаются в однородном пространстве отсечения, делятся на w, отображаются в "
    "область просмотра, привязываются к 1/256 пикселя и покрываются по правилу «верх-лево»; "
    "глубина — z окна в [0, 1], интерполируется как плоскость через привязанные вершины (z/w "
    "аффинно в экранном пространстве) и хранится как 32-битный float."};
constexpr Phrase kDepthBufferStarts{
    "The depth buffer starts at 1 (far) and a fragment is written when its depth is less than the "
    "stored one (equal keeps the earlier).",
    "奥行きバッファは 1 (遠方) で始まり, 断片は奥行きが格納値より小さいときに書き込まれる "
    "(等しければ先のまま).",
    "Буфер глубины начинается с 1 (далеко), фрагмент записывается, если его глубина меньше "
    "сохранённой (при равенстве остаётся прежний)."};
constexpr Phrase kEveryDecisionExact{
    "Every decision (clipping, facing, snapping, the depth test) is exact: taken on the computed "
    "values when their error bound proves it, else by exact arithmetic on the given numbers.",
    "判定 (クリッピング, 表裏, スナップ, 奥行き比較) はすべて厳密: "
    "計算値の誤差限界が判定を保証するときは計算値で, "
    "そうでなければ与えられた数での厳密な計算で決める.",
    "Каждое решение (отсечение, ориентация, привязка к сетке, тест глубины) точное: принимается по "
    "вычисленным значениям, когда их оценка погрешности его гарантирует, иначе точной арифметикой "
    "над заданными числами."};
constexpr Phrase kLighting{
    "Lighting as Processing's lights(): ambient {0} + directional {1} travelling along {2}, flat "
    "and two-sided.",
    "照明は Processing の lights() と同じ: 環境光 {0} + 方向 {2} に進む平行光 {1}, "
    "フラットシェーディング, 両面.",
    "Освещение как lights() в Processing: фоновое {0} + направленное {1} вдоль {2}, плоское, "
    "двустороннее."};
constexpr Phrase kNoLight{"No light: each triangle has its fill colour.",
                          "照明なし: 各三角形は塗りつぶし色のまま.",
                          "Без освещения: у каждого треугольника свой цвет заливки."};
constexpr Phrase kGeometry{"Geometry: model → world → clip → window",
                           "幾何: モデル → ワールド → クリップ → ウィンドウ",
                           "Геометрия: модель → мир → отсечение → окно"};
constexpr Phrase kObjects{"{0} objects.", "物体 {0} 個.", "Объектов: {0}."};
constexpr Phrase kOnlyQueriedPixels{
    "Only the queried pixels are resolved: a triangle competes for a pixel when its screen bounds "
    "hold the pixel centre; no {0} frame is allocated.",
    "問われた画素だけを求める: 画面上の範囲が画素中心を含む三角形がその画素を争う. {0} "
    "のフレームは確保しない.",
    "Вычисляются только запрошенные пиксели: треугольник претендует на пиксель, если его экранные "
    "границы содержат центр пикселя; кадр {0} не выделяется."};
constexpr Phrase kExactGeometry{
    "Exact arithmetic on the given numbers decided the clipping, facing or snapping of {0} "
    "triangle(s) that rounding could not settle.",
    "丸め誤差で決まらなかった三角形 {0} 個のクリッピング, 表裏またはスナップは, "
    "与えられた数での厳密な計算で決めた.",
    "Отсечение, ориентацию или привязку к сетке для треугольников ({0}), которые округление не "
    "позволяло определить, решила точная арифметика над заданными числами."};
// A pixel's z-buffer trace.
constexpr Phrase kPixelAt{"Pixel {0}", "画素 {0}", "Пиксель {0}"};
constexpr Phrase kCleared{"cleared", "初期化済み", "очищено"};
constexpr Phrase kColour{"colour", "色", "цвет"};
constexpr Phrase kTraceHeader{
    "Z-buffer trace, drawing order ({0} competitor(s)):", "Z バッファの経過, 描画順 (候補 {0} 個):",
    "Трассировка Z-буфера в порядке рисования (претендентов: {0}):"};
constexpr Phrase kTraceWritten{
    "{0}. triangle {1} ({2} face {3}, {4}): z = {5} → written, colour {6}",
    "{0}. 三角形 {1} (`{2}` の面 {3}, {4}): z = {5} → 書き込む, 色 {6}",
    "{0}. треугольник {1} (`{2}`, грань {3}, {4}): z = {5} → записан, цвет {6}"};
constexpr Phrase kTraceHidden{"{0}. triangle {1} ({2} face {3}, {4}): z = {5} → hidden",
                              "{0}. 三角形 {1} (`{2}` の面 {3}, {4}): z = {5} → 隠れる",
                              "{0}. треугольник {1} (`{2}`, грань {3}, {4}): z = {5} → скрыт"};
constexpr Phrase kMoreCompetitors{"… {0} more", "… 他 {0} 個", "… ещё {0}"};
constexpr Phrase kNoTriangleCovers{"No triangle covers this pixel centre.",
                                   "この画素中心を覆う三角形はない.",
                                   "Ни один треугольник не покрывает центр этого пикселя."};
constexpr Phrase kDepthTestExact{
    "The depth test was decided by exact arithmetic on the given numbers (the computed depths were "
    "within rounding of each other).",
    "奥行き比較は与えられた数での厳密な計算で決めた (計算した奥行きの差が丸め誤差の範囲内だった).",
    "Тест глубины решён точной арифметикой над заданными числами (вычисленные глубины совпадали в "
    "пределах округления)."};

struct Render {
  static constexpr const char* kName = "render";
  static constexpr Phrase kSummary{
      "colour and depth of queried pixels of a rendered scene (z-buffer trace)",
      "レンダリングしたシーンの指定した画素の色と奥行き (Zバッファ法の追跡)",
      "цвет и глубина заданных пикселей визуализированной сцены (трассировка z-буфера)"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr std::size_t kMaxPixels = 64;
  // World triangles of an exercise's scene (the paper plane has 5 293): each goes through the
  // geometry with exact decisions where rounding cannot settle them, and competes for every
  // queried pixel, so the work is triangles × pixels, not the frame's.
  static constexpr long kMaxTriangles = 100'000;
  static constexpr std::size_t kMaxTraceLines = 24;     // competitors listed per pixel
  static constexpr const char* kIndent = "\n        ";  // trace lines line up under the note
  using Given = RenderGiven;

  static std::vector<std::string> given_fields() { return {"scene", "pixels"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "pixels", .kind = AnswerKind::Matrix, .label = say(words::kPixels)},
            {.name = "color", .kind = AnswerKind::Matrix, .label = say(kColor)},
            {.name = "depth", .kind = AnswerKind::Vector, .label = say(words::kDepth)},
            {.name = "object", .kind = AnswerKind::Sequence, .label = say(kObject)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    g.conventions = c;
    GivenReader s = r.child("scene", scene_fields());
    g.spec = read_scene(s, c, /*keep_exact=*/true);
    if (g.spec.triangles > kMaxTriangles)
      s.fail("objects", fmt::format("{} triangles (repeats counted): a render problem may have at "
                                    "most {} (the limit is {} triangles; `frustum render` draws "
                                    "larger scenes)",
                                    g.spec.triangles, kMaxTriangles, kMaxTriangles));
    // The frame `frustum render` would draw of this scene is within its bound too.
    try {
      price_frame(g.spec.scene);
    } catch (const DomainError& e) {
      s.fail("objects", e.what());
    }
    const std::size_t n = r.list_size("pixels");
    if (n > kMaxPixels)
      r.fail("pixels", fmt::format("at most {} pixels may be queried", kMaxPixels));
    for (std::size_t k = 0; k < n; ++k) {
      const std::vector<Exact> p = r.numbers_at("pixels", k, 2);
      std::array<int, 2> px{};
      const int limits[2] = {g.spec.scene.width, g.spec.scene.height};
      for (int a = 0; a < 2; ++a) {
        const std::string field = fmt::format("pixels[{}][{}]", k, a);
        if (!GiNaC::is_a<GiNaC::numeric>(p[a]) ||
            !GiNaC::ex_to<GiNaC::numeric>(p[a]).is_integer() || exact_sign(p[a]) < 0 ||
            exact_sign(p[a] - limits[a]) >= 0)
          throw InputError(r.locate(
              field, fmt::format("expected a pixel index from 0 to {} (the viewport is {} × {})",
                                 limits[a] - 1, limits[0], limits[1])));
        px[static_cast<std::size_t>(a)] = GiNaC::ex_to<GiNaC::numeric>(p[a]).to_int();
      }
      g.pixels.push_back(px);
    }
    return g;
  }

  static std::string depth_text(float z) { return fmt::format("{:.7g}", z); }
  static std::string color_text(Rgb c) { return fmt::format("({}, {}, {})", c.r, c.g, c.b); }

  // Grading scales (docs/grading.md §2): colour channels of size 255, depths in [0, 1] of size 1
  // (a pixel's row [r, g, b, depth] must not lend the depth the colour's tolerance).
  static AnswerScales scales(const Given&, const Answers& key) {
    AnswerScales out;
    if (const Value* p = key.find("pixels"); p && p->cols == 4) {
      AnswerScale s;
      for (int r = 0; r < p->rows; ++r) s.magnitude.insert(s.magnitude.end(), {255, 255, 255, 1});
      out.emplace_back("pixels", s);
    }
    if (const Value* d = key.find("depth"))
      out.emplace_back("depth", uniform_scale(d->numbers.size(), 1));
    return out;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    // The rasterizer names its own `triangle`; this kind's given has a scene, not a triangle.
    try {
      return solve_scene(g, steps);
    } catch (const DomainError& e) {
      throw DomainError("scene.objects", std::string("a triangle of the scene: ") + e.what());
    }
  }

  static Answers solve_scene(const Given& g, Derivation* steps) {
    const Scene& scene = g.spec.scene;
    const Api api = scene.api;
    if (steps) {
      steps->note(
          say(kConventionsAndModel),
          say(window_y_down(api) ? kPixelYDown : kPixelYUp) + say(kTrianglesClipped) +
              say(kDepthBufferStarts) + say(kEveryDecisionExact) +
              (scene.light ? say(kLighting, fmt::format("{}", scene.light->ambient),
                                 fmt::format("{}", scene.light->diffuse),
                                 fmt::format("({:.4g}, {:.4g}, {:.4g})", scene.light->direction(0),
                                             scene.light->direction(1), scene.light->direction(2)))
                           : say(kNoLight)));
    }
    // The exact projection · camera, for the decisions the computed values cannot settle.
    const FlatScene flat = flatten(scene);
    CertifiedScene cs = certified_geometry(scene, flat, exact_clip_from_world(g.spec, api, steps));
    const GeometryStats& gs = cs.stats;
    if (steps) {
      Step& geometry = steps->add(say(kGeometry), {}, {},
                                  counts({{gs.triangles, "triangles"}}) + tex("\\colon ") +
                                      counts({{gs.outside, "outside the view volume"},
                                              {gs.clipped, "clipped"},
                                              {gs.culled, "back faces culled"}}) +
                                      tex(" \\to ") + counts({{gs.window, "window triangles"}}));
      geometry.note = say(kObjects, flat.objects.size()) +
                      say(kOnlyQueriedPixels, fmt::format("{} × {}", scene.width, scene.height));
      if (cs.exact_geometry > 0) geometry.note += say(kExactGeometry, cs.exact_geometry);
    }
    Value pixels, color_rows, depth;
    pixels.shape = Value::Shape::Matrix;
    pixels.cols = 4;
    std::vector<std::vector<Exact>> colors;
    std::vector<double> depths;
    std::vector<std::string> objects;
    for (const auto& q : g.pixels) {
      bool exact_depths = false;
      const PixelTrace t =
          certified_trace(cs, scene, flat, q[0], raster_row(q[1], scene.height, api), exact_depths);
      const std::string winner =
          t.winner < 0
              ? "background"
              : flat.objects[static_cast<std::size_t>(
                    flat.triangles[static_cast<std::size_t>(
                                       cs.pieces[static_cast<std::size_t>(t.winner)].source)]
                        .object)];
      pixels.numbers.insert(pixels.numbers.end(), {double(t.color.r), double(t.color.g),
                                                   double(t.color.b), double(t.depth)});
      ++pixels.rows;
      colors.push_back({Exact(t.color.r), Exact(t.color.g), Exact(t.color.b)});
      depths.push_back(t.depth);
      objects.push_back(winner);
      if (!steps) continue;
      // Each line of the trace under the note's first line.
      const Said indent = Said::verbatim(kIndent);
      Said trace = say(kTraceHeader, t.competitors.size());
      float stored = kDepthClear;
      for (std::size_t k = 0; k < t.competitors.size(); ++k) {
        const Competitor& c = t.competitors[k];
        if (k == kMaxTraceLines) {
          trace.append(indent).append(say(kMoreCompetitors, t.competitors.size() - k));
          break;
        }
        const CertifiedPiece& w = cs.pieces[static_cast<std::size_t>(c.triangle)];
        const WorldTriangle& src = flat.triangles[static_cast<std::size_t>(w.source)];
        const std::string z = fmt::format("{} {} Z = {}", depth_text(c.depth), c.passed ? "<" : "≥",
                                          depth_text(stored));
        const std::string& object = flat.objects[static_cast<std::size_t>(src.object)];
        const Phrase& side = w.front ? words::kFront : words::kBack;
        trace.append(indent).append(
            c.passed ? say(kTraceWritten, k + 1, w.source, object, src.face, side, z,
                           color_text(w.color))
                     : say(kTraceHidden, k + 1, w.source, object, src.face, side, z));
        if (c.passed) stored = c.depth;
      }
      if (t.competitors.empty()) trace.append(indent).append(say(kNoTriangleCovers));
      if (exact_depths) trace.append(indent).append(say(kDepthTestExact));
      // The winner is an object's name, as the scene gives it, or the background.
      const MathText winner_word =
          t.winner < 0 ? word(words::kBackground) : word(Said::verbatim(winner));
      Step& s = steps->add(say(kPixelAt, fmt::format("({}, {})", q[0], q[1])),
                           tex("Z = 1\\ (") + word(kCleared) + tex("),\\; F = ") +
                               word(words::kBackground) + tex("\\ " + color_text(scene.background)),
                           {},
                           word(kColour) + tex("\\ " + color_text(t.color) + ",\\; ") +
                               word(words::kDepth) + tex("\\ " + depth_text(t.depth) + "\\quad (") +
                               winner_word + math(")"));
      s.note = trace;
    }
    std::vector<MathText> shown;
    for (int r = 0; r < pixels.rows; ++r)
      for (int k = 0; k < 4; ++k)
        shown.push_back(math(k < 3 ? fmt::format("{}", pixels.numbers[4 * r + k])
                                   : fmt::format("{:.7g}", pixels.numbers[4 * r + k])));
    pixels.display = matrix_of(shown, 4);
    color_rows = Value::matrix(colors);
    depth = Value::vector(depths);
    Answers out;
    out.set("pixels", pixels);
    out.set("color", color_rows);
    out.set("depth", depth);
    out.set("object", Value::word_list(objects));
    if (steps)
      for (const char* a : {"pixels", "color", "depth", "object"}) steps->yields(a);
    return out;
  }
  // Default generator: a 64 × 48 view from (0, 0, 10) of one to three flat coloured
  // triangles at distinct depths (hard: all at one depth, so equal depths keep the earlier),
  // and three queried pixels.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node scene, projection, objects(YAML::NodeType::Sequence),
        pixels(YAML::NodeType::Sequence);
    scene["viewport"] = YAML::Load("{width: 64, height: 48}");
    scene["camera"] = YAML::Load("{eye: [0, 0, 10], center: [0, 0, 0], up: [0, 1, 0]}");
    projection["fovy"] = gen_angle(60, o.conventions);
    projection["aspect"] = gen_fraction(4, 3);
    projection["near"] = gen_number(1);
    projection["far"] = gen_number(100);
    scene["perspective"] = projection;
    const std::int64_t shared = -rng.integer(0, 3);
    const auto count = rng.integer(1, 3);
    for (std::int64_t i = 0; i < count; ++i) {
      const std::int64_t z = o.hard ? shared : 2 - 2 * i;
      std::vector<IVec3> t;
      for (int k = 0; k < 3; ++k) t.push_back({rng.integer(-5, 5), rng.integer(-4, 4), z});
      YAML::Node obj;
      obj["name"] = gen_word("t" + std::to_string(i + 1));
      obj["triangle"] = gen_points(t);
      obj["fill"] =
          gen_list({rng.integer(0, 5) * 51, rng.integer(0, 5) * 51, rng.integer(0, 5) * 51});
      objects.push_back(obj);
    }
    scene["objects"] = objects;
    for (int k = 0; k < 3; ++k)
      pixels.push_back(gen_list({rng.integer(0, 63), rng.integer(0, 47)}));
    pixels.SetStyle(YAML::EmitterStyle::Flow);
    YAML::Node g;
    g["scene"] = scene;
    g["pixels"] = pixels;
    return g;
  }
};

}  // namespace

KindInfo render_kind() {
  KindInfo k = make_kind<Render>();
  k.order = 190;
  k.doc_given = "`scene`, `pixels`";
  k.doc_answers = "`pixels` (colour and depth per queried pixel)";
  return k;
}

}  // namespace frustum
