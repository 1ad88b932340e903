// Front/back faces and the three classes of edges of a closed polyhedron (seed 003):
//   A) both faces front: visible;  B) front and back: silhouette (輪郭線);  C) both back: hidden.
// For a single convex polyhedron this is exact hidden-line removal: the drawing is the edges
// of the front faces, and the silhouette is one closed loop.
#pragma once

#include <string>
#include <vector>

#include "solver/geometry/predicates.hpp"
#include "solver/visibility/mesh.hpp"

namespace frustum {

using Facing = FacingSide;  // facing_side(sign) and facing_word(f): predicates.hpp
enum class EdgeClass { Visible, Silhouette, Hidden };

const char* edge_class_word(EdgeClass c);  // "visible", "silhouette", "hidden"

struct FaceTest {
  Exact df;  // D_f = (p_eye − p_i)·n, p_i the face's first vertex
  Facing facing = Facing::Back;
};

// D_f and its exact sign for every face.
std::vector<FaceTest> face_tests(const Mesh& m, const std::vector<Vec3<Exact>>& normals,
                                 const Vec3<Exact>& eye);

// Whether a face counts as front for the edge classes. A face seen exactly edge-on
// (D_f = 0) counts as back, as back-face culling treats it (it covers no area on screen);
// the silhouette then runs along its front neighbour and stays one loop.
inline bool counts_as_front(Facing f) { return f == Facing::Front; }

// The class of every edge of a closed, consistently oriented mesh (edges as check_mesh
// returns them, two faces each).
std::vector<EdgeClass> classify_edges(const std::vector<MeshEdge>& edges,
                                      const std::vector<FaceTest>& faces);

// The silhouette edges chained into closed loops of vertex indices (first vertex repeated
// at the end). A convex polyhedron seen from outside gives exactly one loop; `ok` is false
// when the edges do not chain (a vertex met by other than two silhouette edges).
struct SilhouetteLoops {
  std::vector<std::vector<int>> loops;
  bool ok = true;
};
SilhouetteLoops silhouette_loops(const std::vector<MeshEdge>& edges,
                                 const std::vector<EdgeClass>& classes);

}  // namespace frustum
