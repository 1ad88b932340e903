// Which writing systems a text uses: what a LaTeX document needs to print it (LuaLaTeX with
// luatexja for Japanese, a font with Cyrillic for Russian).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace frustum {

// Decodes one UTF-8 character at s[i], advancing i; an invalid byte gives U+FFFD.
char32_t next_code_point(std::string_view s, std::size_t& i);
// The characters of a UTF-8 text, each as its bytes: a byte and the continuation bytes after it.
std::vector<std::string_view> characters_of(std::string_view s);
// Kana, CJK ideographs, CJK punctuation and full-width forms.
bool is_cjk(char32_t c);
// U+0400–U+04FF.
bool is_cyrillic(char32_t c);
// Whether the text holds Chinese or Japanese characters (is_cjk).
bool has_cjk(std::string_view text);
// Whether the text holds Cyrillic letters.
bool has_cyrillic(std::string_view text);

}  // namespace frustum
