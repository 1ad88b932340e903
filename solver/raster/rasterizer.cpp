#include "solver/raster/rasterizer.hpp"

#include <cmath>

#include "solver/util/diagnostic.hpp"

namespace frustum {

namespace {

constexpr const char* kRangeMessage = "window coordinates must be finite and at most 2^20 in size";

void make_edge(EdgeFunction& e, const FixedPoint2& from, const FixedPoint2& to) {
  e.from = from;
  e.to = to;
  // E(p) = (to − from) × (p − from) = a·x + b·y + c
  e.a = -(to.y - from.y);
  e.b = to.x - from.x;
  e.c = -(e.a * from.x + e.b * from.y);
  const std::int64_t dx = to.x - from.x, dy = to.y - from.y;
  e.top = dy == 0 && dx < 0;
  e.left = dy < 0;
}

}  // namespace

std::int64_t to_fixed(double v) {
  // llround without the library call: |v·2⁸| ≤ 2²⁸, so the truncation and the fraction
  // s − trunc(s) are exact; halves round away from zero, as llround does.
  const double s = v * static_cast<double>(kSubpixelScale);
  auto t = static_cast<std::int64_t>(s);
  const double f = s - static_cast<double>(t);
  t += (f >= 0.5) - (f <= -0.5);
  return t;
}

TriangleSetup setup_triangle(const std::array<Vec2<double>, 3>& window) {
  TriangleSetup t;
  setup_triangle(window, t);
  return t;
}

std::int64_t to_fixed(const Exact& v, bool& off_grid) {
  const double d = to_double(v);
  if (!std::isfinite(d) || std::abs(d) > kMaxWindowCoordinate)
    throw DomainError("triangle", kRangeMessage);
  const Exact q = v * static_cast<long>(kSubpixelScale);
  if (GiNaC::is_a<GiNaC::numeric>(q) && GiNaC::ex_to<GiNaC::numeric>(q).is_rational()) {
    // ⌊|q| + ½⌋ with q's sign: halves away from zero.
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(q);
    const GiNaC::numeric a = GiNaC::abs(n) + GiNaC::numeric(1, 2);
    const long k = GiNaC::iquo(a.numer(), a.denom()).to_long();
    off_grid = off_grid || !n.is_integer();
    return n.is_negative() ? -k : k;
  }
  // Any other exact value (a radical, a nested radical, a trigonometric value, or a rational
  // GiNaC holds unreduced, such as (√2 + 1)(√2 − 1)): the same rule, k = sign(q)·⌊|q| + ½⌋,
  // decided by exact signs of |q| against the half-way points next to the double's rounding.
  // |q| = k + ½ exactly rounds up (away from zero) on both sides of 0.
  const int sign = exact_sign(q);
  if (sign == 0) return 0;
  const Exact magnitude = sign > 0 ? q : Exact(-q);
  const auto half_above = [](std::int64_t c) { return Exact(static_cast<long>(c)) + Exact(1) / 2; };
  std::int64_t k = std::abs(to_fixed(d));
  while (k > 0 && exact_sign(magnitude - half_above(k - 1)) < 0) --k;  // |q| < k − ½
  while (exact_sign(magnitude - half_above(k)) >= 0) ++k;              // |q| ≥ k + ½
  // On the grid only when |q| is k exactly; a double this far from k proves it is not.
  const double distance =
      std::abs(std::abs(d) * static_cast<double>(kSubpixelScale) - static_cast<double>(k));
  off_grid = off_grid || distance > 1e-6 || exact_sign(magnitude - static_cast<long>(k)) != 0;
  return sign * k;
}

TriangleSetup setup_triangle_exact(const std::array<Vec2<Exact>, 3>& window) {
  std::array<FixedPoint2, 3> in;
  bool off_grid = false;
  for (int k = 0; k < 3; ++k)
    in[k] = {to_fixed(window[k](0), off_grid), to_fixed(window[k](1), off_grid)};
  TriangleSetup t;
  setup_fixed(in, t);
  t.snapped = off_grid;
  return t;
}

void setup_triangle(const std::array<Vec2<double>, 3>& window, TriangleSetup& t) {
  std::array<FixedPoint2, 3> in;
  bool snapped = false;
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 2; ++c)
      if (!std::isfinite(window[k](c)) || std::abs(window[k](c)) > kMaxWindowCoordinate)
        throw DomainError("triangle", kRangeMessage);
    in[k] = {to_fixed(window[k](0)), to_fixed(window[k](1))};
    const double scale = static_cast<double>(kSubpixelScale);
    if (static_cast<double>(in[k].x) != window[k](0) * scale ||
        static_cast<double>(in[k].y) != window[k](1) * scale)
      snapped = true;
  }
  setup_fixed(in, t);
  t.snapped = snapped;
}

void setup_fixed(const std::array<FixedPoint2, 3>& in, TriangleSetup& t) {
  // Every field is assigned here, none read: t may hold an earlier triangle.
  t.snapped = false;
  t.reordered = false;
  t.i_min = 0;
  t.i_max = -1;
  t.j_min = 0;
  t.j_max = -1;
  // Twice the signed area: (v1 − v0) × (v2 − v0); counter-clockwise > 0.
  const std::int64_t area2 =
      (in[1].x - in[0].x) * (in[2].y - in[0].y) - (in[1].y - in[0].y) * (in[2].x - in[0].x);
  t.order = {0, 1, 2};
  if (area2 < 0) {
    t.order = {0, 2, 1};
    t.reordered = true;
  }
  for (int k = 0; k < 3; ++k) t.v[k] = in[t.order[k]];
  t.area2 = area2 < 0 ? -area2 : area2;
  t.degenerate = t.area2 == 0;
  for (int k = 0; k < 3; ++k) make_edge(t.edge[k], t.v[(k + 1) % 3], t.v[(k + 2) % 3]);
  if (t.degenerate) return;
  std::int64_t x0 = t.v[0].x, x1 = x0, y0 = t.v[0].y, y1 = y0;
  for (const FixedPoint2& p : t.v) {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  // Pixels whose centre (i + ½)·2⁸ lies in [x0, x1].
  const std::int64_t half = kSubpixelScale / 2;
  t.i_min = static_cast<int>(ceil_div(x0 - half, kSubpixelScale));
  t.i_max = static_cast<int>(floor_div(x1 - half, kSubpixelScale));
  t.j_min = static_cast<int>(ceil_div(y0 - half, kSubpixelScale));
  t.j_max = static_cast<int>(floor_div(y1 - half, kSubpixelScale));
}

bool covers(const TriangleSetup& t, int i, int j) {
  if (t.degenerate) return false;
  const FixedPoint2 p = pixel_centre(i, j);
  for (const EdgeFunction& e : t.edge) {
    const std::int64_t v = e.at(p.x, p.y);
    if (v < 0 || (v == 0 && !e.top_left())) return false;
  }
  return true;
}

std::vector<Fragment> rasterize(const TriangleSetup& t, int width, int height) {
  std::vector<Fragment> out;
  if (t.degenerate) return out;
  int i0 = t.i_min, i1 = t.i_max, j0 = t.j_min, j1 = t.j_max;
  if (width > 0 && height > 0) {
    i0 = std::max(i0, 0);
    j0 = std::max(j0, 0);
    i1 = std::min(i1, width - 1);
    j1 = std::min(j1, height - 1);
  }
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      if (!covers(t, i, j)) continue;
      const FixedPoint2 p = pixel_centre(i, j);
      out.push_back(
          {i, j, {t.edge[0].at(p.x, p.y), t.edge[1].at(p.x, p.y), t.edge[2].at(p.x, p.y)}});
    }
  return out;
}

}  // namespace frustum
