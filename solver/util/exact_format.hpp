// Printing exact values the way they are written on paper, in three styles.
#pragma once

#include <string>

#include "solver/core/exact.hpp"

namespace frustum {

enum class MathStyle {
  Plain,  // ASCII, machine-readable, re-parsable: "sqrt(3)/3", "-9*sqrt(3)", "100*sqrt(3)", "pi/6"
  Unicode,  // for the terminal: "√3/3", "−9√3", "100√3", "π/6", "−1/2"
  Latex     // for Markdown: "\frac{\sqrt{3}}{3}", "-9\sqrt{3}", "\frac{\pi}{6}"
};

// Formats an exact value (call canonical() first for the paper form).
std::string format_exact(const Exact& e, MathStyle style);

// Shortest decimal text that round-trips to the same double ("0.5773502691896258", "8", "-6").
std::string format_double(double v);
// The same for a long double: the shortest decimal that reads back to it (up to 21 significant
// digits on x86's 64-bit mantissa), so its extra digits reach the reader.
std::string format_long_double(long double v);

// A short decimal for showing beside an exact value: 4 significant digits ("≈ 0.5774").
std::string format_approx(double v, int significant = 4);

// The same for an exact real value of any size: beyond double's range (below 2.2·10⁻³⁰⁸,
// above 1.8·10³⁰⁸) it is still its own leading digits and power of ten ("-1e-380"), never 0
// or inf. "nan" when e is no real number.
std::string format_exact_approx(const Exact& e, int significant = 4);

}  // namespace frustum
