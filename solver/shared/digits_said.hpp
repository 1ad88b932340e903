// How many correct digits each floating-point backend keeps of a value with condition number
// κ, said in every language (the words of condition.hpp's digits_sentence): the ill-conditioning
// warnings of the derivations and of the numeric paths.
#pragma once

#include "solver/numeric/precision.hpp"
#include "solver/util/said.hpp"

namespace frustum {

// "double keeps about 9.3 of its 16.0 digits" / "double keeps no correct digit".
Said backend_digits(double kappa, Precision p);

// "κ ≈ 1.2e+07: float keeps …, double keeps …, long-double keeps …; the exact value shown is
// unaffected", each backend with its own κ (a shorter backend's κ is never below a longer one's).
Said digits_said(double kappa, double kappa_float, double kappa_double, double kappa_long_double);
inline Said digits_said(double kappa) { return digits_said(kappa, kappa, kappa, kappa); }

}  // namespace frustum
