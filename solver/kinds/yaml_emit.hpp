// Writing YAML ourselves, byte for byte the same everywhere (generated sets and answer keys
// are pinned by tests): flow style for values, double quotes only where a plain scalar would
// be misread, keys in the order given.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace frustum {

// A scalar as YAML text: plain when safe ("3", "-1/2", "sqrt(3)/3", "front"), else quoted.
std::string emit_scalar(const std::string& s, bool was_quoted = false);
// A node on one line: 3, [1, 2], {a: 1, b: [2, 3]}.
std::string emit_flow(const YAML::Node& n);

}  // namespace frustum
