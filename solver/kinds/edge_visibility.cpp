// seed 003: hidden lines of a polyhedron. Each face is front or back by the exact sign of
// D_f = (p_eye − p_i)·n; each edge is visible (front–front), silhouette (front–back, 輪郭線)
// or hidden (back–back). Back-face culling alone removes every hidden surface only for a
// single closed convex polyhedron (the seed's (a)–(d) question).
#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "solver/geometry/polygon_normal.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/steps/kind_steps.hpp"
#include "solver/steps/scene_reader.hpp"
#include "solver/steps/transform_steps.hpp"
#include "solver/steps/viewing_steps.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/viewing/transforms.hpp"
#include "solver/visibility/drawable.hpp"
#include "solver/visibility/edge_classes.hpp"

namespace frustum {

namespace {

// More faces than this and the derivation lists only the counts, not the D_f table.
constexpr std::size_t kMaxTableFaces = 60;

struct EdgeVisibility {
  static constexpr const char* kName = "edge_visibility";
  static constexpr const char* kSummary =
      "front/back faces and visible, silhouette and hidden edges of a polyhedron";
  static constexpr ConventionUse kUses{.api = false, .angles = true, .handedness = true};
  struct Given {
    Mesh mesh;
    std::string solid;  // empty for a given mesh
    std::string field;  // "solid" or "mesh.faces": where a bad mesh is reported
    std::vector<TransformStep> transform;
    Vec3<Exact> eye;
    // A left-handed course under OpenGL's or Processing's winding (counter-clockwise from
    // outside = front): the front normal is n = e₁ × e₀, as in the backface kind. A named
    // solid is listed counter-clockwise from outside in that frame (its faces reversed).
    bool left_handed = false;
  };
  static std::vector<std::string> given_fields() { return {"mesh", "solid", "transform", "eye"}; }
  static std::vector<AnswerSpec> answers() {
    return {{"faces", AnswerKind::WordMap, {}, {"front", "back", "edge_on"}},
            // An edge is an unordered pair of vertices: "1-0" is the edge 0-1.
            {.name = "edges",
             .kind = AnswerKind::WordMap,
             .depends_on = {"faces"},
             .words = {"visible", "silhouette", "hidden"},
             .unordered_pairs = true},
            {.name = "silhouette",
             .kind = AnswerKind::WordList,
             .depends_on = {"edges"},
             .unordered_pairs = true},
            {.name = "hidden",
             .kind = AnswerKind::WordList,
             .depends_on = {"edges"},
             .unordered_pairs = true},
            {"convex", AnswerKind::Bool, {}, {"convex", "not convex"}},
            {"backface_sufficient", AnswerKind::Bool, {"convex"}, {}}};
  }

  static Mesh read_mesh(GivenReader& r) {
    GivenReader m = r.child("mesh", {"vertices", "faces"});
    return frustum::read_mesh(m, 4, 4);
  }

  static Given parse(GivenReader& r, const Conventions& c) {
    Given g;
    if (r.has("mesh") == r.has("solid"))
      r.fail(r.has("mesh") ? "solid" : "mesh", "give exactly one of mesh and solid");
    if (r.has("solid")) {
      g.solid = r.word("solid", solid_names());
      g.mesh = named_solid(g.solid);
      g.field = "solid";
    } else {
      g.mesh = read_mesh(r);
      g.field = "mesh.faces";
    }
    // The `transform` kind's steps in 3D, shear excepted.
    if (r.has("transform"))
      g.transform = read_transform_steps(r, "transform", 3, c,
                                         {.max_count = kMaxGivenListItems, .shear = false});
    g.eye = r.vector<3>("eye");
    g.left_handed = left_handed_columns(c);
    if (g.left_handed && !g.solid.empty()) g.mesh = reversed_faces(g.mesh);
    return g;
  }

  // Each face walked the other way from the same first vertex (a b c d → a d c b).
  static Mesh reversed_faces(Mesh m) {
    for (std::vector<int>& f : m.faces)
      if (!f.empty()) std::reverse(f.begin() + 1, f.end());
    return m;
  }

  // The mesh the computations read: its faces wound so that the usual n = e₀ × e₁ (Newell)
  // is the front normal — in a left-handed course, each face's vertex order reversed.
  static Mesh right_handed_winding(const Given& g, const Mesh& shown) {
    return g.left_handed ? reversed_faces(shown) : shown;
  }

  // Error carried forward: the edge classes of the student's own front and back faces (A), B),
  // C) on the solid's edges), and the silhouette and hidden edges of the student's own classes.
  static Answers carry_forward(const Given& g, const Answers& student) {
    Answers out;
    if (const Value* f = student.find("faces"); f && !f->entries.empty()) try {
        const Mesh mesh = right_handed_winding(g, transformed(g, nullptr));
        const MeshCheck check = check_mesh(mesh);
        std::vector<FaceTest> tests(mesh.faces.size());
        std::vector<bool> given(mesh.faces.size(), false);
        bool readable = check.closed && check.oriented;
        for (const auto& [face, side] : f->entries) {
          const std::size_t k = face.find_first_not_of("0123456789") == std::string::npos &&
                                        !face.empty() && face.size() < 7
                                    ? std::stoul(face)
                                    : mesh.faces.size();
          if (k >= mesh.faces.size()) {
            readable = false;
            break;
          }
          given[k] = true;
          tests[k].facing = side == "front"     ? Facing::Front
                            : side == "edge_on" ? Facing::EdgeOn
                                                : Facing::Back;
        }
        if (readable && std::all_of(given.begin(), given.end(), [](bool b) { return b; })) {
          const std::vector<EdgeClass> classes = classify_edges(check.edges, tests);
          std::vector<std::pair<std::string, std::string>> edges;
          for (std::size_t k = 0; k < classes.size(); ++k)
            edges.emplace_back(check.edges[k].name(), edge_class_word(classes[k]));
          out.set("edges", Value::word_map(edges));
        }
      } catch (const std::exception&) {
        // A solid the kind cannot classify: solving it says why; nothing to carry.
      }
    if (const Value* e = student.find("edges"); e && !e->entries.empty()) {
      std::vector<std::string> silhouette, hidden;
      for (const auto& [edge, kind] : e->entries) {
        if (kind == "silhouette") silhouette.push_back(edge);
        if (kind == "hidden") hidden.push_back(edge);
      }
      out.set("silhouette", Value::word_list(silhouette));
      out.set("hidden", Value::word_list(hidden));
    }
    return out;
  }

  static std::string face_text(const std::vector<int>& face) {
    std::string s;
    for (int v : face) s += (s.empty() ? "" : " ") + std::to_string(v);
    return s;
  }

  static std::string join(const std::vector<std::string>& words) {
    std::string s;
    for (const std::string& w : words) s += (s.empty() ? "" : ", ") + w;
    return s.empty() ? "none" : s;
  }

  // Applies the composite transform to the vertices; a mirror (det < 0) reverses every
  // face so that counter-clockwise from outside still means front.
  static Mesh transformed(const Given& g, Derivation* steps) {
    Mesh mesh = g.mesh;
    if (g.transform.empty()) return mesh;
    MatX<Exact> m = MatX<Exact>::Identity(4, 4);
    for (const TransformStep& a : g.transform) m = canonical(MatX<Exact>(a.matrix * m));
    const int det = filtered_sign(canonical(m.topLeftCorner(3, 3).determinant()));
    if (det == 0)
      throw DomainError("transform",
                        "the transform flattens space (det = 0): the solid has no volume");
    for (Vec3<Exact>& v : mesh.vertices) {
      const std::vector<Exact> p = transform_point(m, std::vector<Exact>{v(0), v(1), v(2)});
      v = Vec3<Exact>(canonical(p[0]), canonical(p[1]), canonical(p[2]));
    }
    if (det < 0)
      for (std::vector<int>& f : mesh.faces) std::reverse(f.begin(), f.end());
    if (steps) {
      std::string order, product, product_latex;
      for (std::size_t i = 0; i < g.transform.size(); ++i) {
        order += fmt::format("{}A{}: {}", i ? "; " : "", i + 1, g.transform[i].title);
        product = fmt::format("A{}", i + 1) + (i ? "·" : "") + product;
        product_latex = fmt::format("A_{{{}}}", i + 1) + product_latex;
      }
      Step& s = steps->add("Transform the solid (first step applied first)",
                           math("M = " + product, "M = " + product_latex), {},
                           math("M = ") + matrix_text(m));
      s.note = order + ". Every vertex moves by P′ = M·P; faces keep their vertex lists.";
      if (det < 0)
        s.note +=
            " det M < 0 mirrors the solid, so every face's vertex order is reversed to stay "
            "counter-clockwise seen from outside.";
    }
    return mesh;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    if (steps && !g.solid.empty()) {
      std::string text = fmt::format("{}: {} vertices, {} faces (counter-clockwise from outside).",
                                     g.solid, g.mesh.vertices.size(), g.mesh.faces.size());
      if (g.solid == "icosahedron" || g.solid == "dodecahedron")
        text += " φ = (1 + √5)/2 is kept exact.";
      steps->note("The solid", text);
    }
    const Mesh shown = transformed(g, steps);
    const Mesh mesh = right_handed_winding(g, shown);
    if (steps && g.left_handed)
      steps->note("Winding in a left-handed frame",
                  "The faces are listed counter-clockwise seen from outside in this "
                  "left-handed frame, where e₀ × e₁ points inward: each face's outward (front) "
                  "normal is n = e₁ × e₀.");
    for (std::size_t f = 0; f < mesh.faces.size() && g.solid.empty(); ++f) {
      const PolygonAnalysis a = analyse_face(mesh, f);
      if (a.degenerate)
        throw DomainError(
            fmt::format("mesh.faces[{}]", f),
            "the face is degenerate: its vertices are collinear, so it has no normal");
      // Front or back is a property of a plane: a face whose vertices are not in one plane
      // has none (its Newell normal would answer anyway).
      if (!a.planar)
        throw DomainError(fmt::format("mesh.faces[{}]", f),
                          fmt::format("the face is not planar: vertex {} is off the plane of the "
                                      "face's other vertices",
                                      mesh.faces[f][a.off_plane_vertex]));
    }
    const MeshCheck check = check_mesh(mesh);
    if (!check.closed || !check.oriented)
      throw DomainError(g.field, check.problem +
                                     " — front/back faces of a closed, consistently "
                                     "oriented polyhedron are needed to classify its edges");
    if (steps)
      steps
          ->add("Closed and consistently oriented", math("V − E + F", "V - E + F"), {},
                math(fmt::format("{} − {} + {} = {}", mesh.vertices.size(), check.edges.size(),
                                 mesh.faces.size(),
                                 static_cast<long>(mesh.vertices.size()) -
                                     static_cast<long>(check.edges.size()) +
                                     static_cast<long>(mesh.faces.size())),
                     fmt::format("{} - {} + {} = {}", mesh.vertices.size(), check.edges.size(),
                                 mesh.faces.size(),
                                 static_cast<long>(mesh.vertices.size()) -
                                     static_cast<long>(check.edges.size()) +
                                     static_cast<long>(mesh.faces.size()))))
          .note = "Every edge joins exactly two faces, which walk it in opposite directions.";

    // Front or back per face (seed 003).
    const std::vector<Vec3<Exact>> normals = face_normals(mesh);
    const std::vector<FaceTest> tests = face_tests(mesh, normals, g.eye);
    Answers out;
    std::vector<std::pair<std::string, std::string>> faces;
    std::string table;
    std::vector<std::string> edge_on;
    for (std::size_t f = 0; f < tests.size(); ++f) {
      faces.emplace_back(std::to_string(f), facing_word(tests[f].facing));
      if (tests[f].facing == Facing::EdgeOn) edge_on.push_back(std::to_string(f));
      if (f < kMaxTableFaces)
        table += fmt::format("\nface {} [{}]: n = {}, D_f = {} → {}", f, face_text(shown.faces[f]),
                             vec(normals[f]).unicode, exact(tests[f].df, true).unicode,
                             facing_word(tests[f].facing));
    }
    out.set("faces", Value::word_map(faces));
    if (steps) {
      Step& s = steps->add(
          "Front or back per face",
          math("D_f = (p_eye − p_i)·n",
               "D_f = (\\mathbf{p}_{\\text{eye}} - \\mathbf{p}_i)\\cdot\\mathbf{n}"),
          math("p_eye = ", "\\mathbf{p}_{\\text{eye}} = ") + vec(g.eye),
          counts({{std::count_if(tests.begin(), tests.end(),
                                 [](const FaceTest& t) { return t.facing == Facing::Front; }),
                   "front"},
                  {std::count_if(tests.begin(), tests.end(),
                                 [](const FaceTest& t) { return t.facing == Facing::Back; }),
                   "back"},
                  {static_cast<long>(edge_on.size()), "edge-on"}}));
      s.note =
          "D_f > 0: front; D_f < 0: back (p_i is the face's first vertex, n its normal, "
          "counter-clockwise = front)." +
          table;
      steps->yields("faces");
      if (!edge_on.empty())
        steps->note(
            "Edge-on faces",
            "Face(s) " + join(edge_on) +
                " have D_f = 0 exactly: the eye lies in their plane, "
                "so they cover no area on screen. They count as back for the edge classes, as "
                "back-face culling treats them.");
    }

    // Edge classes A), B), C).
    const std::vector<EdgeClass> classes = classify_edges(check.edges, tests);
    std::vector<std::pair<std::string, std::string>> edges;
    std::vector<std::string> silhouette, hidden, visible;
    for (std::size_t k = 0; k < classes.size(); ++k) {
      const std::string name = check.edges[k].name();
      edges.emplace_back(name, edge_class_word(classes[k]));
      (classes[k] == EdgeClass::Silhouette ? silhouette
       : classes[k] == EdgeClass::Hidden   ? hidden
                                           : visible)
          .push_back(name);
    }
    out.set("edges", Value::word_map(edges));
    out.set("silhouette", Value::word_list(silhouette));
    out.set("hidden", Value::word_list(hidden));
    if (steps) {
      std::vector<std::string> front_edges = visible;
      front_edges.insert(front_edges.end(), silhouette.begin(), silhouette.end());
      steps
          ->add("Edge classes",
                word("front") + math("–", "\\text{–}") + word("front") + math(": ", "\\colon ") +
                    word("visible") + math(";  ", ";\\; ") + word("front") +
                    math("–", "\\text{–}") + word("back") + math(": ", "\\colon ") +
                    word("silhouette") + math(";  ", ";\\; ") + word("back") +
                    math("–", "\\text{–}") + word("back") + math(": ", "\\colon ") + word("hidden"),
                {},
                counts({{static_cast<long>(visible.size()), "visible"},
                        {static_cast<long>(silhouette.size()), "silhouette"},
                        {static_cast<long>(hidden.size()), "hidden"}}))
          .note =
          "An edge is classified by the two faces that share it. Hidden-line "
          "drawing = the edges of the front faces (visible + silhouette): " +
          join(front_edges) + ".";
      steps->yields("edges");
    }

    // Convexity: every vertex on the inner side of every face plane.
    std::string witness;
    const bool convex = is_convex(mesh, normals, &witness);
    out.set("convex", Value::boolean(convex));

    if (steps) {
      const SilhouetteLoops loops = silhouette_loops(check.edges, classes);
      std::string loop_text;
      for (const std::vector<int>& loop : loops.loops) {
        std::string s;
        for (int v : loop) s += (s.empty() ? "" : " → ") + std::to_string(v);
        loop_text += (loop_text.empty() ? "" : ";  ") + s;
      }
      Step& s = steps->add("Silhouette: the front–back edges", {}, {},
                           silhouette.empty() ? word("none") : word(join(silhouette)));
      if (loops.ok && !loops.loops.empty())
        s.note = fmt::format("Chained by shared vertices: {} ({} loop{}).", loop_text,
                             loops.loops.size(), loops.loops.size() == 1 ? "" : "s") +
                 (convex ? " A convex polyhedron's silhouette is one closed loop, a convex polygon "
                           "on screen."
                         : "");
      else if (!loops.ok)
        s.note = "The silhouette edges do not chain into simple loops (the solid is not convex).";
      steps->yields("silhouette");
      steps
          ->add("Hidden edges: the back–back edges", {}, {},
                hidden.empty() ? word("none") : word(join(hidden)))
          .note = "Drawing only these shows the lines that should be hidden.";
      steps->yields("hidden");
      steps
          ->add("Convex?",
                math("n_f·(v − p_f) ≤ 0  ∀ v, f",
                     "\\mathbf{n}_f\\cdot(\\mathbf{v} - \\mathbf{p}_f) \\le 0 \\quad "
                     "\\forall\\, \\mathbf{v}, f"),
                {}, word(convex ? "convex" : "not convex"))
          .note = convex ? "Every vertex lies on the inner side of (or on) every face plane."
                         : "Not convex: " + witness + ".";
      steps->yields("convex");
    }
    out.set("backface_sufficient", Value::boolean(convex));
    if (steps) {
      steps->add("Back-face culling alone?", {}, {}, word(convex ? "yes" : "no")).note =
          convex ? "A single closed convex polyhedron: no front face can hide another, so "
                   "culling the back faces removes every hidden surface."
                 : "Not convex: from some viewpoints a front face hides part of another front "
                   "face, so back-face culling alone does not always remove the hidden surfaces; "
                   "a depth test is still needed.";
      steps->yields("backface_sufficient");
    }
    return out;
  }

  // `frustum draw`: the transformed mesh seen from the eye, hidden lines removed per segment.
  static Drawable drawable(const Given& g) {
    Drawable d;
    d.picture = Drawable::Picture::HiddenLines;
    d.mesh = right_handed_winding(g, transformed(g, nullptr));
    d.left_handed = g.left_handed;
    const MeshCheck check = check_mesh(d.mesh);
    if (!check.closed || !check.oriented)
      throw DomainError(g.field, check.problem +
                                     " — the hidden-line picture needs a closed, consistently "
                                     "oriented polyhedron");
    d.viewer.eye = g.eye;
    return d;
  }

  static PolygonAnalysis analyse_face(const Mesh& m, std::size_t f) {
    Polygon3<Exact> p;
    for (int k : m.faces[f]) p.push_back(m.vertices[static_cast<std::size_t>(k)]);
    return analyse_polygon(p);
  }
  // Default generator: one of the five solids seen from an integer eye at distance ≥ 5 (outside
  // every solid); hard: the eye in a face's plane (cube face x = ±1 or octahedron face
  // x + y + z = 1), so that face is edge-on.
  static YAML::Node generate(Rng& rng, const GenerateOptions& o) {
    YAML::Node g;
    IVec3 eye{};
    if (o.hard && rng.chance(1, 2)) {
      g["solid"] = gen_word("cube");
      const IVec3 e = {rng.pick(std::vector<std::int64_t>{-1, 1}), rng.nonzero(-5, 5) * 2,
                       rng.integer(-5, 5)};
      const auto shift = rng.below(3);
      for (std::size_t i = 0; i < 3; ++i) eye[(i + shift) % 3] = e[i];
    } else if (o.hard) {
      g["solid"] = gen_word("octahedron");
      const std::int64_t a = rng.integer(2, 5), b = rng.integer(-5, 5);
      eye = {a, b, 1 - a - b};
    } else {
      g["solid"] = gen_word(rng.pick(solid_names()));
      do {
        eye = gen_ivec3(rng, -9, 9);
      } while (idot(eye, eye) < 25);
    }
    g["eye"] = gen_list(to_list(eye));
    return g;
  }

  static std::string ill_conditioned(const Given&, const Answers& a) {
    if (const Value* f = a.find("faces"))
      for (const auto& [face, word] : f->entries)
        if (word == "edge_on") return "the eye is in the plane of face " + face;
    return "";
  }
};

}  // namespace

KindInfo edge_visibility_kind() {
  KindInfo k = make_kind<EdgeVisibility>();
  k.order = 170;
  k.doc_given = "`mesh` {`vertices`, `faces`} or `solid` (+ `transform`), `eye`";
  k.doc_answers = "`faces`, `edges`, `silhouette`, `hidden`, `convex`, `backface_sufficient`";
  return k;
}

}  // namespace frustum
