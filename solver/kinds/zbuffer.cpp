// The Z-buffer algorithm on a small grid (seed 001, p.133, the ①②③ walk-through): the
// polygons (window coordinates x, y and depth z) are drawn in the listed order; Z(i, j) starts
// at +∞ and F(i, j) at "."; a covered pixel takes the polygon's label when its z is smaller
// than Z(i, j) (seed 001: "ポリゴンのZ値が Z(i,j) より小さいならば"). Convex polygons are split
// into a fan of triangles from their first vertex; coverage follows the top-left rule with
// pixel centres at (i + ½, j + ½), y up. Grids are reported top row (j = h − 1) first, as
// drawn on paper; +∞ is written 1e30 in numbers and "inf" in the derivation, and a student may
// write it inf, ∞ or infinity (or 1e30).
#include "solver/raster/zbuffer.hpp"

#include <fmt/format.h>

#include <cctype>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/raster/filtered_depth.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kFrame{"frame", "フレーム", "кадр"};
constexpr Phrase kSteps{"steps", "手順", "шаги"};

constexpr Phrase kPixelsOrientationDepthTest{"Pixels, orientation and the depth test",
                                             "画素, 向きと奥行きテスト",
                                             "Пиксели, ориентация и тест глубины"};
constexpr Phrase kPixelCentreWindowYUp{
    "Pixel (i, j) has its centre at (i + ½, j + ½), window y up; grids are written top row first.",
    "画素 (i, j) の中心は (i + ½, j + ½), ウィンドウの y は上向き. 格子は上の行から書く.",
    "Центр пикселя (i, j) — в (i + ½, j + ½), ось y окна вверх; сетки записаны с верхней строки."};
constexpr Phrase kCoverageFan{
    "Coverage uses the top-left fill rule; convex polygons are split into a fan of triangles from "
    "their first vertex; z is interpolated linearly in x and y (the plane through the vertices).",
    "被覆は左上規則による. 凸多角形は最初の頂点から扇形に三角形分割する. z は x と y "
    "について線形に補間する (頂点を通る平面).",
    "Покрытие — по правилу «верх-лево»; выпуклые многоугольники разбиваются веером треугольников "
    "от первой вершины; z интерполируется линейно по x и y (плоскость через вершины)."};
constexpr Phrase kOverwrittenWhenSmaller{
    "A pixel is overwritten when the polygon's z is smaller than Z(i, j); equal z keeps the "
    "earlier polygon.",
    "多角形の z が Z(i, j) より小さいとき画素を上書きする. z が等しいときは先の多角形のまま.",
    "Пиксель перезаписывается, если z многоугольника меньше Z(i, j); при равных z остаётся "
    "прежний многоугольник."};
constexpr Phrase kInitialise{"Initialise", "初期化", "Инициализация"};
constexpr Phrase kGridsNotWritten{"(grids larger than 32 × 32 are not written out)",
                                  "(32 × 32 より大きい格子は書き出さない)",
                                  "(сетки больше 32 × 32 не выписываются)"};
constexpr Phrase kFrameColon{"frame:", "フレーム:", "кадр:"};
constexpr Phrase kDepthColon{"depth:", "奥行き:", "глубина:"};
constexpr Phrase kPolygonLabel{"Polygon {0} (label {1})", "多角形 {0} (ラベル {1})",
                               "Многоугольник {0} (метка {1})"};
constexpr Phrase kDegeneratePolygon{"Degenerate polygon {0}", "退化した多角形 {0}",
                                    "Вырожденный многоугольник {0}"};
constexpr Phrase kFanTrianglesZeroArea{
    "{0} of its fan triangles have zero area in x, y and cover no pixels.",
    "扇形分割の三角形のうち {0} 個は x, y での面積が 0 で, どの画素も覆わない.",
    "Треугольников веера с нулевой площадью в x, y (они не покрывают пикселей): {0}."};
constexpr Phrase kFinalFrameBuffer{"Final frame buffer", "最終のフレームバッファ",
                                   "Итоговый буфер кадра"};
constexpr Phrase kRowsTopFirst{"Rows top first, joined by “/”.",
                               "行は上から順に “/” でつないで書く.",
                               "Строки сверху вниз, через «/»."};

struct ZBuffer {
  static constexpr const char* kName = "zbuffer";
  static constexpr Phrase kSummary{
      "frame and depth buffers of the Z-buffer algorithm on a small grid",
      "小さな格子上の Zバッファ法のフレームバッファと奥行きバッファ",
      "буфер кадра и буфер глубины алгоритма z-буфера на малой сетке"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr int kMaxSize = 256;       // the largest grid: 256 × 256 pixels
  static constexpr int kMaxShownSize = 32;   // larger grids are not written into the derivation
  static constexpr double kInfinity = 1e30;  // +∞ in the numbers of `depth`
  static constexpr std::size_t kMaxPolygons = 1000;
  // Every polygon tests every pixel with exact depths, so the work is width × height ×
  // polygons; this bound keeps one problem to about a second (256 × 256 with one polygon,
  // 64 × 64 with 16).
  static constexpr double kMaxPixelTests = 65536;
  struct Polygon {
    std::string label;
    Polygon3<Exact> points;
  };
  struct Given {
    int width = 0, height = 0;
    std::vector<Polygon> polygons;
  };
  static std::vector<std::string> given_fields() { return {"size", "polygons"}; }
  // Grading scales (docs/grading.md §2): every depth is judged at the size of the polygons'
  // depths, so an empty pixel's far value (10³⁰) in the same row lends nothing to the others.
  static AnswerScales scales(const Given& g, const Answers& key) {
    double z = 0;
    for (const auto& poly : g.polygons)
      for (const auto& v : poly.points) z = std::max(z, std::abs(to_double(v(2))));
    const Value* depth = key.find("depth");
    if (!depth) return {};
    AnswerScale s;
    for (const double d : depth->numbers) s.magnitude.push_back(std::abs(d) > z ? std::abs(d) : z);
    return {{"depth", s}};
  }

  static std::vector<AnswerSpec> answers() {
    return {{.name = "frame", .kind = AnswerKind::Sequence, .label = say(kFrame)},
            {.name = "depth",
             .kind = AnswerKind::Matrix,
             .infinity = kInfinity,
             .label = say(words::kDepth)},
            {.name = "steps", .kind = AnswerKind::Sequence, .label = say(kSteps)}};
  }

  static int read_dimension(GivenReader& r, const Exact& e, const std::string& name) {
    if (!GiNaC::is_a<GiNaC::numeric>(e) || !GiNaC::ex_to<GiNaC::numeric>(e).is_integer() ||
        exact_sign(e) <= 0)
      r.fail("size", "the " + name + " must be a positive integer");
    if (exact_sign(e - kMaxSize) > 0)
      r.fail("size", "the grid may be at most " + std::to_string(kMaxSize) + " × " +
                         std::to_string(kMaxSize) + " pixels (the zbuffer kind's limit); got " +
                         name + " " + exact(e).unicode);
    return GiNaC::ex_to<GiNaC::numeric>(e).to_int();
  }

  // One UTF-8 code point ("1", "A", "①"), not the background ".".
  static bool one_character(const std::string& s) {
    if (s.empty()) return false;
    const unsigned char c = static_cast<unsigned char>(s[0]);
    const std::size_t len = c < 0x80         ? 1
                            : (c >> 5) == 6  ? 2
                            : (c >> 4) == 14 ? 3
                            : (c >> 3) == 30 ? 4
                                             : 0;
    return len == s.size() && !(len == 1 && std::isspace(c));
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const std::vector<Exact> size = r.numbers("size", 2);
    g.width = read_dimension(r, size[0], "width");
    g.height = read_dimension(r, size[1], "height");
    const std::size_t n = r.list_size("polygons", 1);
    if (n > kMaxPolygons)
      r.fail("polygons", "at most " + std::to_string(kMaxPolygons) + " polygons");
    if (static_cast<double>(g.width) * g.height * static_cast<double>(n) > kMaxPixelTests)
      r.fail("polygons", fmt::format("{} × {} pixels × {} polygons is more than the zbuffer kind's "
                                     "limit of {} pixel tests (256 × 256 with one polygon, 64 × 64 "
                                     "with 16)",
                                     g.width, g.height, n, kMaxPixelTests));
    for (std::size_t i = 0; i < n; ++i) {
      GivenReader it = r.item("polygons", i, {"label", "points"});
      Polygon p;
      const YAML::Node& node = it.node();
      const YAML::Node label = node["label"];
      if (!label.IsDefined() || label.IsNull()) it.fail("label", "missing required field");
      if (!label.IsScalar()) it.fail("label", "expected one character such as \"1\"");
      p.label = label.Scalar();
      if (!one_character(p.label) || p.label == kBackground)
        it.fail("label", "a label is one character other than \".\" (the background), got '" +
                             p.label + "'");
      p.points = it.points("points", 3);
      it.finish();
      g.polygons.push_back(std::move(p));
    }
    return g;
  }

  static std::string depth_text(const std::optional<Exact>& z) {
    return z ? exact(*z).unicode : "inf";
  }

  // The frame and depth grids as text, top row first, columns aligned.
  static Said grids(const FrameBuffer& frame, const DepthBuffer<Exact>& depth) {
    std::size_t wide = 1;
    for (const auto& z : depth.data) wide = std::max(wide, depth_text(z).size());
    // Continuation lines are indented to line up under the note in the text renderer.
    std::string rows;
    for (const std::string& row : frame_rows(frame)) rows += "\n        " + row;
    Said s = say(kFrameColon);
    s.append(Said::verbatim(rows + "\n      "));
    s.append(say(kDepthColon));
    rows.clear();
    for (int j = depth.height - 1; j >= 0; --j) {
      rows += "\n       ";
      for (int i = 0; i < depth.width; ++i) {
        const std::string cell = depth_text(depth.at(i, j));
        rows += " " + std::string(wide - cell.size(), ' ') + cell;
      }
    }
    return s.append(Said::verbatim(rows));
  }

  static std::string joined(const std::vector<std::string>& rows) {
    std::string s;
    for (const std::string& r : rows) s += (s.empty() ? "" : "/") + r;
    return s;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    FrameBuffer frame(g.width, g.height, kBackground);
    FilteredDepthBuffer filtered(g.width, g.height);
    const DepthBuffer<Exact>& depth = filtered.exact;
    const bool show = g.width <= kMaxShownSize && g.height <= kMaxShownSize;
    if (steps) {
      steps->note(say(kPixelsOrientationDepthTest),
                  say(kPixelCentreWindowYUp) + say(kCoverageFan) + say(kOverwrittenWhenSmaller));
      steps->add(say(kInitialise), {}, {}, tex("F(i, j) = \\text{“.”},\\; Z(i, j) = \\infty"))
          .note = show ? grids(frame, depth) : say(kGridsNotWritten);
    }
    std::vector<std::string> after;
    for (std::size_t k = 0; k < g.polygons.size(); ++k) {
      const Polygon& p = g.polygons[k];
      DrawCount total;
      int degenerate = 0;
      for (std::size_t v = 1; v + 1 < p.points.size(); ++v) {
        const std::array<const Vec3<Exact>*, 3> tri{&p.points[0], &p.points[v], &p.points[v + 1]};
        std::array<Vec2<Exact>, 3> xy;  // snapped exactly by setup_triangle_exact
        std::array<Exact, 3> z;
        for (int c = 0; c < 3; ++c) {
          xy[c] = Vec2<Exact>((*tri[c])(0), (*tri[c])(1));
          z[c] = (*tri[c])(2);
        }
        TriangleSetup t;
        try {
          t = setup_triangle_exact(xy);
        } catch (const DomainError& e) {
          throw DomainError("polygons[" + std::to_string(k) + "].points", e.what());
        }
        if (t.degenerate) ++degenerate;
        const DrawCount n = draw_triangle_filtered(t, z, p.label, filtered, frame);
        total.covered += n.covered;
        total.written += n.written;
      }
      // Only the cells this polygon wrote hold new values (the others are canonical already).
      for (const std::size_t cell : filtered.written)
        filtered.exact.data[cell] = canonical(*filtered.exact.data[cell]);
      filtered.written.clear();
      after.push_back(joined(frame_rows(frame)));
      if (steps) {
        Step& s = steps->add(say(kPolygonLabel, k + 1, p.label), {}, {},
                             counts({{total.covered, "pixel(s) covered"},
                                     {total.written, "nearer than Z(i, j) and written"}}));
        s.note = show ? grids(frame, depth) : Said();
        if (degenerate > 0)
          steps->warn(say(kDegeneratePolygon, k + 1), say(kFanTrianglesZeroArea, degenerate));
      }
    }
    Answers out;
    out.set("frame", Value::word_list(frame_rows(frame)));
    Value d;
    d.shape = Value::Shape::Matrix;
    d.rows = g.height;
    d.cols = g.width;
    for (int j = g.height - 1; j >= 0; --j)
      for (int i = 0; i < g.width; ++i) {
        const std::optional<Exact>& z = depth.at(i, j);
        d.exact.push_back(z ? *z : Exact(GiNaC::pow(GiNaC::numeric(10), 30)));
        d.numbers.push_back(z ? to_double(*z) : kInfinity);
      }
    out.set("depth", d);
    out.set("steps", Value::word_list(after));
    if (steps)
      steps->add(say(kFinalFrameBuffer), {}, {}, word(Said::verbatim(joined(frame_rows(frame)))))
          .yields("frame")
          .yields("depth")
          .yields("steps")
          .note = say(kRowsTopFirst);
    return out;
  }
  // Default generator: a 3–6 × 3–5 grid and two or three labelled rectangles ("1", "2", "3")
  // at integer depths 1…9, now and then sloped in x (nice: flat; hard: all at one depth, so the
  // strict "smaller than" test and the draw order decide).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::int64_t w = rng.integer(3, 6), h = rng.integer(3, 5);
    const std::int64_t shared = rng.integer(2, 8);
    YAML::Node polygons(YAML::NodeType::Sequence);
    const auto count = rng.integer(2, 3);
    for (std::int64_t i = 0; i < count; ++i) {
      const std::int64_t x0 = rng.integer(0, w - 2), x1 = rng.integer(x0 + 1, w);
      const std::int64_t y0 = rng.integer(0, h - 2), y1 = rng.integer(y0 + 1, h);
      const std::int64_t z = o.hard ? shared : rng.integer(2, 8);
      const std::int64_t slope = o.nice || o.hard || rng.chance(1, 2) ? 0 : rng.nonzero(-1, 1);
      YAML::Node p;
      p["label"] = gen_word(std::to_string(i + 1));
      p["points"] = gen_rows({{x0, y0, z}, {x1, y0, z + slope}, {x1, y1, z + slope}, {x0, y1, z}});
      p.SetStyle(YAML::EmitterStyle::Flow);
      polygons.push_back(p);
    }
    YAML::Node g;
    g["size"] = gen_list({w, h});
    g["polygons"] = polygons;
    return g;
  }
};

}  // namespace

KindInfo zbuffer_kind() {
  KindInfo k = make_kind<ZBuffer>();
  k.order = 160;
  k.doc_given = "`size` [w, h] (at most 256 × 256), `polygons` (each with `label`)";
  k.doc_answers = "`frame`, `depth`, `steps`";
  return k;
}

}  // namespace frustum
