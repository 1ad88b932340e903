#include "solver/util/scripts.hpp"

namespace frustum {

char32_t next_code_point(std::string_view s, std::size_t& i) {
  const unsigned char c = static_cast<unsigned char>(s[i]);
  const int n = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
  if (n == 0 || i + static_cast<std::size_t>(n) > s.size()) {
    ++i;
    return 0xFFFD;
  }
  char32_t cp = n == 1 ? c : c & (0x3F >> (n - 1));
  for (int k = 1; k < n; ++k)
    cp = (cp << 6) | (static_cast<unsigned char>(s[i + static_cast<std::size_t>(k)]) & 0x3F);
  i += static_cast<std::size_t>(n);
  return cp;
}

std::vector<std::string_view> characters_of(std::string_view s) {
  std::vector<std::string_view> out;
  for (std::size_t i = 0; i < s.size();) {
    std::size_t n = 1;
    while (i + n < s.size() && (static_cast<unsigned char>(s[i + n]) & 0xC0) == 0x80) ++n;
    out.push_back(s.substr(i, n));
    i += n;
  }
  return out;
}

bool is_cyrillic(char32_t c) { return c >= 0x0400 && c <= 0x04FF; }

bool is_cjk(char32_t c) {
  return (c >= 0x3000 && c <= 0x30FF) || (c >= 0x3400 && c <= 0x9FFF) ||
         (c >= 0xFF00 && c <= 0xFFEF) || (c >= 0xF900 && c <= 0xFAFF);
}

bool has_cjk(std::string_view text) {
  for (std::size_t i = 0; i < text.size();)
    if (is_cjk(next_code_point(text, i))) return true;
  return false;
}

bool has_cyrillic(std::string_view text) {
  for (std::size_t i = 0; i < text.size();)
    if (is_cyrillic(next_code_point(text, i))) return true;
  return false;
}

}  // namespace frustum
