// An answer as a student types it in a browser, made the YAML value an answers file would hold:
// text starting with [ or { is read as a YAML list or mapping (the forms of a matrix, a point
// list, a word map); anything else is one string, which the answer parser reads as written.
#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <string>

namespace frustum::server {

inline constexpr std::size_t kMaxAnswerChars = 4000;  // one answer's text

YAML::Node answer_node(const std::string& text);

// The answers file of one submission: student, and answers: {problem: {name: value}}.
std::string answers_yaml(const std::string& student, const std::string& problem,
                         const std::map<std::string, std::string>& answers);

}  // namespace frustum::server
