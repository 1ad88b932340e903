#include "solver/input/yaml_emit.hpp"

#include <cstdio>
#include <regex>
#include <string_view>

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

// What a plain scalar resolves to in YAML 1.1 (the type repository's bool, null, int, float:
// PyYAML, older readers) and in YAML 1.2's core schema, as regular expressions over the whole
// scalar.
enum class Resolved { String, Bool, Null, Int, Float };

// One reader's implicit types, tried in order.
struct Reader {
  std::regex boolean, null, integer, real;
  Resolved resolve(const std::string& s) const {
    if (std::regex_match(s, boolean)) return Resolved::Bool;
    if (std::regex_match(s, null)) return Resolved::Null;
    if (std::regex_match(s, integer)) return Resolved::Int;
    if (std::regex_match(s, real)) return Resolved::Float;
    return Resolved::String;
  }
};

const Reader& yaml11() {
  static const Reader r{
      std::regex(
          "y|Y|yes|Yes|YES|n|N|no|No|NO|true|True|TRUE|false|False|FALSE|on|On|ON|off|Off|OFF"),
      std::regex("~|null|Null|NULL"),
      std::regex("[-+]?0b[01_]+|[-+]?0[0-7_]+|[-+]?(0|[1-9][0-9_]*)|[-+]?0x[0-9a-fA-F_]+"
                 "|[-+]?[1-9][0-9_]*(:[0-5]?[0-9])+"),
      std::regex("[-+]?([0-9][0-9_]*)?\\.[0-9.]*([eE][-+][0-9]+)?|[-+]?[0-9][0-9_]*(:[0-5]?[0-9])+"
                 "\\.[0-9_]*"
                 "|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)")};
  return r;
}

const Reader& yaml12() {
  static const Reader r{std::regex("true|True|TRUE|false|False|FALSE"),
                        std::regex("~|null|Null|NULL"),
                        std::regex("[-+]?[0-9]+|0o[0-7]+|0x[0-9a-fA-F]+"),
                        std::regex("[-+]?(\\.[0-9]+|[0-9]+(\\.[0-9]*)?)([eE][-+]?[0-9]+)?"
                                   "|[-+]?\\.(inf|Inf|INF)|\\.(nan|NaN|NAN)")};
  return r;
}

// Scalars both readers take alike without trying their expressions (most of what a variant and
// its key write): a decimal integer without leading zeros is the same int to both; a '/' or a
// parenthesis (1/2, -sqrt(3)/3) is in no pattern of either; and a scalar that starts with a
// letter can only be a boolean or a null word (the numbers start with a sign, a digit or a dot),
// so anything else that starts with one (AC, kind, seed001-plane) is a string to both.
bool readers_agree_plainly(const std::string& s) {
  if (s.find_first_of("/()") != std::string::npos) return true;
  if ((s[0] >= 'a' && s[0] <= 'z') || (s[0] >= 'A' && s[0] <= 'Z')) {
    static constexpr std::string_view kWords[] = {
        "y",  "Y",    "yes",  "Yes",  "YES",   "n",     "N",     "no", "No",
        "NO", "true", "True", "TRUE", "false", "False", "FALSE", "on", "On",
        "ON", "off",  "Off",  "OFF",  "null",  "Null",  "NULL"};
    for (const std::string_view w : kWords)
      if (s == w) return false;
    return true;
  }
  const std::size_t start = s[0] == '-' || s[0] == '+' ? 1 : 0;
  if (start == s.size() || (s[start] == '0' && s.size() > start + 1)) return false;
  return s.find_first_not_of("0123456789", start) == std::string::npos;
}

// The two read the scalar as different things (yes: a boolean or a string; 1e3: a string or a
// float), or as integers of different values (0010 is octal 8 in YAML 1.1 and 10 in 1.2).
bool readers_disagree(const std::string& s) {
  if (!s.empty() && readers_agree_plainly(s)) return false;
  const Resolved a = yaml11().resolve(s), b = yaml12().resolve(s);
  if (a != b) return true;
  static const std::regex leading_zero("[-+]?0[0-9_]+");
  return a == Resolved::Int && std::regex_match(s, leading_zero);
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
  return yaml11().resolve(s) == Resolved::String && yaml12().resolve(s) == Resolved::String;
}

YAML::Node string_node(const std::string& s) {
  YAML::Node n(s);
  if (!plain_reads_as_string(s)) n.SetTag("!");
  return n;
}

namespace {

// emit_flow's text appended to `out`: children are visited by iterator (indexing a yaml-cpp
// node by position builds a new node handle each time) and written in place.
void append_flow(const YAML::Node& n, std::string& out) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar:
      out += emit_scalar(n.Scalar(), n.Tag() == "!");
      return;
    case YAML::NodeType::Sequence: {
      out += '[';
      bool first = true;
      for (const YAML::Node& item : n) {
        if (!first) out += ", ";
        append_flow(item, out);
        first = false;
      }
      out += ']';
      return;
    }
    case YAML::NodeType::Map: {
      out += '{';
      bool first = true;
      for (auto it = n.begin(); it != n.end(); ++it) {
        if (!first) out += ", ";
        append_flow(it->first, out);
        out += ": ";
        append_flow(it->second, out);
        first = false;
      }
      out += '}';
      return;
    }
    default:
      out += "null";
  }
}

}  // namespace

std::string emit_flow(const YAML::Node& n) {
  std::string out;
  append_flow(n, out);
  return out;
}

}  // namespace frustum
