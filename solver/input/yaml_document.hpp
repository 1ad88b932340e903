// Reading a YAML file or text into a document, with a located error instead of an exception.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>

#include "solver/util/diagnostic.hpp"

namespace frustum {

// Files larger than this are refused before parsing (a problem set or answer file is small).
inline constexpr std::size_t kMaxYamlFileBytes = 16 * 1024 * 1024;
// Nodes of the document with every alias expanded: a few lines of anchors and aliases can
// stand for billions of nodes ("billion laughs"), which no reader should walk. Counted while
// parsing, before yaml-cpp builds a node: each node it builds takes far more memory than its
// text, so a file within kMaxYamlFileBytes could take gigabytes before any check ran. A million
// is 40 times the largest set we ship (a 1 000-problem set is about 25 000 values).
inline constexpr std::size_t kMaxYamlNodes = 1'000'000;
// An answers file holds a student's answers, not a set: 20 problems of 5 answers, each a list
// of 16 numbers at most, are under 2 000 values. A file of hundreds of thousands of values
// would cost each grading child hundreds of megabytes; this limit keeps a child small.
inline constexpr std::size_t kMaxAnswerNodes = 50'000;

struct YamlDocument {
  YAML::Node root;
  std::optional<Diagnostic> error;  // nothing could be read
  // Bytes that are not UTF-8 were replaced by U+FFFD and the rest was read; this names the
  // first of them. Readers report it and carry on.
  std::optional<Diagnostic> invalid_utf8;
};

// Besides YAML syntax, refuses: mapping keys that are not plain names ({[a]: 1}), a key
// written twice in one mapping (yaml-cpp keeps the first silently), a second document after
// `---`, text in UTF-16 or UTF-32, and documents that expand to more than kMaxYamlNodes nodes.
// `max_nodes`: kMaxYamlNodes for a problem set, kMaxAnswerNodes for an answers file.
YamlDocument parse_yaml(const std::string& text, const std::string& name,
                        std::size_t max_nodes = kMaxYamlNodes);
// The scalar the text states under `key` in its top mapping, read without building nodes and
// without reading past it: for a document parse_yaml accepts, parse_yaml(text,
// name).root[key].Scalar() when that is a scalar, else nothing. A text that parse_yaml refuses
// still states the value when everything up to it is valid (`student: s1` above a broken
// answer): a class's student ids are read this way, so that a broken file's error row is filed
// under the student it names, at the cost of scanning only the file's first lines.
std::optional<std::string> top_scalar(const std::string& text, const std::string& name,
                                      const std::string& key);
// Reads the file first with read_text_file (kMaxYamlFileBytes).
YamlDocument load_yaml_file(const std::string& path, std::size_t max_nodes = kMaxYamlNodes);

// The whole of a regular file of at most max_bytes, checked before anything is read: a FIFO,
// a device (/dev/zero), a directory or a larger file is refused with a located message, and
// opening never blocks (a FIFO with no writer). The size is checked again while reading (a
// file that grows).
std::optional<Diagnostic> read_text_file(const std::string& path, std::size_t max_bytes,
                                         std::string& out);

}  // namespace frustum
