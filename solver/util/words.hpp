// Words as people write them: trimmed, and compared without case in Latin and Cyrillic.
#pragma once

#include <string>
#include <string_view>

namespace frustum {

// Trimmed, with Latin and Cyrillic capitals lowered (a Russian student may write "Да").
std::string trim_lower(std::string s);

// A–Z lowered, every other byte as it is (names, file extensions, labels of the key).
std::string ascii_lower(std::string_view s);

}  // namespace frustum
