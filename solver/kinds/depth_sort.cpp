// seeds 001, 003: the depth-sort (painter's) algorithm — centroids, depths, the back-to-front
// order — and the pairs where it fails: cyclic overlap (三すくみ), interpenetration (貫通) and
// concave polygons, decided exactly from the geometry over each pair's overlap on screen.
#include <fmt/format.h>

#include <algorithm>

#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/steps/kind_steps.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/depth_order.hpp"
#include "solver/visibility/drawable.hpp"

namespace frustum {

namespace {

struct DepthSort {
  static constexpr const char* kName = "depth_sort";
  static constexpr const char* kSummary =
      "painter's algorithm: centroid order back to front, and its conflicts";
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
    return {{"centroids", AnswerKind::Matrix, {}, {}},
            {"depths", AnswerKind::Vector, {"centroids"}, {}},
            {"order", AnswerKind::Sequence, {"depths"}, {}},
            // Two polygons whose order needs a further test: "1-0" is the pair 0-1.
            {.name = "conflicts",
             .kind = AnswerKind::WordList,
             .depends_on = {"order"},
             .unordered_pairs = true}};
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

    const MathText sep = math(",  ", ",\\; ");
    MathText lines;
    for (std::size_t k = 0; k < n; ++k)
      lines += (k ? sep : MathText{}) +
               math(fmt::format("g{} = ", k), fmt::format("\\mathbf{{g}}_{{{}}} = ", k)) +
               vec(res.centroids[k]);
    steps->add("Centroids",
               math("g = (p₀ + p₁ + ⋯ + p_{n−1}) / n",
                    "\\mathbf{g} = \\frac{1}{n}(\\mathbf{p}_0 + \\cdots + \\mathbf{p}_{n-1})"),
               {}, lines);
    steps->yields("centroids");
    MathText depths;
    for (std::size_t k = 0; k < n; ++k)
      depths += (k ? sep : MathText{}) +
                math(fmt::format("depth{} = ", k), fmt::format("\\text{{depth}}_{{{}}} = ", k)) +
                exact(res.depths[k], true);
    if (g.viewer.eye)
      steps
          ->add("Depth: distance from the eye",
                math("depth = ‖g − p_eye‖",
                     "\\text{depth} = \\lVert\\mathbf{g} - \\mathbf{p}_{\\text{eye}}\\rVert"),
                math("p_eye = ", "\\mathbf{p}_{\\text{eye}} = ") + vec(*g.viewer.eye), depths)
          .note = "Larger depth = farther from the eye.";
    else
      steps
          ->add("Depth along the view direction",
                math("depth = g·v̂", "\\text{depth} = \\mathbf{g}\\cdot\\hat{\\mathbf{v}}"),
                math("v = ", "\\mathbf{v} = ") + vec(*g.viewer.view_direction), depths)
          .note =
          "v is the direction the viewer looks (into the scene), so larger depth = farther "
          "(with v = (0, 0, −1), OpenGL's default view, depth = −z).";
    steps->yields("depths");
    MathText seq;
    for (const std::string& k : order)
      seq += (seq.empty() ? MathText{} : math(" → ", " \\to ")) + word(k);
    // Said only where two depths are equal: the tie rule decides nothing otherwise.
    bool tie = false;
    for (std::size_t a = 0; a < res.depths.size(); ++a)
      for (std::size_t b = a + 1; b < res.depths.size(); ++b)
        tie = tie || exact_sign(res.depths[a] - res.depths[b]) == 0;
    Step& draw = steps->add("Draw back to front (farthest centroid first)", {}, {}, seq);
    if (tie) draw.note = "Equal depths keep the listed order.";
    steps->yields("order");

    std::string pairs;
    for (const PairReport& p : res.overlapping) {
      const std::string rel =
          p.order == PairOrder::FirstBehind    ? fmt::format("{} is behind {}", p.i, p.j)
          : p.order == PairOrder::SecondBehind ? fmt::format("{} is behind {}", p.j, p.i)
          : p.order == PairOrder::Interpenetrating
              ? std::string("nearer one changes: they interpenetrate")
          : p.order == PairOrder::WrapsAround
              ? std::string("nearer one differs between parts: one wraps around the other")
              : std::string("depths are equal (coplanar)");
      pairs += fmt::format(
          "\n{}: overlap on screen; over the overlap {}; plane tests: {} {} "
          "the plane of {}, {} {} the plane of {}{}",
          p.name(), rel, p.i,
          p.planes.i_behind_plane_j  ? "entirely behind"
          : p.planes.i_front_plane_j ? "entirely in front of"
                                     : "on both sides of",
          p.j, p.j,
          p.planes.j_behind_plane_i  ? "entirely behind"
          : p.planes.j_front_plane_i ? "entirely in front of"
                                     : "on both sides of",
          p.i, p.conflict ? " — CONFLICT: " + p.reason : " — the centroid order is right");
    }
    MathText conflicts = word(res.conflicts.empty() ? "no conflicts" : "conflicts");
    for (std::size_t k = 0; k < res.conflicts.size(); ++k)
      conflicts += (k ? sep : math(": ", "\\colon ")) + word(res.conflicts[k]);
    Step& s = steps->add("Check each overlapping pair (Newell)", {}, {}, conflicts);
    s.note =
        "Overlap is decided exactly by the " + res.projection +
        " (each polygon cut into triangles on screen). Over each overlapping piece the depths "
        "of the two planes are compared at the piece's corners (depth is affine there), which "
        "gives the true order; Newell's plane tests are shown beside it. A pair conflicts when "
        "the centroid order is wrong, they interpenetrate, one wraps around the other, or they "
        "lie on a cycle (polygons have size, so one centroid cannot order them)." +
        (res.overlapping.empty()
             ? std::string("\nNo two polygons overlap on screen: any order is right.")
             : pairs);
    if (!res.edge_on.empty()) {
      std::string e;
      for (int k : res.edge_on) e += (e.empty() ? "" : ", ") + std::to_string(k);
      s.note += "\nSeen edge-on (no area on screen, never in conflict): " + e + ".";
    }
    steps->yields("conflicts");
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
