// Words as people write them: trimmed, and compared without case in Latin and Cyrillic.
#pragma once

#include <string>

namespace frustum {

// Trimmed, with Latin and Cyrillic capitals lowered (a Russian student may write "Да").
std::string trim_lower(std::string s);

}  // namespace frustum
