// What the pieces of the expression parser share (solver/util/expression_*.cpp): tokens,
// values carried with their size bounds, located parse errors, the guarded GiNaC calls and
// the bounds checked before GiNaC computes anything. Not part of the public interface
// (solver/util/expression.hpp).
#pragma once

#include <ginac/ginac.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "solver/util/expression.hpp"
#include "solver/util/said.hpp"

namespace frustum::expression_internal {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// What more than one piece says: evaluate() below, the lexer and the parser. A quoted token
// ('{0}') is placed as written, without its quotes (excerpt()).
inline constexpr Phrase kDivisionByZero{"division by zero", "0 で割っています", "деление на ноль"};
inline constexpr Phrase kCannotComputeValue{
    "this value cannot be computed (it is too large or undefined)",
    "この値は計算できません (大きすぎるか, 定義されていません)",
    "это значение нельзя вычислить (оно слишком велико или не определено)"};

// Internal only: parse_expression turns it into an ExpressionResult.
struct ParseError {
  Said message;
  std::size_t offset;
};

[[noreturn]] inline void fail(Said message, std::size_t offset) {
  throw ParseError{std::move(message), offset};
}
// A reason is said as a phrase (say(kX, ...)), never as English text to be looked up.
void fail(const char* english, std::size_t offset) = delete;
void fail(const std::string& english, std::size_t offset) = delete;

// ---------------------------------------------------------------------------------------
// Tokens (expression_lexer.cpp)

enum class TokenKind {
  kNumber,
  kName,
  kPlus,
  kMinus,
  kTimes,
  kDivide,
  kPower,        // ^ or **
  kSuperscript,  // ², ³, ⁻¹ ...: an exponent already
  kRoot,         // √
  kPi,           // π
  kDegree,       // °: read only where ExpressionOptions::degree_sign allows it
  kOpen,
  kClose,
  kEquals,
  kEnd,
};

struct Token {
  TokenKind kind;
  std::size_t offset;  // bytes into the original text
  std::size_t size;    // bytes
  numeric number;      // kNumber, kSuperscript
  std::string name;    // kName, folded to ASCII
};

// The tokens of `text`, ending with kEnd. Throws ParseError on invalid UTF-8 and on
// characters outside the grammar.
std::vector<Token> tokenize(std::string_view text);

// The source text of a token in quotes, shortened at a character boundary.
std::string quoted(std::string_view text, std::size_t offset, std::size_t size);
// The same without its quotes, for a phrase that places it in each language's own quotes
// ('{0}' in English, `{0}` in Japanese and Russian).
std::string excerpt(std::string_view text, std::size_t offset, std::size_t size);

// ---------------------------------------------------------------------------------------
// Size bounds carried with every value (expression_limits.cpp)

// An exact value with a bound on what raising it to a power exactly can cost.
struct Value {
  ex value;
  // log2 of the largest numerator or denominator an exact evaluation of this can produce;
  // raising it to k costs about |k| * height bits. A magnitude, so GiNaC's rewriting of
  // the value ((√2)^4 -> 4, 2^(1/2)*2^(1/3) -> 2^(5/6)) leaves it valid.
  double height = 0;
};

// Tightens the bounds when GiNaC has already reduced the value to an atom.
void settle(Value& v);

// Short human form of a value for messages ("2", "(1/2)", "a 1001-digit number").
std::string describe(const ex& e);

// x rounded up, without decimals ("10000").
std::string whole_number(double x);

// The nesting depth the parser allows: options.max_depth, capped to fit a thread's stack.
int nesting_limit(const ExpressionOptions& options);

// Counts one nesting level for as long as it lives; refuses a level beyond `limit`.
class Nesting {
 public:
  Nesting(int& depth, int limit, std::size_t offset);
  ~Nesting() { --depth_; }
  Nesting(const Nesting&) = delete;
  Nesting& operator=(const Nesting&) = delete;

 private:
  int& depth_;
};

// Refuses a value whose exponents, numbers or expanded size exceed the options' bounds.
void check_value_size(const Value& v, const ExpressionOptions& options, std::size_t offset);

// Refuses base^exponent (exponent a real constant, approximately k) before GiNaC computes it:
// roots beyond kMaxParsedRootIndex, results beyond options.max_exact_bits and exponents
// beyond options.max_exponent.
void check_power(const Value& base, const Value& exponent, const numeric& k,
                 const ExpressionOptions& options, std::size_t offset, std::size_t exponent_offset);

// ---------------------------------------------------------------------------------------
// GiNaC evaluation, guarded (expression_exact.cpp)

// Runs a GiNaC operation, turning its exceptions into a located error.
template <class F>
ex evaluate(F&& f, std::size_t offset, const Phrase& pole = kDivisionByZero) {
  try {
    return f();
  } catch (const GiNaC::pole_error&) {
    fail(say(pole), offset);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    fail(say(kCannotComputeValue), offset);
  }
}

// Floating approximation of a constant (no symbols).
numeric approximate(const ex& e, std::size_t offset);

// The solver is real-valued: a constant must evaluate to a real number. `why` is the error
// when it does not (empty: "not a real number").
void require_real(const ex& e, std::size_t offset, const Said& why = {});

}  // namespace frustum::expression_internal
