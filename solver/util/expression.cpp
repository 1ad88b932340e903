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
#include "solver/util/expression.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <new>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/core/work_budget.hpp"

namespace frustum {
namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// 1e±400 spans every physical constant a problem needs; bigger powers of ten are typos.
constexpr long kMaxDecimalExponent = 400;
// expand() (here on divisors, and downstream) multiplies sums out; (a+b+c+d)^1000 or a
// product of many sums would create more terms than memory holds.
constexpr double kMaxExpandedTerms = 10'000;
// Proving a divisor zero by expand() costs up to ~40 us a term for sums of radicals, so one
// parse spends at most this many terms on it, then falls back to a numeric test.
constexpr double kMaxZeroTestTerms = 2'000;
// A nesting level costs about 1.5 KB of stack in an unoptimised build, so a caller's
// overridden max_depth is capped to fit a 512 KB thread stack.
constexpr int kMaxSafeDepth = 256;
// No problem needs a larger angle, and near 10^17 radians GiNaC's default precision leaves
// sin, cos and tan without a correct digit.
constexpr double kMaxTrigArgument = 1e6;
constexpr std::size_t kMaxQuotedBytes = 32;

// Internal only: parse_expression turns it into an ExpressionResult.
struct ParseError {
  std::string message;
  std::size_t offset;
};

[[noreturn]] void fail(std::string message, std::size_t offset) {
  throw ParseError{std::move(message), offset};
}

// ---------------------------------------------------------------------------------------
// Characters

// One decoded character; `code` is folded to the ASCII it stands for (full-width digits,
// Unicode minus and times signs...), `original` is what was typed.
struct Glyph {
  char32_t code;
  char32_t original;
  std::size_t offset;
  std::size_t size;
};

std::string hex_code(char32_t c) {
  std::ostringstream out;
  out << "U+" << std::uppercase << std::hex << std::setw(4) << std::setfill('0')
      << static_cast<std::uint32_t>(c);
  return out.str();
}

// Maps the look-alikes students paste from word processors to the ASCII they mean.
char32_t fold(char32_t c) {
  if (c >= 0xFF01 && c <= 0xFF5E) return c - 0xFEE0;  // full-width ASCII
  switch (c) {
    case 0x3000:  // ideographic space
    case 0x00A0:  // no-break space
    case 0x2009:  // thin space
    case 0x202F:  // narrow no-break space
      return U' ';
    case 0x2212:  // minus sign
    case 0x2013:  // en dash
      return U'-';
    case 0x00D7:  // multiplication sign
    case 0x00B7:  // middle dot
    case 0x22C5:  // dot operator
    case 0x2217:  // asterisk operator
      return U'*';
    case 0x00F7:  // division sign
    case 0x2215:  // division slash
      return U'/';
    default:
      return c;
  }
}

// Strict UTF-8 (no overlong forms, surrogates or values above U+10FFFF).
std::vector<Glyph> decode_utf8(std::string_view text) {
  std::vector<Glyph> glyphs;
  glyphs.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char b0 = byte(i);
    std::size_t size = 0;
    char32_t code = 0;
    unsigned char low = 0x80;
    unsigned char high = 0xBF;
    if (b0 < 0x80) {
      size = 1;
      code = b0;
    } else if (b0 >= 0xC2 && b0 <= 0xDF) {
      size = 2;
      code = b0 & 0x1F;
    } else if (b0 >= 0xE0 && b0 <= 0xEF) {
      size = 3;
      code = b0 & 0x0F;
      if (b0 == 0xE0) low = 0xA0;   // overlong
      if (b0 == 0xED) high = 0x9F;  // surrogates
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
      size = 4;
      code = b0 & 0x07;
      if (b0 == 0xF0) low = 0x90;   // overlong
      if (b0 == 0xF4) high = 0x8F;  // above U+10FFFF
    }
    bool valid = size != 0 && i + size <= text.size();
    for (std::size_t k = 1; valid && k < size; ++k) {
      const unsigned char b = byte(i + k);
      const unsigned char lo = k == 1 ? low : 0x80;
      const unsigned char hi = k == 1 ? high : 0xBF;
      if (b < lo || b > hi) valid = false;
      code = (code << 6) | (b & 0x3F);
    }
    // parse_yaml replaces invalid bytes with U+FFFD; name the cause, not the placeholder.
    if (valid && code == 0xFFFD)
      fail("invalid UTF-8: a byte that is not text (shown as \uFFFD)", i);
    if (!valid) {
      std::ostringstream out;
      out << "invalid UTF-8: byte 0x" << std::uppercase << std::hex << std::setw(2)
          << std::setfill('0') << static_cast<unsigned>(b0) << std::dec << " at byte " << i
          << " does not start a valid character";
      fail(out.str(), i);
    }
    glyphs.push_back({fold(code), code, i, size});
    i += size;
  }
  return glyphs;
}

// Superscript digits 0-9 as values, -1 for others.
int superscript_digit(char32_t c) {
  switch (c) {
    case 0x2070:
      return 0;
    case 0x00B9:
      return 1;
    case 0x00B2:
      return 2;
    case 0x00B3:
      return 3;
    default:
      return (c >= 0x2074 && c <= 0x2079) ? static_cast<int>(c - 0x2070) : -1;
  }
}

constexpr char32_t kSuperscriptMinus = 0x207B;
constexpr char32_t kRootSign = 0x221A;
constexpr char32_t kPiSign = 0x03C0;
constexpr char32_t kInfinitySign = 0x221E;

bool is_digit(char32_t c) { return c >= U'0' && c <= U'9'; }
bool is_letter(char32_t c) { return (c >= U'a' && c <= U'z') || (c >= U'A' && c <= U'Z'); }
bool is_space(char32_t c) { return c == U' ' || c == U'\t' || c == U'\n' || c == U'\r'; }

// ---------------------------------------------------------------------------------------
// Tokens

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

// The source text of a token in quotes, shortened at a character boundary.
std::string quoted(std::string_view text, std::size_t offset, std::size_t size) {
  std::string_view s = text.substr(offset, size);
  const bool shorten = s.size() > kMaxQuotedBytes;
  if (shorten) {
    std::size_t cut = kMaxQuotedBytes;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
    s = s.substr(0, cut);
  }
  std::string out;
  out.reserve(s.size() + 5);
  out += '\'';
  out.append(s);
  out += shorten ? "...'" : "'";
  return out;
}

// Exact value of the decimal digits in `digits` (ASCII, bounded by the input length).
numeric integer_from_digits(const std::string& digits) {
  constexpr std::size_t kChunk = 9;
  numeric value = 0;
  for (std::size_t i = 0; i < digits.size(); i += kChunk) {
    const std::string chunk = digits.substr(i, kChunk);
    value = value * numeric(10).power(static_cast<long>(chunk.size())) + numeric(std::stol(chunk));
  }
  return value;
}

class Lexer {
 public:
  Lexer(std::string_view text, std::vector<Glyph> glyphs)
      : text_(text), glyphs_(std::move(glyphs)) {}

  std::vector<Token> run() {
    std::vector<Token> tokens;
    while (i_ < glyphs_.size()) {
      const Glyph& g = glyphs_[i_];
      const char32_t c = g.code;
      if (is_space(c)) {
        ++i_;
      } else if (is_digit(c) || (c == U'.' && is_digit(code_at(i_ + 1)))) {
        tokens.push_back(number());
      } else if (is_letter(c)) {
        tokens.push_back(name());
      } else if (superscript_digit(c) >= 0 || c == kSuperscriptMinus) {
        tokens.push_back(superscript());
      } else if (c == kInfinitySign) {
        fail("'∞' is not a finite number", g.offset);
      } else {
        tokens.push_back(punctuation());
      }
    }
    tokens.push_back({TokenKind::kEnd, text_.size(), 0, 0, {}});
    return tokens;
  }

 private:
  char32_t code_at(std::size_t i) const { return i < glyphs_.size() ? glyphs_[i].code : 0; }
  std::size_t offset_at(std::size_t i) const {
    return i < glyphs_.size() ? glyphs_[i].offset : text_.size();
  }

  Token make(TokenKind kind, std::size_t first, numeric number = 0, std::string name = {}) {
    const std::size_t begin = glyphs_[first].offset;
    return {kind, begin, offset_at(i_) - begin, std::move(number), std::move(name)};
  }

  // digits ['.' digits] [('e' | 'E') ['+' | '-'] digits], or '.' digits: an exact rational.
  Token number() {
    const std::size_t first = i_;
    std::string mantissa;
    std::size_t fraction_digits = 0;
    while (is_digit(code_at(i_))) mantissa += static_cast<char>(glyphs_[i_++].code);
    if (code_at(i_) == U'.') {
      ++i_;
      while (is_digit(code_at(i_))) {
        mantissa += static_cast<char>(glyphs_[i_++].code);
        ++fraction_digits;
      }
    }
    long exponent = 0;
    const char32_t e = code_at(i_);
    const char32_t sign = code_at(i_ + 1);
    const bool has_sign = sign == U'+' || sign == U'-';
    // "2e3" is 2000, but "2exp(1)" is 2*exp(1): 'e' belongs to the number only before digits.
    if ((e == U'e' || e == U'E') && is_digit(code_at(i_ + (has_sign ? 2 : 1)))) {
      i_ += has_sign ? 2 : 1;
      std::string digits;
      while (is_digit(code_at(i_))) digits += static_cast<char>(glyphs_[i_++].code);
      digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size()));
      const bool too_large =
          digits.size() > 6 || (!digits.empty() && std::stol(digits) > kMaxDecimalExponent);
      if (too_large) {
        fail("exponent too large in " +
                 quoted(text_, glyphs_[first].offset, offset_at(i_) - glyphs_[first].offset) +
                 " (powers of ten are limited to e±" + std::to_string(kMaxDecimalExponent) + ")",
             glyphs_[first].offset);
      }
      exponent = digits.empty() ? 0 : std::stol(digits);
      if (sign == U'-') exponent = -exponent;
    }
    // value = mantissa * 10^(exponent - fraction digits), exactly.
    const long scale = exponent - static_cast<long>(fraction_digits);
    const numeric ten_power = numeric(10).power(std::labs(scale));
    numeric value = integer_from_digits(mantissa);
    value = scale >= 0 ? value * ten_power : value / ten_power;
    return make(TokenKind::kNumber, first, value);
  }

  Token name() {
    const std::size_t first = i_;
    std::string text;
    while (is_letter(code_at(i_)) || is_digit(code_at(i_)) || code_at(i_) == U'_') {
      text += static_cast<char>(glyphs_[i_++].code);
    }
    return make(TokenKind::kName, first, 0, std::move(text));
  }

  // An optional superscript minus then superscript digits: x⁻¹, x²³ = x^23.
  Token superscript() {
    const std::size_t first = i_;
    const bool negative = glyphs_[i_].code == kSuperscriptMinus;
    if (negative) ++i_;
    std::string digits;
    while (superscript_digit(code_at(i_)) >= 0) {
      digits += static_cast<char>('0' + superscript_digit(glyphs_[i_++].code));
    }
    if (digits.empty()) fail("'⁻' must be followed by superscript digits", glyphs_[first].offset);
    const numeric value = integer_from_digits(digits);
    return make(TokenKind::kSuperscript, first, negative ? -value : value);
  }

  Token punctuation() {
    const std::size_t first = i_;
    const Glyph& g = glyphs_[i_++];
    // Only a typed '*' pair is '**'; "××" is not a power.
    const auto is_asterisk = [](const Glyph& x) {
      return x.original == U'*' || x.original == 0xFF0A;
    };
    switch (g.code) {
      case U'+':
        return make(TokenKind::kPlus, first);
      case U'-':
        return make(TokenKind::kMinus, first);
      case U'*':
        if (is_asterisk(g) && i_ < glyphs_.size() && is_asterisk(glyphs_[i_])) {
          ++i_;
          return make(TokenKind::kPower, first);
        }
        return make(TokenKind::kTimes, first);
      case U'/':
        return make(TokenKind::kDivide, first);
      case U'^':
        return make(TokenKind::kPower, first);
      case U'(':
        return make(TokenKind::kOpen, first);
      case U')':
        return make(TokenKind::kClose, first);
      case U'=':
        return make(TokenKind::kEquals, first);
      case kRootSign:
        return make(TokenKind::kRoot, first);
      case kPiSign:
        return make(TokenKind::kPi, first);
      default:
        break;
    }
    std::string message = "unsupported character ";
    // Control characters are named by code only; printing them would garble the message.
    if (g.original >= 0x20 && g.original != 0x7F && !(g.original >= 0x80 && g.original < 0xA0)) {
      message += quoted(text_, g.offset, g.size) + " (" + hex_code(g.original) + ")";
    } else {
      message += hex_code(g.original);
    }
    message += " at byte " + std::to_string(g.offset);
    if (g.code == U',') message += "; write decimals with a point, e.g. 0.5";
    if (g.code == U'[' || g.code == U']' || g.code == U'{' || g.code == U'}') {
      message += "; use ( ) for grouping";
    }
    fail(message, g.offset);
  }

  std::string_view text_;
  std::vector<Glyph> glyphs_;
  std::size_t i_ = 0;
};

// ---------------------------------------------------------------------------------------
// Size bounds carried with every value

// An exact value with a bound on what raising it to a power exactly can cost.
struct Value {
  ex value;
  // log2 of the largest numerator or denominator an exact evaluation of this can produce;
  // raising it to k costs about |k| * height bits. A magnitude, so GiNaC's rewriting of
  // the value ((√2)^4 -> 4, 2^(1/2)*2^(1/3) -> 2^(5/6)) leaves it valid.
  double height = 0;
};

// log2(max(|numerator|, denominator)) of a rational, accurate for any size.
double rational_height(const numeric& r) {
  numeric m = std::max(GiNaC::abs(r.numer()), r.denom());
  const long bits = m.int_length();
  constexpr long kKeep = 60;
  if (bits <= kKeep) return std::log2(m.to_double());
  const long shift = bits - kKeep;
  return static_cast<double>(shift) +
         std::log2(GiNaC::iquo(m, numeric(2).power(shift)).to_double());
}

// Tightens the bounds when GiNaC has already reduced the value to an atom.
void settle(Value& v) {
  if (is_a<numeric>(v.value)) {
    const numeric& n = ex_to<numeric>(v.value);
    if (n.is_rational()) v.height = rational_height(n);
  } else if (is_a<GiNaC::symbol>(v.value) || is_a<GiNaC::constant>(v.value)) {
    v.height = 0;
  }
}

// Short human form of a value for messages ("2", "(1/2)", "a 1001-digit number").
std::string describe(const ex& e) {
  std::ostringstream out;
  out << e;
  std::string s = out.str();
  if (s.size() > 24) {
    if (is_a<numeric>(e) && ex_to<numeric>(e).is_integer()) {
      const std::size_t digits = s.size() - (s[0] == '-' ? 1 : 0);
      return "[a " + std::to_string(digits) + "-digit number]";
    }
    return "[a long expression]";
  }
  if (s.find_first_of("+-*/^ ") != std::string::npos) s = "(" + s + ")";
  return s;
}

std::string whole_number(double x) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(0) << std::ceil(x);
  return out.str();
}

// Runs a GiNaC operation, turning its exceptions into a located error.
template <class F>
ex evaluate(F&& f, std::size_t offset, const char* pole_message = "division by zero") {
  try {
    return f();
  } catch (const GiNaC::pole_error&) {
    fail(pole_message, offset);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    fail("this value cannot be computed (it is too large or undefined)", offset);
  }
}

// Floating approximation of a constant (no symbols).
numeric approximate(const ex& e, std::size_t offset) {
  const ex a = evaluate([&] { return e.evalf(); }, offset);
  if (!is_a<numeric>(a)) fail("this value cannot be computed", offset);
  return ex_to<numeric>(a);
}

// The solver is real-valued: a constant must evaluate to a real number.
void require_real(const ex& e, std::size_t offset, const std::string& hint) {
  if (has_symbol(e)) return;
  if (!approximate(e, offset).is_real()) fail("not a real number" + hint, offset);
}

// ---------------------------------------------------------------------------------------
// Parser

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

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

// Built-in names are case-insensitive (students write Pi, SQRT); variables are not.
std::optional<Function> find_function(std::string_view name) {
  const std::string key = lower(name);
  for (const FunctionName& f : kFunctions) {
    if (f.name == key) return f.function;
  }
  return std::nullopt;
}

// Counts one nesting level for as long as it lives.
class Nesting {
 public:
  Nesting(int& depth, int limit, std::size_t offset) : depth_(depth) {
    if (depth_ >= limit) {
      fail("nested too deeply (more than " + std::to_string(limit) +
               " levels of brackets, functions, signs or powers)",
           offset);
    }
    ++depth_;
  }
  ~Nesting() { --depth_; }
  Nesting(const Nesting&) = delete;
  Nesting& operator=(const Nesting&) = delete;

 private:
  int& depth_;
};

class Parser {
 public:
  Parser(std::string_view text, std::vector<Token> tokens, const ExpressionOptions& options)
      : text_(text),
        tokens_(std::move(tokens)),
        options_(options),
        max_depth_(std::min(options.max_depth, kMaxSafeDepth)) {}

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
    check_size(value, 0);
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
    const std::string key = lower(t.name);
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

  void check_size(const Value& v, std::size_t offset) const {
    const ExactSize size = exact_size(v.value);
    // GiNaC merges powers: (x^1000)^4 is x^4000.
    if (size.max_exponent > numeric(options_.max_exponent)) {
      fail("exponent too large (the powers combine to an exponent of " +
               describe(size.max_exponent) + "; the limit is " +
               std::to_string(options_.max_exponent) + ")",
           offset);
    }
    // Products of big numbers are bounded like powers: 99^99*99^99*... grows without one.
    if (static_cast<std::size_t>(size.max_bits) > options_.max_exact_bits) {
      fail("number too large (it would have " + std::to_string(size.max_bits + 1) +
               " bits; the limit is " + std::to_string(options_.max_exact_bits) + ")",
           offset);
    }
    if (size.work > kMaxExpandedTerms) {
      fail("the expression is too big (expanded it would have more than " +
               whole_number(kMaxExpandedTerms) + " terms)",
           offset);
    }
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
    if (op == TokenKind::kTimes || op == TokenKind::kDivide) check_size(r, offset);
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
    const bool rational = is_a<numeric>(exponent.value);  // exact numerics are rational here
    const numeric exact_k = rational ? ex_to<numeric>(exponent.value) : numeric(0);
    const bool integer = rational && exact_k.is_integer();
    if (rational && !integer && exact_k.denom() > kMaxParsedRootIndex) {
      std::ostringstream k_text;
      k_text << exact_k;
      fail("roots beyond the " + std::to_string(kMaxParsedRootIndex) +
               "th are not supported (exponent " + k_text.str() + ")",
           exponent_offset);
    }

    // GiNaC evaluates rational^(p/q) through rational^p: about |p| * height bits.
    const numeric abs_k = GiNaC::abs(k);
    const numeric cost_k = rational ? GiNaC::abs(exact_k.numer()) : abs_k;
    const numeric kHuge(1'000'000'000'000'000L);
    const double cost_bits =
        cost_k > kHuge ? std::numeric_limits<double>::infinity() : cost_k.to_double() * base.height;
    const double max_bits = static_cast<double>(options_.max_exact_bits);
    if (cost_bits > max_bits) {
      const std::string size = std::isinf(cost_bits) ? "far more than " + whole_number(max_bits)
                                                     : whole_number(cost_bits);
      fail("exponent too large (" + describe(base.value) + "^" + describe(exponent.value) +
               " would have " + size + " bits; the limit is " + whole_number(max_bits) + ")",
           offset);
    }
    if (abs_k > numeric(options_.max_exponent)) {
      fail("exponent too large (" + describe(exponent.value) + "; the limit is " +
               std::to_string(options_.max_exponent) + ")",
           exponent_offset);
    }

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
    check_size(r, offset);
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
    check_size(r, offset);
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

std::string quote_excerpt(std::string_view text) { return quoted(text, 0, text.size()); }

// A plain decimal literal ("-12", "0.57735", "1.5e-3") as the exact rational it denotes,
// without the lexer and parser: most numbers in problem sets and answers are these.
// Anything else (or an exponent beyond ±400) is left to the parser.
std::optional<GiNaC::ex> parse_decimal_literal(std::string_view text) {
  std::size_t i = 0;
  const std::size_t n = text.size();
  while (i < n && text[i] == ' ') ++i;
  bool negative = false;
  if (i < n && (text[i] == '-' || text[i] == '+')) negative = text[i++] == '-';
  std::string digits;
  long scale = 0;
  bool any = false;
  for (; i < n && std::isdigit(static_cast<unsigned char>(text[i])); ++i, any = true)
    digits += text[i];
  if (i < n && text[i] == '.') {
    for (++i; i < n && std::isdigit(static_cast<unsigned char>(text[i])); ++i, any = true) {
      digits += text[i];
      --scale;
    }
  }
  if (!any || digits.size() > 40) return std::nullopt;
  if (i < n && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    bool exp_negative = false;
    if (i < n && (text[i] == '-' || text[i] == '+')) exp_negative = text[i++] == '-';
    long e = 0;
    bool exp_digits = false;
    for (; i < n && std::isdigit(static_cast<unsigned char>(text[i])) && e < 1000;
         ++i, exp_digits = true)
      e = e * 10 + (text[i] - '0');
    if (!exp_digits || e > 400) return std::nullopt;
    scale += exp_negative ? -e : e;
  }
  while (i < n && text[i] == ' ') ++i;
  if (i != n) return std::nullopt;
  // Up to 18 digits fit a long exactly; longer mantissas go through CLN's reader.
  long small = 0;
  if (digits.size() <= 18)
    for (const char c : digits) small = small * 10 + (c - '0');
  const GiNaC::numeric mantissa =
      digits.size() <= 18 ? GiNaC::numeric(small) : GiNaC::numeric(digits.c_str());
  const GiNaC::numeric value =
      scale == 0 ? mantissa : mantissa * GiNaC::numeric(10).power(GiNaC::numeric(scale));
  return GiNaC::ex(negative ? -value : value);
}

ExpressionResult parse_expression(std::string_view text, const ExpressionOptions& options) {
  // Length first: nothing else runs on oversized input.
  if (text.size() > options.max_length) {
    return failure("the expression is too long (" + std::to_string(text.size()) +
                       " bytes; the limit is " + std::to_string(options.max_length) + ")",
                   options.max_length);
  }
  if (const std::optional<GiNaC::ex> d = parse_decimal_literal(text)) {
    ExpressionResult r;
    r.value = *d;
    return r;
  }
  try {
    Lexer lexer(text, decode_utf8(text));
    Parser parser(text, lexer.run(), options);
    return parser.run();
  } catch (const ParseError& e) {
    return failure(e.message, e.offset);
  } catch (const std::bad_alloc&) {
    return failure("the expression is too large to evaluate (out of memory)", 0);
  } catch (const std::exception&) {
    return failure("the expression cannot be evaluated", 0);
  } catch (...) {
    return failure("the expression cannot be evaluated", 0);
  }
}

}  // namespace frustum
