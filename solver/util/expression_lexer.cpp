// The expression parser's lexer: strict UTF-8 decoding, look-alike characters folded to the
// ASCII they stand for, and tokens (exact numbers, names, operators, superscripts).
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "solver/util/expression.hpp"
#include "solver/util/expression_internal.hpp"

namespace frustum {
namespace expression_internal {
namespace {

// Why a text is not read: its characters. A quoted token ('{0}') is placed as written.
constexpr Phrase kNotText{"invalid UTF-8: a byte that is not text (shown as \uFFFD)",
                          "不正な UTF-8: 文字でないバイトがあります (\uFFFD と表示)",
                          "неверная кодировка UTF-8: байт, не являющийся текстом (показан как "
                          "\uFFFD)"};
// {0} is the byte in hexadecimal (0xC3), {1} where it is.
constexpr Phrase kInvalidByte{
    "invalid UTF-8: byte {0} at byte {1} does not start a valid character",
    "不正な UTF-8: バイト {1} の `{0}` は正しい文字の始まりではありません",
    "неверная кодировка UTF-8: байт `{0}` (позиция {1}) не начинает допустимый символ"};
constexpr Phrase kDecimalExponentTooLarge{
    "exponent too large in '{0}' (powers of ten are limited to e±{1})",
    "`{0}` の指数が大きすぎます (10 のべきは e±{1} まで)",
    "слишком большой показатель в `{0}` (степени десяти — не дальше e±{1})"};
constexpr Phrase kSuperscriptMinusAlone{"'⁻' must be followed by superscript digits",
                                        "'⁻' の後には上付きの数字が必要です",
                                        "после '⁻' должны идти цифры верхнего индекса"};
// {0} is the character as shown (quoted, with its code: "'€' (U+20AC)"; a control character
// by its code only), {1} where it is.
constexpr Phrase kUnsupportedCharacter{"unsupported character {0} at byte {1}",
                                       "使えない文字 `{0}` (バイト {1})",
                                       "недопустимый символ `{0}` (байт {1})"};
constexpr Phrase kUnsupportedComma{
    "unsupported character {0} at byte {1}; write decimals with a point, e.g. 0.5",
    "使えない文字 `{0}` (バイト {1}). 小数は小数点で書きます (例: 0.5)",
    "недопустимый символ `{0}` (байт {1}); дробную часть отделяйте точкой, например 0.5"};
constexpr Phrase kUnsupportedBracket{
    "unsupported character {0} at byte {1}; use ( ) for grouping",
    "使えない文字 `{0}` (バイト {1}). まとめるには ( ) を使います",
    "недопустимый символ `{0}` (байт {1}); для группировки используйте ( )"};

constexpr std::size_t kMaxQuotedBytes = 32;

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
    if (valid && code == 0xFFFD) fail(say(kNotText), i);
    if (!valid) {
      std::ostringstream hex;
      hex << "0x" << std::uppercase << std::hex << std::setw(2) << std::setfill('0')
          << static_cast<unsigned>(b0);
      fail(say(kInvalidByte, hex.str(), i), i);
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
constexpr char32_t kDegreeSign = 0x00B0;

bool is_digit(char32_t c) { return c >= U'0' && c <= U'9'; }
bool is_letter(char32_t c) { return (c >= U'a' && c <= U'z') || (c >= U'A' && c <= U'Z'); }
bool is_space(char32_t c) { return c == U' ' || c == U'\t' || c == U'\n' || c == U'\r'; }

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
        fail(say(kNotFiniteNumber, "∞"), g.offset);
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
        const std::size_t begin = glyphs_[first].offset;
        fail(say(kDecimalExponentTooLarge, excerpt(text_, begin, offset_at(i_) - begin),
                 kMaxDecimalExponent),
             begin);
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
    if (digits.empty()) fail(say(kSuperscriptMinusAlone), glyphs_[first].offset);
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
      case kDegreeSign:
        return make(TokenKind::kDegree, first);
      default:
        break;
    }
    // Control characters are named by code only; printing them would garble the message.
    const std::string shown =
        g.original >= 0x20 && g.original != 0x7F && !(g.original >= 0x80 && g.original < 0xA0)
            ? quoted(text_, g.offset, g.size) + " (" + hex_code(g.original) + ")"
            : hex_code(g.original);
    const bool bracket = g.code == U'[' || g.code == U']' || g.code == U'{' || g.code == U'}';
    const Phrase& why = g.code == U',' ? kUnsupportedComma
                        : bracket      ? kUnsupportedBracket
                                       : kUnsupportedCharacter;
    fail(say(why, shown, g.offset), g.offset);
  }

  std::string_view text_;
  std::vector<Glyph> glyphs_;
  std::size_t i_ = 0;
};

}  // namespace

// The source text of a token, shortened at a character boundary ("1+1+1...").
std::string excerpt(std::string_view text, std::size_t offset, std::size_t size) {
  std::string_view s = text.substr(offset, size);
  const bool shorten = s.size() > kMaxQuotedBytes;
  if (shorten) {
    std::size_t cut = kMaxQuotedBytes;
    while (cut > 0 && (static_cast<unsigned char>(s[cut]) & 0xC0) == 0x80) --cut;
    s = s.substr(0, cut);
  }
  std::string out;
  out.reserve(s.size() + 3);
  out.append(s);
  if (shorten) out += "...";
  return out;
}

// The same in quotes.
std::string quoted(std::string_view text, std::size_t offset, std::size_t size) {
  return "'" + excerpt(text, offset, size) + "'";
}

std::vector<Token> tokenize(std::string_view text) { return Lexer(text, decode_utf8(text)).run(); }

}  // namespace expression_internal

std::string quote_excerpt(std::string_view text) {
  return expression_internal::quoted(text, 0, text.size());
}

}  // namespace frustum
