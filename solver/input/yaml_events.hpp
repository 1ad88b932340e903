// Reading YAML text with libyaml, reported as yaml-cpp's parser reports it.
#pragma once

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/mark.h>

#include <optional>
#include <string>
#include <string_view>

namespace frustum {

// Collections nested deeper than this are refused (yaml-cpp's own parser stops at 500 levels;
// the same limit keeps every later walk of the tree shallow).
inline constexpr int kMaxYamlDepth = 500;

// yaml-cpp's null, for a plain untagged scalar: ~, null, Null, NULL or nothing.
bool null_scalar(std::string_view value);

struct FirstDocument {
  bool any = false;                  // the text holds a document
  std::optional<YAML::Mark> second;  // where a second document starts, if there is one
};

// Reports the first document of `text` (UTF-8) to `handler` event by event, as yaml-cpp's
// YAML::Parser::HandleNextDocument does: the same events, tags ("?" for an untagged plain node,
// "!" for a quoted scalar), nulls (an empty node, or a plain ~, null, Null or NULL), anchors
// numbered 1, 2, … in order, styles and 0-based marks (columns in characters, where yaml-cpp
// counts bytes; an empty value marked after its key). libyaml scans the text: it reads the
// same YAML several times faster than yaml-cpp's scanner, which was most of the cost of reading
// a class's answer files. Then looks for the start of a second document; text after the first
// document that starts none is refused (a line indented less than the document's first line,
// which ended the document: its lines are never dropped in silence).
//
// Throws YAML::ParserException for text that is not YAML (libyaml's problem and its context,
// e.g. "did not find expected key (while parsing a block mapping that starts at line 2,
// column 1)") and for collections nested deeper than kMaxYamlDepth; whatever `handler` throws
// passes through, and the reading stops there.
FirstDocument read_first_document(const std::string& text, YAML::EventHandler& handler);

}  // namespace frustum
