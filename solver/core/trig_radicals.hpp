// Radical forms of sine, cosine and tangent at the angles a course draws: rational multiples of
// π whose denominator divides 24 (every multiple of 7.5°, among them the halves of the fields of
// view 15°, 22.5°, 30°, 45°, 60°, 75°). GiNaC evaluates the multiples of π/12 itself and leaves
// sin(π/8) or tan(π/24) as they are, so their signs could only be refined numerically and a
// value that is exactly 0 (a point on a frustum plane at fovy = 45°) was never decided.
#pragma once

#include <ginac/ginac.h>

namespace frustum {

// sin(rπ), cos(rπ) or tan(rπ) with 24·r an integer as square roots of rationals (nested at
// most twice): cos θ = ±√(2 + 2·cos 2θ)/2 and tan θ = sin 2θ / (1 + cos 2θ), so tan(π/8)
// becomes √2/2 / (1 + √2/2) (= √2 − 1 once canonical). False for any other expression, for
// other angles and at a pole of tan.
bool trig_radical(const GiNaC::ex& e, GiNaC::ex& out);

// e with every such sine, cosine and tangent replaced by its radical form.
GiNaC::ex trig_to_radicals(const GiNaC::ex& e);

}  // namespace frustum
