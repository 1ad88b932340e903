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

// Why a text is not read: its grammar, its names and its values. A quoted token ('{0}') is
// placed as written; so are a name's example, the variables and a limit.
constexpr Phrase kEmptyExpression{"empty expression", "式が空です", "пустое выражение"};
constexpr Phrase kEquationNotAllowed{"'=' is not allowed here: give an expression, not an equation",
                                     "ここでは '=' は使えません: 方程式ではなく式を書いてください",
                                     "здесь нельзя писать '=': нужно выражение, а не уравнение"};
constexpr Phrase kOnlyOneEquals{"only one '=' is allowed", "'=' は 1 つだけ書けます",
                                "допускается только один знак '='"};
constexpr Phrase kUnmatchedClose{"unmatched ')'", "対応する '(' のない ')'", "')' без парной '('"};
constexpr Phrase kUnexpected{"unexpected '{0}'", "予期しない `{0}` があります",
                             "неожиданно встретилось `{0}`"};
constexpr Phrase kMissingOperator{"missing operator before '{0}' (write * to multiply)",
                                  "`{0}` の前に演算子がありません (掛け算は * で書きます)",
                                  "перед `{0}` нет знака операции (умножение пишется через *)"};
// {1}: where the degree sign is.
constexpr Phrase kDegreeSignInGiven{
    "unsupported character '{0}' (U+00B0) at byte {1}: give the angle as a number in the "
    "set's unit",
    "使えない文字 `{0}` (U+00B0, バイト {1}): 角度はこの問題集の単位で数として書いてください",
    "недопустимый символ `{0}` (U+00B0, байт {1}): запишите угол числом в единицах задания"};
constexpr Phrase kIncomplete{"incomplete expression: expected a number, name or '(' after '{0}'",
                             "式が途中で終わっています: `{0}` の後に数, 名前または '(' が必要です",
                             "незаконченное выражение: после `{0}` нужно число, имя или '('"};
constexpr Phrase kEmptyBrackets{"empty brackets '()'", "空の括弧 '()'", "пустые скобки '()'"};
constexpr Phrase kExpectedFactor{"expected a number, name or '(' but found '{0}'",
                                 "数, 名前または '(' が必要ですが, `{0}` があります",
                                 "нужно число, имя или '(', а встретилось `{0}`"};
// {0}: where the '(' is.
constexpr Phrase kNeverClosed{"the '(' at byte {0} is never closed",
                              "バイト {0} の '(' が閉じていません",
                              "скобка '(' в байте {0} не закрыта"};
constexpr Phrase kExpectedClose{"expected ')' but found '{0}'",
                                "')' が必要ですが, `{0}` があります",
                                "нужна ')', а встретилось `{0}`"};
// {1}: the function written with an argument, sqrt(3).
constexpr Phrase kNeedsBrackets{"'{0}' needs its argument in brackets, e.g. {1}",
                                "`{0}` の引数は括弧で囲みます (例: `{1}`)",
                                "аргумент `{0}` пишется в скобках, например `{1}`"};
constexpr Phrase kUnknownName{"unknown name '{0}'", "未知の名前 `{0}`", "неизвестное имя `{0}`"};
constexpr Phrase kUnknownNameEuler{"unknown name '{0}' (write exp(1) for Euler's number)",
                                   "未知の名前 `{0}` (ネイピア数は exp(1) と書きます)",
                                   "неизвестное имя `{0}` (число Эйлера пишется exp(1))"};
// {1}: the name's letters as a product, x*y.
constexpr Phrase kUnknownNameProduct{
    "unknown name '{0}' (write a product with '*' or spaces, e.g. {1})",
    "未知の名前 `{0}` (積は '*' か空白で書きます. 例: `{1}`)",
    "неизвестное имя `{0}` (произведение пишется через '*' или пробел, например `{1}`)"};
// {1}: the variables, x y z.
constexpr Phrase kUnknownNameVariables{"unknown name '{0}' (the variables here are {1})",
                                       "未知の名前 `{0}` (ここで使える変数: `{1}`)",
                                       "неизвестное имя `{0}` (переменные здесь: `{1}`)"};
constexpr Phrase kNegativePowerOfZero{"division by zero (0 to a negative power)",
                                      "0 で割っています (0 の負のべき)",
                                      "деление на ноль (0 в отрицательной степени)"};
constexpr Phrase kUnknownOperator{"internal error: unknown operator", "内部エラー: 未知の演算子",
                                  "внутренняя ошибка: неизвестная операция"};
constexpr Phrase kExponentWithVariables{
    "the exponent must be a number, not an expression with variables",
    "指数は変数を含まない数でなければなりません",
    "показатель степени должен быть числом, а не выражением с переменными"};
constexpr Phrase kExponentNotReal{"not a real number (the exponent)", "実数ではありません (指数)",
                                  "не действительное число (показатель степени)"};
constexpr Phrase kNegativeToIrrational{
    "not a real number (a negative number to an irrational power)",
    "実数ではありません (負の数の無理数乗)",
    "не действительное число (отрицательное число в иррациональной степени)"};
constexpr Phrase kEvenRootOfNegative{
    "not a real number (an even root of a negative number)",
    "実数ではありません (負の数の偶数乗根)",
    "не действительное число (корень чётной степени из отрицательного числа)"};
// {0}: asin or acos as written.
constexpr Phrase kNeedsUnitRange{"not a real number ('{0}' needs a value between -1 and 1)",
                                 "実数ではありません (`{0}` の引数は -1 から 1 の間です)",
                                 "не действительное число (аргумент `{0}` должен быть от -1 до 1)"};
constexpr Phrase kLogNeedsPositive{
    "not a real number (log needs a positive number)",
    "実数ではありません (log の引数は正の数です)",
    "не действительное число (аргумент log должен быть положительным)"};
constexpr Phrase kZeroToZero{"0^0 is undefined", "0^0 は定義されていません", "0^0 не определено"};
constexpr Phrase kLogOfZero{"log(0) is undefined", "log(0) は定義されていません",
                            "log(0) не определён"};
constexpr Phrase kTanPole{"undefined: tan has a pole here (division by zero)",
                          "定義されていません: tan はここで極をもちます (0 で割っています)",
                          "не определено: здесь у tan полюс (деление на ноль)"};
// {1}: the limit.
constexpr Phrase kAngleTooLarge{"the angle in '{0}' is too large (at most {1})",
                                "`{0}` の角度が大きすぎます (最大 {1})",
                                "угол в `{0}` слишком велик (не больше {1})"};
constexpr Phrase kArgumentTooLarge{"the argument of '{0}' is too large (at most {1})",
                                   "`{0}` の引数が大きすぎます (最大 {1})",
                                   "аргумент `{0}` слишком велик (не больше {1})"};
// The whole text: {0} its length, {1} the limit, in bytes.
constexpr Phrase kTooLong{"the expression is too long ({0} bytes; the limit is {1})",
                          "式が長すぎます ({0} バイトあります. 上限は {1})",
                          "выражение слишком длинное ({0} байт; предел {1})"};
constexpr Phrase kOutOfMemory{"the expression is too large to evaluate (out of memory)",
                              "式が大きすぎて評価できません (メモリ不足)",
                              "выражение слишком велико для вычисления (не хватает памяти)"};
constexpr Phrase kCannotEvaluate{"the expression cannot be evaluated", "式を評価できません",
                                 "выражение нельзя вычислить"};

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
    if (peek().kind == TokenKind::kEnd) fail(say(kEmptyExpression), 0);
    Value value = sum();
    if (peek().kind == TokenKind::kEquals) {
      const Token& equals = advance();
      if (!options_.allow_equation) fail(say(kEquationNotAllowed), equals.offset);
      const Value rhs = sum();
      if (peek().kind == TokenKind::kEquals) fail(say(kOnlyOneEquals), peek().offset);
      value = combine(value, rhs, TokenKind::kMinus, equals.offset);
      result.equation = true;
    }
    const Token& end = peek();
    if (end.kind == TokenKind::kClose) fail(say(kUnmatchedClose), end.offset);
    if (end.kind != TokenKind::kEnd) fail(say(kUnexpected, shown(end)), end.offset);
    check_value_size(value, options_, 0);
    require_real(value.value, 0);
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
  // A token as a phrase quotes it ('{0}'), without the quotes.
  std::string shown(const Token& t) const { return excerpt(text_, t.offset, t.size); }

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
        if (next.kind == TokenKind::kNumber) fail(say(kMissingOperator, shown(next)), next.offset);
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
        fail(say(kDegreeSignInGiven, shown(degree), degree.offset), degree.offset);
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
    if (t.kind == TokenKind::kEnd) fail(say(kIncomplete, shown(previous)), t.offset);
    if (t.kind == TokenKind::kClose && pos_ > 0 && previous.kind == TokenKind::kOpen) {
      fail(say(kEmptyBrackets), previous.offset);
    }
    fail(say(kExpectedFactor, shown(t)), t.offset);
  }

  void close(const Token& open) {
    const Token& t = peek();
    if (t.kind == TokenKind::kClose) {
      advance();
    } else if (t.kind == TokenKind::kEnd) {
      fail(say(kNeverClosed, open.offset), open.offset);
    } else {
      fail(say(kExpectedClose, shown(t)), t.offset);
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
    if (function) fail(say(kNeedsBrackets, shown(t), t.name + "(3)"), t.offset);
    if (key == "inf" || key == "infinity" || key == "nan") {
      fail(say(kNotFiniteNumber, shown(t)), t.offset);
    }
    if (key == "e") fail(say(kUnknownNameEuler, shown(t)), t.offset);
    if (t.name.size() > 1 && std::all_of(t.name.begin(), t.name.end(), [&](char c) {
          return options_.symbols.count(std::string(1, c)) > 0;
        })) {
      std::string product(1, t.name[0]);
      for (std::size_t i = 1; i < t.name.size(); ++i) product += std::string("*") + t.name[i];
      fail(say(kUnknownNameProduct, shown(t), product), t.offset);
    }
    if (!options_.symbols.empty()) {
      std::string variables;
      for (const auto& entry : options_.symbols)
        variables += (variables.empty() ? "" : " ") + entry.first;
      fail(say(kUnknownNameVariables, shown(t), variables), t.offset);
    }
    fail(say(kUnknownName, shown(t)), t.offset);
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
          fail(say(kDivisionByZero), offset);
        }
        r.value = evaluate(
            [&] { return op == TokenKind::kTimes ? a.value * b.value : a.value / b.value; },
            offset);
        r.height = a.height + b.height;
        break;
      default:
        fail(say(kUnknownOperator), offset);
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
      fail(say(kExponentWithVariables), exponent_offset);
    }
    const numeric k = approximate(exponent.value, exponent_offset);
    if (!k.is_real()) fail(say(kExponentNotReal), exponent_offset);
    check_power(base, exponent, k, options_, offset, exponent_offset);
    const bool rational = is_a<numeric>(exponent.value);  // exact numerics are rational here
    const numeric exact_k = rational ? ex_to<numeric>(exponent.value) : numeric(0);
    const bool integer = rational && exact_k.is_integer();
    const numeric abs_k = GiNaC::abs(k);

    Value r;
    const bool constant_base = !has_symbol(base.value);
    if (constant_base && is_exact_zero(base.value, offset)) {
      if (k.is_zero()) fail(say(kZeroToZero), offset);
      if (k.is_negative()) fail(say(kNegativePowerOfZero), offset);
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
      if (!rational) fail(say(kNegativeToIrrational), offset);
      if (exact_k.denom().is_even()) fail(say(kEvenRootOfNegative), offset);
      const ex magnitude = evaluate([&] { return GiNaC::pow(-base.value, exact_k); }, offset);
      r.value = exact_k.numer().is_odd() ? -magnitude : magnitude;
    } else {
      r.value = evaluate([&] { return GiNaC::pow(base.value, exponent.value); }, offset);
    }
    r.height = base.height * abs_k.to_double();
    settle(r);
    check_value_size(r, options_, offset);
    require_real(r.value, offset);
    return r;
  }

  Value call(Function function, const Value& argument, const Token& name) {
    const std::size_t offset = name.offset;
    const ex& x = argument.value;
    const bool constant = !has_symbol(x);
    Value r;
    Said why_not_real;  // empty: "not a real number"
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
            fail(say(kAngleTooLarge, shown(name), whole_number(kMaxTrigArgument)), offset);
          }
        }
        r.value = evaluate(
            [&] {
              return function == Function::kSin   ? GiNaC::sin(x)
                     : function == Function::kCos ? GiNaC::cos(x)
                                                  : GiNaC::tan(x);
            },
            offset, kTanPole);
        break;
      case Function::kAsin:
      case Function::kAcos:
        r.value = evaluate(
            [&] { return function == Function::kAsin ? GiNaC::asin(x) : GiNaC::acos(x); }, offset);
        why_not_real = say(kNeedsUnitRange, shown(name));
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
            fail(say(kArgumentTooLarge, shown(name), whole_number(std::floor(limit))), offset);
          }
        }
        r.value = evaluate([&] { return GiNaC::exp(x); }, offset);
        break;
      case Function::kLog:
        if (constant) {
          if (is_exact_zero(x, offset)) fail(say(kLogOfZero), offset);
          const numeric a = approximate(x, offset);
          if (a.is_real() && a.is_negative()) fail(say(kLogNeedsPositive), offset);
        }
        r.value = evaluate([&] { return GiNaC::log(x); }, offset, kLogOfZero);
        break;
      case Function::kAbs:
        r.value = evaluate([&] { return GiNaC::abs(x); }, offset);
        break;
    }
    // Functions stay symbolic, but exp(log(n)) and abs(n) can give back the argument's size.
    r.height = argument.height;
    settle(r);
    check_value_size(r, options_, offset);
    require_real(r.value, offset, why_not_real);
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

ExpressionResult failure(Said message, std::size_t offset) {
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
    return expression_internal::failure(
        say(expression_internal::kTooLong, text.size(), options.max_length), options.max_length);
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
    return expression_internal::failure(say(expression_internal::kOutOfMemory), 0);
  } catch (const std::exception&) {
    return expression_internal::failure(say(expression_internal::kCannotEvaluate), 0);
  } catch (...) {
    return expression_internal::failure(say(expression_internal::kCannotEvaluate), 0);
  }
}

}  // namespace frustum
