#include "solver/visibility/hidden_lines.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "solver/geometry/predicates.hpp"
#include "solver/geometry/triangulate.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

using V3 = Eigen::Vector3d;

double orient3d_value(const V3& a, const V3& b, const V3& c, const V3& d) {
  return (b - a).cross(c - a).dot(d - a);
}

// One affine condition g(t) > 0 along the edge, g(0) = ga, g(1) = gb with exact signs sa, sb:
// narrows [lo, hi]; false when it holds nowhere on the edge.
bool narrow(int sa, int sb, double ga, double gb, double& lo, double& hi) {
  if (sa > 0 && sb > 0) return true;
  if (sa <= 0 && sb <= 0) return false;
  const double cut = sa == 0 ? 0.0 : sb == 0 ? 1.0 : std::abs(ga) / (std::abs(ga) + std::abs(gb));
  if (sa > 0)
    hi = std::min(hi, cut);
  else
    lo = std::max(lo, cut);
  return hi - lo > kMinSpan;
}

}  // namespace

std::vector<Occluder> face_triangles(const Mesh& m) {
  std::vector<Occluder> out;
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    std::vector<V3> p;
    for (int k : m.faces[f]) p.push_back(to_double(m.vertices[static_cast<std::size_t>(k)]));
    // Newell's normal; the face is laid flat by dropping its largest component, reversed when
    // that view sees it clockwise.
    V3 n = V3::Zero();
    for (std::size_t k = 0; k < p.size(); ++k) n += p[k].cross(p[(k + 1) % p.size()]);
    int drop = 0;
    for (int k = 1; k < 3; ++k)
      if (std::abs(n(k)) > std::abs(n(drop))) drop = k;
    const int ax = (drop + 1) % 3, ay = (drop + 2) % 3;
    std::vector<int> order(p.size());
    for (std::size_t k = 0; k < p.size(); ++k) order[k] = static_cast<int>(k);
    if (n(drop) < 0) std::reverse(order.begin(), order.end());
    std::vector<Eigen::Vector2d> flat;
    for (int k : order)
      flat.emplace_back(p[static_cast<std::size_t>(k)](ax), p[static_cast<std::size_t>(k)](ay));
    const auto orient = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const Eigen::Vector2d& c) {
      const double d = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
      return d > 0 ? 1 : d < 0 ? -1 : 0;
    };
    for (const std::array<int, 3>& t : ear_clip(flat, orient)) {
      Occluder o;
      for (int k = 0; k < 3; ++k)
        o.v[static_cast<std::size_t>(k)] = p[static_cast<std::size_t>(
            order[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])])];
      o.face = static_cast<int>(f);
      out.push_back(o);
    }
  }
  return out;
}

std::vector<Interval> covered_by(const V3& a, const V3& b, const V3& eye, const Occluder& o) {
  const V3 &p = o.v[0], &q = o.v[1], &r = o.v[2];
  const int sigma = orient3d_sign(eye, p, q, r);  // the triangle's turn seen from the eye
  const int eye_side = orient3d_sign(p, q, r, eye);
  if (sigma == 0 || eye_side == 0) return {};  // seen edge-on: covers no area
  double lo = 0, hi = 1;
  // X inside the three wedges through the eye and the triangle's edges.
  const std::array<std::array<const V3*, 2>, 3> wedges = {{{&p, &q}, {&q, &r}, {&r, &p}}};
  for (const auto& w : wedges) {
    const int sa = sigma * orient3d_sign(eye, *w[0], *w[1], a),
              sb = sigma * orient3d_sign(eye, *w[0], *w[1], b);
    if (!narrow(sa, sb, orient3d_value(eye, *w[0], *w[1], a), orient3d_value(eye, *w[0], *w[1], b),
                lo, hi))
      return {};
  }
  // X strictly behind the triangle's plane, the eye in front.
  const int sa = -eye_side * orient3d_sign(p, q, r, a), sb = -eye_side * orient3d_sign(p, q, r, b);
  if (!narrow(sa, sb, orient3d_value(p, q, r, a), orient3d_value(p, q, r, b), lo, hi)) return {};
  return {{lo, hi}};
}

std::vector<Interval> merge_intervals(std::vector<Interval> spans) {
  std::sort(spans.begin(), spans.end());
  std::vector<Interval> out;
  for (const Interval& s : spans) {
    const Interval c = {std::max(0.0, s.first), std::min(1.0, s.second)};
    if (c.second - c.first <= kMinSpan) continue;
    if (!out.empty() && c.first <= out.back().second + kMinSpan)
      out.back().second = std::max(out.back().second, c.second);
    else
      out.push_back(c);
  }
  return out;
}

HiddenLines hidden_lines(const Mesh& m, const Vec3<Exact>& eye, std::int64_t max_pairs) {
  HiddenLines h;
  const std::vector<MeshEdge> edges = mesh_edges(m);
  h.faces = face_tests(m, face_normals(m), eye);
  const std::vector<EdgeClass> classes = classify_edges(edges, h.faces);
  const std::vector<Occluder> occluders = face_triangles(m);
  const auto tested = static_cast<std::int64_t>(std::count_if(
      classes.begin(), classes.end(), [](EdgeClass c) { return c != EdgeClass::Hidden; }));
  std::int64_t pairs = 0;
  if (__builtin_mul_overflow(tested, static_cast<std::int64_t>(occluders.size()), &pairs) ||
      pairs > max_pairs)
    throw DomainError(
        "mesh.faces",
        fmt::format("the hidden lines of {} edges against {} face triangles are {} pairs to test "
                    "(the limit is {} edge–face pairs a picture); draw a mesh of fewer faces",
                    tested, occluders.size(), pairs, max_pairs));
  const V3 e = to_double(eye);
  for (std::size_t k = 0; k < edges.size(); ++k) {
    EdgeLines lines;
    lines.edge = edges[k];
    lines.cls = classes[k];
    if (lines.cls == EdgeClass::Hidden) {  // back–back: its own faces hide it
      lines.spans = {{0, 1, false}};
      h.edges.push_back(lines);
      continue;
    }
    const V3 a = to_double(m.vertices[static_cast<std::size_t>(edges[k].i)]);
    const V3 b = to_double(m.vertices[static_cast<std::size_t>(edges[k].j)]);
    const auto own = [&](int f) {
      return std::find(edges[k].forward.begin(), edges[k].forward.end(), f) !=
                 edges[k].forward.end() ||
             std::find(edges[k].backward.begin(), edges[k].backward.end(), f) !=
                 edges[k].backward.end();
    };
    std::vector<Interval> covered;
    for (const Occluder& o : occluders)
      if (!own(o.face))
        for (const Interval& s : covered_by(a, b, e, o)) covered.push_back(s);
    // Alternate visible and covered spans from t = 0 to 1; a sliver at either end joins its
    // neighbour.
    double t = 0;
    for (const Interval& c : merge_intervals(covered)) {
      const bool gap = c.first - t > kMinSpan;
      if (gap) lines.spans.push_back({t, c.first, true});
      lines.spans.push_back({gap ? c.first : t, c.second, false});
      t = c.second;
    }
    if (1 - t > kMinSpan)
      lines.spans.push_back({t, 1, true});
    else
      lines.spans.back().t1 = 1;
    if (lines.spans.size() > 1) ++h.split_edges;
    h.edges.push_back(lines);
  }
  return h;
}

}  // namespace frustum
