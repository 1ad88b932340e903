#include "solver/core/rational_power.hpp"

#include <cln/rational.h>

namespace frustum {

namespace {

// A product's factors as it stores them: pairs (base, exponent) and a numeric coefficient.
// expairseq keeps them protected; a member pointer formed through a derived class reads them
// without changing the object.
struct StoredFactors : GiNaC::expairseq {
  static const GiNaC::epvector& of(const GiNaC::expairseq& s) { return s.*(&StoredFactors::seq); }
};

bool positive_rational(const GiNaC::ex& e) {
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(e)) return false;
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
  return n.is_rational() && n.is_positive();
}

bool fractional_exponent(const GiNaC::ex& e) {
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(e)) return false;
  const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
  return n.is_rational() && !n.is_integer();
}

}  // namespace

bool rational_power(const GiNaC::ex& e, RationalPower& out) {
  if (GiNaC::is_exactly_a<GiNaC::power>(e)) {
    const GiNaC::ex& base = e.op(0);  // power::op returns what it stores
    const GiNaC::ex& exponent = e.op(1);
    if (!positive_rational(base) || !fractional_exponent(exponent)) return false;
    out = {1, GiNaC::ex_to<GiNaC::numeric>(base), GiNaC::ex_to<GiNaC::numeric>(exponent)};
    return true;
  }
  if (!GiNaC::is_exactly_a<GiNaC::mul>(e)) return false;
  const GiNaC::mul& product = GiNaC::ex_to<GiNaC::mul>(e);
  const GiNaC::epvector& factors = StoredFactors::of(product);
  if (factors.size() != 1 || e.nops() != 2) return false;
  // The coefficient is the product's last operand, returned as stored.
  const GiNaC::ex coefficient = e.op(1);
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(coefficient) ||
      !GiNaC::ex_to<GiNaC::numeric>(coefficient).is_rational())
    return false;
  const GiNaC::expair& factor = factors.front();
  if (!positive_rational(factor.rest) || !fractional_exponent(factor.coeff)) return false;
  out = {GiNaC::ex_to<GiNaC::numeric>(coefficient), GiNaC::ex_to<GiNaC::numeric>(factor.rest),
         GiNaC::ex_to<GiNaC::numeric>(factor.coeff)};
  return true;
}

bool rational_multiple(const GiNaC::ex& x, RationalMultiple& out) {
  if (GiNaC::is_exactly_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_rational()) {
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

int square_root_sign(const GiNaC::numeric& q) {
  if (!q.is_rational() || q.is_integer()) return 0;
  const cln::cl_RA r = cln::the<cln::cl_RA>(q.to_cl_N());
  if (cln::denominator(r) != 2) return 0;
  const cln::cl_I n = cln::numerator(r);
  return n == 1 ? 1 : n == -1 ? -1 : 0;
}

}  // namespace frustum
