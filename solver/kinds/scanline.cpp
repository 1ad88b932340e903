// The scan-line method of hidden-surface removal (seed 000, 9.8): on one horizontal line of the
// screen, each polygon's section (where the line crosses it, with its depth at both ends), then
// on every piece of the line the section nearest the viewer. Window coordinates x, y and depth z
// as in the Z-buffer (smaller z is nearer; on a tie the polygon listed first stays, as the
// Z-buffer keeps a pixel unless a later polygon is strictly nearer). Convex planar polygons;
// exact throughout.
#include <fmt/format.h>

#include <algorithm>

#include "solver/derivation/vocabulary.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kSpans{"spans", "断面", "сечения"};
constexpr Phrase kVisibleSections{"visible", "各区間で見える断面", "видимые сечения по отрезкам"};
constexpr Phrase kBreaks{"breaks", "区切り点", "точки разбиения"};

constexpr const char* kBackground = ".";

constexpr Phrase kSections{"Sections of the polygons on the scan line", "走査線上のポリゴンの断面",
                           "Сечения многоугольников строкой развёртки"};
constexpr Phrase kSectionEnds{
    "Each polygon's edges that the line crosses give the two ends of its section; along the "
    "section the depth changes linearly, as the polygon is planar.",
    "走査線が横切るポリゴンの辺から断面の両端が求まる. ポリゴンは平面なので, "
    "断面に沿って奥行きは線形に変わる.",
    "Рёбра многоугольника, которые пересекает строка, дают два конца его сечения; вдоль сечения "
    "глубина меняется линейно, так как многоугольник плоский."};
constexpr Phrase kDepthsCross{"Where two sections' depths cross", "2 つの断面の奥行きが交わる位置",
                              "Где пересекаются глубины двух сечений"};
constexpr Phrase kNearestOnEachPiece{"Nearest section on each piece", "各区間で最も手前の断面",
                                     "Ближайшее сечение на каждом отрезке"};
constexpr Phrase kSmallestZSeen{
    "On each piece between two breakpoints one section is nearest all along (depths are linear and "
    "cross only at breakpoints): the smallest z is seen. The method keeps one line's sections at a "
    "time, not a depth for every pixel.",
    "2 つの区切り点の間の各区間では, 1 つの断面が全体にわたって最も手前にある (奥行きは線形で, "
    "区切り点でしか交わらない): z が最も小さい断面が見える. この方法は 1 "
    "本の走査線の断面だけを保持し, 画素ごとの奥行きは持たない.",
    "На каждом отрезке между двумя точками разбиения одно сечение ближе всех на всём отрезке "
    "(глубины линейны и пересекаются только в точках разбиения): видно сечение с наименьшим z. "
    "Метод хранит сечения одной строки, а не глубину каждого пикселя."};

constexpr Phrase kLargerDepthTakenAsNearer{"larger depth taken as nearer",
                                           "z の大きいほうを手前とした",
                                           "большая глубина принята за ближнюю"};
constexpr Phrase kDepthGrowsAwayFromViewer{
    "Depth z grows away from the viewer: on each piece the section with the smallest z is the one "
    "seen.",
    "奥行き z は視点から遠いほど大きい: 各区間で z が最も小さい断面が見える.",
    "Глубина z растёт при удалении от наблюдателя: на каждом отрезке видно сечение с наименьшим "
    "z."};

struct Section {
  std::size_t polygon;
  Exact x_left, z_left, x_right, z_right;
  // Depth of the section at x (x_left ≤ x ≤ x_right): linear along the line, as the polygon
  // is planar.
  Exact z_at(const Exact& x) const {
    return canonical(z_left + (x - x_left) * (z_right - z_left) / (x_right - x_left));
  }
};

struct Crossing {
  std::size_t a, b;  // polygons
  Exact x;
};

struct Piece {
  Exact from, to;
  std::string label;
};

bool less(const Exact& a, const Exact& b) { return exact_sign(a - b) < 0; }

struct Scanline {
  static constexpr const char* kName = "scanline";
  static constexpr Phrase kSummary{
      "the scan-line method: sections of polygons on one line and the nearest on each piece",
      "スキャンライン法: 1 本の走査線上のポリゴンの断面と, 各区間で最も手前の断面",
      "метод строки развёртки: сечения многоугольников одной строкой и ближайшее на каждом "
      "отрезке"};
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr std::size_t kMaxPolygons = 50;
  struct Polygon {
    std::string label;
    Polygon3<Exact> points;
  };
  struct Given {
    std::vector<Polygon> polygons;
    Exact y;
  };
  static std::vector<std::string> given_fields() { return {"polygons", "y"}; }
  static std::vector<AnswerSpec> answers() {
    return {{.name = "spans", .kind = AnswerKind::Matrix, .label = say(kSpans)},
            {.name = "visible",
             .kind = AnswerKind::Sequence,
             .depends_on = {"spans"},
             .label = say(kVisibleSections)},
            {.name = "breaks",
             .kind = AnswerKind::Vector,
             .depends_on = {"spans"},
             .label = say(kBreaks)}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    g.y = r.number("y");
    const std::size_t n = r.list_size("polygons", 1, kMaxPolygons);
    for (std::size_t i = 0; i < n; ++i) {
      GivenReader it = r.item("polygons", i, {"label", "points"});
      Polygon p;
      const YAML::Node label = it.node()["label"];
      // Letters and digits only: a label is written inside formulas (z_A), in both notations.
      const auto plain = [](const std::string& t) {
        return !t.empty() && t.size() <= 8 && std::all_of(t.begin(), t.end(), [](char c) {
          return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9');
        });
      };
      if (!label.IsDefined() || !label.IsScalar() || !plain(label.Scalar()))
        it.fail("label", "1 to 8 letters or digits, such as A");
      p.label = label.Scalar();
      for (const Polygon& q : g.polygons)
        if (q.label == p.label) it.fail("label", "'" + p.label + "' labels two polygons");
      p.points = it.points("points", 3, 64);
      check_convex_planar(it, p.points);
      it.finish();
      g.polygons.push_back(std::move(p));
    }
    return g;
  }

  // The section needs a convex polygon (the line meets it in one piece) in one plane (depth is
  // linear along the piece).
  static void check_convex_planar(GivenReader& it, const Polygon3<Exact>& p) {
    const std::size_t n = p.size();
    int turn = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec3<Exact>&a = p[k], &b = p[(k + 1) % n], &c = p[(k + 2) % n];
      const int s = exact_sign((b(0) - a(0)) * (c(1) - b(1)) - (b(1) - a(1)) * (c(0) - b(0)));
      if (s != 0 && turn != 0 && s != turn)
        it.fail("points",
                "the polygon is not convex on the screen: give convex polygons (split "
                "a concave one)");
      if (s != 0) turn = s;
    }
    if (turn == 0) it.fail("points", "the polygon has no area on the screen");
    // Planar: every vertex on the plane of three that span it.
    for (std::size_t k = 0; k + 2 < n; ++k) {
      const Vec3<Exact> u = p[k + 1] - p[0], v = p[k + 2] - p[0];
      const Vec3<Exact> normal(u(1) * v(2) - u(2) * v(1), u(2) * v(0) - u(0) * v(2),
                               u(0) * v(1) - u(1) * v(0));
      if (exact_sign(normal(2)) == 0) continue;
      for (const Vec3<Exact>& q : p)
        if (exact_sign((q - p[0]).dot(normal)) != 0)
          it.fail("points", "the polygon's vertices are not in one plane");
      return;
    }
  }

  // Where the line y = g.y crosses polygon i: the least and the greatest x of its crossings
  // with the edges (an edge lying on the line gives both its ends), with their depths; nothing
  // when the line misses it or only touches a vertex.
  static std::optional<Section> section(const Given& g, std::size_t i) {
    const Polygon3<Exact>& p = g.polygons[i].points;
    std::vector<std::pair<Exact, Exact>> hits;  // (x, z)
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Vec3<Exact>&a = p[k], &b = p[(k + 1) % p.size()];
      const int sa = exact_sign(a(1) - g.y), sb = exact_sign(b(1) - g.y);
      if (sa == 0) hits.emplace_back(a(0), a(2));
      if (sb == 0) hits.emplace_back(b(0), b(2));
      if (sa * sb < 0) {
        const Exact t = (g.y - a(1)) / (b(1) - a(1));
        hits.emplace_back(canonical(a(0) + t * (b(0) - a(0))), canonical(a(2) + t * (b(2) - a(2))));
      }
    }
    if (hits.empty()) return std::nullopt;
    const auto by_x = [](const auto& u, const auto& v) { return less(u.first, v.first); };
    const auto [lo, hi] = std::minmax_element(hits.begin(), hits.end(), by_x);
    if (exact_sign(hi->first - lo->first) == 0) return std::nullopt;
    return Section{i, canonical(lo->first), canonical(lo->second), canonical(hi->first),
                   canonical(hi->second)};
  }

  // The pieces of the line between consecutive breakpoints (section ends and the points where
  // two sections' depths cross), each with its nearest section; `farthest` takes the greatest
  // depth instead (a mistake), equal neighbours merged.
  static std::vector<Piece> pieces(const Given& g, const std::vector<Section>& sections,
                                   std::vector<Crossing>* crossings, bool farthest = false) {
    std::vector<Exact> xs;
    for (const Section& s : sections) {
      xs.push_back(s.x_left);
      xs.push_back(s.x_right);
    }
    for (std::size_t a = 0; a < sections.size(); ++a)
      for (std::size_t b = a + 1; b < sections.size(); ++b) {
        const Section &s = sections[a], &t = sections[b];
        const Exact lo = less(s.x_left, t.x_left) ? t.x_left : s.x_left;
        const Exact hi = less(s.x_right, t.x_right) ? s.x_right : t.x_right;
        if (!less(lo, hi)) continue;
        // z_s(x) − z_t(x) is linear: it changes sign inside (lo, hi) at its root.
        const Exact d_lo = s.z_at(lo) - t.z_at(lo), d_hi = s.z_at(hi) - t.z_at(hi);
        if (exact_sign(d_lo) * exact_sign(d_hi) < 0) {
          const Exact x = canonical(lo + (hi - lo) * d_lo / (d_lo - d_hi));
          xs.push_back(x);
          if (crossings) crossings->push_back({s.polygon, t.polygon, x});
        }
      }
    std::sort(xs.begin(), xs.end(), less);
    xs.erase(std::unique(xs.begin(), xs.end(),
                         [](const Exact& a, const Exact& b) { return exact_sign(a - b) == 0; }),
             xs.end());
    std::vector<Piece> out;
    for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
      const Exact mid = canonical((xs[k] + xs[k + 1]) / 2);
      const Section* best = nullptr;
      Exact best_z;
      for (const Section& s : sections) {
        if (!less(s.x_left, mid) || !less(mid, s.x_right)) continue;
        const Exact z = s.z_at(mid);
        if (!best || (farthest ? less(best_z, z) : less(z, best_z))) {
          best = &s;
          best_z = z;
        }
      }
      const std::string label = best ? g.polygons[best->polygon].label : kBackground;
      if (!out.empty() && out.back().label == label)
        out.back().to = xs[k + 1];
      else
        out.push_back({xs[k], xs[k + 1], label});
    }
    return out;
  }

  static void set_pieces(Answers& out, const std::vector<Piece>& ps) {
    std::vector<std::string> labels;
    std::vector<Exact> breaks;
    for (const Piece& p : ps) {
      labels.push_back(p.label);
      breaks.push_back(p.from);
    }
    if (!ps.empty()) breaks.push_back(ps.back().to);
    out.set("visible", Value::word_list(labels));
    out.set("breaks", Value::vector(breaks));
  }

  static std::vector<Section> sections(const Given& g) {
    std::vector<Section> out;
    for (std::size_t i = 0; i < g.polygons.size(); ++i)
      if (auto s = section(g, i)) out.push_back(*s);
    return out;
  }

  // The nearest taken for the farthest: the larger z read as nearer.
  static std::vector<Misconception> misconceptions(const Given& g) {
    const std::vector<Section> ss = sections(g);
    if (ss.size() < 2) return {};
    Answers a;
    set_pieces(a, pieces(g, ss, nullptr, true));
    return {{say(kLargerDepthTakenAsNearer), say(kDepthGrowsAwayFromViewer),
             say(kNearestOnEachPiece), a}};
  }

  static Answers solve(const Given& g, Derivation* steps) {
    const std::vector<Section> ss = sections(g);
    if (ss.empty())
      throw DomainError("y", "the line y = " + exact(g.y).unicode + " crosses no polygon");
    std::vector<std::vector<Exact>> rows;
    for (const Section& s : ss) rows.push_back({s.x_left, s.z_left, s.x_right, s.z_right});
    std::vector<Crossing> crossings;
    const std::vector<Piece> ps = pieces(g, ss, &crossings);
    Answers out;
    out.set("spans", Value::matrix(rows));
    set_pieces(out, ps);
    if (!steps) return out;

    MathText found;
    for (const Section& s : ss)
      found += tex(found.empty() ? "" : ",\\quad") + math(g.polygons[s.polygon].label + ": ") +
               tex("x \\in [") + exact(s.x_left) + math(", ") + exact(s.x_right) + math("], z: ") +
               exact(s.z_left) + tex(" \\to ") + exact(s.z_right);
    steps
        ->add(say(kSections),
              tex("x = x_0 + \\frac{(y - y_0)(x_1 - x_0)}{y_1 - y_0},\\quad z = z_0 + "
                  "\\frac{(y - y_0)(z_1 - z_0)}{y_1 - y_0}"),
              math("y = ") + exact(g.y), found)
        .yields("spans")
        .note = say(kSectionEnds);
    MathText where;
    for (const Crossing& c : crossings) {
      const std::string& a = g.polygons[c.a].label;
      const std::string& b = g.polygons[c.b].label;
      where += tex(where.empty() ? "" : ",\\quad") +
               tex(fmt::format(
                   "z_{{\\mathrm{{{}}}}}(x) = z_{{\\mathrm{{{}}}}}(x) \\Rightarrow x = ", a, b)) +
               exact(c.x);
    }
    if (!crossings.empty()) steps->add(say(kDepthsCross), math("z_a(x) = z_b(x)"), {}, where);
    MathText shown;
    for (const Piece& p : ps)
      shown += tex(shown.empty() ? "" : ",\\quad") + math("[") + exact(p.from) + math(", ") +
               exact(p.to) + math("]: ") +
               (p.label == kBackground ? word(words::kBackground) : math(p.label));
    steps->add(say(kNearestOnEachPiece), word(words::kVisible) + tex(": \\min z"), {}, shown)
        .yields("visible")
        .yields("breaks")
        .note = say(kSmallestZSeen);
    return out;
  }

  // Default generator: two or three triangles with whole coordinates in a 12 × 12 window, each
  // crossed by the line y = k + ½ (nice: a line through whole numbers is not drawn; the half
  // keeps the line off the vertices), depths 1–9.
  static YAML::Node generate(Rng& rng, const GenerateOptions&) {
    const std::int64_t y = rng.integer(3, 8);
    YAML::Node g;
    g["y"] = gen_fraction(2 * y + 1, 2);
    const int count = static_cast<int>(rng.integer(2, 3));
    for (int i = 0; i < count; ++i) {
      YAML::Node p;
      p["label"] = std::string(1, static_cast<char>('A' + i));
      const std::int64_t x0 = rng.integer(0, 8);
      std::vector<std::vector<std::int64_t>> v = {
          {x0, rng.integer(0, y), rng.integer(1, 9)},
          {x0 + rng.integer(2, 4), rng.integer(0, y), rng.integer(1, 9)},
          {x0 + rng.integer(0, 4), rng.integer(y + 1, 11), rng.integer(1, 9)}};
      // Counter-clockwise or not, a triangle is convex; a flat one is drawn again by parse.
      YAML::Node pts;
      for (const auto& q : v) pts.push_back(gen_list(q));
      p["points"] = pts;
      g["polygons"].push_back(p);
    }
    return g;
  }

  // A draw worth solving: at least two sections that overlap (else nothing is hidden).
  static std::string ill_conditioned(const Given& g, const Answers& a) {
    const Value* v = a.find("visible");
    const std::size_t seen = v ? v->words.size() : 0;
    std::size_t overlaps = 0;
    const std::vector<Section> ss = sections(g);
    for (std::size_t i = 0; i < ss.size(); ++i)
      for (std::size_t j = i + 1; j < ss.size(); ++j)
        overlaps += less(ss[i].x_left, ss[j].x_right) && less(ss[j].x_left, ss[i].x_right);
    return overlaps == 0 || seen < 2 ? "no two sections overlap on the line" : "";
  }
};

}  // namespace

KindInfo scanline_kind() {
  KindInfo k = make_kind<Scanline>();
  k.order = 165;
  k.doc_given =
      "`polygons` (each `label` and convex planar `points` [x, y, z] in window coordinates; "
      "smaller z nearer), `y` (the scan line)";
  k.doc_answers =
      "`spans` ([x_left, z_left, x_right, z_right] of each polygon the line crosses, in the "
      "listed order), `visible` (labels left to right, `.` for a gap), `breaks` (the x where "
      "each visible piece starts, and where the last ends)";
  return k;
}

}  // namespace frustum
