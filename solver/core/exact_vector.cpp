#include "solver/core/exact_vector.hpp"

#include <optional>

#include "solver/core/rational_power.hpp"

namespace frustum {

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
