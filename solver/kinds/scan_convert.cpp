// Scan conversion of one triangle in window coordinates: which pixel centres it covers under
// the top-left fill rule (rasterizer.hpp). Pixel (i, j) has its centre at (i + ½, j + ½),
// window y up; vertices are snapped to 1/256 pixel and the edge functions evaluated exactly.
// `pixels` lists [i, j] sorted by j, then i.
#include <map>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/raster/rasterizer.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr Phrase kPixelsAndFillRule{"Pixels and the fill rule", "画素と塗りつぶし規則",
                                    "Пиксели и правило заполнения"};
constexpr Phrase kWindowYUp{
    "Window y points up; pixel (i, j) has its centre at (i + ½, j + ½).",
    "ウィンドウの y は上向き. 画素 (i, j) の中心は (i + ½, j + ½).",
    "Ось y окна направлена вверх; центр пикселя (i, j) — в (i + ½, j + ½)."};
constexpr Phrase kVerticesSnapped{
    "Vertices are snapped to 1/256 pixel and the edge functions are evaluated exactly.",
    "頂点は 1/256 画素に丸め, エッジ関数は厳密に評価する.",
    "Вершины привязываются к 1/256 пикселя, функции рёбер вычисляются точно."};
constexpr Phrase kTopLeftRule{
    "Top-left rule: a centre exactly on an edge is covered only when the edge is a top edge "
    "(horizontal, interior below) or a left edge (interior to its right); on a bottom or right "
    "edge it is not.",
    "左上規則: ちょうど辺上にある中心が覆われるのは, その辺が上辺 (水平で内部が下) か左辺 "
    "(内部が右) のときだけで, 下辺や右辺では覆われない.",
    "Правило «верх-лево»: центр ровно на ребре покрыт, только если ребро верхнее (горизонтальное, "
    "внутренность ниже) или левое (внутренность справа); на нижнем или правом ребре — нет."};
constexpr Phrase kSnappedToGrid{"Vertices snapped to the sub-pixel grid",
                                "頂点をサブピクセル格子に丸める",
                                "Вершины привязаны к субпиксельной сетке"};
constexpr Phrase kNotAMultiple{
    "Some vertex is not a multiple of 1/256 pixel; it was rounded to the nearest one, as a GPU "
    "does.",
    "1/256 画素の倍数でない頂点があるので, GPU と同じく最も近い倍数に丸めた.",
    "Некоторая вершина не кратна 1/256 пикселя; она округлена до ближайшей, как это делает GPU."};
constexpr Phrase kOrientation{"Orientation", "向き", "Ориентация"};
constexpr Phrase kClockwiseScannedAs{
    "The triangle {0} is clockwise; it is scanned as {1} (counter-clockwise) so the interior has "
    "E > 0 on every edge.",
    "三角形 {0} は時計回りなので, {1} (反時計回り) として走査し, 内部がすべての辺で E > 0 "
    "となるようにする.",
    "Треугольник {0} обходится по часовой стрелке; он сканируется как {1} (против часовой), чтобы "
    "внутри E > 0 на каждом ребре."};
constexpr Phrase kCullsNothing{"Scan conversion culls nothing.", "走査変換では何も除去しない.",
                               "Растеризация ничего не отбрасывает."};
constexpr Phrase kDegenerateTriangle{"Degenerate triangle", "退化した三角形",
                                     "Вырожденный треугольник"};
constexpr Phrase kCollinear{
    "The three vertices are collinear (zero area): the triangle covers no pixels.",
    "3 つの頂点が一直線上にある (面積 0): 三角形はどの画素も覆わない.",
    "Три вершины лежат на одной прямой (нулевая площадь): треугольник не покрывает ни одного "
    "пикселя."};
constexpr Phrase kEdgeFunction{"Edge function {0}", "エッジ関数 {0}", "Функция ребра {0}"};
constexpr Phrase kTopEdge{"top edge: centres on it are covered", "上辺: その上の画素中心は覆われる",
                          "верхнее ребро: центры на нём покрыты"};
constexpr Phrase kLeftEdge{"left edge: centres on it are covered",
                           "左辺: その上の画素中心は覆われる",
                           "левое ребро: центры на нём покрыты"};
constexpr Phrase kBottomOrRightEdge{"bottom or right edge: centres on it are not covered",
                                    "下辺または右辺: その上の画素中心は覆われない",
                                    "нижнее или правое ребро: центры на нём не покрыты"};
constexpr Phrase kBoundingBox{"Bounding box of the pixel centres",
                              "画素中心のバウンディングボックス",
                              "Ограничивающий прямоугольник центров пикселей"};
constexpr Phrase kPixelCovered{
    "A pixel is covered when E > 0 on all three edges, or E = 0 on an edge that is top or left.",
    "画素が覆われるのは, 3 辺すべてで E > 0 のとき, または E = 0 となる辺が上辺か左辺のとき.",
    "Пиксель покрыт, если E > 0 на всех трёх рёбрах или E = 0 на верхнем или левом ребре."};
constexpr Phrase kCoveredPixelsByRow{"Covered pixels, row by row", "覆われる画素 (行ごと)",
                                     "Покрытые пиксели, по строкам"};
constexpr Phrase kPixelsCovered{"{0} pixel(s) covered.", "{0} 個の画素を覆う.",
                                "Покрыто пикселей: {0}."};

// Fixed-point (1/2⁸ pixel) numbers as exact rationals in pixels.
Exact pixels_of(std::int64_t v, int power = 1) {
  return GiNaC::numeric(static_cast<long>(v)) / GiNaC::pow(GiNaC::numeric(kSubpixelScale), power);
}

struct ScanConvert {
  static constexpr const char* kName = "scan_convert";
  static constexpr Phrase kSummary{
      "pixels covered by a triangle (top-left fill rule)", "三角形が覆う画素 (左上規則)",
      "пиксели, покрытые треугольником (правило верхнего левого края)"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr int kMaxBox = 256;  // the bounding box may span at most 256 × 256 pixels
  struct Given {
    std::array<Vec2<Exact>, 3> triangle;
  };
  static std::vector<std::string> given_fields() { return {"triangle"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "pixels", .kind = AnswerKind::PointSet, .label = say(words::kPixels)}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    if (r.list_size("triangle", 3) != 3) r.fail("triangle", "expected 3 points");
    const YAML::Node& root = r.node();
    for (std::size_t k = 0; k < 3; ++k) {
      const YAML::Node p = root["triangle"][k];
      const std::size_t dims = p.IsSequence() && p.size() == 3 ? 3 : 2;
      const std::vector<Exact> v = r.numbers_at("triangle", k, dims);
      g.triangle[k] = Vec2<Exact>(v[0], v[1]);
    }
    return g;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const TriangleSetup t = setup_triangle_exact(g.triangle);
    const long box_w = t.i_max - t.i_min + 1, box_h = t.j_max - t.j_min + 1;
    if (box_w > kMaxBox || box_h > kMaxBox)
      throw DomainError("triangle", "the triangle's bounding box spans " + std::to_string(box_w) +
                                        " × " + std::to_string(box_h) +
                                        " pixels; scan_convert handles at most " +
                                        std::to_string(kMaxBox) + " × " + std::to_string(kMaxBox));
    const std::vector<Fragment> frags = rasterize(t);
    const char* names = "ABC";
    if (steps) {
      steps->note(say(kPixelsAndFillRule),
                  say(kWindowYUp) + say(kVerticesSnapped) + say(kTopLeftRule));
      if (t.snapped) steps->warn(say(kSnappedToGrid), say(kNotAMultiple));
      if (t.reordered)
        steps->note(say(kOrientation), say(kClockwiseScannedAs, "ABC", "ACB") + say(kCullsNothing));
    }
    if (t.degenerate) {
      if (steps) steps->warn(say(kDegenerateTriangle), say(kCollinear)).yields("pixels");
      Answers out;
      out.set("pixels", Value::matrix({}));
      return out;
    }
    if (steps) {
      for (int k = 0; k < 3; ++k) {
        const EdgeFunction& e = t.edge[k];
        const std::string from(1, names[t.order[(k + 1) % 3]]), to(1, names[t.order[(k + 2) % 3]]);
        const Phrase& cls = e.top ? kTopEdge : e.left ? kLeftEdge : kBottomOrRightEdge;
        steps
            ->add(say(kEdgeFunction, "E_" + from + to),
                  tex("E_{" + from + to + "}(x, y) = (x_" + to + " - x_" + from + ")(y - y_" +
                      from + ") - (y_" + to + " - y_" + from + ")(x - x_" + from + ")"),
                  {},
                  tex("E_{" + from + to + "}(x, y) = ") +
                      linear_expression(
                          {{pixels_of(e.a), "x"}, {pixels_of(e.b), "y"}, {pixels_of(e.c, 2), ""}}))
            .note = say(cls);
      }
      steps
          ->add(say(kBoundingBox), {}, {},
                tex(std::to_string(t.i_min) + " \\le i \\le " + std::to_string(t.i_max) + ",\\; " +
                    std::to_string(t.j_min) + " \\le j \\le " + std::to_string(t.j_max)))
          .note = say(kPixelCovered);
      std::map<int, std::string> rows;
      for (const Fragment& f : frags)
        rows[f.j] += (rows[f.j].empty() ? "" : ", ") + std::to_string(f.i);
      MathText text;
      for (const auto& [j, is] : rows)
        text += (text.empty() ? MathText{} : tex(";\\quad")) +
                tex("j = " + std::to_string(j) + "\\colon i = " + is);
      steps->add(say(kCoveredPixelsByRow), {}, {}, text.empty() ? word(words::kNone) : text)
          .yields("pixels")
          .note = say(kPixelsCovered, frags.size());
    }
    std::vector<std::vector<Exact>> px;
    for (const Fragment& f : frags) px.push_back({Exact(f.i), Exact(f.j)});
    Answers out;
    out.set("pixels", Value::matrix(px));
    return out;
  }
  // Default generator: a triangle with integer vertices in [0, 8]² (hard: at pixel centres,
  // so that edges pass through centres and the top-left rule decides).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    std::vector<Exact> t[3];
    for (int attempt = 0; attempt < 1000; ++attempt) {
      std::vector<std::vector<double>> d;
      for (auto& v : t) {
        v = {Exact(rng.integer(0, 8)), Exact(rng.integer(0, 8))};
        if (o.hard) v = {v[0] + GiNaC::numeric(1, 2), v[1] + GiNaC::numeric(1, 2)};
        d.push_back(doubles(v));
      }
      if (triangle_shape(d) >= kMinTriangleShape) break;
    }
    YAML::Node g, tri(YAML::NodeType::Sequence);
    for (const auto& v : t) tri.push_back(gen_list(v));
    tri.SetStyle(YAML::EmitterStyle::Flow);
    g["triangle"] = tri;
    return g;
  }

  static std::string ill_conditioned(const Given& g, const Answers& a) {
    std::vector<std::vector<double>> d;
    for (const auto& v : g.triangle) d.push_back(doubles(v));
    if (triangle_shape(d) < kMinTriangleShape) return "the triangle is nearly degenerate";
    const Value* p = a.find("pixels");
    return p && p->rows == 0 ? "the triangle covers no pixel centre" : "";
  }
};

}  // namespace

KindInfo scan_convert_kind() {
  KindInfo k = make_kind<ScanConvert>();
  k.order = 150;
  k.doc_given = "`triangle` (window coordinates)";
  k.doc_answers = "`pixels`";
  return k;
}

}  // namespace frustum
