#include "server/given_tex.hpp"

#include <regex>

namespace frustum::server {

namespace {

// \text{…} with LaTeX's special characters made literal.
std::string text_tex(const std::string& s) {
  std::string out = "\\text{";
  for (const char c : s) {
    switch (c) {
      case '\\':
        out += "\\textbackslash{}";
        break;
      case '{':
      case '}':
      case '$':
      case '&':
      case '#':
      case '_':
      case '%':
        out += '\\';
        out += c;
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      default:
        out += c;
    }
  }
  return out + "}";
}

std::string scalar_tex(const std::string& s) {
  static const std::regex kNumber(R"(-?[0-9]+(\.[0-9]+)?)");
  static const std::regex kFraction(R"((-?)([0-9]+)/([0-9]+))");
  std::smatch m;
  if (std::regex_match(s, kNumber)) return s;
  if (std::regex_match(s, m, kFraction))
    return m[1].str() + "\\frac{" + m[2].str() + "}{" + m[3].str() + "}";
  return text_tex(s);
}

template <typename Scalar, typename Join>
std::string render(const YAML::Node& v, Scalar scalar, Join join) {
  if (v.IsScalar()) return scalar(v.Scalar());
  std::vector<std::string> parts;
  if (v.IsSequence()) {
    for (const YAML::Node& item : v) parts.push_back(render(item, scalar, join));
    return join(parts, false);
  }
  if (v.IsMap()) {
    for (auto it = v.begin(); it != v.end(); ++it)
      parts.push_back(scalar(it->first.as<std::string>()) + " = " +
                      render(it->second, scalar, join));
    return join(parts, true);
  }
  return "";
}

}  // namespace

std::string given_tex(const YAML::Node& value) {
  return render(value, scalar_tex, [](const std::vector<std::string>& parts, bool map) {
    std::string out = map ? "\\{" : "\\left(";
    for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? ",\\ " : "") + parts[i];
    return out + (map ? "\\}" : "\\right)");
  });
}

std::string given_plain(const YAML::Node& value) {
  return render(
      value, [](const std::string& s) { return s; },
      [](const std::vector<std::string>& parts, bool map) {
        std::string out = map ? "{" : "(";
        for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? ", " : "") + parts[i];
        return out + (map ? "}" : ")");
      });
}

}  // namespace frustum::server
