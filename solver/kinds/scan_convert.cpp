// Scan conversion of one triangle in window coordinates: which pixel centres it covers under
// the top-left fill rule (rasterizer.hpp). Pixel (i, j) has its centre at (i + ½, j + ½),
// window y up; vertices are snapped to 1/256 pixel and the edge functions evaluated exactly.
// `pixels` lists [i, j] sorted by j, then i.
#include <map>

#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/raster/rasterizer.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

// Fixed-point (1/2⁸ pixel) numbers as exact rationals in pixels.
Exact pixels_of(std::int64_t v, int power = 1) {
  return GiNaC::numeric(static_cast<long>(v)) / GiNaC::pow(GiNaC::numeric(kSubpixelScale), power);
}

struct ScanConvert {
  static constexpr const char* kName = "scan_convert";
  static constexpr const char* kSummary = "pixels covered by a triangle (top-left fill rule)";
  static constexpr ConventionUse kUses{.api = false, .angles = false};
  static constexpr int kMaxBox = 256;  // the bounding box may span at most 256 × 256 pixels
  struct Given {
    std::array<Vec2<Exact>, 3> triangle;
  };
  static std::vector<std::string> given_fields() { return {"triangle"}; }
  static std::vector<AnswerSpec> answers() { return {{"pixels", AnswerKind::PointSet, {}, {}}}; }

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
      steps->note("Pixels and the fill rule",
                  "Window y points up; pixel (i, j) has its centre at (i + ½, j + ½). Vertices are "
                  "snapped to 1/256 "
                  "pixel and the edge functions are evaluated exactly. Top-left rule: a centre "
                  "exactly on an edge is "
                  "covered only when the edge is a top edge (horizontal, interior below) or a left "
                  "edge (interior to "
                  "its right); on a bottom or right edge it is not.");
      if (t.snapped)
        steps->warn("Vertices snapped to the sub-pixel grid",
                    "Some vertex is not a multiple of 1/256 pixel; it was rounded to the nearest "
                    "one, as a GPU does.");
      if (t.reordered)
        steps->note(
            "Orientation",
            "The triangle ABC is clockwise; it is scanned as ACB (counter-clockwise) so the "
            "interior has E > 0 on every edge. Scan conversion culls nothing.");
    }
    if (t.degenerate) {
      if (steps) {
        steps->warn("Degenerate triangle",
                    "The three vertices are collinear (zero area): the triangle covers no pixels.");
        steps->yields("pixels");
      }
      Answers out;
      out.set("pixels", Value::matrix({}));
      return out;
    }
    if (steps) {
      for (int k = 0; k < 3; ++k) {
        const EdgeFunction& e = t.edge[k];
        const std::string from(1, names[t.order[(k + 1) % 3]]), to(1, names[t.order[(k + 2) % 3]]);
        const std::string cls = e.top    ? "top edge: centres on it are covered"
                                : e.left ? "left edge: centres on it are covered"
                                         : "bottom or right edge: centres on it are not covered";
        steps
            ->add("Edge function E_" + from + to,
                  math("E(x, y) = (x_" + to + " − x_" + from + ")(y − y_" + from + ") − (y_" + to +
                           " − y_" + from + ")(x − x_" + from + ")",
                       "E_{" + from + to + "}(x, y) = (x_" + to + " - x_" + from + ")(y - y_" +
                           from + ") - (y_" + to + " - y_" + from + ")(x - x_" + from + ")"),
                  {},
                  math("E_" + from + to + "(x, y) = ", "E_{" + from + to + "}(x, y) = ") +
                      linear_expression(
                          {{pixels_of(e.a), "x"}, {pixels_of(e.b), "y"}, {pixels_of(e.c, 2), ""}}))
            .note = cls;
      }
      steps
          ->add("Bounding box of the pixel centres", {}, {},
                math("i = " + std::to_string(t.i_min) + " … " + std::to_string(t.i_max) +
                         ",  j = " + std::to_string(t.j_min) + " … " + std::to_string(t.j_max),
                     std::to_string(t.i_min) + " \\le i \\le " + std::to_string(t.i_max) + ",\\; " +
                         std::to_string(t.j_min) + " \\le j \\le " + std::to_string(t.j_max)))
          .note =
          "A pixel is covered when E > 0 on all three edges, or E = 0 on an edge that is top or "
          "left.";
      std::map<int, std::string> rows;
      for (const Fragment& f : frags)
        rows[f.j] += (rows[f.j].empty() ? "" : ", ") + std::to_string(f.i);
      MathText text;
      for (const auto& [j, is] : rows)
        text += (text.empty() ? MathText{} : math(";  ", ";\\quad ")) +
                math("j = " + std::to_string(j) + ": i = " + is,
                     "j = " + std::to_string(j) + "\\colon i = " + is);
      steps->add("Covered pixels, row by row", {}, {}, text.empty() ? word("none") : text).note =
          std::to_string(frags.size()) + " pixel(s) covered.";
      steps->yields("pixels");
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
