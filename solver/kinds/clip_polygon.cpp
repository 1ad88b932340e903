// Sutherland–Hodgman polygon clipping of `points` (2D or 3D) against a `window` or a
// `volume` (default: the NDC cube), one stage per clip plane in the order left (x ≥ xmin),
// right (x ≤ xmax), bottom (y ≥ ymin), top (y ≤ ymax), then z ≥ zmin, z ≤ zmax. A vertex on a
// plane is inside. The answer is the vertex list after the last stage, or null when fewer
// than three vertices are left.
#include "solver/clipping/polygon_clip.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/input/clip_given.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"

namespace frustum {

namespace {

constexpr Phrase kNoVertices{"no vertices", "頂点なし", "вершин нет"};
constexpr Phrase kSutherlandHodgman{
    "Sutherland–Hodgman: clip against one boundary at a time; for each edge S → E keep E when it "
    "is inside (on the boundary counts as inside) and add the intersection where the edge "
    "crosses.",
    "Sutherland–Hodgman: 境界を一つずつ使ってクリップする. 各辺 S → E について, E が内側なら E "
    "を残し (境界上は内側), 辺が境界を横切るところでは交点を加える.",
    "Sutherland–Hodgman: отсекаем по одной границе за раз; для каждого ребра S → E оставляем E, "
    "если она внутри (на границе — тоже внутри), и добавляем точку пересечения, где ребро "
    "пересекает границу."};
constexpr Phrase kClipAgainst{"Clip against {0}", "クリップ: {0}", "Отсечение: {0}"};
constexpr Phrase kTopSide{"top: {0}", "上端: {0}", "верх: {0}"};
constexpr Phrase kBottomSide{"bottom: {0}", "下端: {0}", "низ: {0}"};
constexpr Phrase kLeftSide{"left: {0}", "左端: {0}", "лево: {0}"};
constexpr Phrase kRightSide{"right: {0}", "右端: {0}", "право: {0}"};
constexpr Phrase kNothingIsLeft{"Nothing is left", "何も残らない", "Ничего не остаётся"};
constexpr Phrase kNoVertexRemains{"No vertex remains: the polygon lies outside the region.",
                                  "頂点は一つも残らない: 多角形は領域の外にある.",
                                  "Не остаётся ни одной вершины: многоугольник лежит вне области."};
constexpr Phrase kFewerThanThreeRemain{
    "Fewer than three vertices remain: the polygon only touches the region's boundary (at a "
    "point or along an edge), which encloses no area.",
    "残る頂点は 3 つ未満: 多角形は領域の境界に (1 点または 1 辺で) 接するだけで, 面積をもつ部分は"
    "ない.",
    "Остаётся меньше трёх вершин: многоугольник лишь касается границы области (в точке или по "
    "ребру), а это не ограничивает никакой площади."};

// The clip plane of stage `k` of clip_polygon_box (polygon_clip.hpp), in its order: left
// (x ≥ xmin), right (x ≤ xmax), bottom (y ≥ ymin), top (y ≤ ymax), then z ≥ zmin, z ≤ zmax.
Said stage_plane(std::size_t k) {
  switch (k) {
    case 0:
      return say(kLeftSide, "x ≥ xmin");
    case 1:
      return say(kRightSide, "x ≤ xmax");
    case 2:
      return say(kBottomSide, "y ≥ ymin");
    case 3:
      return say(kTopSide, "y ≤ ymax");
    case 4:
      return Said::verbatim("z ≥ zmin");
    default:
      return Said::verbatim("z ≤ zmax");
  }
}

struct ClipPolygon {
  static constexpr const char* kName = "clip_polygon";
  static constexpr Phrase kSummary{
      "Sutherland–Hodgman clipping of a polygon (2D window or 3D volume)",
      "Sutherland–Hodgman のアルゴリズムによる多角形のクリッピング "
      "(2次元のウィンドウまたは3次元の視体積)",
      "отсечение многоугольника алгоритмом Сазерленда — Ходжмана (Sutherland–Hodgman): окном 2D "
      "или объёмом 3D"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr std::size_t kMaxVertices = 1000;
  struct Given {
    std::vector<std::vector<Exact>> points;
    clip_given::Region region;
  };
  static std::vector<std::string> given_fields() { return {"points", "window", "volume"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "clipped", .kind = AnswerKind::Polygon, .label = say(words::kClippingResult)}};
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    const std::size_t n = r.list_size("points", 3);
    if (n > kMaxVertices) r.fail("points", "at most " + std::to_string(kMaxVertices) + " vertices");
    const YAML::Node& root = r.node();
    const YAML::Node first = root["points"][0];
    const std::size_t dims = first.IsSequence() && first.size() == 3 ? 3 : 2;
    for (std::size_t i = 0; i < n; ++i) g.points.push_back(r.numbers_at("points", i, dims));
    g.region = clip_given::read_region(r, static_cast<int>(dims), "points", c.api);
    return g;
  }

  template <int N>
  static MathText vertex_list(const std::vector<Eigen::Matrix<Exact, N, 1>>& vs) {
    if (vs.empty()) return word(kNoVertices);
    MathText m;
    for (std::size_t i = 0; i < vs.size(); ++i) {
      if (i) m += tex(",\\;");
      m += vec(vs[i]);
    }
    return m;
  }

  template <int N>
  static Answers solve_in(const Given& g, const ClipBox<Exact, N>& box, Derivation* steps) {
    using V = Eigen::Matrix<Exact, N, 1>;
    std::vector<V> poly;
    for (const auto& p : g.points) poly.push_back(Eigen::Map<const V>(p.data()));
    const PolygonClipResult<V> r = clip_polygon_box(poly, box);
    if (steps) {
      steps
          ->add(g.region.title(), {}, word(words::kPolygon) + tex("\\colon ") + vertex_list(poly),
                clip_given::box_text(box))
          .note = say(kSutherlandHodgman);
      for (std::size_t k = 0; k < r.stages.size(); ++k)
        steps->add(say(kClipAgainst, stage_plane(k)), {}, {}, vertex_list(r.stages[k].vertices));
    }
    Answers out;
    if (r.empty()) {
      out.set("clipped", Value::null());
      if (steps) {
        // One or two vertices left: the polygon meets the region's boundary only.
        steps->add(say(kNothingIsLeft)).yields("clipped").note =
            say(r.clipped.empty() ? kNoVertexRemains : kFewerThanThreeRemain);
      }
      return out;
    }
    std::vector<std::vector<Exact>> rows;
    for (const V& v : r.clipped) rows.emplace_back(v.data(), v.data() + N);
    out.set("clipped", Value::matrix(rows));
    if (steps) steps->yields("clipped");
    return out;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    return g.region.dims == 2 ? solve_in<2>(g, g.region.window, steps)
                              : solve_in<3>(g, g.region.volume, steps);
  }
  // Default generator: an integer triangle or rectangle overlapping an integer window (drawn
  // again when wholly outside); hard: vertices on the window's edges.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    const std::int64_t xmin = rng.integer(0, 2), xmax = xmin + rng.integer(3, 6);
    const std::int64_t ymin = rng.integer(0, 2), ymax = ymin + rng.integer(3, 6);
    std::vector<std::vector<std::int64_t>> pts;
    if (o.hard) {
      pts = {{xmin, rng.integer(ymin - 2, ymax + 2)},
             {rng.integer(xmin + 1, xmax + 3), ymin},
             {xmax, rng.integer(ymin + 1, ymax + 3)}};
    } else if (rng.chance(1, 3)) {
      const std::int64_t x0 = rng.integer(xmin - 3, xmax), y0 = rng.integer(ymin - 3, ymax);
      const std::int64_t x1 = x0 + rng.integer(2, 6), y1 = y0 + rng.integer(2, 6);
      pts = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
    } else {
      for (;;) {
        pts.clear();
        for (int i = 0; i < 3; ++i)
          pts.push_back({rng.integer(xmin - 4, xmax + 4), rng.integer(ymin - 4, ymax + 4)});
        const std::int64_t area2 = (pts[1][0] - pts[0][0]) * (pts[2][1] - pts[0][1]) -
                                   (pts[1][1] - pts[0][1]) * (pts[2][0] - pts[0][0]);
        if (area2 != 0) break;
      }
    }
    YAML::Node g;
    g["points"] = gen_rows(pts);
    g["window"] = gen_window(xmin, xmax, ymin, ymax);
    return g;
  }

  static std::string ill_conditioned(const Given& g, const Answers& a) {
    const Value* c = a.find("clipped");
    if (c && c->shape == Value::Shape::Null) return "the polygon is wholly outside";
    std::vector<std::vector<double>> pts;
    for (const auto& p : g.points) pts.push_back(doubles(p));
    return triangle_shape(pts) < kMinTriangleShape ? "the polygon is nearly degenerate" : "";
  }
};

}  // namespace

KindInfo clip_polygon_kind() {
  KindInfo k = make_kind<ClipPolygon>();
  k.order = 140;
  k.doc_given = "`points`, `window` or `volume`";
  k.doc_answers = "`clipped`";
  return k;
}

}  // namespace frustum
