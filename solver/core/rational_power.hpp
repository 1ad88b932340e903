// c·k^q with c, k and q rational, k > 0 and q not an integer: the shape of a unit vector's
// component, a length, a square root. GiNaC's product reads its stored factor k^q back
// (mul::op) by building a new power and evaluating it again, which tests k for an exact root on
// every read; rational_power reads the factor as the product stores it.
#pragma once

#include <ginac/ginac.h>

#include <optional>

namespace frustum {

struct RationalPower {
  GiNaC::numeric c;         // the rational coefficient (1 for a power alone)
  GiNaC::numeric base;      // k > 0
  GiNaC::numeric exponent;  // q
};

// e as c·k^q (a power alone, or a product of exactly one such power and a rational), else
// false. e is evaluated, as every GiNaC expression is once built.
bool rational_power(const GiNaC::ex& e, RationalPower& out);

// x = q·R with q rational and R = k^p (a RationalPower whose c is 1), or R = 1 (no radical):
// the components of a unit normal n/‖n‖ and d = n̂·A once canonical.
struct RationalMultiple {
  GiNaC::numeric q;
  std::optional<RationalPower> radical;
};
bool rational_multiple(const GiNaC::ex& x, RationalMultiple& out);

// Whether two radicals (nullopt: none) are the same k^p.
bool same_radical(const std::optional<RationalPower>& a, const std::optional<RationalPower>& b);

// +1 when q = 1/2, -1 when q = -1/2, else 0 (read off q without building either number).
int square_root_sign(const GiNaC::numeric& q);

}  // namespace frustum
