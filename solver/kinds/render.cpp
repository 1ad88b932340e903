// render: the colour and depth of a few queried pixels of a scene (issue 4). Only what the
// question needs is modelled: every triangle goes through the geometry stages (cheap), but
// only triangles whose screen bounds hold a queried pixel centre are set up and tested, and
// no frame is allocated. The derivation is a z-buffer trace per pixel: the triangles that
// covered it, in drawing order, with their depths, and the winner.
#include "solver/kinds/render.hpp"

#include <fmt/format.h>

#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/raster/certified_trace.hpp"
#include "solver/raster/frame_work.hpp"

namespace frustum {

namespace {

struct Render {
  static constexpr const char* kName = "render";
  static constexpr const char* kSummary =
      "colour and depth of queried pixels of a rendered scene (z-buffer trace)";
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
    return {{"pixels", AnswerKind::Matrix, {}, {}},
            {"color", AnswerKind::Matrix, {}, {}},
            {"depth", AnswerKind::Vector, {}, {}},
            {"object", AnswerKind::Sequence, {}, {}}};
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
          "Conventions and model",
          std::string("Pixel (i, j) is counted in the ") +
              (window_y_down(api) ? "y-down window (row 0 at the top)"
                                  : "y-up window (row 0 at the bottom)") +
              " and has its centre at (i + ½, j + ½). Triangles are clipped in homogeneous clip "
              "space, divided "
              "by w, mapped by the viewport, snapped to 1/256 pixel and covered under the top-left "
              "rule; depth "
              "is window z in [0, 1], interpolated as the plane through the snapped vertices (z/w "
              "is affine "
              "in screen space) and stored as a 32-bit float. The depth buffer starts at 1 (far) "
              "and a "
              "fragment is written when its depth is less than the stored one (equal keeps the "
              "earlier). "
              "Every decision (clipping, facing, snapping, the depth test) is exact: taken on the "
              "computed "
              "values when their error bound proves it, else by exact arithmetic on the given "
              "numbers. " +
              (scene.light
                   ? fmt::format("Lighting as Processing's lights(): ambient {} + directional {} "
                                 "travelling along ({:.4g}, {:.4g}, {:.4g}), flat and two-sided.",
                                 scene.light->ambient, scene.light->diffuse,
                                 scene.light->direction(0), scene.light->direction(1),
                                 scene.light->direction(2))
                   : std::string("No light: each triangle has its fill colour.")));
    }
    // The exact projection · camera, for the decisions the computed values cannot settle.
    const FlatScene flat = flatten(scene);
    CertifiedScene cs = certified_geometry(scene, flat, exact_clip_from_world(g.spec, api, steps));
    const GeometryStats& gs = cs.stats;
    if (steps) {
      Step& geometry =
          steps->add("Geometry: model → world → clip → window", {}, {},
                     counts({{gs.triangles, "triangles"}}) + math(": ", "\\colon ") +
                         counts({{gs.outside, "outside the view volume"},
                                 {gs.clipped, "clipped"},
                                 {gs.culled, "back faces culled"}}) +
                         math(" → ", " \\to ") + counts({{gs.window, "window triangles"}}));
      geometry.note = fmt::format(
          "{} objects. Only the queried pixels are resolved: a triangle competes for a pixel when "
          "its screen bounds hold the pixel centre; no {} × {} frame is allocated.",
          flat.objects.size(), scene.width, scene.height);
      if (cs.exact_geometry > 0)
        geometry.note += fmt::format(
            " Exact arithmetic on the given numbers decided the clipping, facing or snapping "
            "of {} triangle(s) that rounding could not settle.",
            cs.exact_geometry);
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
      std::string trace;
      float stored = kDepthClear;
      for (std::size_t k = 0; k < t.competitors.size(); ++k) {
        const Competitor& c = t.competitors[k];
        if (k == kMaxTraceLines) {
          trace += fmt::format("{}… {} more", kIndent, t.competitors.size() - k);
          break;
        }
        const CertifiedPiece& w = cs.pieces[static_cast<std::size_t>(c.triangle)];
        const WorldTriangle& src = flat.triangles[static_cast<std::size_t>(w.source)];
        trace += fmt::format("{}{}. triangle {} ({} face {}, {}): z = {} {} Z = {} → {}", kIndent,
                             k + 1, w.source, flat.objects[static_cast<std::size_t>(src.object)],
                             src.face, w.front ? "front" : "back", depth_text(c.depth),
                             c.passed ? "<" : "≥", depth_text(stored),
                             c.passed ? "written, colour " + color_text(w.color) : "hidden");
        if (c.passed) stored = c.depth;
      }
      if (t.competitors.empty())
        trace = std::string(kIndent) + "No triangle covers this pixel centre.";
      Step& s = steps->add(
          fmt::format("Pixel ({}, {})", q[0], q[1]),
          math("Z = 1 (", "Z = 1\\ (") + word("cleared") + math("),  F = ", "),\\; F = ") +
              word("background") +
              math(" " + color_text(scene.background), "\\ " + color_text(scene.background)),
          {},
          word("colour") +
              math(" " + color_text(t.color) + ", ", "\\ " + color_text(t.color) + ",\\; ") +
              word("depth") +
              math(" " + depth_text(t.depth) + "  (", "\\ " + depth_text(t.depth) + "\\quad (") +
              word(winner) + math(")"));
      s.note =
          fmt::format("Z-buffer trace, drawing order ({} competitor(s)):", t.competitors.size()) +
          trace;
      if (exact_depths)
        s.note += std::string(kIndent) +
                  "The depth test was decided by exact arithmetic on the given numbers (the "
                  "computed depths were within rounding of each other).";
    }
    std::string shown, shown_latex;
    for (int r = 0; r < pixels.rows; ++r) {
      const std::string row =
          fmt::format("{}, {}, {}, {:.7g}", pixels.numbers[4 * r], pixels.numbers[4 * r + 1],
                      pixels.numbers[4 * r + 2], pixels.numbers[4 * r + 3]);
      shown += (r ? "; " : "") + row;
      shown_latex +=
          (r ? " \\\\ " : "") + fmt::format("{} & {} & {} & {:.7g}", pixels.numbers[4 * r],
                                            pixels.numbers[4 * r + 1], pixels.numbers[4 * r + 2],
                                            pixels.numbers[4 * r + 3]);
    }
    pixels.display = math("[" + shown + "]", "\\begin{bmatrix}" + shown_latex + "\\end{bmatrix}");
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
  // Default generator (issue 6): a 64 × 48 view from (0, 0, 10) of one to three flat coloured
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
