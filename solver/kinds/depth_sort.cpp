// seeds 001, 003: the depth-sort (painter's) algorithm — centroids, depths, the back-to-front
// order — and the pairs where it fails: cyclic overlap (三すくみ), interpenetration (貫通) and
// concave polygons, decided exactly from the geometry over each pair's overlap on screen.
#include "solver/kinds/given_reader.hpp"
#include "solver/kinds/registry.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/depth_order.hpp"

#include <fmt/format.h>

namespace frustum {

namespace {

struct DepthSort {
  static constexpr const char* kName = "depth_sort";
  static constexpr const char* kSummary = "painter's algorithm: centroid order back to front, and its conflicts";
  struct Given {
    std::vector<Polygon3<Exact>> polygons;
    DepthViewer viewer;
  };
  static std::vector<std::string> given_fields() { return {"polygons", "eye", "view_direction"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"centroids", AnswerKind::Matrix, {}, {}},
            {"depths", AnswerKind::Vector, {"centroids"}, {}},
            {"order", AnswerKind::Sequence, {"depths"}, {}},
            {"conflicts", AnswerKind::WordList, {"order"}, {}}};
  }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    if (r.has("eye") == r.has("view_direction"))
      r.fail(r.has("eye") ? "view_direction" : "eye", "give exactly one of eye and view_direction");
    const std::size_t n = r.list_size("polygons");
    for (std::size_t k = 0; k < n; ++k) {
      // Each polygon is a list of points; read it through a one-field view of the item.
      const YAML::Node item = r.node()["polygons"][k];
      YAML::Node wrap;
      wrap["points"] = item;
      GivenReader one(wrap, r.file(), fmt::format("polygons[{}]", k), {"points"});
      if (!item.IsSequence() || item.size() < 3)
        throw InputError(r.locate(fmt::format("polygons[{}]", k), "expected a polygon: a list of at least 3 points [x, y, z]"));
      try {
        g.polygons.push_back(one.points("points", 3));
      } catch (const InputError& e) {
        Diagnostic d = e.diagnostic();
        const std::string prefix = fmt::format("polygons[{}].points", k);
        if (d.field.rfind(prefix, 0) == 0) d.field = fmt::format("polygons[{}]", k) + d.field.substr(prefix.size());
        throw InputError(r.locate(d.field, d.message));
      }
    }
    if (r.has("eye")) g.viewer.eye = r.vector<3>("eye");
    else g.viewer.view_direction = r.vector<3>("view_direction");
    return g;
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

    std::string lines;
    for (std::size_t k = 0; k < n; ++k)
      lines += fmt::format("{}g{} = {}", k ? ",  " : "", k, vec(res.centroids[k]).unicode);
    steps->add("Centroids", math("g = (p₀ + p₁ + ⋯ + p_{n−1}) / n", "\\mathbf{g} = \\frac{1}{n}(\\mathbf{p}_0 + \\cdots + \\mathbf{p}_{n-1})"),
               {}, math(lines));
    steps->yields("centroids");
    std::string depths;
    for (std::size_t k = 0; k < n; ++k)
      depths += fmt::format("{}depth{} = {}", k ? ",  " : "", k, exact(res.depths[k], true).unicode);
    if (g.viewer.eye)
      steps->add("Depth: distance from the eye", math("depth = ‖g − p_eye‖", "\\text{depth} = \\lVert\\mathbf{g} - \\mathbf{p}_{\\text{eye}}\\rVert"),
                 math("p_eye = ", "\\mathbf{p}_{\\text{eye}} = ") + vec(*g.viewer.eye), math(depths))
          .note = "Larger depth = farther from the eye.";
    else
      steps->add("Depth along the view direction", math("depth = g·v̂", "\\text{depth} = \\mathbf{g}\\cdot\\hat{\\mathbf{v}}"),
                 math("v = ") + vec(*g.viewer.view_direction), math(depths))
          .note = "v is the direction the viewer looks (into the scene), so larger depth = farther "
                  "(with v = (0, 0, −1), OpenGL's default view, depth = −z).";
    steps->yields("depths");
    std::string seq;
    for (const std::string& k : order) seq += (seq.empty() ? "" : " → ") + k;
    steps->add("Draw back to front (farthest centroid first)", {}, {}, math(seq))
        .note = "Equal depths keep the listed order.";
    steps->yields("order");

    std::string pairs;
    for (const PairReport& p : res.overlapping) {
      const std::string rel = p.order == PairOrder::FirstBehind    ? fmt::format("{} is behind {}", p.i, p.j)
                              : p.order == PairOrder::SecondBehind ? fmt::format("{} is behind {}", p.j, p.i)
                              : p.order == PairOrder::Interpenetrating ? std::string("nearer one changes: they interpenetrate")
                              : p.order == PairOrder::WrapsAround      ? std::string("nearer one differs between parts: one wraps around the other")
                                                                       : std::string("depths are equal (coplanar)");
      pairs += fmt::format("\n{}: overlap on screen; over the overlap {}; plane tests: {} {} "
                           "the plane of {}, {} {} the plane of {}{}",
                           p.name(), rel, p.i,
                           p.planes.i_behind_plane_j ? "entirely behind" : p.planes.i_front_plane_j ? "entirely in front of" : "on both sides of",
                           p.j, p.j,
                           p.planes.j_behind_plane_i ? "entirely behind" : p.planes.j_front_plane_i ? "entirely in front of" : "on both sides of",
                           p.i, p.conflict ? " — CONFLICT: " + p.reason : " — the centroid order is right");
    }
    Step& s = steps->add("Check each overlapping pair (Newell)", {}, {},
                         math(res.conflicts.empty() ? "no conflicts" : "conflicts: " + [&] {
                           std::string c;
                           for (const std::string& x : res.conflicts) c += (c.empty() ? "" : ", ") + x;
                           return c;
                         }()));
    s.note = "Overlap is decided exactly by the " + res.projection +
             " (each polygon cut into triangles on screen). Over each overlapping piece the depths "
             "of the two planes are compared at the piece's corners (depth is affine there), which "
             "gives the true order; Newell's plane tests are shown beside it. A pair conflicts when "
             "the centroid order is wrong, they interpenetrate, one wraps around the other, or they "
             "lie on a cycle (seed 003: polygons have size, so one centroid cannot order them)." +
             (res.overlapping.empty() ? std::string("\nNo two polygons overlap on screen: any order is right.") : pairs);
    if (!res.edge_on.empty()) {
      std::string e;
      for (int k : res.edge_on) e += (e.empty() ? "" : ", ") + std::to_string(k);
      s.note += "\nSeen edge-on (no area on screen, never in conflict): " + e + ".";
    }
    steps->yields("conflicts");
    return out;
  }
};

}  // namespace

KindInfo depth_sort_kind() { return make_kind<DepthSort>(); }

}  // namespace frustum
