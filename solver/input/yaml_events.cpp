#include "solver/input/yaml_events.hpp"

#include <yaml-cpp/exceptions.h>
#include <yaml.h>

#include <map>
#include <string>
#include <string_view>

namespace frustum {

namespace {

YAML::Mark mark_of(const yaml_mark_t& m) {
  YAML::Mark out;
  out.pos = static_cast<int>(m.index);
  out.line = static_cast<int>(m.line);
  out.column = static_cast<int>(m.column);
  return out;
}

// Where byte `offset` of the text is (libyaml names a reader problem by its offset only).
YAML::Mark mark_at(std::string_view text, std::size_t offset) {
  YAML::Mark out;
  out.pos = static_cast<int>(offset);
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++out.line;
      out.column = 0;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++out.column;  // a character, not a continuation byte
    }
  }
  return out;
}

// The text without its byte-order mark: the parser is told the encoding, and so does not look
// for the mark; it would read it as a character of the first line, put the first key in column 2
// and end the top mapping at the next line (everything after the first line of a file saved
// with the mark, as some Windows editors save UTF-8, would be lost). Columns count from after
// the mark, as an editor shows them.
std::string_view without_mark(const std::string& text) {
  std::string_view v(text);
  if (v.substr(0, 3) == "\xEF\xBB\xBF") v.remove_prefix(3);
  return v;
}

// One libyaml parser over the text, freed however the reading ends.
class Parser {
 public:
  explicit Parser(const std::string& text) : text_(without_mark(text)) {
    if (!yaml_parser_initialize(&parser_)) throw std::bad_alloc();
    yaml_parser_set_input_string(&parser_, reinterpret_cast<const unsigned char*>(text_.data()),
                                 text_.size());
    yaml_parser_set_encoding(&parser_, YAML_UTF8_ENCODING);
  }
  ~Parser() { yaml_parser_delete(&parser_); }
  Parser(const Parser&) = delete;
  Parser& operator=(const Parser&) = delete;

  // The next event; the text's problem as a YAML::ParserException.
  void next(yaml_event_t& event) {
    if (yaml_parser_parse(&parser_, &event)) return;
    if (parser_.error == YAML_MEMORY_ERROR) throw std::bad_alloc();
    std::string message = parser_.problem ? parser_.problem : "the text cannot be read";
    if (parser_.error == YAML_READER_ERROR)
      throw YAML::ParserException(mark_at(text_, parser_.problem_offset), message);
    if (parser_.context)
      message += std::string(" (") + parser_.context + " that starts at line " +
                 std::to_string(parser_.context_mark.line + 1) + ", column " +
                 std::to_string(parser_.context_mark.column + 1) + ")";
    throw YAML::ParserException(mark_of(parser_.problem_mark), message);
  }

 private:
  std::string_view text_;
  yaml_parser_t parser_;
};

// One event, freed when it goes.
struct Event {
  yaml_event_t e{};
  Event() = default;
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;
  ~Event() { yaml_event_delete(&e); }
  void read(Parser& p) {
    yaml_event_delete(&e);
    e = yaml_event_t{};
    p.next(e);
  }
};

std::string text_of(const yaml_char_t* s) { return s ? reinterpret_cast<const char*>(s) : ""; }

YAML::EmitterStyle::value style_of(bool flow, bool block) {
  return flow    ? YAML::EmitterStyle::Flow
         : block ? YAML::EmitterStyle::Block
                 : YAML::EmitterStyle::Default;
}

}  // namespace

bool null_scalar(std::string_view value) {
  return value.empty() || value == "~" || value == "null" || value == "Null" || value == "NULL";
}

FirstDocument read_first_document(const std::string& text, YAML::EventHandler& handler) {
  Parser parser(text);
  Event event;
  event.read(parser);  // the stream's start
  event.read(parser);
  FirstDocument out;
  if (event.e.type != YAML_DOCUMENT_START_EVENT) return out;
  out.any = true;
  std::map<std::string, YAML::anchor_t> anchors;  // name → number (a name defined again: the later)
  YAML::anchor_t last_anchor = 0;
  int depth = 0;
  bool started = false;
  // A node's anchor: numbered in order of definition, as yaml-cpp numbers them.
  const auto anchor_of = [&](const yaml_char_t* name, const YAML::Mark& mark) -> YAML::anchor_t {
    if (!name || !*name) return YAML::NullAnchor;
    const std::string n = text_of(name);
    handler.OnAnchor(mark, n);
    return anchors[n] = ++last_anchor;
  };
  const auto tag_of = [](const yaml_char_t* tag, bool plain) {
    return tag ? text_of(tag) : std::string(plain ? "?" : "!");
  };
  YAML::Mark first;  // where the document's first node is
  for (;;) {
    event.read(parser);
    const yaml_event_t& e = event.e;
    const YAML::Mark mark = mark_of(e.start_mark);
    if (!started) {
      first = mark;
      handler.OnDocumentStart(mark);  // yaml-cpp marks the document where its first node is
      started = true;
    }
    switch (e.type) {
      case YAML_SCALAR_EVENT: {
        const auto& s = e.data.scalar;
        const YAML::anchor_t anchor = anchor_of(s.anchor, mark);
        const bool plain = s.style == YAML_PLAIN_SCALAR_STYLE;
        std::string value(reinterpret_cast<const char*>(s.value), s.length);
        if (plain && !s.tag && null_scalar(value))
          handler.OnNull(mark, anchor);
        else
          handler.OnScalar(mark, tag_of(s.tag, plain), anchor, value);
        break;
      }
      case YAML_ALIAS_EVENT: {
        const std::string name = text_of(e.data.alias.anchor);
        const auto it = anchors.find(name);
        if (it == anchors.end())
          throw YAML::ParserException(mark, "the alias *" + name + " names no anchor before it");
        handler.OnAlias(mark, it->second);
        break;
      }
      case YAML_SEQUENCE_START_EVENT:
      case YAML_MAPPING_START_EVENT: {
        if (++depth > kMaxYamlDepth)
          throw YAML::ParserException(mark, "nested too deeply (the limit is " +
                                                std::to_string(kMaxYamlDepth) + " levels)");
        const bool map = e.type == YAML_MAPPING_START_EVENT;
        const yaml_char_t* anchor_name =
            map ? e.data.mapping_start.anchor : e.data.sequence_start.anchor;
        const YAML::anchor_t anchor = anchor_of(anchor_name, mark);
        if (map) {
          const auto& m = e.data.mapping_start;
          handler.OnMapStart(
              mark, tag_of(m.tag, true), anchor,
              style_of(m.style == YAML_FLOW_MAPPING_STYLE, m.style == YAML_BLOCK_MAPPING_STYLE));
        } else {
          const auto& q = e.data.sequence_start;
          handler.OnSequenceStart(
              mark, tag_of(q.tag, true), anchor,
              style_of(q.style == YAML_FLOW_SEQUENCE_STYLE, q.style == YAML_BLOCK_SEQUENCE_STYLE));
        }
        break;
      }
      case YAML_SEQUENCE_END_EVENT:
        --depth;
        handler.OnSequenceEnd();
        break;
      case YAML_MAPPING_END_EVENT:
        --depth;
        handler.OnMapEnd();
        break;
      case YAML_DOCUMENT_END_EVENT: {
        handler.OnDocumentEnd();
        try {
          event.read(parser);
          if (event.e.type == YAML_DOCUMENT_START_EVENT) out.second = mark_of(event.e.start_mark);
        } catch (const YAML::ParserException& after) {
          // Text after the document that starts no other one: a line indented less than the
          // document's first line ends the document there (a space before the first key, a
          // byte-order mark read as a character). Never dropped in silence: yaml-cpp's Load
          // kept the document above and lost the rest (a student's answers below `student:`).
          if (after.mark.line > first.line && after.mark.column < first.column)
            throw YAML::ParserException(
                after.mark,
                "this line is indented less than the first line (column " +
                    std::to_string(first.column + 1) +
                    "), which ends the document before it; indent the top-level keys alike");
          throw YAML::ParserException(after.mark,
                                      "text after the end of the document: " + after.msg);
        }
        return out;
      }
      default:
        break;
    }
  }
}

}  // namespace frustum
