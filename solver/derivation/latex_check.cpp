#include "solver/derivation/latex_check.hpp"

#include <algorithm>
#include <array>

namespace frustum {

namespace {

// Products of single-letter quantities written side by side, as textbooks do.
constexpr std::array<std::string_view, 14> kProducts = {"fn", "nf", "xy", "xz", "yx", "yz", "zx",
                                                        "zy", "xs", "ys", "zs", "ax", "by", "cz"};

bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// Index just past the brace group starting at `at` (which holds '{'), or npos if unbalanced.
std::size_t skip_group(std::string_view s, std::size_t at) {
  int depth = 0;
  for (std::size_t i = at; i < s.size(); ++i) {
    if (s[i] == '\\') {
      ++i;
      continue;
    }
    if (s[i] == '{') ++depth;
    if (s[i] == '}' && --depth == 0) return i + 1;
  }
  return std::string_view::npos;
}

std::size_t utf8_length(unsigned char lead) {
  return lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 1;
}

}  // namespace

std::vector<std::string> latex_problems(std::string_view s) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\\') {
      std::size_t j = i + 1;
      while (j < s.size() && is_letter(s[j])) ++j;
      if (j == i + 1) {  // a one-character command: \\ \, \; \{ …
        i = std::min(s.size(), i + 2);
        continue;
      }
      const std::string_view name = s.substr(i + 1, j - i - 1);
      const bool takes_words = name == "text" || name == "mathrm" || name == "operatorname" ||
                               name == "textbf" || name == "textit" || name == "mbox" ||
                               name == "mathbf" || name == "overrightarrow" || name == "begin" ||
                               name == "end";
      if (takes_words && j < s.size() && s[j] == '{') {
        const std::size_t end = skip_group(s, j);
        if (end == std::string_view::npos) {
          out.push_back("unbalanced braces after \\" + std::string(name));
          return out;
        }
        i = end;
      } else {
        i = j;
      }
      continue;
    }
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      const std::size_t n = std::min(utf8_length(byte), s.size() - i);
      out.push_back("Unicode character '" + std::string(s.substr(i, n)) +
                    "' in math mode (write its LaTeX command)");
      i += n;
      continue;
    }
    if (is_letter(c)) {
      std::size_t j = i;
      while (j < s.size() && is_letter(s[j])) ++j;
      const std::string_view run = s.substr(i, j - i);
      // Two or three capitals name points (E_{AB}, OA); lower-case runs are words unless products.
      const bool points = run.size() <= 3 && std::all_of(run.begin(), run.end(), [](char l) {
                            return l >= 'A' && l <= 'Z';
                          });
      if (run.size() >= 2 && !points &&
          std::find(kProducts.begin(), kProducts.end(), run) == kProducts.end())
        out.push_back("word '" + std::string(run) +
                      "' in math italic (use \\text{} or \\mathrm{})");
      i = j;
      continue;
    }
    ++i;
  }
  return out;
}

}  // namespace frustum
