#include "solver/visibility/depth_order.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "solver/geometry/polygon_normal.hpp"
#include "solver/geometry/triangulate.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/mesh.hpp"

namespace frustum {

namespace {

using Pt = Vec2<Exact>;
using Poly2 = std::vector<Pt>;

// The filter first, on the value as it is: canonical() only where the filter cannot decide
// (exact_sign simplifies then), not on every value compared.
int sign(const Exact& e) { return filtered_sign(e); }

Exact cross2(const Pt& a, const Pt& b) { return a(0) * b(1) - a(1) * b(0); }

// Twice the signed area (shoelace): > 0 counter-clockwise.
Exact area2(const Poly2& p) {
  Exact s = 0;
  for (std::size_t k = 0; k < p.size(); ++k) s += cross2(p[k], p[(k + 1) % p.size()]);
  return canonical(s);
}

// Orientation of c relative to the directed line a → b: > 0 left.
int orient(const Pt& a, const Pt& b, const Pt& c) { return sign(cross2(b - a, c - a)); }

// A simple polygon (counter-clockwise) into triangles by ear clipping (exact orientation).
std::vector<std::array<Pt, 3>> triangulate(const Poly2& p) {
  std::vector<std::array<Pt, 3>> out;
  for (const std::array<int, 3>& t : ear_clip(p, orient))
    out.push_back({p[static_cast<std::size_t>(t[0])], p[static_cast<std::size_t>(t[1])],
                   p[static_cast<std::size_t>(t[2])]});
  return out;
}

// Sutherland–Hodgman: the part of `subject` inside the counter-clockwise triangle `clip`.
Poly2 clip_to_triangle(Poly2 subject, const std::array<Pt, 3>& clip) {
  for (int e = 0; e < 3 && !subject.empty(); ++e) {
    const Pt& a = clip[static_cast<std::size_t>(e)];
    const Pt& b = clip[static_cast<std::size_t>((e + 1) % 3)];
    Poly2 kept;
    for (std::size_t k = 0; k < subject.size(); ++k) {
      const Pt& p = subject[k];
      const Pt& q = subject[(k + 1) % subject.size()];
      const Exact sp = cross2(b - a, p - a), sq = cross2(b - a, q - a);
      const int s_p = sign(sp), s_q = sign(sq);
      if (s_p >= 0) kept.push_back(p);
      if ((s_p > 0 && s_q < 0) || (s_p < 0 && s_q > 0)) {
        const Exact t = canonical(sp / (sp - sq));
        kept.emplace_back(canonical(p(0) + t * (q(0) - p(0))), canonical(p(1) + t * (q(1) - p(1))));
      }
    }
    subject = kept;
  }
  return subject;
}

// One polygon as the viewer sees it.
struct Seen {
  Poly2 screen;                           // projected vertices
  std::vector<std::array<Pt, 3>> pieces;  // its triangles on screen (counter-clockwise)
  std::array<Exact, 3> h;                 // h(s) = h0 + h1 s_x + h2 s_y: larger = farther
  bool edge_on = false;
  Vec3<Exact> normal;
  Exact d;  // plane n·x = d
};

Exact eval(const std::array<Exact, 3>& h, const Pt& s) { return h[0] + h[1] * s(0) + h[2] * s(1); }

// An axis least aligned with v, so v × axis is far from zero.
Vec3<Exact> helper_axis(const Vec3<Exact>& v) {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (std::abs(to_double(v(k))) < std::abs(to_double(v(best)))) best = k;
  Vec3<Exact> a(0, 0, 0);
  a(best) = 1;
  return a;
}

Vec3<Exact> canon(const Vec3<Exact>& v) {
  return Vec3<Exact>(canonical(v(0)), canonical(v(1)), canonical(v(2)));
}

}  // namespace

std::string PairReport::name() const { return fmt::format("{}-{}", i, j); }

DepthSortResult depth_sort(const std::vector<Polygon3<Exact>>& polygons,
                           const DepthViewer& viewer) {
  DepthSortResult r;
  const std::size_t n = polygons.size();
  const bool perspective = viewer.eye.has_value();

  // Centroids g = (p₀ + … + p_{n−1})/n.
  for (const Polygon3<Exact>& p : polygons) {
    Vec3<Exact> g(0, 0, 0);
    for (const Vec3<Exact>& v : p) g += v;
    r.centroids.push_back(canon(g / Exact(static_cast<long>(p.size()))));
  }

  // Depth keys: squared distance from the eye, or g·v along the view direction; both
  // compared exactly, larger = farther.
  std::vector<Exact> key;
  Vec3<Exact> f;  // forward direction of the projection
  if (perspective) {
    for (const Vec3<Exact>& g : r.centroids) {
      key.push_back(canonical((g - *viewer.eye).squaredNorm()));
      r.depths.push_back(canonical(GiNaC::sqrt(key.back())));
    }
    Vec3<Exact> mean(0, 0, 0);
    for (const Vec3<Exact>& g : r.centroids) mean += g;
    f = canon(mean / Exact(static_cast<long>(n)) - *viewer.eye);
    if (canonical(f.squaredNorm()).is_zero())
      throw DomainError("eye",
                        "the eye is at the centre of the scene: there is no direction to look in");
  } else {
    f = *viewer.view_direction;
    if (canonical(f.squaredNorm()).is_zero())
      throw DomainError("view_direction", "the zero vector is not a direction");
    const Exact len = canonical(GiNaC::sqrt(canonical(f.squaredNorm())));
    for (const Vec3<Exact>& g : r.centroids) {
      key.push_back(canonical(g.dot(f)));
      r.depths.push_back(canonical(key.back() / len));
    }
  }
  r.order.resize(n);
  for (std::size_t k = 0; k < n; ++k) r.order[k] = static_cast<int>(k);
  std::stable_sort(r.order.begin(), r.order.end(), [&](int a, int b) {
    return sign(key[static_cast<std::size_t>(a)] - key[static_cast<std::size_t>(b)]) > 0;
  });

  // The projection plane: u, w, f mutually orthogonal (not unit, so everything stays
  // rational for rational input). Orthographic: s = (x·u, x·w). Perspective onto the plane
  // (x − e)·f = 1: s = ((x − e)·u, (x − e)·w) / ((x − e)·f).
  const Vec3<Exact> u = canon(f.cross(helper_axis(f)));
  const Vec3<Exact> w = canon(f.cross(u));
  const Exact uu = canonical(u.squaredNorm()), ww = canonical(w.squaredNorm()),
              ff = canonical(f.squaredNorm());
  r.projection = perspective
                     ? "perspective projection from the eye onto the plane perpendicular to the "
                       "direction from the eye to the mean centroid"
                     : "orthographic projection along the view direction";

  std::vector<Seen> seen(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Polygon3<Exact>& p = polygons[k];
    Seen& s = seen[k];
    Vec3<Exact> nrm = newell_normal(p);
    s.normal = canon(nrm);
    if (canonical(s.normal.squaredNorm()).is_zero())
      throw DomainError(fmt::format("polygons[{}]", k),
                        "the polygon is degenerate: it has no normal");
    s.d = canonical(s.normal.dot(p[0]));
    for (const Vec3<Exact>& x : p) {
      if (perspective) {
        const Vec3<Exact> rel = x - *viewer.eye;
        const Exact depth = canonical(rel.dot(f));
        if (sign(depth) <= 0)
          throw DomainError(
              "eye", fmt::format("a vertex of polygon {} is not in front of the eye (looking "
                                 "toward the scene's mean centroid)",
                                 k));
        s.screen.emplace_back(canonical(rel.dot(u) / depth), canonical(rel.dot(w) / depth));
      } else {
        s.screen.emplace_back(canonical(x.dot(u)), canonical(x.dot(w)));
      }
    }
    const int turn = sign(area2(s.screen));
    // Depth over the screen as an affine function h(s).
    if (perspective) {
      // Ray point λ·rel(s), rel(s) = f/|f|² + s_x u/|u|² + s_y w/|w|²; λ = a/(n·rel(s)) with
      // a = d − n·e. 1/λ is affine in s, and λ larger = farther, so h = −(n·rel(s))/a.
      const Exact a = canonical(s.d - s.normal.dot(*viewer.eye));
      if (sign(a) == 0 || turn == 0) {
        s.edge_on = true;
      } else {
        s.h = {canonical(-s.normal.dot(f) / ff / a), canonical(-s.normal.dot(u) / uu / a),
               canonical(-s.normal.dot(w) / ww / a)};
      }
    } else {
      // x = s_x u/|u|² + s_y w/|w|² + t f/|f|²; t = x·f is the depth along f.
      const Exact nf = canonical(s.normal.dot(f));
      if (sign(nf) == 0 || turn == 0) {
        s.edge_on = true;
      } else {
        s.h = {canonical(s.d * ff / nf), canonical(-s.normal.dot(u) / uu * ff / nf),
               canonical(-s.normal.dot(w) / ww * ff / nf)};
      }
    }
    if (s.edge_on) {
      r.edge_on.push_back(static_cast<int>(k));
      continue;
    }
    Poly2 ccw = s.screen;
    if (turn < 0) std::reverse(ccw.begin(), ccw.end());
    s.pieces = triangulate(ccw);
  }

  // Newell's plane tests: which side of B's plane A's vertices are on, against the eye's side.
  auto eye_side = [&](const Seen& b, const Polygon3<Exact>& bp) {
    return perspective ? sign(b.normal.dot(*viewer.eye - bp[0])) : -sign(b.normal.dot(f));
  };
  auto all_on_side = [&](const Polygon3<Exact>& a, const Seen& b, int side) {
    for (const Vec3<Exact>& x : a) {
      const int sx = sign(b.normal.dot(x) - b.d);
      if (sx != 0 && sx != side) return false;
    }
    return true;
  };

  // Overlaps and the true order over each overlap.
  std::vector<std::vector<bool>> before(n, std::vector<bool>(n, false));  // a must precede b
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      if (seen[i].edge_on || seen[j].edge_on) continue;
      bool overlap = false, any_mixed = false, i_far = false, j_far = false;
      for (const auto& ti : seen[i].pieces)
        for (const auto& tj : seen[j].pieces) {
          const Poly2 piece = clip_to_triangle(Poly2(ti.begin(), ti.end()), tj);
          if (piece.size() < 3 || sign(area2(piece)) <= 0) continue;
          overlap = true;
          bool pos = false, neg = false;
          for (const Pt& s : piece) {
            const int d = sign(eval(seen[i].h, s) - eval(seen[j].h, s));
            pos |= d > 0;
            neg |= d < 0;
          }
          if (pos && neg) any_mixed = true;
          i_far |= pos;
          j_far |= neg;
        }
      if (!overlap) continue;
      PairReport p;
      p.i = static_cast<int>(i);
      p.j = static_cast<int>(j);
      p.order = any_mixed        ? PairOrder::Interpenetrating
                : i_far && j_far ? PairOrder::WrapsAround
                : i_far          ? PairOrder::FirstBehind
                : j_far          ? PairOrder::SecondBehind
                                 : PairOrder::Coplanar;
      const int side_j = eye_side(seen[j], polygons[j]), side_i = eye_side(seen[i], polygons[i]);
      p.planes.i_behind_plane_j = side_j != 0 && all_on_side(polygons[i], seen[j], -side_j);
      p.planes.i_front_plane_j = side_j != 0 && all_on_side(polygons[i], seen[j], side_j);
      p.planes.j_behind_plane_i = side_i != 0 && all_on_side(polygons[j], seen[i], -side_i);
      p.planes.j_front_plane_i = side_i != 0 && all_on_side(polygons[j], seen[i], side_i);
      if (p.order == PairOrder::FirstBehind) before[i][j] = true;
      if (p.order == PairOrder::SecondBehind) before[j][i] = true;
      r.overlapping.push_back(p);
    }

  // Cycles of "must precede" (三すくみ): a and b on one cycle when each reaches the other.
  std::vector<std::vector<bool>> reach = before;
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t a = 0; a < n; ++a)
      if (reach[a][k])
        for (std::size_t b = 0; b < n; ++b)
          if (reach[k][b]) reach[a][b] = true;
  std::vector<std::size_t> position(n);
  for (std::size_t k = 0; k < n; ++k) position[static_cast<std::size_t>(r.order[k])] = k;

  for (PairReport& p : r.overlapping) {
    const auto i = static_cast<std::size_t>(p.i), j = static_cast<std::size_t>(p.j);
    const bool i_first = position[i] < position[j];
    p.cyclic = reach[i][j] && reach[j][i];
    if (p.order == PairOrder::Interpenetrating) {
      p.reason =
          "they interpenetrate (貫通): over their overlap the nearer polygon changes inside "
          "one piece, so no order of whole polygons is right";
    } else if (p.order == PairOrder::WrapsAround) {
      p.reason =
          "one wraps around the other (a concave polygon): part of the overlap has one in "
          "front, part the other, so no order of whole polygons is right";
    } else if (p.cyclic) {
      p.reason =
          "they lie on a cycle of overlaps (三すくみ): each polygon must be drawn before the "
          "next, around the cycle, so no order of whole polygons is right";
    } else if ((p.order == PairOrder::FirstBehind && !i_first) ||
               (p.order == PairOrder::SecondBehind && i_first)) {
      const int far = p.order == PairOrder::FirstBehind ? p.i : p.j;
      const int near = far == p.i ? p.j : p.i;
      p.centroid_tie =
          sign(key[static_cast<std::size_t>(near)] - key[static_cast<std::size_t>(far)]) == 0;
      const bool tie = p.centroid_tie;
      p.reason = fmt::format(
          "over their overlap {} is nearer everywhere, but its centroid is {} {}'s, "
          "so the centroid order draws {} first and {} paints over it",
          near, tie ? "as far as" : "farther than", far, near, far);
    }
    p.conflict = !p.reason.empty();
    if (p.conflict) r.conflicts.push_back(p.name());
  }
  return r;
}

}  // namespace frustum
