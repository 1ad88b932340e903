#include "solver/core/trig_radicals.hpp"

namespace frustum {

namespace {

using GiNaC::ex;
using GiNaC::numeric;

constexpr long kDenominator = 24;

// r reduced to [0, 2): the angle rπ within one turn.
numeric one_turn(const numeric& r) {
  const numeric n = r.numer(), d = 2 * r.denom();
  numeric turns = GiNaC::iquo(n, d);  // r/2 rounded toward zero, then down
  if (n.is_negative() && turns * d != n) turns -= 1;
  return r - 2 * turns;
}

// cos(rπ) for 24·r an integer, r in [0, 2): GiNaC's own value when r's denominator divides 12,
// else the half-angle formula from cos(2rπ), whose denominator is half of r's.
ex cos_of(const numeric& r) {
  if ((12 / r.denom()).is_integer()) return GiNaC::cos(r * GiNaC::Pi);
  const ex c2 = cos_of(one_turn(2 * r));
  // θ = rπ is never a multiple of π/2 here (its denominator is 8 or 24): cos θ > 0 exactly
  // in the first and the fourth quarter of the turn.
  const int sign = (r < numeric(1, 2) || r > numeric(3, 2)) ? 1 : -1;
  return sign * GiNaC::sqrt(2 + 2 * c2) / 2;
}

// The multiple r of π in e = rπ, when 24·r is an integer.
bool multiple_of_pi(const ex& angle, numeric& r) {
  const ex q = (angle / GiNaC::Pi).expand();
  if (!GiNaC::is_a<numeric>(q)) return false;
  const numeric& n = GiNaC::ex_to<numeric>(q);
  if (!n.is_rational() || !(n * kDenominator).is_integer()) return false;
  r = one_turn(n);
  return true;
}

struct ToRadicals : GiNaC::map_function {
  ex operator()(const ex& e) override {
    const ex mapped = e.map(*this);
    ex out;
    return trig_radical(mapped, out) ? out : mapped;
  }
};

}  // namespace

bool trig_radical(const ex& e, ex& out) {
  const bool is_sin = GiNaC::is_the_function<GiNaC::sin_SERIAL>(e);
  const bool is_cos = GiNaC::is_the_function<GiNaC::cos_SERIAL>(e);
  const bool is_tan = GiNaC::is_the_function<GiNaC::tan_SERIAL>(e);
  if (!is_sin && !is_cos && !is_tan) return false;
  numeric r;
  if (!multiple_of_pi(e.op(0), r)) return false;
  if (is_cos) {
    out = cos_of(r);
  } else if (is_sin) {
    out = cos_of(one_turn(numeric(1, 2) - r));  // sin θ = cos(π/2 − θ)
  } else {
    // tan θ = sin 2θ / (1 + cos 2θ); 1 + cos 2θ = 0 exactly at the poles θ = π/2 + kπ.
    const numeric r2 = one_turn(2 * r);
    if (r2 == 1) return false;
    out = cos_of(one_turn(numeric(1, 2) - r2)) / (1 + cos_of(r2));
  }
  return true;
}

ex trig_to_radicals(const ex& e) {
  ToRadicals to_radicals;
  return to_radicals(e);
}

}  // namespace frustum
