#include "solver/kinds/yaml_document.hpp"

#include <yaml-cpp/depthguard.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace frustum {

namespace {

// Length of the valid UTF-8 character at text[i], or 0 (strict: no overlong forms, surrogates
// or values above U+10FFFF).
std::size_t utf8_length(const std::string& text, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = b(i);
  std::size_t size = 0;
  unsigned char low = 0x80, high = 0xBF;
  if (b0 < 0x80) return 1;
  if (b0 >= 0xC2 && b0 <= 0xDF) size = 2;
  else if (b0 >= 0xE0 && b0 <= 0xEF) size = 3, low = b0 == 0xE0 ? 0xA0 : 0x80, high = b0 == 0xED ? 0x9F : 0xBF;
  else if (b0 >= 0xF0 && b0 <= 0xF4) size = 4, low = b0 == 0xF0 ? 0x90 : 0x80, high = b0 == 0xF4 ? 0x8F : 0xBF;
  else return 0;
  if (i + size > text.size()) return 0;
  for (std::size_t k = 1; k < size; ++k)
    if (b(i + k) < (k == 1 ? low : 0x80) || b(i + k) > (k == 1 ? high : 0xBF)) return 0;
  return size;
}

// The text with every byte that does not start a valid character replaced by U+FFFD.
std::string valid_utf8(const std::string& text) {
  std::string out;
  out.reserve(text.size() + 16);
  for (std::size_t k = 0; k < text.size();) {
    const std::size_t n = utf8_length(text, k);
    if (n == 0) {
      out += "\xEF\xBF\xBD";
      ++k;
    } else {
      out.append(text, k, n);
      k += n;
    }
  }
  return out;
}

// Replaces every byte that does not start a valid character by U+FFFD, so that everything
// read from the document is text (JSON output, terminals); names the first one.
std::optional<Diagnostic> repair_utf8(std::string& text, const std::string& name) {
  std::size_t i = 0;
  while (i < text.size() && utf8_length(text, i) > 0) i += utf8_length(text, i);
  if (i == text.size()) return std::nullopt;
  int line = 1, column = 1;
  for (std::size_t k = 0; k < i; k += utf8_length(text, k)) {
    if (text[k] == '\n') ++line, column = 1;
    else ++column;
  }
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[i])));
  Diagnostic d{SourceLocation{name, line, column}, "",
               std::string("invalid UTF-8: byte ") + hex +
                   " is not text; it and any like it are read as U+FFFD (save the file as UTF-8)"};
  text = valid_utf8(text);
  return d;
}

// Walks the document with aliases expanded (iteratively: depth costs no stack) and returns
// the first problem: a key that is not a scalar, or more than kMaxYamlNodes nodes.
std::optional<Diagnostic> check_tree(const YAML::Node& root, const std::string& name) {
  std::vector<YAML::Node> stack{root};
  std::size_t visited = 0;
  const auto at = [&](const YAML::Node& n, std::string message) {
    const YAML::Mark m = n.Mark();
    return Diagnostic{SourceLocation{name, m.line >= 0 ? m.line + 1 : 0, m.line >= 0 ? m.column + 1 : 0}, "",
                      std::move(message)};
  };
  while (!stack.empty()) {
    const YAML::Node n = stack.back();
    stack.pop_back();
    if (++visited > kMaxYamlNodes)
      return at(n, "the document expands to more than " + std::to_string(kMaxYamlNodes) +
                       " values (through anchors and aliases?)");
    if (n.IsSequence()) {
      for (std::size_t i = n.size(); i-- > 0;) stack.push_back(n[i]);
    } else if (n.IsMap()) {
      for (auto it = n.begin(); it != n.end(); ++it) {
        if (!it->first.IsScalar() && !it->first.IsNull())
          return at(it->first, std::string("a key must be a name, not a ") +
                                   (it->first.IsMap() ? "mapping" : "list"));
        stack.push_back(it->second);
      }
    }
  }
  return std::nullopt;
}

}  // namespace

YamlDocument parse_yaml(const std::string& text, const std::string& name) {
  YamlDocument doc;
  std::string repaired = text;
  doc.invalid_utf8 = repair_utf8(repaired, name);
  try {
    doc.root = YAML::Load(repaired);
    doc.error = check_tree(doc.root, name);
  } catch (const YAML::DeepRecursion& e) {
    doc.error = Diagnostic{SourceLocation{name, e.mark.line + 1, e.mark.column + 1}, "",
                           "invalid YAML: nested too deeply (the limit is " +
                               std::to_string(e.depth()) + " levels)"};
  } catch (const YAML::ParserException& e) {
    doc.error = Diagnostic{SourceLocation{name, e.mark.line + 1, e.mark.column + 1}, "",
                           "invalid YAML: " + valid_utf8(e.msg)};  // may quote one byte of a character
  } catch (const std::exception& e) {
    doc.error = Diagnostic{SourceLocation{name, 0, 0}, "", "invalid YAML: " + valid_utf8(e.what())};
  }
  if (doc.error) doc.root = YAML::Node();
  return doc;
}

YamlDocument load_yaml_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return {YAML::Node(), Diagnostic{SourceLocation{path, 0, 0}, "", "cannot open the file"}, {}};
  const std::streamoff size = in.tellg();
  if (size < 0 || static_cast<std::size_t>(size) > kMaxYamlFileBytes)
    return {YAML::Node(), Diagnostic{SourceLocation{path, 0, 0}, "",
                                     "the file is larger than 16 MiB"}, {}};
  in.seekg(0);
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_yaml(ss.str(), path);
}

}  // namespace frustum
