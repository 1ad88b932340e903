// Sutherland–Hodgman polygon clipping of `points` (2D or 3D) against a `window` or a
// `volume` (default: the NDC cube), one stage per clip plane in the order left (x ≥ xmin),
// right (x ≤ xmax), bottom (y ≥ ymin), top (y ≤ ymax), then z ≥ zmin, z ≤ zmax. A vertex on a
// plane is inside. The answer is the vertex list after the last stage, or null when fewer
// than three vertices are left.
#include "solver/clipping/polygon_clip.hpp"
#include "solver/kinds/clip_given.hpp"
#include "solver/kinds/registry.hpp"

namespace frustum {

namespace {

struct ClipPolygon {
  static constexpr const char* kName = "clip_polygon";
  static constexpr const char* kSummary = "Sutherland–Hodgman clipping of a polygon (2D window or 3D volume)";
  static constexpr std::size_t kMaxVertices = 1000;
  struct Given {
    std::vector<std::vector<Exact>> points;
    clip_given::Region region;
  };
  static std::vector<std::string> given_fields() { return {"points", "window", "volume"}; }
  static std::vector<AnswerSpec> answers() { return {{"clipped", AnswerKind::Polygon, {}, {}}}; }

  static Given parse(GivenReader& r, const Conventions&) {
    Given g;
    const std::size_t n = r.list_size("points", 3);
    if (n > kMaxVertices) r.fail("points", "at most " + std::to_string(kMaxVertices) + " vertices");
    const YAML::Node& root = r.node();
    const YAML::Node first = root["points"][0];
    const std::size_t dims = first.IsSequence() && first.size() == 3 ? 3 : 2;
    for (std::size_t i = 0; i < n; ++i) g.points.push_back(r.numbers_at("points", i, dims));
    g.region = clip_given::read_region(r, static_cast<int>(dims), "points");
    return g;
  }

  template <int N>
  static MathText vertex_list(const std::vector<Eigen::Matrix<Exact, N, 1>>& vs) {
    if (vs.empty()) return math("(no vertices)");
    MathText m;
    for (std::size_t i = 0; i < vs.size(); ++i) m += math(i ? ", " : "") + vec(vs[i]);
    return m;
  }

  template <int N>
  static Answers solve_in(const Given& g, const ClipBox<Exact, N>& box, Derivation* steps) {
    using V = Eigen::Matrix<Exact, N, 1>;
    std::vector<V> poly;
    for (const auto& p : g.points) poly.push_back(Eigen::Map<const V>(p.data()));
    const PolygonClipResult<V> r = clip_polygon_box(poly, box);
    if (steps) {
      steps->add(N == 2 ? "Clip window" : g.region.default_volume ? "Clip volume (default: the NDC cube)" : "Clip volume",
                 {}, math("polygon: ") + vertex_list(poly), clip_given::box_text(box))
          .note = "Sutherland–Hodgman: clip against one boundary at a time; for each edge S → E keep E when it is "
                  "inside (on the boundary counts as inside) and add the intersection where the edge crosses.";
      for (const auto& s : r.stages)
        steps->add("Clip against " + s.plane, {}, {}, vertex_list(s.vertices));
    }
    Answers out;
    if (r.empty()) {
      out.set("clipped", Value::null());
      if (steps) {
        steps->add("Nothing is left").note = "Fewer than three vertices remain: the polygon lies outside the region.";
        steps->yields("clipped");
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
    return g.region.dims == 2 ? solve_in<2>(g, g.region.window, steps) : solve_in<3>(g, g.region.volume, steps);
  }
};

}  // namespace

KindInfo clip_polygon_kind() { return make_kind<ClipPolygon>(); }

}  // namespace frustum
