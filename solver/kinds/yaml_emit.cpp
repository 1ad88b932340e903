#include "solver/kinds/yaml_emit.hpp"

#include <cstdio>

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

std::string quote(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
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
  return !was_quoted && plain_safe(s) ? s : quote(s);
}

std::string emit_flow(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar: return emit_scalar(n.Scalar(), n.Tag() == "!");
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
    default: return "null";
  }
}

}  // namespace frustum
