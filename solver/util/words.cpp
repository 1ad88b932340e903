#include "solver/util/words.hpp"

#include <algorithm>
#include <cctype>

namespace frustum {

std::string trim_lower(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto c = static_cast<unsigned char>(s[i]);
    if (c < 128) {
      s[i] = static_cast<char>(std::tolower(c));
    } else if (c == 0xD0 && i + 1 < s.size()) {  // U+0400–U+043F
      const auto d = static_cast<unsigned char>(s[i + 1]);
      if (d >= 0x90 && d <= 0x9F) {  // А–П → а–п
        s[i + 1] = static_cast<char>(d + 0x20);
      } else if (d >= 0xA0 && d <= 0xAF) {  // Р–Я → р–я
        s[i] = static_cast<char>(0xD1);
        s[i + 1] = static_cast<char>(d - 0x20);
      } else if (d == 0x81) {  // Ё → ё
        s[i] = static_cast<char>(0xD1);
        s[i + 1] = static_cast<char>(0x91);
      }
      ++i;
    }
  }
  return s;
}

std::string ascii_lower(std::string_view s) {
  std::string out(s);
  for (char& c : out)
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  return out;
}

}  // namespace frustum
