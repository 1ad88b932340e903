// A bounded recursive-descent parser from untrusted text to exact GiNaC values.
//
// Grammar, loosest binding first (implicit multiplication is a product without '*'):
//   input   := sum ['=' sum]
//   sum     := product {('+' | '-') product}
//   product := signed {('*' | '/') signed | power}
//   signed  := ('+' | '-') signed | power
//   power   := rooted {superscript} ['^' signed]          '^' is right-associative
//   rooted  := '√' rooted | primary                       √3^2 = (√3)^2
//   primary := number | 'pi' | 'π' | name | function '(' sum ')' | '(' sum ')'
// So -2^2 = -4, 2^-1 = 1/2, 2^3^2 = 512, 1/2x = (1/2)*x, 100√3 = 100*sqrt(3) and
// √3/3 = sqrt(3)/3. A number never follows another factor implicitly ("2 3", "x 2", "π2"
// are errors), so "1 000" cannot silently become 0.
#include <algorithm>
#include <cmath>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/core/work_budget.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/expression_internal.hpp"
#include "solver/util/words.hpp"

namespace frustum {
namespace expression_internal {
namespace {

// Proving a divisor zero by expand() costs up to ~40 us a term for sums of radicals, so one
// parse spends at most this many terms on it, then falls back to a numeric test.
constexpr double kMaxZeroTestTerms = 2'000;
// No problem needs a larger angle, and near 10^17 radians GiNaC's default precision leaves
// sin, cos and tan without a correct digit.
constexpr double kMaxTrigArgument = 1e6;

enum class Function { kSqrt, kCbrt, kSin, kCos, kTan, kAsin, kAcos, kAtan, kExp, kLog, kAbs };

struct FunctionName {
  std::string_view name;
  Function function;
};

constexpr FunctionName kFunctions[] = {
    {"sqrt", Function::kSqrt}, {"cbrt", Function::kCbrt}, {"sin", Function::kSin},
    {"cos", Function::kCos},   {"tan", Function::kTan},   {"asin", Function::kAsin},
    {"acos", Function::kAcos}, {"atan", Function::kAtan}, {"exp", Function::kExp},
    {"log", Function::kLog},   {"ln", Function::kLog},    {"abs", Function::kAbs},
};

// Built-in names are case-insensitive (students write Pi, SQRT); variables are not.
std::optional<Function> find_function(std::string_view name) {
  const std::string key = ascii_lower(name);
  for (const FunctionName& f : kFunctions) {
    if (f.name == key) return f.function;
  }
  return std::nullopt;
}

class Parser {
 public:
  Parser(std::string_view text, std::vector<Token> tokens, const ExpressionOptions& options)
      : text_(text),
        tokens_(std::move(tokens)),
        options_(options),
        max_depth_(nesting_limit(options)) {}

  ExpressionResult run() {
    ExpressionResult result;
    if (peek().kind == TokenKind::kEnd) fail("empty expression", 0);
    Value value = sum();
    if (peek().kind == TokenKind::kEquals) {
      const Token& equals = advance();
      if (!options_.allow_equation) {
        fail("'=' is not allowed here: give an expression, not an equation", equals.offset);
      }
      const Value rhs = sum();
      if (peek().kind == TokenKind::kEquals) fail("only one '=' is allowed", peek().offset);
      value = combine(value, rhs, TokenKind::kMinus, equals.offset);
      result.equation = true;
    }
    const Token& end = peek();
    if (end.kind == TokenKind::kClose) fail("unmatched ')'", end.offset);
    if (end.kind != TokenKind::kEnd) fail("unexpected " + quote(end), end.offset);
    check_value_size(value, options_, 0);
    require_real(value.value, 0, "");
    result.value = value.value;
    return result;
  }

 private:
  const Token& peek() const { return tokens_[pos_]; }
  const Token& advance() {
    const Token& t = tokens_[pos_];
    if (t.kind != TokenKind::kEnd) ++pos_;
    return t;
  }
  std::string quote(const Token& t) const { return quoted(text_, t.offset, t.size); }

  static bool starts_factor(TokenKind kind) {
    return kind == TokenKind::kNumber || kind == TokenKind::kName || kind == TokenKind::kPi ||
           kind == TokenKind::kOpen || kind == TokenKind::kRoot;
  }

  Value sum() {
    Value left = product();
    while (peek().kind == TokenKind::kPlus || peek().kind == TokenKind::kMinus) {
      const Token& op = advance();
      const Value right = product();
      left = combine(left, right, op.kind, op.offset);
    }
    return left;
  }

  Value product() {
    Value left = signed_factor();
    for (;;) {
      const Token& next = peek();
      if (next.kind == TokenKind::kTimes || next.kind == TokenKind::kDivide) {
        advance();
        const Value right = signed_factor();
        left = combine(left, right, next.kind, next.offset);
      } else if (starts_factor(next.kind)) {
        if (next.kind == TokenKind::kNumber) {
          fail("missing operator before " + quote(next) + " (write * to multiply)", next.offset);
        }
        const Value right = power();
        left = combine(left, right, TokenKind::kTimes, next.offset);
      } else {
        return left;
      }
    }
  }

  Value signed_factor() {
    const Token& sign = peek();
    if (sign.kind != TokenKind::kPlus && sign.kind != TokenKind::kMinus) return power();
    Nesting nesting(depth_, max_depth_, sign.offset);
    advance();
    Value v = signed_factor();
    if (sign.kind == TokenKind::kMinus) {
      v.value = evaluate([&] { return -v.value; }, sign.offset);
      settle(v);
    }
    return v;
  }

  Value power() {
    Value base = rooted();
    while (peek().kind == TokenKind::kSuperscript) {
      const Token& sup = advance();
      base = raise(base, Value{sup.number}, sup.offset, sup.offset);
    }
    if (peek().kind == TokenKind::kDegree) {
      const Token& degree = advance();
      if (!options_.degree_sign)
        fail("unsupported character " + quote(degree) + " (U+00B0) at byte " +
                 std::to_string(degree.offset) + ": give the angle as a number in the set's unit",
             degree.offset);
      Value per_degree{numeric(1, 180)};
      settle(per_degree);
      base = combine(combine(base, per_degree, TokenKind::kTimes, degree.offset), Value{GiNaC::Pi},
                     TokenKind::kTimes, degree.offset);
    }
    if (peek().kind != TokenKind::kPower) return base;
    const Token& caret = advance();
    // Each step of a right-associative chain 2^2^2^... is one level deeper.
    Nesting nesting(depth_, max_depth_, caret.offset);
    const std::size_t exponent_offset = peek().offset;
    const Value exponent = signed_factor();
    return raise(base, exponent, caret.offset, exponent_offset);
  }

  Value rooted() {
    const Token& root = peek();
    if (root.kind != TokenKind::kRoot) return primary();
    Nesting nesting(depth_, max_depth_, root.offset);
    advance();
    if (!starts_factor(peek().kind)) expected_factor(root);
    const Value radicand = rooted();
    return raise(radicand, Value{numeric(1, 2)}, root.offset, root.offset);
  }

  Value primary() {
    const Token& t = peek();
    switch (t.kind) {
      case TokenKind::kNumber: {
        advance();
        Value v{t.number};
        settle(v);
        return v;
      }
      case TokenKind::kPi:
        advance();
        return Value{GiNaC::Pi};
      case TokenKind::kOpen: {
        Nesting nesting(depth_, max_depth_, t.offset);
        advance();
        Value inner = sum();
        close(t);
        return inner;
      }
      case TokenKind::kName:
        return name();
      default:
        expected_factor(tokens_[pos_ == 0 ? 0 : pos_ - 1]);
    }
  }

  [[noreturn]] void expected_factor(const Token& previous) const {
    const Token& t = peek();
    if (t.kind == TokenKind::kEnd) {
      fail("incomplete expression: expected a number, name or '(' after " + quote(previous),
           t.offset);
    }
    if (t.kind == TokenKind::kClose && pos_ > 0 && previous.kind == TokenKind::kOpen) {
      fail("empty brackets '()'", previous.offset);
    }
    fail("expected a number, name or '(' but found " + quote(t), t.offset);
  }

  void close(const Token& open) {
    const Token& t = peek();
    if (t.kind == TokenKind::kClose) {
      advance();
    } else if (t.kind == TokenKind::kEnd) {
      fail("the '(' at byte " + std::to_string(open.offset) + " is never closed", open.offset);
    } else {
      fail("expected ')' but found " + quote(t), t.offset);
    }
  }

  Value name() {
    const Token& t = advance();
    const std::optional<Function> function = find_function(t.name);
    if (function && peek().kind == TokenKind::kOpen) {
      const Token& open = advance();
      Nesting nesting(depth_, max_depth_, t.offset);
      const Value argument = sum();
      close(open);
      return call(*function, argument, t);
    }
    if (const auto it = options_.symbols.find(t.name); it != options_.symbols.end()) {
      return Value{it->second};
    }
    const std::string key = ascii_lower(t.name);
    if (key == "pi") return Value{GiNaC::Pi};
    if (function) {
      fail(quote(t) + " needs its argument in brackets, e.g. " + t.name + "(3)", t.offset);
    }
    if (key == "inf" || key == "infinity" || key == "nan") {
      fail(quote(t) + " is not a finite number", t.offset);
    }
    std::string message = "unknown name " + quote(t);
    if (key == "e") {
      message += " (write exp(1) for Euler's number)";
    } else if (t.name.size() > 1 && std::all_of(t.name.begin(), t.name.end(), [&](char c) {
                 return options_.symbols.count(std::string(1, c)) > 0;
               })) {
      std::string product(1, t.name[0]);
      for (std::size_t i = 1; i < t.name.size(); ++i) product += std::string("*") + t.name[i];
      message += " (write a product with '*' or spaces, e.g. " + product + ")";
    } else if (!options_.symbols.empty()) {
      message += " (the variables here are";
      for (const auto& entry : options_.symbols) message += " " + entry.first;
      message += ")";
    }
    fail(message, t.offset);
  }

  // ---- operations, each guarded before GiNaC computes anything large

  // Zero as far as GiNaC can prove: (√2+1)(√2-1)-1 needs expand(); when the budget for
  // that is spent, a constant counts as zero only if it evaluates to exactly zero.
  bool is_exact_zero(const ex& e, std::size_t offset) {
    if (e.is_zero()) return true;
    if (zero_test_budget_.spend(exact_size(e).work))
      return evaluate([&] { return e.expand(); }, offset).is_zero();
    return !has_symbol(e) && approximate(e, offset).is_zero();
  }

  Value combine(const Value& a, const Value& b, TokenKind op, std::size_t offset) {
    Value r;
    switch (op) {
      case TokenKind::kPlus:
      case TokenKind::kMinus:
        r.value = evaluate(
            [&] { return op == TokenKind::kPlus ? a.value + b.value : a.value - b.value; }, offset);
        // |p + q| <= 2^a + 2^b, so a long sum of like terms grows by log2 of its length.
        r.height =
            std::max(a.height, b.height) + std::log2(1 + std::exp2(-std::abs(a.height - b.height)));
        break;
      case TokenKind::kTimes:
      case TokenKind::kDivide:
        if (op == TokenKind::kDivide && is_exact_zero(b.value, offset)) {
          fail("division by zero", offset);
        }
        r.value = evaluate(
            [&] { return op == TokenKind::kTimes ? a.value * b.value : a.value / b.value; },
            offset);
        r.height = a.height + b.height;
        break;
      default:
        fail("internal error: unknown operator", offset);
    }
    settle(r);
    // A sum only adds its parts' terms; checking every '+' of a long sum would cost O(n^2),
    // so sums are checked where they are multiplied or raised, and once at the end.
    if (op == TokenKind::kTimes || op == TokenKind::kDivide) check_value_size(r, options_, offset);
    return r;
  }

  // base^exponent for a real constant exponent, refusing results whose exact evaluation
  // would exceed the bit budget before GiNaC attempts it.
  Value raise(const Value& base, const Value& exponent, std::size_t offset,
              std::size_t exponent_offset) {
    if (has_symbol(exponent.value)) {
      fail("the exponent must be a number, not an expression with variables", exponent_offset);
    }
    const numeric k = approximate(exponent.value, exponent_offset);
    if (!k.is_real()) fail("not a real number (the exponent)", exponent_offset);
    check_power(base, exponent, k, options_, offset, exponent_offset);
    const bool rational = is_a<numeric>(exponent.value);  // exact numerics are rational here
    const numeric exact_k = rational ? ex_to<numeric>(exponent.value) : numeric(0);
    const bool integer = rational && exact_k.is_integer();
    const numeric abs_k = GiNaC::abs(k);

    Value r;
    const bool constant_base = !has_symbol(base.value);
    if (constant_base && is_exact_zero(base.value, offset)) {
      if (k.is_zero()) fail("0^0 is undefined", offset);
      if (k.is_negative()) fail("division by zero (0 to a negative power)", offset);
      // 0 to any positive power is 0. GiNaC leaves 0^(irrational) unevaluated, and dividing by
      // it later throws from inside GiNaC's evalf, which leaks (found by fuzz_expression).
      r.value = 0;
      r.height = 0;
      return r;
    }
    // Odd roots of negative numbers are real: (-8)^(1/3) = -2, as a student means it.
    const bool negative_base = constant_base && !integer && [&] {
      const numeric b = approximate(base.value, offset);
      return b.is_real() && b.is_negative();
    }();
    if (negative_base) {
      if (!rational) fail("not a real number (a negative number to an irrational power)", offset);
      if (exact_k.denom().is_even()) {
        fail("not a real number (an even root of a negative number)", offset);
      }
      const ex magnitude = evaluate([&] { return GiNaC::pow(-base.value, exact_k); }, offset);
      r.value = exact_k.numer().is_odd() ? -magnitude : magnitude;
    } else {
      r.value = evaluate([&] { return GiNaC::pow(base.value, exponent.value); }, offset);
    }
    r.height = base.height * abs_k.to_double();
    settle(r);
    check_value_size(r, options_, offset);
    require_real(r.value, offset, "");
    return r;
  }

  Value call(Function function, const Value& argument, const Token& name) {
    const std::size_t offset = name.offset;
    const ex& x = argument.value;
    const bool constant = !has_symbol(x);
    Value r;
    std::string hint;
    switch (function) {
      case Function::kSqrt:
        return raise(argument, Value{numeric(1, 2)}, offset, offset);
      case Function::kCbrt:
        return raise(argument, Value{numeric(1, 3)}, offset, offset);
      case Function::kSin:
      case Function::kCos:
      case Function::kTan:
        if (constant) {
          const numeric a = approximate(x, offset);
          if (a.is_real() && GiNaC::abs(a) > numeric(kMaxTrigArgument)) {
            fail("the angle in " + quote(name) + " is too large (at most " +
                     whole_number(kMaxTrigArgument) + ")",
                 offset);
          }
        }
        r.value = evaluate(
            [&] {
              return function == Function::kSin   ? GiNaC::sin(x)
                     : function == Function::kCos ? GiNaC::cos(x)
                                                  : GiNaC::tan(x);
            },
            offset, "undefined: tan has a pole here (division by zero)");
        break;
      case Function::kAsin:
      case Function::kAcos:
        r.value = evaluate(
            [&] { return function == Function::kAsin ? GiNaC::asin(x) : GiNaC::acos(x); }, offset);
        hint = " (" + quote(name) + " needs a value between -1 and 1)";
        break;
      case Function::kAtan:
        r.value = evaluate([&] { return GiNaC::atan(x); }, offset);
        break;
      case Function::kExp:
        // Beyond this, exp(x) exceeds the largest exact power allowed.
        if (constant) {
          const numeric a = approximate(x, offset);
          const double limit = static_cast<double>(options_.max_exact_bits) * std::log(2.0);
          if (a.is_real() && GiNaC::abs(a) > numeric(limit)) {
            fail("the argument of " + quote(name) + " is too large (at most " +
                     whole_number(std::floor(limit)) + ")",
                 offset);
          }
        }
        r.value = evaluate([&] { return GiNaC::exp(x); }, offset);
        break;
      case Function::kLog:
        if (constant) {
          if (is_exact_zero(x, offset)) fail("log(0) is undefined", offset);
          const numeric a = approximate(x, offset);
          if (a.is_real() && a.is_negative()) {
            fail("not a real number (log needs a positive number)", offset);
          }
        }
        r.value = evaluate([&] { return GiNaC::log(x); }, offset, "log(0) is undefined");
        break;
      case Function::kAbs:
        r.value = evaluate([&] { return GiNaC::abs(x); }, offset);
        break;
    }
    // Functions stay symbolic, but exp(log(n)) and abs(n) can give back the argument's size.
    r.height = argument.height;
    settle(r);
    check_value_size(r, options_, offset);
    require_real(r.value, offset, hint);
    return r;
  }

  std::string_view text_;
  std::vector<Token> tokens_;
  const ExpressionOptions& options_;
  int max_depth_;
  int depth_ = 0;
  std::size_t pos_ = 0;
  WorkBudget zero_test_budget_{kMaxZeroTestTerms};
};

ExpressionResult failure(std::string message, std::size_t offset) {
  ExpressionResult result;
  result.error = std::move(message);
  result.offset = offset;
  return result;
}

}  // namespace

}  // namespace expression_internal

ExpressionResult parse_expression(std::string_view text, const ExpressionOptions& options) {
  // Length first: nothing else runs on oversized input.
  if (text.size() > options.max_length) {
    return expression_internal::failure("the expression is too long (" +
                                            std::to_string(text.size()) + " bytes; the limit is " +
                                            std::to_string(options.max_length) + ")",
                                        options.max_length);
  }
  if (const std::optional<GiNaC::ex> d = parse_decimal_literal(text)) {
    ExpressionResult r;
    r.value = *d;
    return r;
  }
  try {
    expression_internal::Parser parser(text, expression_internal::tokenize(text), options);
    return parser.run();
  } catch (const expression_internal::ParseError& e) {
    return expression_internal::failure(e.message, e.offset);
  } catch (const std::bad_alloc&) {
    return expression_internal::failure("the expression is too large to evaluate (out of memory)",
                                        0);
  } catch (const std::exception&) {
    return expression_internal::failure("the expression cannot be evaluated", 0);
  } catch (...) {
    return expression_internal::failure("the expression cannot be evaluated", 0);
  }
}

}  // namespace frustum
