// Reading a YAML file or text into a document, with a located error instead of an exception.
#pragma once

#include "solver/util/diagnostic.hpp"

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

namespace frustum {

// Files larger than this are refused before parsing (a problem set or answer file is small).
inline constexpr std::size_t kMaxYamlFileBytes = 16 * 1024 * 1024;

struct YamlDocument {
  YAML::Node root;
  std::optional<Diagnostic> error;
};

YamlDocument parse_yaml(const std::string& text, const std::string& name);
YamlDocument load_yaml_file(const std::string& path);

}  // namespace frustum
