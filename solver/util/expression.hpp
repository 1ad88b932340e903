// A bounded parser for the exact expressions that instructors write in `given` and students
// write in answers: "100*sqrt(3)", "100√3", "1/√3", "pi/6", "−2/3", "1.0e2", "x + y − z = −6".
// Student answers are hostile input, so length, nesting depth and exponent size are bounded
// before GiNaC evaluates anything (GiNaC's own parser recurses without limit and evaluates
// exact powers without bound).
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include "solver/util/said.hpp"

namespace frustum {

// Named defaults; every limit can be overridden per call.
inline constexpr std::size_t kMaxExpressionLength = 4096;  // bytes of input
inline constexpr int kMaxExpressionDepth = 64;             // nested (), function calls, unary ops
inline constexpr long kMaxExponent = 1024;                 // |integer exponent|
inline constexpr std::size_t kMaxExactBits = 16384;        // bits of an exact power's result
// |power of ten| of a decimal (1e-4932): as large as an exact number may be (2¹⁶³⁸⁴ ≈ 10⁴⁹³²),
// so a key the solver computes from givens within the bounds can be written as a decimal.
inline constexpr long kMaxDecimalExponent =
    static_cast<long>(static_cast<double>(kMaxExactBits) * 0.30102999566398120);

struct ExpressionOptions {
  std::size_t max_length = kMaxExpressionLength;
  int max_depth = kMaxExpressionDepth;
  long max_exponent = kMaxExponent;
  std::size_t max_exact_bits = kMaxExactBits;
  // Free variables the expression may use (e.g. x, y, z in a plane equation); any other
  // identifier is an error.
  std::map<std::string, GiNaC::symbol> symbols;
  // Accept one top-level "lhs = rhs"; the result is then lhs - rhs.
  bool allow_equation = false;
  // Accept the degree sign after a factor: "30°" is 30·π/180, so cos(30°) = cos(π/6) (students'
  // answers). Off for a problem's givens, whose angles are numbers in the set's unit.
  bool degree_sign = false;
};

// Why a text is not a number a student may write: the reader says it of '∞', the grader of an
// answer that reads as one.
inline constexpr Phrase kNotFiniteNumber{
    "'{0}' is not a finite number", "`{0}` は有限の数ではありません", "`{0}` — не конечное число"};

struct ExpressionResult {
  std::optional<GiNaC::ex> value;  // set on success
  Said error;                      // set on failure: why, for the person who wrote it
  std::size_t offset = 0;          // byte offset of the error in the input
  bool equation = false;           // the input was "lhs = rhs"
  explicit operator bool() const { return value.has_value(); }
};

// Untrusted text quoted for a message: at most 32 bytes, cut at a character boundary, with
// "..." when shortened ('1+1+1+1+1+1+1+1+1+1+1+1+1+1+1+1...').
std::string quote_excerpt(std::string_view text);

// A plain decimal literal ("-12", "0.57735", "1.5e-3", at most 40 digits and an exponent of at
// most ±400) as the exact rational it denotes, without the lexer and parser; nullopt for
// anything else. parse_expression takes this shortcut itself.
std::optional<GiNaC::ex> parse_decimal_literal(std::string_view text);

// Parses text into an exact GiNaC expression. Never throws, never recurses deeper than
// options.max_depth, never builds a power whose exact result exceeds options.max_exact_bits.
ExpressionResult parse_expression(std::string_view text, const ExpressionOptions& options = {});

}  // namespace frustum
