// Ear clipping of a simple polygon into triangles, on any scalar: the caller supplies the
// orientation predicate (exact for Exact, filtered or plain for doubles). A convex polygon
// becomes a fan.
#pragma once

#include <array>
#include <numeric>
#include <vector>

namespace frustum {

// `points` counter-clockwise; orient(a, b, c) > 0 when c lies left of a → b. Returns triangles
// as index triples into `points`, each counter-clockwise. A straight corner (orient = 0) adds
// no triangle and is dropped. When no ear is found (the polygon is not simple) the rest is
// kept as a fan of its counter-clockwise triangles.
template <typename P, typename Orient>
std::vector<std::array<int, 3>> ear_clip(const std::vector<P>& points, Orient orient) {
  std::vector<int> p(points.size());
  std::iota(p.begin(), p.end(), 0);
  const auto at = [&](int k) -> const P& { return points[static_cast<std::size_t>(k)]; };
  std::vector<std::array<int, 3>> out;
  while (p.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < p.size() && !clipped; ++k) {
      const std::size_t prev = (k + p.size() - 1) % p.size(), next = (k + 1) % p.size();
      const int a = p[prev], b = p[k], c = p[next];
      const int turn = orient(at(a), at(b), at(c));
      if (turn < 0) continue;
      if (turn == 0) {  // a straight corner adds nothing: drop the vertex
        p.erase(p.begin() + static_cast<long>(k));
        clipped = true;
        continue;
      }
      bool empty = true;
      for (std::size_t m = 0; m < p.size() && empty; ++m) {
        if (m == k || m == prev || m == next) continue;
        const P& q = at(p[m]);
        if (orient(at(a), at(b), q) >= 0 && orient(at(b), at(c), q) >= 0 &&
            orient(at(c), at(a), q) >= 0)
          empty = false;
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      p.erase(p.begin() + static_cast<long>(k));
      clipped = true;
    }
    if (!clipped) break;
  }
  for (std::size_t k = 1; k + 1 < p.size(); ++k)
    if (orient(at(p[0]), at(p[k]), at(p[k + 1])) > 0) out.push_back({p[0], p[k], p[k + 1]});
  return out;
}

}  // namespace frustum
