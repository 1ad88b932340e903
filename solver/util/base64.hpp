// Base64 (RFC 4648, with padding): fonts and figures inlined as data: URLs in the pages Frustum
// writes (the HTML derivation's KaTeX fonts, the PrairieLearn answer panel's figure).
#pragma once

#include <string>

namespace frustum {

std::string base64(const std::string& bytes);

}  // namespace frustum
