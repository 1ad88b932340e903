// A problem's given values as LaTeX for KaTeX (and as plain text beside it, the fallback
// without JavaScript): numbers as numbers, lists as tuples, anything else as text.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace frustum::server {

std::string given_tex(const YAML::Node& value);
std::string given_plain(const YAML::Node& value);

}  // namespace frustum::server
