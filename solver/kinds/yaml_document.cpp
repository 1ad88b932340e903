#include "solver/kinds/yaml_document.hpp"

#include <fstream>
#include <sstream>

namespace frustum {

YamlDocument parse_yaml(const std::string& text, const std::string& name) {
  YamlDocument doc;
  try {
    doc.root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    doc.error = Diagnostic{SourceLocation{name, e.mark.line + 1, e.mark.column + 1}, "",
                           "invalid YAML: " + e.msg};
  } catch (const std::exception& e) {
    doc.error = Diagnostic{SourceLocation{name, 0, 0}, "", std::string("invalid YAML: ") + e.what()};
  }
  return doc;
}

YamlDocument load_yaml_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return {YAML::Node(), Diagnostic{SourceLocation{path, 0, 0}, "", "cannot open the file"}};
  const std::streamoff size = in.tellg();
  if (size < 0 || static_cast<std::size_t>(size) > kMaxYamlFileBytes)
    return {YAML::Node(), Diagnostic{SourceLocation{path, 0, 0}, "",
                                     "the file is larger than 16 MiB"}};
  in.seekg(0);
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_yaml(ss.str(), path);
}

}  // namespace frustum
