#include "solver/kinds/yaml_emit.hpp"

#include <cstdio>
#include <regex>

namespace frustum {

namespace {

bool plain_safe(const std::string& s) {
  if (s.empty()) return false;
  for (const char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '.' || c == '+' || c == '-' || c == '/' || c == '*' ||
                    c == '(' || c == ')' || c == '^';
    if (!ok) return false;
  }
  // Indicators that may not start a plain scalar, and "-" alone (a list item).
  if (s[0] == '*' || s == "-" || (s[0] == '-' && s.size() > 1 && s[1] == '-')) return false;
  return true;
}

// What YAML 1.1 (the type repository's bool, int, float, null) and YAML 1.2 (the core schema)
// resolve a plain scalar to, as regular expressions over the whole scalar.
const std::regex& yaml11_non_string() {
  static const std::regex r(
      "y|Y|yes|Yes|YES|n|N|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF"
      "|~|null|Null|NULL"
      "|[-+]?0b[01_]+|[-+]?0[0-7_]+|[-+]?(0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+|[-+]?[1-9][0-9_]*(:["
      "0-5]?[0-9])+"
      "|[-+]?([0-9][0-9_]*)?\\.[0-9.]*([eE][-+][0-9]+)?|[-+]?[0-9][0-9_]*(:[0-5]?[0-9])+\\.[0-9_]*"
      "|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)");
  return r;
}
const std::regex& yaml12_non_string() {
  static const std::regex r(
      "true|True|TRUE|false|False|FALSE|~|null|Null|NULL"
      "|[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+"
      "|[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|"
      "NAN)");
  return r;
}

// The same plain scalar read as different things (or the same number with different values:
// 0010 is 8 in YAML 1.1 and 10 in 1.2). Integers and decimals written plainly agree.
bool readers_disagree(const std::string& s) {
  static const std::regex agreed(
      "[-+]?(0|[1-9][0-9]*)(\\.[0-9]+)?|true|false|True|False|TRUE|FALSE|~|null|Null|NULL");
  if (std::regex_match(s, agreed)) return false;
  return std::regex_match(s, yaml11_non_string()) || std::regex_match(s, yaml12_non_string());
}

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

}  // namespace

std::string emit_scalar(const std::string& s, bool was_quoted) {
  return !was_quoted && plain_safe(s) && !readers_disagree(s) ? s : quote(s);
}

bool plain_reads_as_string(const std::string& s) {
  return !std::regex_match(s, yaml11_non_string()) && !std::regex_match(s, yaml12_non_string());
}

YAML::Node string_node(const std::string& s) {
  YAML::Node n(s);
  if (!plain_reads_as_string(s)) n.SetTag("!");
  return n;
}

std::string emit_flow(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar:
      return emit_scalar(n.Scalar(), n.Tag() == "!");
    case YAML::NodeType::Sequence: {
      std::string out = "[";
      for (std::size_t i = 0; i < n.size(); ++i) out += (i ? ", " : "") + emit_flow(n[i]);
      return out + "]";
    }
    case YAML::NodeType::Map: {
      std::string out = "{";
      bool first = true;
      for (auto it = n.begin(); it != n.end(); ++it) {
        out += (first ? "" : ", ") + emit_flow(it->first) + ": " + emit_flow(it->second);
        first = false;
      }
      return out + "}";
    }
    default:
      return "null";
  }
}

}  // namespace frustum
