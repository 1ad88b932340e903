// seeds 001, 003: the depth-sort (painter's) algorithm — centroids, depths, the back-to-front
// order — and the pairs where it fails: cyclic overlap (三すくみ), interpenetration (貫通) and
// concave polygons, decided exactly from the geometry over each pair's overlap on screen.
#include <fmt/format.h>

#include <algorithm>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/depth_order.hpp"
#include "solver/visibility/drawable.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kCentroidsLabel{"centroids", "重心", "центроиды"};
constexpr Phrase kDepths{"depths", "奥行き", "глубины"};
constexpr Phrase kDrawingOrder{"order", "描画順", "порядок рисования"};
constexpr Phrase kConflictingPairs{"conflicts", "競合", "конфликты"};

// Centroids, depths and the order.
constexpr Phrase kCentroids{"Centroids", "重心", "Центры тяжести"};
constexpr Phrase kDepthFromEye{"Depth: distance from the eye", "奥行き: 視点からの距離",
                               "Глубина: расстояние от глаза"};
constexpr Phrase kLargerDepthFarther{"Larger depth = farther from the eye.",
                                     "奥行きが大きいほど視点から遠い.",
                                     "Большая глубина = дальше от глаза."};
constexpr Phrase kDepthAlongView{"Depth along the view direction", "視線方向の奥行き",
                                 "Глубина вдоль направления взгляда"};
constexpr Phrase kViewDirectionDepth{
    "v is the direction the viewer looks (into the scene), so larger depth = farther (with v = (0, "
    "0, −1), OpenGL's default view, depth = −z).",
    "v は見る人が見る方向 (シーンの奥へ) なので, 奥行きが大きいほど遠い (OpenGL の既定の v = (0, "
    "0, −1) では奥行き = −z).",
    "v — направление взгляда наблюдателя (в сцену), поэтому большая глубина = дальше (при v = (0, "
    "0, −1), взгляде OpenGL по умолчанию, глубина = −z)."};
constexpr Phrase kDrawBackToFront{
    "Draw back to front (farthest centroid first)", "奥から手前へ描く (重心が最も遠いものから)",
    "Рисование от дальних к ближним (сначала самый дальний центр тяжести)"};
constexpr Phrase kEqualDepthsKeepOrder{"Equal depths keep the listed order.",
                                       "奥行きが等しいものは列挙した順のまま.",
                                       "Равные глубины сохраняют исходный порядок."};
// The overlapping pairs.
constexpr Phrase kCheckEachPair{"Check each overlapping pair (Newell)", "重なる組を調べる (Newell)",
                                "Проверка каждой перекрывающейся пары (Newell)"};
constexpr Phrase kConflicts{"conflicts", "矛盾", "конфликты"};
constexpr Phrase kNoConflicts{"no conflicts", "矛盾なし", "конфликтов нет"};
constexpr Phrase kOverlapOrthographic{
    "Overlap is decided exactly by the orthographic projection along the view direction (each "
    "polygon cut into triangles on screen).",
    "重なりは視線方向への平行投影で厳密に判定する (各多角形を画面上で三角形に分割).",
    "Перекрытие определяется точно ортографической проекцией вдоль направления взгляда (каждый "
    "многоугольник разрезан на треугольники на экране)."};
constexpr Phrase kOverlapPerspective{
    "Overlap is decided exactly by the perspective projection from the eye onto the plane "
    "perpendicular to the direction from the eye to the mean centroid (each polygon cut into "
    "triangles on screen).",
    "重なりは, 視点から平均重心への方向に垂直な平面への, 視点からの透視投影で厳密に判定する "
    "(各多角形を画面上で三角形に分割).",
    "Перекрытие определяется точно перспективной проекцией из глаза на плоскость, перпендикулярную "
    "направлению от глаза к среднему центру тяжести (каждый многоугольник разрезан на треугольники "
    "на экране)."};
constexpr Phrase kCompareAtCorners{
    "Over each overlapping piece the depths of the two planes are compared at the piece's corners "
    "(depth is affine there), which gives the true order; Newell's plane tests are shown beside "
    "it.",
    "重なる各部分で, 2 つの平面の奥行きをその部分の角で比べる (そこでは奥行きはアフィン). "
    "これが本当の前後関係を与える. Newell の平面テストも並べて示す.",
    "На каждом перекрывающемся куске глубины двух плоскостей сравниваются в углах куска (там "
    "глубина аффинна), что даёт истинный порядок; рядом показаны плоскостные тесты Newell."};
constexpr Phrase kWhenPairConflicts{
    "A pair conflicts when the centroid order is wrong, they interpenetrate, one wraps around the "
    "other, or they lie on a cycle (polygons have size, so one centroid cannot order them).",
    "重心の順序が誤っているとき, 貫通しているとき, 一方が他方を包むとき, または三すくみのとき, "
    "その組は矛盾する (ポリゴンには「大きさ」があるので, 重心だけでは前後関係が定まらない).",
    "Пара конфликтует, если порядок центров тяжести неверен, они взаимно проникают, одна "
    "охватывает другую или они лежат на цикле (у многоугольников есть размер, поэтому один центр "
    "тяжести не упорядочивает их)."};
constexpr Phrase kNoOverlap{
    "No two polygons overlap on screen: any order is right.",
    "画面上で重なる多角形の組はない: どの順序でも正しい.",
    "Никакие два многоугольника не перекрываются на экране: любой порядок верен."};
constexpr Phrase kSeenEdgeOn{
    "Seen edge-on (no area on screen, never in conflict): {0}.",
    "真横から見える (画面上で面積がなく, 矛盾することはない): {0}.",
    "Видны с ребра (на экране не занимают площади и ни с чем не конфликтуют): {0}."};
constexpr Phrase kPairLine{
    "{0}-{1}: overlap on screen; over the overlap {2}; plane tests: {3}, {5} — {4}",
    "{0}-{1}: 画面上で重なる. 重なりでは {2}. 平面テスト: {3}, {5} — {4}",
    "{0}-{1}: перекрываются на экране; на перекрытии {2}; плоскостные тесты: {3}, {5} — {4}"};
constexpr Phrase kIsBehind{"{0} is behind {1}", "{0} が {1} の奥", "{0} за {1}"};
constexpr Phrase kNearerChanges{"nearer one changes: they interpenetrate",
                                "手前のものが入れ替わる: 貫通している",
                                "ближний меняется: они взаимно проникают"};
constexpr Phrase kNearerDiffers{"nearer one differs between parts: one wraps around the other",
                                "部分によって手前のものが異なる: 一方が他方を包んでいる",
                                "ближний различается по частям: один охватывает другой"};
constexpr Phrase kDepthsEqual{"depths are equal (coplanar)", "奥行きが等しい (同一平面上)",
                              "глубины равны (компланарны)"};
constexpr Phrase kEntirelyBehind{"{0} entirely behind the plane of {1}",
                                 "{0} は {1} の平面の完全に奥", "{0} целиком за плоскостью {1}"};
constexpr Phrase kEntirelyInFront{"{0} entirely in front of the plane of {1}",
                                  "{0} は {1} の平面の完全に手前",
                                  "{0} целиком перед плоскостью {1}"};
constexpr Phrase kOnBothSides{"{0} on both sides of the plane of {1}",
                              "{0} は {1} の平面の両側にある", "{0} по обе стороны плоскости {1}"};
constexpr Phrase kCentroidOrderRight{"the centroid order is right", "重心の順序で正しい",
                                     "порядок центров тяжести верен"};
constexpr Phrase kConflictCycle{
    "CONFLICT: they lie on a cycle of overlaps (三すくみ): each polygon must be drawn before the "
    "next, around the cycle, so no order of whole polygons is right",
    "矛盾: 三すくみ. 各多角形を次のものより先に描かねばならず, それが一巡するので, "
    "多角形単位のどの順序も正しくない",
    "КОНФЛИКТ: они лежат на цикле перекрытий: каждый многоугольник нужно рисовать раньше "
    "следующего по циклу, поэтому никакой порядок целых многоугольников не верен"};
constexpr Phrase kConflictInterpenetrate{
    "CONFLICT: they interpenetrate (貫通): over their overlap the nearer polygon changes inside "
    "one piece, so no order of whole polygons is right",
    "矛盾: 貫通している. 重なりの一つの部分の中で手前の多角形が入れ替わるので, "
    "多角形単位のどの順序も正しくない",
    "КОНФЛИКТ: они взаимно проникают: на их перекрытии ближний многоугольник меняется внутри "
    "одного куска, поэтому никакой порядок целых многоугольников не верен"};
constexpr Phrase kConflictWraps{
    "CONFLICT: one wraps around the other (a concave polygon): part of the overlap has one in "
    "front, part the other, so no order of whole polygons is right",
    "矛盾: 一方が他方を包んでいる (凹ポリゴン). 重なりの一部では一方が, 残りでは他方が手前なので, "
    "多角形単位のどの順序も正しくない",
    "КОНФЛИКТ: один охватывает другой (невыпуклый многоугольник): на части перекрытия впереди "
    "один, на части — другой, поэтому никакой порядок целых многоугольников не верен"};
constexpr Phrase kConflictFartherThan{
    "CONFLICT: over their overlap {0} is nearer everywhere, but its centroid is farther than "
    "{1}'s, so the centroid order draws {2} first and {3} paints over it",
    "矛盾: 重なりではどこでも {0} が手前だが, その重心は {1} の重心より奥にあるので, 重心の順では "
    "{2} を先に描き, {3} がその上に描かれてしまう",
    "КОНФЛИКТ: на перекрытии {0} везде ближе, но его центр тяжести дальше, чем у {1}, поэтому "
    "порядок по центрам тяжести рисует {2} первым, и {3} закрашивает его"};
constexpr Phrase kConflictAsFarAs{
    "CONFLICT: over their overlap {0} is nearer everywhere, but its centroid is as far as {1}'s, "
    "so the centroid order draws {2} first and {3} paints over it",
    "矛盾: 重なりではどこでも {0} が手前だが, その重心は {1} の重心と同じ奥行きなので, "
    "重心の順では {2} を先に描き, {3} がその上に描かれてしまう",
    "КОНФЛИКТ: на перекрытии {0} везде ближе, но его центр тяжести так же далеко, как у {1}, "
    "поэтому порядок по центрам тяжести рисует {2} первым, и {3} закрашивает его"};

// How two overlapping polygons i < j relate over their overlap.
Said relation(const PairReport& p) {
  switch (p.order) {
    case PairOrder::FirstBehind:
      return say(kIsBehind, p.i, p.j);
    case PairOrder::SecondBehind:
      return say(kIsBehind, p.j, p.i);
    case PairOrder::Interpenetrating:
      return say(kNearerChanges);
    case PairOrder::WrapsAround:
      return say(kNearerDiffers);
    case PairOrder::Coplanar:
      break;
  }
  return say(kDepthsEqual);
}

// Newell's plane test of polygon a against the plane of b.
Said plane_test(int a, int b, bool behind, bool in_front) {
  return say(behind ? kEntirelyBehind : in_front ? kEntirelyInFront : kOnBothSides, a, b);
}

// Why a pair conflicts, as depth_sort decided it (PairReport::reason, in the same order).
Said conflict(const PairReport& p) {
  if (p.order == PairOrder::Interpenetrating) return say(kConflictInterpenetrate);
  if (p.order == PairOrder::WrapsAround) return say(kConflictWraps);
  if (p.cyclic) return say(kConflictCycle);
  const int far = p.order == PairOrder::FirstBehind ? p.i : p.j;
  const int near = far == p.i ? p.j : p.i;
  return say(p.centroid_tie ? kConflictAsFarAs : kConflictFartherThan, near, far, near, far);
}

struct DepthSort {
  static constexpr const char* kName = "depth_sort";
  static constexpr Phrase kSummary{
      "painter's algorithm: centroid order back to front, and its conflicts",
      "奥行きソート法: 奥から手前への重心の順序と, その矛盾",
      "алгоритм художника: порядок центров тяжести от дальних к ближним и его конфликты"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  struct Given {
    std::vector<Polygon3<Exact>> polygons;
    DepthViewer viewer;
  };
  static std::vector<std::string> given_fields() { return {"polygons", "eye", "view_direction"}; }
  // Grading scales (docs/grading.md §2): a centroid's coordinate is the mean of the polygon's
  // same coordinates, so it is judged at their size (not at the size of the other coordinates).
  static AnswerScales scales(const Given& g, const Answers&) {
    AnswerScale s;
    for (const Polygon3<Exact>& poly : g.polygons)
      for (int k = 0; k < 3; ++k) {
        double m = 0;
        for (const Vec3<Exact>& v : poly) m = std::max(m, std::abs(to_double(v(k))));
        s.magnitude.push_back(m);
      }
    return {{"centroids", s}};
  }

  static std::vector<AnswerSpec> answers() {
    return {{.name = "centroids", .kind = AnswerKind::Matrix, .label = say(kCentroidsLabel)},
            {.name = "depths",
             .kind = AnswerKind::Vector,
             .depends_on = {"centroids"},
             .label = say(kDepths)},
            {.name = "order",
             .kind = AnswerKind::Sequence,
             .depends_on = {"depths"},
             .label = say(kDrawingOrder)},
            // Two polygons whose order needs a further test: "1-0" is the pair 0-1.
            {.name = "conflicts",
             .kind = AnswerKind::WordList,
             .depends_on = {"order"},
             .unordered_pairs = true,
             .label = say(kConflictingPairs)}};
  }

  // Error carried forward: the depths of the student's own centroids (their distance from the
  // eye, or their component along the view direction), and the order of the student's own
  // depths (farthest first, equal depths in the listed order, compared exactly).
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    const std::size_t n = g.polygons.size();
    if (const auto c = carried(student, "centroids", 3 * n)) {
      std::vector<Exact> depths;
      const Exact length =
          g.viewer.eye ? Exact(1)
                       : canonical(GiNaC::sqrt(canonical(g.viewer.view_direction->squaredNorm())));
      for (std::size_t k = 0; k < n; ++k) {
        const Vec3<Exact> centroid((*c)[3 * k], (*c)[3 * k + 1], (*c)[3 * k + 2]);
        depths.push_back(g.viewer.eye ? canonical(GiNaC::sqrt(
                                            canonical((centroid - *g.viewer.eye).squaredNorm())))
                                      : canonical(centroid.dot(*g.viewer.view_direction) / length));
      }
      out.set("depths", Value::vector(depths));
    }
    if (const auto d = carried(student, "depths", n)) {
      std::vector<std::size_t> order(n);
      for (std::size_t k = 0; k < n; ++k) order[k] = k;
      try {
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
          return exact_sign(canonical((*d)[a] - (*d)[b])) > 0;
        });
        std::vector<std::string> words;
        for (const std::size_t k : order) words.push_back(std::to_string(k));
        out.set("order", Value::word_list(words));
      } catch (const std::exception&) {
        // A sign of the student's depths that exact arithmetic cannot decide: nothing carried.
      }
    }
    return out;
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    if (r.has("eye") == r.has("view_direction"))
      r.fail(r.has("eye") ? "view_direction" : "eye", "give exactly one of eye and view_direction");
    const std::size_t n = r.list_size("polygons", 1, kMaxDepthSortPolygons);
    for (std::size_t k = 0; k < n; ++k) {
      // Each polygon is a list of points; read it through a one-field view of the item.
      const YAML::Node item = r.node()["polygons"][k];
      YAML::Node wrap;
      wrap["points"] = item;
      GivenReader one(wrap, r.file(), fmt::format("polygons[{}]", k), {"points"});
      if (!item.IsSequence() || item.size() < 3)
        throw InputError(r.locate(fmt::format("polygons[{}]", k),
                                  "expected a polygon: a list of at least 3 points [x, y, z]"));
      try {
        g.polygons.push_back(one.points("points", 3));
      } catch (const InputError& e) {
        Diagnostic d = e.diagnostic();
        const std::string prefix = fmt::format("polygons[{}].points", k);
        if (d.field.rfind(prefix, 0) == 0)
          d.field = fmt::format("polygons[{}]", k) + d.field.substr(prefix.size());
        throw InputError(r.locate(d.field, d.message));
      }
    }
    if (r.has("eye"))
      g.viewer.eye = r.vector<3>("eye");
    else
      g.viewer.view_direction = r.vector<3>("view_direction");
    return g;
  }

  // `frustum draw`: the painter's result next to the z-buffer's.
  static Drawable drawable(const Given& g) {
    Drawable d;
    d.picture = Drawable::Picture::PainterVsZBuffer;
    d.polygons = g.polygons;
    d.viewer = g.viewer;
    return d;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const DepthSortResult res = depth_sort(g.polygons, g.viewer);
    const std::size_t n = g.polygons.size();
    Answers out;
    std::vector<std::vector<Exact>> rows;
    for (const Vec3<Exact>& c : res.centroids) rows.push_back({c(0), c(1), c(2)});
    out.set("centroids", Value::matrix(rows));
    out.set("depths", Value::vector(res.depths));
    std::vector<std::string> order;
    for (int k : res.order) order.push_back(std::to_string(k));
    out.set("order", Value::word_list(order));
    out.set("conflicts", Value::word_list(res.conflicts));
    if (!steps) return out;

    const MathText sep = tex(",\\; ");
    MathText lines;
    for (std::size_t k = 0; k < n; ++k)
      lines += (k ? sep : MathText{}) + tex(fmt::format("\\mathbf{{g}}_{{{}}} = ", k)) +
               vec(res.centroids[k]);
    steps
        ->add(say(kCentroids),
              tex("\\mathbf{g} = \\frac{\\mathbf{p}_0 + \\mathbf{p}_1 + \\cdots + "
                  "\\mathbf{p}_{n-1}}{n}"),
              {}, lines)
        .yields("centroids");
    MathText depths;
    for (std::size_t k = 0; k < n; ++k)
      depths += (k ? sep : MathText{}) + tex(fmt::format("\\text{{depth}}_{{{}}} = ", k)) +
                exact(res.depths[k], true);
    if (g.viewer.eye)
      steps
          ->add(say(kDepthFromEye),
                tex("\\text{depth} = \\lVert\\mathbf{g} - \\mathbf{p}_{\\text{eye}}\\rVert"),
                tex("\\mathbf{p}_{\\text{eye}} = ") + vec(*g.viewer.eye), depths)
          .yields("depths")
          .note = say(kLargerDepthFarther);
    else
      steps
          ->add(say(kDepthAlongView), tex("\\text{depth} = \\mathbf{g}\\cdot\\hat{\\mathbf{v}}"),
                tex("\\mathbf{v} = ") + vec(*g.viewer.view_direction), depths)
          .yields("depths")
          .note = say(kViewDirectionDepth);
    MathText seq;
    for (const std::string& k : order)
      seq += (seq.empty() ? MathText{} : tex(" \\to ")) + word(Said::verbatim(k));
    // Said only where two depths are equal: the tie rule decides nothing otherwise.
    bool tie = false;
    for (std::size_t a = 0; a < res.depths.size(); ++a)
      for (std::size_t b = a + 1; b < res.depths.size(); ++b)
        tie = tie || exact_sign(res.depths[a] - res.depths[b]) == 0;
    Step& draw = steps->add(say(kDrawBackToFront), {}, {}, seq).yields("order");
    if (tie) draw.note = say(kEqualDepthsKeepOrder);

    MathText conflicts = word(res.conflicts.empty() ? kNoConflicts : kConflicts);
    for (std::size_t k = 0; k < res.conflicts.size(); ++k)
      conflicts += (k ? sep : tex("\\colon ")) + word(Said::verbatim(res.conflicts[k]));
    Step& s = steps->add(say(kCheckEachPair), {}, {}, conflicts).yields("conflicts");
    // Overlap is decided in the projection depth_sort chose: from the eye when there is one.
    s.note = say(g.viewer.eye ? kOverlapPerspective : kOverlapOrthographic) +
             say(kCompareAtCorners) + say(kWhenPairConflicts);
    const Said line_break = Said::verbatim("\n");
    if (res.overlapping.empty()) s.note.append(line_break).append(say(kNoOverlap));
    for (const PairReport& p : res.overlapping)
      s.note.append(line_break)
          .append(say(kPairLine, p.i, p.j, relation(p),
                      plane_test(p.i, p.j, p.planes.i_behind_plane_j, p.planes.i_front_plane_j),
                      p.conflict ? conflict(p) : say(kCentroidOrderRight),
                      plane_test(p.j, p.i, p.planes.j_behind_plane_i, p.planes.j_front_plane_i)));
    if (!res.edge_on.empty()) {
      std::string e;
      for (int k : res.edge_on) e += (e.empty() ? "" : ", ") + std::to_string(k);
      s.note.append(line_break).append(say(kSeenEdgeOn, e));
    }
    return out;
  }
  // Default generator: two or three rectangles facing the viewer at distinct integer depths
  // (some sloped), seen along −z or from the origin; hard: two sloped polygons crossing in depth
  // over the same area (interpenetrating: the centroid order cannot be right everywhere).
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node polygons(YAML::NodeType::Sequence);
    auto quad = [&](std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1,
                    std::int64_t z0, std::int64_t z1) {
      polygons.push_back(gen_rows({{x0, y0, z0}, {x1, y0, z1}, {x1, y1, z1}, {x0, y1, z0}}));
    };
    if (o.hard) {
      const std::int64_t near = -rng.integer(2, 4), far = near - rng.integer(4, 8);
      quad(-3, -2, 3, 2, near, far);
      quad(-2, -3, 2, 3, far, near + rng.integer(-1, 0));
    } else {
      std::vector<std::int64_t> depths = {-2, -3, -4, -5, -6, -7, -8, -9, -10, -11, -12};
      const auto count = rng.integer(2, 3);
      for (std::int64_t i = 0; i < count; ++i) {
        const std::size_t k = static_cast<std::size_t>(rng.below(depths.size()));
        const std::int64_t z = depths[k];
        depths.erase(depths.begin() + static_cast<std::ptrdiff_t>(k));
        const std::int64_t x0 = rng.integer(-4, 1), y0 = rng.integer(-4, 1);
        const std::int64_t slope = o.nice || rng.chance(2, 3) ? 0 : rng.nonzero(-1, 1);
        quad(x0, y0, x0 + rng.integer(2, 5), y0 + rng.integer(2, 5), z, z + slope);
      }
    }
    polygons.SetStyle(YAML::EmitterStyle::Flow);
    YAML::Node g;
    g["polygons"] = polygons;
    if (rng.chance(1, 3))
      g["eye"] = gen_list({0, 0, 0});
    else
      g["view_direction"] = gen_list({0, 0, -1});
    return g;
  }

  static std::string ill_conditioned(const Given&, const Answers& a) {
    const Value* d = a.find("depths");
    if (!d) return "";
    for (std::size_t i = 0; i < d->numbers.size(); ++i)
      for (std::size_t j = i + 1; j < d->numbers.size(); ++j)
        if (d->numbers[i] == d->numbers[j])
          return "two centroids at the same depth (the order is ambiguous)";
    return "";
  }
};

}  // namespace

KindInfo depth_sort_kind() {
  KindInfo k = make_kind<DepthSort>();
  k.order = 180;
  k.doc_given = "`polygons`, `eye` or `view_direction`";
  k.doc_answers = "`centroids`, `depths`, `order`, `conflicts`";
  return k;
}

}  // namespace frustum
