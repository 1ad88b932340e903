#include "solver/core/exact_vector.hpp"

#include <optional>

#include "solver/core/rational_power.hpp"

namespace frustum {

namespace {

// x = q·R with q rational and R = k^p (k > 0, p rational), or R = 1 (no radical).
struct RationalMultiple {
  GiNaC::numeric q;
  std::optional<RationalPower> radical;  // its c is 1
};

bool rational_multiple(const Exact& x, RationalMultiple& out) {
  if (is_rational(x)) {
    out = {GiNaC::ex_to<GiNaC::numeric>(x), std::nullopt};
    return true;
  }
  RationalPower parts;
  if (!rational_power(x, parts)) return false;
  out = {parts.c, RationalPower{1, parts.base, parts.exponent}};
  return true;
}

bool same_radical(const std::optional<RationalPower>& a, const std::optional<RationalPower>& b) {
  if (!a || !b) return !a && !b;
  return a->base.is_equal(b->base) && a->exponent.is_equal(b->exponent);
}

}  // namespace

Exact canonical_dot(const Vec3<Exact>& a, const Vec3<Exact>& b) {
  GiNaC::numeric sum = 0;
  std::optional<std::optional<RationalPower>> common;  // the radical of the non-zero terms
  for (int i = 0; i < 3; ++i) {
    RationalMultiple x, y;
    if (!rational_multiple(a(i), x) || !rational_multiple(b(i), y) || (x.radical && y.radical))
      return canonical(a.dot(b));
    const GiNaC::numeric term = x.q * y.q;
    if (term.is_zero()) continue;
    const std::optional<RationalPower>& radical = x.radical ? x.radical : y.radical;
    if (!common) common = radical;
    if (!same_radical(*common, radical)) return canonical(a.dot(b));
    sum += term;
  }
  if (sum.is_zero() || !common || !*common) return sum;
  const RationalPower& r = **common;
  return canonical(sum * GiNaC::pow(Exact(r.base), Exact(r.exponent)));
}

Exact canonical_norm(const Vec3<Exact>& v) {
  if (!is_rational(v(0)) || !is_rational(v(1)) || !is_rational(v(2))) return canonical(norm(v));
  GiNaC::numeric squares = 0;
  for (int i = 0; i < 3; ++i) {
    const GiNaC::numeric& x = GiNaC::ex_to<GiNaC::numeric>(v(i));
    squares += x * x;
  }
  return canonical(GiNaC::sqrt(Exact(squares)));
}

}  // namespace frustum
