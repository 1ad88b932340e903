// Reading a YAML file or text into a document, with a located error instead of an exception.
#pragma once

#include "solver/util/diagnostic.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

namespace frustum {

// Files larger than this are refused before parsing (a problem set or answer file is small).
inline constexpr std::size_t kMaxYamlFileBytes = 16 * 1024 * 1024;
// Nodes of the document with every alias expanded: a few lines of anchors and aliases can
// stand for billions of nodes ("billion laughs"), which no reader should walk.
inline constexpr std::size_t kMaxYamlNodes = 1'000'000;

struct YamlDocument {
  YAML::Node root;
  std::optional<Diagnostic> error;    // nothing could be read
  // Bytes that are not UTF-8 were replaced by U+FFFD and the rest was read; this names the
  // first of them. Readers report it and carry on.
  std::optional<Diagnostic> invalid_utf8;
};

// Besides YAML syntax, refuses mapping keys that are not plain names ({[a]: 1}) and documents
// that expand to more than kMaxYamlNodes nodes.
YamlDocument parse_yaml(const std::string& text, const std::string& name);
YamlDocument load_yaml_file(const std::string& path);

}  // namespace frustum
