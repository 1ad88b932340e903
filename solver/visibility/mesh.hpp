// Polyhedral meshes as exact data (seed 003): vertex coordinates plus, per face, the vertex
// indices in counter-clockwise order seen from outside (= the front). Checks that a mesh is
// closed and consistently oriented, and whether it is convex, all decided exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/core/matrix.hpp"

namespace frustum {

struct Mesh {
  std::vector<Vec3<Exact>> vertices;
  std::vector<std::vector<int>> faces;  // counter-clockwise seen from outside
};

// The five regular solids, centred at the origin. Vertices are the textbook coordinates
// (the icosahedron's (0, ±1, ±φ) and cyclic, the dodecahedron's (±1, ±1, ±1), (0, ±1/φ, ±φ)
// and cyclic, φ = (1 + √5)/2 exactly); the cube keeps seed 003's numbering (top 0 1 2 3,
// bottom 4 7 6 5, right 1 5 6 2, left 0 3 7 4, front 0 4 5 1, back 3 2 6 7; y up, z front).
const std::vector<std::string>& solid_names();
// Throws std::invalid_argument for a name not in solid_names().
Mesh named_solid(const std::string& name);

// An edge i-j (i < j) and the faces on its two sides: `forward` walks i → j, `backward`
// walks j → i. In a closed, consistently oriented mesh each edge has exactly one of each.
struct MeshEdge {
  int i = 0, j = 0;
  std::vector<int> forward, backward;
  std::string name() const;  // "i-j"
};

// Every edge, sorted by (i, j).
std::vector<MeshEdge> mesh_edges(const Mesh& m);

struct MeshCheck {
  bool closed = true;    // every edge shared by exactly two faces
  bool oriented = true;  // each shared edge walked in opposite directions by its two faces
  std::string bad_edge;  // the first offending edge "i-j" (empty when both hold)
  std::string problem;   // why, in a sentence
  std::vector<MeshEdge> edges;
};
MeshCheck check_mesh(const Mesh& m);

// Face normals by Newell's method (e₀ × e₁ for triangles), exact and canonical.
std::vector<Vec3<Exact>> face_normals(const Mesh& m);

// Why a solid is not convex: a vertex outside (on the outer side of) a face's plane.
struct ConvexityWitness {
  std::size_t vertex = 0, face = 0;
};

// Convex: every vertex on the inner side of (or on) every face plane, n_f·(v − p_f) ≤ 0,
// decided exactly. `witness` gets a vertex outside a face's plane when it is not.
bool is_convex(const Mesh& m, const std::vector<Vec3<Exact>>& normals,
               ConvexityWitness* witness = nullptr);

// Sign of an exact value: doubles decide when the value is clearly away from zero, exact
// arithmetic (exact_sign) decides the rest.
int filtered_sign(const Exact& e);

}  // namespace frustum
