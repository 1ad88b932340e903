#include "solver/visibility/edge_classes.hpp"

#include <map>

#include "solver/geometry/predicates.hpp"

namespace frustum {

const char* edge_class_word(EdgeClass c) {
  switch (c) {
    case EdgeClass::Visible:
      return "visible";
    case EdgeClass::Silhouette:
      return "silhouette";
    case EdgeClass::Hidden:
      return "hidden";
  }
  return "hidden";
}

std::vector<FaceTest> face_tests(const Mesh& m, const std::vector<Vec3<Exact>>& normals,
                                 const Vec3<Exact>& eye) {
  std::vector<FaceTest> out;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Vec3<Exact>& p = m.vertices[static_cast<std::size_t>(m.faces[f][0])];
    FaceTest t;
    t.df = canonical((eye - p).dot(normals[f]));
    const int s = filtered_sign(t.df);
    t.facing = facing_side(s);
    out.push_back(t);
  }
  return out;
}

std::vector<EdgeClass> classify_edges(const std::vector<MeshEdge>& edges,
                                      const std::vector<FaceTest>& faces) {
  std::vector<EdgeClass> out;
  for (const MeshEdge& e : edges) {
    int front = 0;
    for (const std::vector<int>* side : {&e.forward, &e.backward})
      for (int f : *side)
        front += counts_as_front(faces[static_cast<std::size_t>(f)].facing) ? 1 : 0;
    out.push_back(front == 2   ? EdgeClass::Visible
                  : front == 1 ? EdgeClass::Silhouette
                               : EdgeClass::Hidden);
  }
  return out;
}

SilhouetteLoops silhouette_loops(const std::vector<MeshEdge>& edges,
                                 const std::vector<EdgeClass>& classes) {
  SilhouetteLoops out;
  std::map<int, std::vector<int>> next;  // vertex → silhouette neighbours
  for (std::size_t k = 0; k < edges.size(); ++k)
    if (classes[k] == EdgeClass::Silhouette) {
      next[edges[k].i].push_back(edges[k].j);
      next[edges[k].j].push_back(edges[k].i);
    }
  for (const auto& [v, n] : next)
    if (n.size() != 2) out.ok = false;
  if (!out.ok) return out;
  std::map<int, bool> used;
  for (const auto& [start, n] : next) {
    if (used[start]) continue;
    std::vector<int> loop = {start};
    used[start] = true;
    int prev = start, cur = n[0];
    while (cur != start) {
      loop.push_back(cur);
      used[cur] = true;
      const std::vector<int>& nb = next[cur];
      const int after = nb[0] == prev ? nb[1] : nb[0];
      prev = cur;
      cur = after;
    }
    loop.push_back(start);
    out.loops.push_back(loop);
  }
  return out;
}

}  // namespace frustum
