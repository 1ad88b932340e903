// Writing YAML ourselves, byte for byte the same everywhere (generated sets and answer keys
// are pinned by tests): flow style for values, double quotes only where a plain scalar would
// be misread, keys in the order given.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

namespace frustum {

// A scalar as YAML text: plain when safe ("3", "-1/2", "sqrt(3)/3", "front"), else quoted.
// Plain scalars that YAML 1.1 readers (PyYAML, yaml-cpp's booleans) and YAML 1.2 readers read
// differently are quoted too: "0010" (octal 8 in 1.1, 10 in 1.2), "0b11", "0o7", "1_000",
// "yes"/"no"/"on"/"off"/"y"/"n", "1e3" (1.0e-3 is a float in both and stays plain).
std::string emit_scalar(const std::string& s, bool was_quoted = false);
// Whether a plain scalar is read as a string by every YAML 1.1 and 1.2 reader (no null,
// boolean, integer or float resolves it).
bool plain_reads_as_string(const std::string& s);
// A scalar node for a value that is a string whatever it looks like (a bit string such as
// 1000, a word): emit_flow quotes it when a reader would take it for something else.
YAML::Node string_node(const std::string& s);
// A node on one line: 3, [1, 2], {a: 1, b: [2, 3]}.
std::string emit_flow(const YAML::Node& n);

}  // namespace frustum
