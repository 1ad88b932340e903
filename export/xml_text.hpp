// Text and attribute values escaped for XML (& < > " '), with bytes that XML 1.0 forbids
// (control characters other than tab, newline, carriage return) dropped.
#pragma once

#include <string>
#include <string_view>

namespace frustum {

std::string xml_escape(std::string_view text);

}  // namespace frustum
