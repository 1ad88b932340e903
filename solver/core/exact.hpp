// Exact values: GiNaC expressions used as an Eigen scalar, and the few operations the
// solver needs on them (canonical form, sign, conversion to double).
#pragma once

#include <ginac/ginac.h>

#include <Eigen/Core>
#include <stdexcept>
#include <string>

namespace frustum {

class WorkBudget;
using Exact = GiNaC::ex;

// Canonical form of an exact value: expanded, rational parts normalised, radicals of
// rationals simplified (sqrt(243) -> 9*sqrt(3)) and denominators rationalised
// (1/sqrt(3) -> sqrt(3)/3). Values that compare equal print equal.
Exact canonical(const Exact& e);

// The same within a work budget (solver/core/work_budget.hpp): each expansion is priced
// before it is done, and when the budget cannot pay for it the value comes back exact and
// equal to e but less simplified, with budget.exceeded() set. canonical(e) spends a fresh
// default budget of its own.
Exact canonical(const Exact& e, WorkBudget& budget);

// True when e is a real number that contains no symbols (it may hold sqrt, pi, sin...).
bool is_real_constant(const Exact& e);

// True when e is a rational number (a GiNaC numeric that is rational).
bool is_rational(const Exact& e);
// e = c·√r with c rational and r an integer > 1 (canonical()'s form of a square root), or e = c
// rational (then root = 1): c and √r itself.
bool rational_times_square_root(const Exact& e, GiNaC::numeric& c, Exact& root);

// True when e contains a symbol (a variable such as x) or a GiNaC wildcard anywhere.
bool has_symbol(const Exact& e);

// Roots are bounded in two places, for two different costs, so the bounds differ:
// canonical() simplifies radicals up to this index and leaves larger ones as GiNaC holds them
// (bounded work on whatever value reaches it) ...
inline constexpr unsigned kMaxSimplifiedRootIndex = 64;
// ... while the expression parser refuses p/q powers with q above this (GiNaC computes them as
// an exact q-th root of base^p before canonical() sees them). Raising it would accept answers
// that are refused today; lowering the other would leave values unsimplified that are
// simplified today.
inline constexpr long kMaxParsedRootIndex = 12;

// Nearest double of a real constant; NaN when e is not one.
double to_double(const Exact& e);

// A sign exact arithmetic could not prove: the value is 0 to every precision tried and no
// simplification proves it 0 (more nested radicals than the proof handles, cube roots,
// sines of arbitrary angles). A discrete answer is never decided by the sign of the noise
// left at the last precision: the problem is refused with this error instead.
class UndecidedSign : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

// A rational within a relative 10⁻⁴⁰ of a real constant (e itself when it is a rational), for
// rounding to a backend's format in one step. Throws std::domain_error when e is not real.
GiNaC::numeric rational_near(const Exact& e);

// Exact sign (-1, 0, +1) of a real constant: rationals decided directly, algebraic values
// by interval refinement at growing precision and, when that cannot separate the value
// from zero, by exact simplification. Throws std::domain_error if e is not real, and
// UndecidedSign when neither refinement nor simplification decides.
int exact_sign(const Exact& e);

// arccos in radians, exact for the unit circle's special values (acos(√2/2) = π/4).
Exact exact_acos(const Exact& c);

// Exact value of a double: every finite double is a dyadic rational.
Exact exact_from_double(double v);

}  // namespace frustum

namespace Eigen {
// Lets Eigen's fixed-size vectors and matrices hold exact values (cross, dot, M * p).
template <>
struct NumTraits<GiNaC::ex> : GenericNumTraits<GiNaC::ex> {
  using Real = GiNaC::ex;
  using NonInteger = GiNaC::ex;
  using Nested = GiNaC::ex;
  using Literal = GiNaC::ex;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 10,
    MulCost = 10
  };
  static inline Real epsilon() { return 0; }
  static inline Real dummy_precision() { return 0; }
  static inline int digits10() { return 0; }
};
}  // namespace Eigen
