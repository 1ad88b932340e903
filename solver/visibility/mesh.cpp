#include "solver/visibility/mesh.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "solver/geometry/polygon_normal.hpp"

namespace frustum {

namespace {

// A value above this magnitude (as a double) has a sign no rounding can flip for the
// coordinates of the named solids and of problem inputs (terms far below 10⁹).
constexpr double kSignFilter = 1e-6;

// Faces of the convex hull of points in convex position, found in doubles (the regular
// solids are well conditioned) and returned as index lists, counter-clockwise from outside.
// The exact checks (check_mesh, is_convex) then verify the result on the exact vertices.
std::vector<std::vector<int>> hull_faces(const std::vector<Vec3<Exact>>& exact_points) {
  std::vector<Eigen::Vector3d> p;
  for (const Vec3<Exact>& v : exact_points) p.push_back(to_double(v));
  const int n = static_cast<int>(p.size());
  constexpr double kEps = 1e-9;
  std::set<std::vector<int>> seen;
  std::vector<std::vector<int>> faces;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      for (int c = b + 1; c < n; ++c) {
        Eigen::Vector3d normal = (p[b] - p[a]).cross(p[c] - p[a]);
        if (normal.norm() < kEps) continue;
        normal.normalize();
        int above = 0, below = 0;
        std::vector<int> on;
        for (int k = 0; k < n; ++k) {
          const double s = normal.dot(p[k] - p[a]);
          if (s > kEps)
            ++above;
          else if (s < -kEps)
            ++below;
          else
            on.push_back(k);
        }
        if (above && below) continue;
        if (above) normal = -normal;  // outward: every other vertex below
        if (!seen.insert(on).second) continue;
        // Counter-clockwise around the outward normal, starting at the smallest index.
        Eigen::Vector3d centre = Eigen::Vector3d::Zero();
        for (int k : on) centre += p[k];
        centre /= static_cast<double>(on.size());
        const Eigen::Vector3d u = (p[on[0]] - centre).normalized();
        const Eigen::Vector3d w = normal.cross(u);
        std::sort(on.begin() + 1, on.end(), [&](int x, int y) {
          const Eigen::Vector3d dx = p[x] - centre, dy = p[y] - centre;
          double ax = std::atan2(dx.dot(w), dx.dot(u)), ay = std::atan2(dy.dot(w), dy.dot(u));
          if (ax < 0) ax += 2 * M_PI;
          if (ay < 0) ay += 2 * M_PI;
          return ax < ay;
        });
        faces.push_back(on);
      }
  std::sort(faces.begin(), faces.end());
  return faces;
}

// All sign combinations of (a, b, c) placed by `place` (a permutation of the axes).
void add_signed(std::vector<Vec3<Exact>>& out, const Exact& a, const Exact& b, const Exact& c) {
  for (int sa : {1, -1})
    for (int sb : {1, -1})
      for (int sc : {1, -1}) {
        if ((a.is_zero() && sa < 0) || (b.is_zero() && sb < 0) || (c.is_zero() && sc < 0)) continue;
        out.emplace_back(canonical(sa * a), canonical(sb * b), canonical(sc * c));
      }
}

// (a, b, c) and its cyclic permutations (b, c, a), (c, a, b), with every sign.
void add_cyclic(std::vector<Vec3<Exact>>& out, const Exact& a, const Exact& b, const Exact& c) {
  add_signed(out, a, b, c);
  add_signed(out, b, c, a);
  add_signed(out, c, a, b);
}

Mesh make_solid(const std::string& name) {
  Mesh m;
  const Exact phi = canonical((1 + GiNaC::sqrt(Exact(5))) / 2);
  const Exact inv_phi = canonical(phi - 1);  // 1/φ = φ − 1 = (√5 − 1)/2
  if (name == "cube") {
    // seed 003's numbering: 0..3 the top (y = 1), 4..7 the bottom; z = 1 is the front.
    const int xyz[8][3] = {{-1, 1, 1},  {1, 1, 1},  {1, 1, -1},  {-1, 1, -1},
                           {-1, -1, 1}, {1, -1, 1}, {1, -1, -1}, {-1, -1, -1}};
    for (const auto& v : xyz) m.vertices.emplace_back(Exact(v[0]), Exact(v[1]), Exact(v[2]));
    m.faces = {{0, 1, 2, 3}, {4, 7, 6, 5}, {1, 5, 6, 2}, {0, 3, 7, 4}, {0, 4, 5, 1}, {3, 2, 6, 7}};
    return m;
  }
  if (name == "tetrahedron") {
    m.vertices = {Vec3<Exact>(1, 1, 1), Vec3<Exact>(1, -1, -1), Vec3<Exact>(-1, 1, -1),
                  Vec3<Exact>(-1, -1, 1)};
  } else if (name == "octahedron") {
    add_cyclic(m.vertices, 1, 0, 0);
  } else if (name == "icosahedron") {
    add_cyclic(m.vertices, 0, 1, phi);
  } else if (name == "dodecahedron") {
    add_signed(m.vertices, 1, 1, 1);
    add_cyclic(m.vertices, 0, inv_phi, phi);
  } else {
    throw std::invalid_argument("unknown solid '" + name + "'");
  }
  m.faces = hull_faces(m.vertices);
  return m;
}

}  // namespace

const std::vector<std::string>& solid_names() {
  static const std::vector<std::string> names = {"tetrahedron", "cube", "octahedron",
                                                 "dodecahedron", "icosahedron"};
  return names;
}

Mesh named_solid(const std::string& name) {
  // Built once per name: the hull search and the radicals are not free.
  static const std::map<std::string, Mesh> solids = [] {
    std::map<std::string, Mesh> s;
    for (const std::string& n : solid_names()) s.emplace(n, make_solid(n));
    return s;
  }();
  const auto it = solids.find(name);
  if (it == solids.end()) throw std::invalid_argument("unknown solid '" + name + "'");
  return it->second;
}

std::string MeshEdge::name() const { return fmt::format("{}-{}", i, j); }

std::vector<MeshEdge> mesh_edges(const Mesh& m) {
  std::map<std::pair<int, int>, MeshEdge> edges;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const std::vector<int>& face = m.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int a = face[k], b = face[(k + 1) % face.size()];
      MeshEdge& e = edges[{std::min(a, b), std::max(a, b)}];
      e.i = std::min(a, b);
      e.j = std::max(a, b);
      (a < b ? e.forward : e.backward).push_back(static_cast<int>(f));
    }
  }
  std::vector<MeshEdge> out;
  for (auto& [key, e] : edges) out.push_back(std::move(e));
  return out;
}

MeshCheck check_mesh(const Mesh& m) {
  MeshCheck c;
  c.edges = mesh_edges(m);
  for (const MeshEdge& e : c.edges) {
    const std::size_t count = e.forward.size() + e.backward.size();
    if (count != 2) {
      c.closed = false;
      c.bad_edge = e.name();
      c.problem = count == 1
                      ? fmt::format("edge {} belongs to face {} only: the mesh is not closed",
                                    e.name(), e.forward.empty() ? e.backward[0] : e.forward[0])
                      : fmt::format(
                            "edge {} is shared by {} faces: the mesh is not a closed surface "
                            "(each edge must join exactly two faces)",
                            e.name(), count);
      return c;
    }
    if (e.forward.size() != 1) {
      c.oriented = false;
      c.bad_edge = e.name();
      const std::vector<int>& two = e.forward.empty() ? e.backward : e.forward;
      c.problem = fmt::format(
          "faces {} and {} both walk edge {} in the same direction: the faces "
          "are not consistently oriented (counter-clockwise from outside)",
          two[0], two[1], e.name());
      return c;
    }
  }
  return c;
}

std::vector<Vec3<Exact>> face_normals(const Mesh& m) {
  std::vector<Vec3<Exact>> out;
  for (const std::vector<int>& face : m.faces) {
    Polygon3<Exact> poly;
    for (int k : face) poly.push_back(m.vertices[static_cast<std::size_t>(k)]);
    Vec3<Exact> n = newell_normal(poly);
    for (int i = 0; i < 3; ++i) n(i) = canonical(n(i));
    out.push_back(n);
  }
  return out;
}

int filtered_sign(const Exact& e) {
  if (GiNaC::is_a<GiNaC::numeric>(e)) return GiNaC::ex_to<GiNaC::numeric>(e).csgn();
  const double d = to_double(e);
  if (std::isfinite(d) && std::abs(d) > kSignFilter) return d > 0 ? 1 : -1;
  return exact_sign(e);
}

bool is_convex(const Mesh& m, const std::vector<Vec3<Exact>>& normals, ConvexityWitness* witness) {
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    const Vec3<Exact>& p = m.vertices[static_cast<std::size_t>(m.faces[f][0])];
    for (std::size_t v = 0; v < m.vertices.size(); ++v) {
      if (filtered_sign(canonical(normals[f].dot(m.vertices[v] - p))) > 0) {
        if (witness) *witness = {v, f};
        return false;
      }
    }
  }
  return true;
}

}  // namespace frustum
