#include "grader/visible_text.hpp"

#include <fmt/format.h>
#include <utf8proc.h>

namespace frustum {

namespace {

// One step through `text` at `i`: the code point and its length, or a byte that is not UTF-8
// (length 1, code = the byte, invalid = true). utf8proc refuses overlong forms, surrogates and
// values past U+10FFFF.
struct Step {
  long code;
  std::size_t length;
  bool invalid;
};

Step step_at(std::string_view text, std::size_t i) {
  const auto* s = reinterpret_cast<const utf8proc_uint8_t*>(text.data() + i);
  utf8proc_int32_t cp = 0;
  const utf8proc_ssize_t n =
      utf8proc_iterate(s, static_cast<utf8proc_ssize_t>(text.size() - i), &cp);
  if (n <= 0 || cp < 0) return {static_cast<unsigned char>(text[i]), 1, true};
  return {cp, static_cast<std::size_t>(n), false};
}

bool hidden_code(long cp, Breaks breaks) {
  if (cp == '\n' || cp == '\t') return breaks == Breaks::Escaped;
  if (cp >= 0x20 && cp < 0x7F) return false;
  const auto c = static_cast<utf8proc_int32_t>(cp);
  const utf8proc_category_t cat = utf8proc_category(c);
  if (cat == UTF8PROC_CATEGORY_CC || cat == UTF8PROC_CATEGORY_ZL || cat == UTF8PROC_CATEGORY_ZP)
    return true;
  switch (utf8proc_get_property(c)->bidi_class) {
    case UTF8PROC_BIDI_CLASS_LRE:
    case UTF8PROC_BIDI_CLASS_LRO:
    case UTF8PROC_BIDI_CLASS_RLE:
    case UTF8PROC_BIDI_CLASS_RLO:
    case UTF8PROC_BIDI_CLASS_PDF:
    case UTF8PROC_BIDI_CLASS_LRI:
    case UTF8PROC_BIDI_CLASS_RLI:
    case UTF8PROC_BIDI_CLASS_FSI:
    case UTF8PROC_BIDI_CLASS_PDI:
      return true;
    default:
      return false;
  }
}

bool plain_ascii(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u >= 0x20 && u < 0x7F;
}

}  // namespace

std::string visible_text(std::string_view text, Breaks breaks) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    // Runs of printable ASCII (most text) are copied whole.
    std::size_t end = i;
    while (end < text.size() && plain_ascii(text[end])) ++end;
    out.append(text.substr(i, end - i));
    if (end == text.size()) break;
    i = end;
    const Step s = step_at(text, i);
    if (s.invalid)
      out += fmt::format("\\x{:02X}", s.code);
    else if (hidden_code(s.code, breaks))
      out += fmt::format("\\u{:04X}", s.code);
    else
      out.append(text.substr(i, s.length));
    i += s.length;
  }
  return out;
}

std::vector<std::string> visible_cells(std::vector<std::string> cells) {
  for (std::string& c : cells) c = visible_text(c);
  return cells;
}

std::optional<Hidden> first_hidden(std::string_view text, Breaks breaks) {
  for (std::size_t i = 0; i < text.size();) {
    if (plain_ascii(text[i])) {
      ++i;
      continue;
    }
    const Step s = step_at(text, i);
    if (s.invalid || hidden_code(s.code, breaks)) return Hidden{i, s.code, s.invalid};
    i += s.length;
  }
  return std::nullopt;
}

std::string describe(const Hidden& h) {
  if (h.byte) return fmt::format("the byte 0x{:02X} (not UTF-8 text)", h.code);
  const bool control =
      utf8proc_category(static_cast<utf8proc_int32_t>(h.code)) == UTF8PROC_CATEGORY_CC;
  return fmt::format(
      "U+{:04X} ({})", h.code,
      control ? "a control character" : "a character that breaks or reorders the text around it");
}

}  // namespace frustum
