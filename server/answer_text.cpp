#include "server/answer_text.hpp"

#include "solver/input/yaml_document.hpp"

namespace frustum::server {

YAML::Node answer_node(const std::string& text) {
  const std::size_t start = text.find_first_not_of(" \t");
  if (start != std::string::npos && (text[start] == '[' || text[start] == '{')) {
    const YamlDocument doc = parse_yaml(text, "answer", kMaxAnswerNodes);
    if (!doc.error && (doc.root.IsSequence() || doc.root.IsMap())) return doc.root;
  }
  return YAML::Node(text);
}

std::string answers_yaml(const std::string& student, const std::string& problem,
                         const std::map<std::string, std::string>& answers) {
  YAML::Node root;
  root["student"] = student;
  YAML::Node mine;
  for (const auto& [name, text] : answers) mine[name] = answer_node(text);
  root["answers"][problem] = mine;
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

}  // namespace frustum::server
