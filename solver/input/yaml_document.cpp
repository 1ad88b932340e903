#include "solver/input/yaml_document.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/exceptions.h>
#include <yaml-cpp/node/detail/memory.h>
#include <yaml-cpp/node/detail/node.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "solver/input/yaml_events.hpp"

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
  if (b0 >= 0xC2 && b0 <= 0xDF)
    size = 2;
  else if (b0 >= 0xE0 && b0 <= 0xEF)
    size = 3, low = b0 == 0xE0 ? 0xA0 : 0x80, high = b0 == 0xED ? 0x9F : 0xBF;
  else if (b0 >= 0xF0 && b0 <= 0xF4)
    size = 4, low = b0 == 0xF0 ? 0x90 : 0x80, high = b0 == 0xF4 ? 0x8F : 0xBF;
  else
    return 0;
  if (i + size > text.size()) return 0;
  for (std::size_t k = 1; k < size; ++k)
    if (b(i + k) < (k == 1 ? low : 0x80) || b(i + k) > (k == 1 ? high : 0xBF)) return 0;
  return size;
}

// The code point of the valid n-byte character at text[i].
char32_t code_point(const std::string& text, std::size_t i, std::size_t n) {
  const auto b = [&](std::size_t k) {
    return static_cast<char32_t>(static_cast<unsigned char>(text[k]));
  };
  if (n == 1) return b(i);
  char32_t c = b(i) & (0xFF >> (n + 1));
  for (std::size_t k = 1; k < n; ++k) c = (c << 6) | (b(i + k) & 0x3F);
  return c;
}

// NEL, LINE SEPARATOR and PARAGRAPH SEPARATOR: line breaks to the YAML 1.1 reader (libyaml),
// ordinary characters to YAML 1.2 and invisible in most editors (a NEL is what a Windows "…"
// becomes when its file is converted as Latin-1), so a value holding one would be cut in two.
bool invisible_break(char32_t c) { return c == 0x85 || c == 0x2028 || c == 0x2029; }

// Characters that space text out but that YAML does not read as text: the invisible line breaks
// and the vertical tab and form feed. Read as a space, so that an answer written "8" followed by
// one of them is still the number 8.
bool read_as_space(char32_t c) { return invisible_break(c) || c == 0x0B || c == 0x0C; }

// A character read as text: YAML allows it (YAML 1.1 §5.1, as libyaml checks it: no control
// character other than tab, line feed and carriage return, no U+FFFE or U+FFFF) and it is not
// an invisible line break.
bool yaml_character(char32_t c) {
  return !invisible_break(c) && (c == 0x09 || c == 0x0A || c == 0x0D || (c >= 0x20 && c <= 0x7E) ||
                                 (c >= 0xA0 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
                                 (c >= 0x10000 && c <= 0x10FFFF));
}

// Length of the character at text[i] when it is valid UTF-8 that YAML allows, else 0.
std::size_t text_length(const std::string& text, std::size_t i) {
  const std::size_t n = utf8_length(text, i);
  return n > 0 && yaml_character(code_point(text, i, n)) ? n : 0;
}

// The text with every byte that does not start a valid character, and every character not read
// as text (yaml_character), replaced by U+FFFD, or by a space when it spaces text (read_as_space).
std::string valid_utf8(const std::string& text) {
  std::string out;
  out.reserve(text.size() + 16);
  for (std::size_t k = 0; k < text.size();) {
    const std::size_t n = utf8_length(text, k);
    if (n == 0 || !yaml_character(code_point(text, k, n))) {
      out += n > 0 && read_as_space(code_point(text, k, n)) ? " " : "\xEF\xBF\xBD";
      k += n == 0 ? 1 : n;
    } else {
      out.append(text, k, n);
      k += n;
    }
  }
  return out;
}

// Replaces every byte that does not start a valid character, every control character YAML does
// not allow (a form feed, an escape) and every invisible line break by U+FFFD, so that everything
// read from the document is text (JSON output, terminals) and the rest of the file is still read;
// names the first one.
std::optional<Diagnostic> repair_utf8(std::string& text, const std::string& name) {
  std::size_t i = 0;
  while (i < text.size()) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7F) {  // printable ASCII, most of any file
      ++i;
      continue;
    }
    const std::size_t n = text_length(text, i);
    if (n == 0) break;
    i += n;
  }
  if (i == text.size()) return std::nullopt;
  int line = 1, column = 1;
  for (std::size_t k = 0; k < i; k += utf8_length(text, k)) {
    if (text[k] == '\n')
      ++line, column = 1;
    else
      ++column;
  }
  std::string message;
  if (const std::size_t n = utf8_length(text, i); n > 0) {
    char hex[16];
    std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(code_point(text, i, n)));
    message = std::string("character ") + hex +
              (read_as_space(code_point(text, i, n))
                   ? " (invisible spacing YAML does not read as text) is read as a space, and any "
                     "like it"
                   : " (a control character) is not read as text; it and any like it are read as "
                     "U+FFFD");
  } else {
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X",
                  static_cast<unsigned>(static_cast<unsigned char>(text[i])));
    message = std::string("invalid UTF-8: byte ") + hex +
              " is not text; it and any like it are read as U+FFFD (save the file as UTF-8)";
  }
  Diagnostic d{SourceLocation{name, line, column}, "", message};
  text = valid_utf8(text);
  return d;
}

// Walks the document with aliases expanded (iteratively: depth costs no stack) and returns
// the first problem: a key that is not a scalar, or more than kMaxYamlNodes nodes.
std::optional<Diagnostic> check_tree(const YAML::Node& root, const std::string& name,
                                     std::size_t max_nodes) {
  std::vector<YAML::Node> stack{root};
  std::size_t visited = 0;
  const auto at = [&](const YAML::Node& n, std::string message) {
    const YAML::Mark m = n.Mark();
    return Diagnostic{
        SourceLocation{name, m.line >= 0 ? m.line + 1 : 0, m.line >= 0 ? m.column + 1 : 0}, "",
        std::move(message)};
  };
  while (!stack.empty()) {
    const YAML::Node n = stack.back();
    stack.pop_back();
    if (++visited > max_nodes)
      return at(n, "the document expands to more than " + std::to_string(max_nodes) +
                       " values (through anchors and aliases?); the limit is " +
                       std::to_string(max_nodes) + " values");
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

// Text saved as UTF-16 or UTF-32 (by a byte-order mark, or by the zero bytes of its ASCII
// characters): yaml-cpp reads it as garbage ("unknown escape character").
std::optional<std::string> wide_encoding(const std::string& text) {
  const auto starts = [&](const char* bom, std::size_t n) {
    return text.compare(0, n, bom, n) == 0;
  };
  if (starts("\xFF\xFE\0\0", 4) || starts("\0\0\xFE\xFF", 4)) return "UTF-32";
  if (starts("\xFF\xFE", 2) || starts("\xFE\xFF", 2)) return "UTF-16";
  if (text.size() >= 4 && (text[0] == 0) != (text[1] == 0)) return "UTF-16";
  return std::nullopt;
}

// Stops the pass at the first problem, with where it is.
struct Refusal {
  YAML::Mark mark;
  std::string message;
};
// Stops a top_scalar pass once the value is read.
struct Taken {};

// The one pass over the parser's events: builds the document's nodes as YAML::Load does
// (yaml-cpp's NodeBuilder, with the same tags and styles; marks count characters) and, before each
// node is built, counts the nodes with aliases expanded and checks that no mapping names a key
// twice. Refusing while parsing keeps the bound on memory (a document of millions of nodes stops at
// the limit) without scanning the text a second time. The events come from libyaml
// (read_first_document), reported as yaml-cpp's own parser reports them.
// Nodes are made through yaml-cpp's installed detail API (memory_holder, detail::node); the
// finished root becomes a YAML::Node through a sequence iterator, the public way to wrap one.
//
// Without `build`, nothing is built: the pass then also refuses what parse_yaml's walk of the
// built tree (check_tree) refuses — a key that is a list or a mapping, an alias inside its own
// anchor's node (a cycle) — so that up to where it stops it accepts exactly what parse_yaml
// accepts, and keeps the scalar under `key` in the top mapping (root[key], the first such key);
// it stops (throws Taken) as soon as that value is read.
class StrictBuilder : public YAML::EventHandler {
 public:
  explicit StrictBuilder(std::size_t max_nodes = kMaxYamlNodes)
      : memory_(std::make_shared<YAML::detail::memory_holder>()), max_nodes_(max_nodes) {}
  explicit StrictBuilder(std::string key) : build_(false), key_(std::move(key)) {}

  // The scalar under the key in the top mapping (without build).
  const std::optional<std::string>& top_scalar() const { return value_; }

  // The document's root; a null Node (as YAML::Load gives) when there was none.
  YAML::Node root() {
    if (!root_) return YAML::Node();
    std::vector<YAML::detail::node*> one{root_};
    return *YAML::iterator(YAML::detail::node_iterator(one.begin()), memory_);
  }

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    if (!build_) {
      watch(nullptr);
      if (anchor) anchors_seen_.push_back({false, std::nullopt});
    }
    if (YAML::detail::node* n = leaf(mark, anchor, nullptr)) {
      n->set_null();
      pop();
    }
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    const std::size_t size = sizes_.at(anchor - 1);
    if (!build_) {
      const Anchored& a = anchors_seen_.at(anchor - 1);
      if (size == 0) throw Refusal{mark, "an alias inside its own anchor's node"};
      if (at_key() && a.container) throw Refusal{mark, "a key must be a name"};
      watch(a.scalar ? &*a.scalar : nullptr);
    }
    count(mark, size ? size : 1);  // an alias inside its own anchor's node counts as one
    finish_child(mark, nullptr);
    if (!build_) return;
    push(*anchors_.at(anchor - 1));
    pop();
  }
  void OnScalar(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                const std::string& value) override {
    if (!build_) {
      watch(&value);
      if (anchor) anchors_seen_.push_back({false, value});
    }
    if (YAML::detail::node* n = leaf(mark, anchor, &value)) {
      n->set_scalar(value);
      n->set_tag(tag);
      pop();
    }
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value style) override {
    open(mark, anchor, false, tag, style);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string& tag, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value style) override {
    open(mark, anchor, true, tag, style);
  }
  void OnMapEnd() override { close(); }

 private:
  struct Frame {
    YAML::detail::node* node;
    YAML::Mark mark;
    YAML::anchor_t anchor;
    std::size_t start;  // nodes counted before this one
    bool map;
    bool at_key = true;                 // the next child of a mapping is a key
    std::map<std::string, int> keys;    // key → line (1-based) where it first appears
    YAML::detail::node* key = nullptr;  // a mapping's key waiting for its value
  };

  void count(const YAML::Mark& mark, std::size_t n) {
    nodes_ += n;
    if (nodes_ > max_nodes_)
      throw Refusal{
          mark,
          (sizes_.empty() ? "the document has more than " : "the document expands to more than ") +
              std::to_string(max_nodes_) +
              (sizes_.empty() ? " values" : " values (through anchors and aliases)") +
              " (the limit is " + std::to_string(max_nodes_) + " values)"};
  }
  // A new node at `mark`: counted, checked as a key, registered under its anchor, pushed
  // (null without build).
  YAML::detail::node* leaf(const YAML::Mark& mark, YAML::anchor_t anchor,
                           const std::string* scalar) {
    count(mark, 1);
    finish_child(mark, scalar);
    if (anchor) sizes_.push_back(1);
    if (!build_) return nullptr;
    YAML::detail::node& n = create(mark, anchor);
    push(n);
    return &n;
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool map, const std::string& tag,
            YAML::EmitterStyle::value style) {
    count(mark, 1);
    YAML::detail::node* n = nullptr;
    if (build_) {
      n = &create(mark, anchor);
      n->set_tag(tag);
      n->set_type(map ? YAML::NodeType::Map : YAML::NodeType::Sequence);
      n->set_style(style);
      push(*n);
    } else {
      if (at_key()) throw Refusal{mark, "a key must be a name"};
      watch(nullptr);
      if (anchor) anchors_seen_.push_back({true, std::nullopt});
    }
    if (anchor) sizes_.push_back(0);  // known when it closes
    stack_.push_back(Frame{n, mark, anchor, nodes_ - 1, map, true, {}, nullptr});
  }
  void close() {
    Frame f = std::move(stack_.back());
    stack_.pop_back();
    if (f.anchor) sizes_.at(f.anchor - 1) = nodes_ - f.start;
    finish_child(f.mark, nullptr);
    if (build_) pop();
  }
  bool at_key() const { return !stack_.empty() && stack_.back().map && stack_.back().at_key; }
  // Without build: a node about to start in the top mapping, a scalar's text or null. The
  // first key equal to key_ makes the next value the one kept.
  void watch(const std::string* scalar) {
    if (stack_.size() != 1 || !stack_[0].map) return;
    if (at_key()) {
      if (!found_ && scalar && *scalar == key_) found_ = taking_ = true;
    } else if (taking_) {
      taking_ = false;
      if (scalar) value_ = *scalar;
      throw Taken{};  // the rest of the text is the grading's to read
    }
  }
  YAML::detail::node& create(const YAML::Mark& mark, YAML::anchor_t anchor) {
    YAML::detail::node& n = memory_->create_node();
    n.set_mark(mark);
    if (anchor) anchors_.push_back(&n);  // yaml-cpp numbers anchors 1, 2, … in order
    return n;
  }
  // A node ended inside the innermost container: a mapping's key is checked against the
  // keys before it.
  void finish_child(const YAML::Mark& mark, const std::string* scalar) {
    if (stack_.empty() || !stack_.back().map) return;
    Frame& f = stack_.back();
    if (f.at_key && scalar) {
      const auto [it, fresh] = f.keys.emplace(*scalar, mark.line + 1);
      if (!fresh)
        throw Refusal{mark, "duplicate key '" + valid_utf8(*scalar).substr(0, 64) +
                                "' (first on line " + std::to_string(it->second) +
                                "): a mapping names each key once"};
    }
    f.at_key = !f.at_key;
  }
  // The node being built; added to its container by pop().
  void push(YAML::detail::node& n) { pending_.push_back(&n); }
  void pop() {
    YAML::detail::node& n = *pending_.back();
    pending_.pop_back();
    if (pending_.empty()) {
      root_ = &n;
      return;
    }
    // The container is the innermost frame (a frame's node is pending until it closes).
    Frame& f = stack_.back();
    if (!f.map) {
      f.node->push_back(n, memory_);
    } else if (!f.key) {
      f.key = &n;
    } else {
      f.node->insert(*f.key, n, memory_);
      f.key = nullptr;
    }
  }

  YAML::detail::shared_memory_holder memory_;
  YAML::detail::node* root_ = nullptr;
  std::vector<YAML::detail::node*> pending_;
  std::size_t max_nodes_ = kMaxYamlNodes;
  std::size_t nodes_ = 0;
  std::vector<Frame> stack_;
  std::vector<YAML::detail::node*> anchors_;  // by anchor − 1
  std::vector<std::size_t> sizes_;            // nodes each anchor stands for, by anchor − 1
  bool build_ = true;
  std::string key_;
  bool found_ = false, taking_ = false;
  std::optional<std::string> value_;
  struct Anchored {
    bool container;
    std::optional<std::string> scalar;
  };
  std::vector<Anchored> anchors_seen_;  // by anchor − 1 (without build)
};

// Runs the first document through `builder`; a second document is the error returned. False
// in `any` when there was no document. Throws Refusal, or yaml-cpp's exceptions for invalid
// YAML (read_first_document).
std::optional<Diagnostic> run_checked(const std::string& text, const std::string& name,
                                      StrictBuilder& builder, bool& any) {
  const FirstDocument read = read_first_document(text, builder);
  any = read.any;
  if (!read.second) return std::nullopt;
  // Where the second document starts is where the first one's `---` or `...` ends.
  const YAML::Mark& m = *read.second;
  return Diagnostic{
      SourceLocation{name, m.line >= 0 ? m.line + 1 : 0, m.line >= 0 ? m.column + 1 : 0}, "",
      "a second YAML document (after '---'): a file holds one document"};
}

// Parses the first document into `root` and checks it in one pass (StrictBuilder); a second
// document is the error returned (root is then left as it was).
std::optional<Diagnostic> build_checked(const std::string& text, const std::string& name,
                                        YAML::Node& root, std::size_t max_nodes) {
  StrictBuilder builder(max_nodes);
  bool any = false;
  std::optional<Diagnostic> second = run_checked(text, name, builder, any);
  if (!second) root = any ? builder.root() : YAML::Node();
  return second;
}

}  // namespace

YamlDocument parse_yaml(const std::string& text, const std::string& name, std::size_t max_nodes) {
  YamlDocument doc;
  if (const auto wide = wide_encoding(text)) {
    doc.error = Diagnostic{SourceLocation{name, 1, 1}, "",
                           "the file is " + *wide + " text: save it as UTF-8"};
    return doc;
  }
  std::string repaired = text;
  doc.invalid_utf8 = repair_utf8(repaired, name);
  try {
    // Refused while parsing: the root stays unset (no node is kept).
    if ((doc.error = build_checked(repaired, name, doc.root, max_nodes))) return doc;
    doc.error = check_tree(doc.root, name, max_nodes);
  } catch (const Refusal& r) {
    doc.error = Diagnostic{SourceLocation{name, r.mark.line >= 0 ? r.mark.line + 1 : 0,
                                          r.mark.line >= 0 ? r.mark.column + 1 : 0},
                           "", r.message};
    return doc;
  } catch (const YAML::ParserException& e) {
    doc.error =
        Diagnostic{SourceLocation{name, e.mark.line + 1, e.mark.column + 1}, "",
                   "invalid YAML: " + valid_utf8(e.msg)};  // may quote one byte of a character
  } catch (const std::exception& e) {
    doc.error = Diagnostic{SourceLocation{name, 0, 0}, "", "invalid YAML: " + valid_utf8(e.what())};
  }
  if (doc.error) doc.root = YAML::Node();
  return doc;
}

namespace {

bool name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// The value of the common first line `key: word` (a class's `student: s00042`), read without the
// parser when what follows makes the parser's answer certain: the word is a plain scalar of
// letters, digits and `_ . @ + -` (not YAML's null), the line ends (spaces, then a line feed
// or the end of the text), and the next line is the end of the text or starts another key
// (`name:`) at the left margin, which ends the word and cannot be a continuation of it. The
// parser would read exactly this word: the text up to here is printable ASCII, and it stops
// after the next line's key. Anything else is left to the parser (nothing).
std::optional<std::string> plain_first_line(const std::string& text, const std::string& key) {
  const std::size_t n = text.size();
  if (key.empty() || !std::all_of(key.begin(), key.end(), name_character)) return std::nullopt;
  if (text.compare(0, key.size(), key) != 0 || n < key.size() + 3 || text[key.size()] != ':' ||
      text[key.size() + 1] != ' ')
    return std::nullopt;
  std::size_t i = key.size() + 1;
  while (i < n && text[i] == ' ') ++i;
  const std::size_t start = i;
  const auto word_character = [](char c) {
    return name_character(c) || c == '.' || c == '@' || c == '+' || c == '-';
  };
  while (i < n && word_character(text[i])) ++i;
  if (i == start || !name_character(text[start])) return std::nullopt;
  std::string word = text.substr(start, i - start);
  if (null_scalar(word)) return std::nullopt;
  while (i < n && text[i] == ' ') ++i;
  if (i == n) return word;
  if (text[i] == '\r') ++i;
  if (i == n || text[i] != '\n') return std::nullopt;
  if (++i == n) return word;
  const std::size_t next = i;
  while (i < n && name_character(text[i])) ++i;
  if (i == next || (text[next] >= '0' && text[next] <= '9') || i == n || text[i] != ':')
    return std::nullopt;
  if (i + 1 < n && text[i + 1] != ' ' && text[i + 1] != '\n' && text[i + 1] != '\r')
    return std::nullopt;
  return word;
}

}  // namespace

std::optional<std::string> top_scalar(const std::string& text, const std::string& name,
                                      const std::string& key) {
  if (std::optional<std::string> word = plain_first_line(text, key)) return word;
  if (wide_encoding(text)) return std::nullopt;
  std::string repaired = text;
  repair_utf8(repaired, name);
  StrictBuilder check(key);
  bool any = false;
  try {
    if (run_checked(repaired, name, check, any) || !any) return std::nullopt;
  } catch (const Taken&) {
    return check.top_scalar();
  } catch (const std::exception&) {
    return std::nullopt;
  } catch (const Refusal&) {
    return std::nullopt;
  }
  return check.top_scalar();
}

std::optional<Diagnostic> read_text_file(const std::string& path, std::size_t max_bytes,
                                         std::string& out) {
  const auto refuse = [&](std::string message) {
    return Diagnostic{SourceLocation{path, 0, 0}, "", std::move(message)};
  };
  // O_NONBLOCK: opening a FIFO that no one writes to returns at once instead of waiting.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return refuse(std::string("cannot open the file: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const bool dir = S_ISDIR(st.st_mode);
    ::close(fd);
    return refuse(dir ? "a directory, not a file"
                      : "not a regular file (a pipe, socket or device); give a file");
  }
  const auto too_big = [&] {
    return refuse("the file is larger than the limit of " + std::to_string(max_bytes) + " bytes");
  };
  if (static_cast<std::uintmax_t>(st.st_size) > max_bytes) {
    ::close(fd);
    return too_big();
  }
  out.clear();
  out.reserve(static_cast<std::size_t>(st.st_size));
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const std::string reason = std::strerror(errno);
      ::close(fd);
      return refuse("cannot read the file: " + reason);
    }
    if (n == 0) break;
    if (out.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      return too_big();
    }
    out.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return std::nullopt;
}

YamlDocument load_yaml_file(const std::string& path, std::size_t max_nodes) {
  std::string text;
  if (std::optional<Diagnostic> error = read_text_file(path, kMaxYamlFileBytes, text))
    return {YAML::Node(), std::move(error), {}};
  return parse_yaml(text, path, max_nodes);
}

}  // namespace frustum
