// seed 003: hidden lines of a polyhedron. Each face is front or back by the exact sign of
// D_f = (p_eye − p_i)·n; each edge is visible (front–front), silhouette (front–back, 輪郭線)
// or hidden (back–back). Back-face culling alone removes every hidden surface only for a
// single closed convex polyhedron (the seed's (a)–(d) question).
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include "solver/derivation/vocabulary.hpp"
#include "solver/geometry/polygon_normal.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/shared/derivation_parts.hpp"
#include "solver/shared/scene_reader.hpp"
#include "solver/shared/transform_steps.hpp"
#include "solver/shared/viewing_parts.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/viewing/transforms.hpp"
#include "solver/visibility/drawable.hpp"
#include "solver/visibility/edge_classes.hpp"

namespace frustum {

namespace {

// The answers' names on an exam sheet (in English, the name the answers file uses).
constexpr Phrase kFaces{"faces", "面", "грани"};
constexpr Phrase kSilhouetteEdges{"silhouette", "輪郭線", "контурные рёбра"};
constexpr Phrase kHiddenEdges{"hidden", "不可視の稜線", "невидимые рёбра"};
constexpr Phrase kIsConvex{"convex", "凸か", "выпуклый ли"};
constexpr Phrase kBackfaceSufficient{"backface_sufficient", "バックフェースカリングだけで十分か",
                                     "достаточно ли отсечения нелицевых граней"};

// More faces than this and the derivation lists only the counts, not the D_f table.
constexpr std::size_t kMaxTableFaces = 60;

// The solid and its transform.
constexpr Phrase kTheSolid{"The solid", "立体", "Тело"};
constexpr Phrase kSolidCounts{
    "{0}: {1} vertices, {2} faces (counter-clockwise from outside).",
    "{0}: 頂点 {1} 個, 面 {2} 個 (外から見て反時計回り).",
    "{0}: {1} вершин, {2} граней (против часовой стрелки, если смотреть снаружи)."};
constexpr Phrase kPhiKeptExact{"φ = (1 + √5)/2 is kept exact.", "φ = (1 + √5)/2 は厳密に扱う.",
                               "φ = (1 + √5)/2 хранится точно."};
constexpr Phrase kTetrahedron{"tetrahedron", "正四面体", "тетраэдр"};
constexpr Phrase kCube{"cube", "立方体", "куб"};
constexpr Phrase kOctahedron{"octahedron", "正八面体", "октаэдр"};
constexpr Phrase kDodecahedron{"dodecahedron", "正十二面体", "додекаэдр"};
constexpr Phrase kIcosahedron{"icosahedron", "正二十面体", "икосаэдр"};
constexpr Phrase kTransformTheSolid{"Transform the solid (first step applied first)",
                                    "立体を変換 (最初のステップを最初に適用)",
                                    "Преобразование тела (первый шаг применяется первым)"};
constexpr Phrase kEveryVertexMoves{
    "Every vertex moves by P′ = M·P; faces keep their vertex lists.",
    "各頂点は P′ = M·P で移り, 面の頂点リストは変わらない.",
    "Каждая вершина переходит по P′ = M·P; грани сохраняют свои списки вершин."};
constexpr Phrase kDetMirrors{
    "det M < 0 mirrors the solid, so every face's vertex order is reversed to stay "
    "counter-clockwise seen from outside.",
    "det M < 0 なので立体は鏡映される. 外側から見て反時計回りのままになるよう, "
    "各面の頂点の順序を逆にする.",
    "det M < 0 — тело зеркально отражается, поэтому порядок вершин каждой грани обращается, чтобы "
    "он оставался против часовой стрелки при взгляде снаружи."};
constexpr Phrase kFacesListedLeftHanded{
    "The faces are listed counter-clockwise seen from outside in this left-handed frame, where e₀ "
    "× e₁ points inward: each face's outward (front) normal is n = e₁ × e₀.",
    "この左手系では各面の頂点は外側から見て反時計回りに並べられ, e₀ × e₁ は内側を向く. "
    "各面の外向き(表側)の法線は n = e₁ × e₀ である.",
    "В этой левой системе координат вершины каждой грани перечислены против часовой стрелки при "
    "взгляде снаружи, и e₀ × e₁ направлен внутрь: внешняя (лицевая) нормаль каждой грани — n = e₁ "
    "× e₀."};
constexpr Phrase kClosedAndOriented{"Closed and consistently oriented",
                                    "閉じていて向きがそろっている",
                                    "Замкнут и ориентирован согласованно"};
constexpr Phrase kEveryEdgeJoinsTwo{
    "Every edge joins exactly two faces, which walk it in opposite directions.",
    "どの辺もちょうど 2 つの面に共有され, 2 つの面はその辺を逆向きにたどる.",
    "Каждое ребро соединяет ровно две грани, которые обходят его в противоположных направлениях."};
// Faces.
constexpr Phrase kFrontOrBackPerFace{"Front or back per face", "各面の表裏",
                                     "Лицевая или обратная для каждой грани"};
constexpr Phrase kDfSign{
    "D_f > 0: front; D_f < 0: back (p_i is the face's first vertex, n its normal, "
    "counter-clockwise = front).",
    "D_f > 0: 表, D_f < 0: 裏 (p_i は面の最初の頂点, n はその法線, 反時計回り = 表).",
    "D_f > 0: лицевая; D_f < 0: обратная (p_i — первая вершина грани, n — её нормаль, против "
    "часовой стрелки = лицевая)."};
constexpr Phrase kFaceLine{"face {0}: n = {1}, D_f = {2} → {3}", "面 {0}: n = {1}, D_f = {2} → {3}",
                           "грань {0}: n = {1}, D_f = {2} → {3}"};
constexpr Phrase kEdgeOnFaces{"Edge-on faces", "真横から見た面", "Грани, видимые с ребра"};
constexpr Phrase kFacesHaveDfZero{
    "Face(s) {0} have D_f = 0 exactly: the eye lies in their plane, so they cover no area on "
    "screen.",
    "面 {0} は D_f = 0 (厳密): 視点がその平面上にあるので, 画面上で面積を持たない.",
    "У граней {0} D_f = 0 точно: глаз лежит в их плоскости, поэтому на экране они не занимают "
    "площади."};
constexpr Phrase kCountAsBack{
    "They count as back for the edge classes, as back-face culling treats them.",
    "稜線の分類では, バックフェースカリングと同じく裏として扱う.",
    "При классификации рёбер они считаются обратными, как их и трактует отсечение нелицевых "
    "граней."};
// Edges, silhouette, convexity.
constexpr Phrase kEdgeClasses{"Edge classes", "稜線の分類", "Классы рёбер"};
constexpr Phrase kEdgeClassifiedByFaces{
    "An edge is classified by the two faces that share it.",
    "稜線はそれを共有する 2 つの面で分類される.",
    "Ребро классифицируется по двум граням, которые его разделяют."};
constexpr Phrase kHiddenLineDrawing{
    "Hidden-line drawing = the edges of the front faces (visible + silhouette): {0}.",
    "隠線消去した図 = 表の面の稜線 (見える稜線 + 輪郭線): {0}.",
    "Рисунок с удалёнными невидимыми линиями = рёбра лицевых граней (видимые + силуэт): {0}."};
constexpr Phrase kSilhouetteTitle{"Silhouette: the front–back edges", "輪郭線: 表と裏の境の辺",
                                  "Силуэт: рёбра между лицевой и обратной гранями"};
constexpr Phrase kChainedOneLoop{"Chained by shared vertices: {0} ({1} loop).",
                                 "共有する頂点でつなぐ: {0} (ループ {1} 個).",
                                 "Связаны общими вершинами: {0} ({1} контур)."};
constexpr Phrase kChainedLoops{"Chained by shared vertices: {0} ({1} loops).",
                               "共有する頂点でつなぐ: {0} (ループ {1} 個).",
                               "Связаны общими вершинами: {0} (контуров: {1})."};
constexpr Phrase kConvexSilhouette{
    "A convex polyhedron's silhouette is one closed loop, a convex polygon on screen.",
    "凸多面体の輪郭線は閉じたループ一つで, 画面上では凸多角形になる.",
    "Силуэт выпуклого многогранника — один замкнутый контур, выпуклый многоугольник на экране."};
constexpr Phrase kNotSimpleLoops{
    "The silhouette edges do not chain into simple loops (the solid is not convex).",
    "輪郭線の辺は単純なループにつながらない (立体は凸でない).",
    "Рёбра силуэта не складываются в простые контуры (тело невыпуклое)."};
constexpr Phrase kHiddenEdgesTitle{"Hidden edges: the back–back edges", "隠れる稜線: 裏と裏の辺",
                                   "Невидимые рёбра: между двумя обратными гранями"};
constexpr Phrase kDrawingOnlyThese{
    "Drawing only these shows the lines that should be hidden.",
    "これらだけを描くと, 隠れるべき線が見える.",
    "Если рисовать только их, видны линии, которые должны быть скрыты."};
constexpr Phrase kConvexQ{"Convex?", "凸か?", "Выпуклый?"};
constexpr Phrase kEveryVertexInside{
    "Every vertex lies on the inner side of (or on) every face plane.",
    "どの頂点もすべての面の平面の内側 (または平面上) にある.",
    "Каждая вершина лежит с внутренней стороны каждой плоскости грани (или на ней)."};
constexpr Phrase kNotConvexWitness{"Not convex: vertex {0} lies outside the plane of face {1}.",
                                   "凸でない: 頂点 {0} は面 {1} の平面の外側にある.",
                                   "Невыпуклый: вершина {0} лежит снаружи плоскости грани {1}."};
constexpr Phrase kBackfaceAloneQ{"Back-face culling alone?", "バックフェースカリングだけで十分か?",
                                 "Достаточно ли отсечения нелицевых граней?"};
constexpr Phrase kSingleConvexPolyhedron{
    "A single closed convex polyhedron: no front face can hide another, so culling the back faces "
    "removes every hidden surface.",
    "閉じた凸多面体が一つだけ: 表の面が他の面を隠すことはないので, "
    "裏面を除去すれば隠面はすべて消える.",
    "Один замкнутый выпуклый многогранник: лицевая грань не может закрыть другую, поэтому "
    "отсечение нелицевых граней удаляет все невидимые поверхности."};
constexpr Phrase kNotConvexNeedsDepthTest{
    "Not convex: from some viewpoints a front face hides part of another front face, so back-face "
    "culling alone does not always remove the hidden surfaces; a depth test is still needed.",
    "凸でない: 視点によっては表の面が別の表の面の一部を隠すので, "
    "バックフェースカリングだけでは隠面がいつも消えるとは限らない. 奥行きテストが必要.",
    "Невыпуклый: при некоторых положениях глаза лицевая грань закрывает часть другой лицевой "
    "грани, поэтому одно отсечение нелицевых граней не всегда удаляет невидимые поверхности; нужен "
    "ещё тест глубины."};

// A named solid in words.
Said solid_word(const std::string& name) {
  static constexpr std::pair<const char*, const Phrase*> kSolids[] = {
      {"tetrahedron", &kTetrahedron},
      {"cube", &kCube},
      {"octahedron", &kOctahedron},
      {"dodecahedron", &kDodecahedron},
      {"icosahedron", &kIcosahedron}};
  for (const auto& [key, phrase] : kSolids)
    if (name == key) return say(*phrase);
  return Said::verbatim(name);
}

// A transform step's title as the `transform` reader writes it ("translate (0, 0, −10)"): a
// translation, a scaling and a rotation about an axis in words; rotate_x, rotate_y and rotate_z
// with their angle stay as written, the set's own key.
const Phrase& facing_phrase(Facing f) {
  return f == Facing::Front ? words::kFront : f == Facing::Back ? words::kBack : words::kEdgeOnKey;
}

struct EdgeVisibility {
  static constexpr const char* kName = "edge_visibility";
  static constexpr Phrase kSummary{
      "front/back faces and visible, silhouette and hidden edges of a polyhedron",
      "多面体の表/裏の面と, 見える稜線, 輪郭線, 隠れる稜線",
      "лицевые и нелицевые грани многогранника, его видимые, контурные и невидимые рёбра"};
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
    return {{.name = "faces",
             .kind = AnswerKind::WordMap,
             .words = {"front", "back", "edge_on"},
             .label = say(kFaces)},
            // An edge is an unordered pair of vertices: "1-0" is the edge 0-1.
            {.name = "edges",
             .kind = AnswerKind::WordMap,
             .depends_on = {"faces"},
             .words = {"visible", "silhouette", "hidden"},
             .unordered_pairs = true,
             .label = say(words::kEdges)},
            {.name = "silhouette",
             .kind = AnswerKind::WordList,
             .depends_on = {"edges"},
             .unordered_pairs = true,
             .label = say(kSilhouetteEdges)},
            {.name = "hidden",
             .kind = AnswerKind::WordList,
             .depends_on = {"edges"},
             .unordered_pairs = true,
             .label = say(kHiddenEdges)},
            {.name = "convex",
             .kind = AnswerKind::Bool,
             .words = {"convex", "not convex"},
             .label = say(kIsConvex)},
            {.name = "backface_sufficient",
             .kind = AnswerKind::Bool,
             .depends_on = {"convex"},
             .label = say(kBackfaceSufficient)}};
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

  static std::string join(const std::vector<std::string>& names) {
    std::string s;
    for (const std::string& w : names) s += (s.empty() ? "" : ", ") + w;
    return s;
  }

  // Edges or faces by their numbers, or "none".
  static Said listed(const std::vector<std::string>& names) {
    return names.empty() ? say(words::kNone) : Said::verbatim(join(names));
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
      Said order;
      std::string product;
      for (std::size_t i = 0; i < g.transform.size(); ++i) {
        if (i) order.append(Said::verbatim("; "));
        order.append(say(kStepTitle, i + 1, g.transform[i].heading));
        product = fmt::format("A_{{{}}}", i + 1) + (i ? "\\," : "") + product;
      }
      order.append(Said::verbatim("."));
      Step& s = steps->add(say(kTransformTheSolid), tex("M = " + product), {},
                           math("M = ") + matrix_text(m));
      s.note = order + say(kEveryVertexMoves);
      if (det < 0) s.note += say(kDetMirrors);
    }
    return mesh;
  }

  static Answers solve(const Given& g, Derivation* steps) {
    if (steps && !g.solid.empty()) {
      Said text =
          say(kSolidCounts, solid_word(g.solid), g.mesh.vertices.size(), g.mesh.faces.size());
      if (g.solid == "icosahedron" || g.solid == "dodecahedron") text += say(kPhiKeptExact);
      steps->note(say(kTheSolid), text);
    }
    const Mesh shown = transformed(g, steps);
    const Mesh mesh = right_handed_winding(g, shown);
    if (steps && g.left_handed) steps->note(say(kWindingLeftHanded), say(kFacesListedLeftHanded));
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
          ->add(
              say(kClosedAndOriented), tex("V - E + F"), {},
              tex(fmt::format(
                  "{} - {} + {} = {}", mesh.vertices.size(), check.edges.size(), mesh.faces.size(),
                  static_cast<long>(mesh.vertices.size()) - static_cast<long>(check.edges.size()) +
                      static_cast<long>(mesh.faces.size()))))
          .note = say(kEveryEdgeJoinsTwo);

    // Front or back per face (seed 003).
    const std::vector<Vec3<Exact>> normals = face_normals(mesh);
    const std::vector<FaceTest> tests = face_tests(mesh, normals, g.eye);
    Answers out;
    std::vector<std::pair<std::string, std::string>> faces;
    Said table;
    std::vector<std::string> edge_on;
    for (std::size_t f = 0; f < tests.size(); ++f) {
      faces.emplace_back(std::to_string(f), facing_word(tests[f].facing));
      if (tests[f].facing == Facing::EdgeOn) edge_on.push_back(std::to_string(f));
      if (steps && f < kMaxTableFaces)
        table.append(Said::verbatim("\n"))
            .append(say(kFaceLine, fmt::format("{} [{}]", f, face_text(shown.faces[f])),
                        vec(normals[f]).unicode, exact(tests[f].df, true).unicode,
                        facing_phrase(tests[f].facing)));
    }
    out.set("faces", Value::word_map(faces));
    if (steps) {
      Step& s =
          steps
              ->add(
                  say(kFrontOrBackPerFace),
                  tex("D_f = (\\mathbf{p}_{\\text{eye}} - \\mathbf{p}_i)\\cdot\\mathbf{n}"),
                  tex("\\mathbf{p}_{\\text{eye}} = ") + vec(g.eye),
                  counts(
                      {{std::count_if(tests.begin(), tests.end(),
                                      [](const FaceTest& t) { return t.facing == Facing::Front; }),
                        "front"},
                       {std::count_if(tests.begin(), tests.end(),
                                      [](const FaceTest& t) { return t.facing == Facing::Back; }),
                        "back"},
                       {static_cast<long>(edge_on.size()), "edge-on"}}))
              .yields("faces");
      s.note = say(kDfSign).append(table);
      if (!edge_on.empty())
        steps->note(say(kEdgeOnFaces), say(kFacesHaveDfZero, join(edge_on)) + say(kCountAsBack));
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
          ->add(say(kEdgeClasses),
                word(words::kFront) + tex("\\text{–}") + word(words::kFront) + tex("\\colon ") +
                    word(words::kVisible) + tex(";\\; ") + word(words::kFront) + tex("\\text{–}") +
                    word(words::kBack) + tex("\\colon ") + word(words::kSilhouette) + tex(";\\; ") +
                    word(words::kBack) + tex("\\text{–}") + word(words::kBack) + tex("\\colon ") +
                    word(words::kHidden),
                {},
                counts({{static_cast<long>(visible.size()), "visible"},
                        {static_cast<long>(silhouette.size()), "silhouette"},
                        {static_cast<long>(hidden.size()), "hidden"}}))
          .yields("edges")
          .note = say(kEdgeClassifiedByFaces) + say(kHiddenLineDrawing, listed(front_edges));
    }

    // Convexity: every vertex on the inner side of every face plane.
    ConvexityWitness witness;
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
      Step& s =
          steps->add(say(kSilhouetteTitle), {}, {}, word(listed(silhouette))).yields("silhouette");
      if (loops.ok && !loops.loops.empty()) {
        s.note = say(loops.loops.size() == 1 ? kChainedOneLoop : kChainedLoops, loop_text,
                     loops.loops.size());
        if (convex) s.note += say(kConvexSilhouette);
      } else if (!loops.ok) {
        s.note = say(kNotSimpleLoops);
      }
      steps->add(say(kHiddenEdgesTitle), {}, {}, word(listed(hidden))).yields("hidden").note =
          say(kDrawingOnlyThese);
      steps
          ->add(say(kConvexQ),
                tex("\\mathbf{n}_f\\cdot(\\mathbf{v} - \\mathbf{p}_f) \\le 0 \\quad "
                    "\\forall\\, \\mathbf{v}, f"),
                {}, word(convex ? words::kConvex : words::kNotConvex))
          .yields("convex")
          .note =
          convex ? say(kEveryVertexInside) : say(kNotConvexWitness, witness.vertex, witness.face);
    }
    out.set("backface_sufficient", Value::boolean(convex));
    if (steps)
      steps->add(say(kBackfaceAloneQ), {}, {}, word(convex ? words::kYes : words::kNo))
          .yields("backface_sufficient")
          .note = say(convex ? kSingleConvexPolyhedron : kNotConvexNeedsDepthTest);
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
