// parse_yaml reads a document in one pass: the strict checks (duplicate keys, the node bound
// with aliases expanded, one document) run on the parser's events while the nodes are built.
// The tree must be the one YAML::Load builds, marks included (every located message uses them).
#include "solver/input/yaml_document.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <random>
#include <string>

#include "test_util.hpp"

namespace frustum {
namespace {

// yaml-cpp's column (bytes from the line's start) in characters, as libyaml counts it.
int character_column(const std::string& text, const YAML::Mark& m) {
  if (m.line < 0 || m.column < 0) return m.column;  // a node without a place (an empty document)
  std::size_t start = 0;
  for (int line = 0; line < m.line && start < text.size(); ++line)
    start = std::min(text.size(), text.find('\n', start) + 1);
  int column = 0;
  for (std::size_t i = start; i < std::min(text.size(), start + static_cast<std::size_t>(m.column));
       ++i)
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) ++column;
  return column;
}

// Type, tag, style, mark and text of every node, recursively ("" when alike, else where not),
// between yaml-cpp's YAML::Load (a) and parse_yaml (b), which reads with libyaml. Marks count
// characters in b (yaml-cpp counts bytes), and an empty value (a null that is not written) is
// marked where it would start, after its key or dash, not at the next token as yaml-cpp marks
// it: never on a later line.
std::string difference(const std::string& text, const YAML::Node& a, const YAML::Node& b,
                       const std::string& at = "root") {
  if (a.Type() != b.Type() || a.Tag() != b.Tag() || a.Style() != b.Style())
    return at + ": type, tag or style";
  const bool unwritten = a.IsNull() && b.Mark().line <= a.Mark().line;
  if (!unwritten &&
      (a.Mark().line != b.Mark().line || character_column(text, a.Mark()) != b.Mark().column))
    return at + ": mark";
  if (a.IsScalar()) return a.Scalar() == b.Scalar() ? "" : at + ": text";
  if (a.size() != b.size()) return at + ": size";
  std::size_t k = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j, ++k) {
    const std::string where = at + "." + std::to_string(k);
    const std::string d = a.IsSequence() ? difference(text, *i, *j, where)
                                         : difference(text, i->first, j->first, where + ".key") +
                                               difference(text, i->second, j->second, where);
    if (!d.empty()) return d;
  }
  return "";
}

// Every YAML file shipped under problems/ and tests/: its path and its text.
std::vector<std::pair<std::filesystem::path, std::string>> shipped_yaml() {
  std::vector<std::pair<std::filesystem::path, std::string>> files;
  for (const char* dir : {"problems", "tests"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_path(dir))) {
      const std::string ext = e.path().extension().string();
      if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
        files.emplace_back(e.path(), test::read_file(e.path()));
    }
  return files;
}

TEST(YamlDocument, OnePassBuildsTheTreeYamlLoadBuildsForEveryShippedFile) {
  std::size_t compared = 0;
  for (const auto& [path, text] : shipped_yaml()) {
    const YamlDocument doc = parse_yaml(text, path.string());
    if (doc.error || doc.invalid_utf8) continue;
    ++compared;
    EXPECT_EQ(difference(text, YAML::Load(text), doc.root), "") << path;
  }
  EXPECT_GT(compared, 100u);
}

// A file saved with a byte-order mark (as some Windows editors save UTF-8) is the same
// document: every node where it is without the mark, the same errors at the same places. The
// parser once read the mark as a character of the first line and silently lost every line
// after it (a student's answers, below `student:`).
TEST(YamlDocument, AByteOrderMarkChangesNothing) {
  const std::string mark = "\xEF\xBB\xBF";
  std::size_t compared = 0;
  for (const auto& [path, text] : shipped_yaml()) {
    const YamlDocument plain = parse_yaml(text, "t.yaml");
    if (plain.error && plain.error->message.find(" UTF-") != std::string::npos)
      continue;  // UTF-16 and UTF-32 files: a UTF-8 mark in front of them means nothing
    const YamlDocument marked = parse_yaml(mark + text, "t.yaml");
    ASSERT_EQ(plain.error.has_value(), marked.error.has_value()) << path;
    if (plain.error) {
      EXPECT_EQ(plain.error->format(), marked.error->format()) << path;
      continue;
    }
    if (plain.invalid_utf8) continue;
    ++compared;
    EXPECT_EQ(difference(text, YAML::Load(text), marked.root), "") << path;
    EXPECT_EQ(top_scalar(mark + text, "t.yaml", "title"), top_scalar(text, "t.yaml", "title"));
  }
  EXPECT_GT(compared, 100u);
  const YamlDocument answers = parse_yaml(mark + "student: s1\nanswers:\n  p1: {z: 8}\n", "a.yaml");
  ASSERT_FALSE(answers.error);
  EXPECT_EQ(answers.root["answers"]["p1"]["z"].as<std::string>(), "8");
  EXPECT_EQ(answers.root["answers"]["p1"].Mark().line, 2);
  EXPECT_EQ(answers.root["answers"]["p1"].Mark().column, 6);
  EXPECT_EQ(answers.root["student"].Mark().column, 9);
  EXPECT_EQ(parse_yaml(mark + "a: 1\nb: [\n", "t.yaml").error->format(),
            parse_yaml("a: 1\nb: [\n", "t.yaml").error->format());
}

TEST(YamlDocument, AnchorsAliasesAndStylesAsYamlLoadReadsThem) {
  for (const std::string text :
       {"a: &x [1, 2]\nb: *x\nc: {p: *x, q: \"s\", r: 'ok'}\n", "&k a: 1\n*k : 2\n",
        "- !!str 12\n- ~\n- |\n  two\n  lines\n- {? a}\n", "x: &s scalar\ny: *s\n", "",
        "# nothing\n"}) {
    const YamlDocument doc = parse_yaml(text, "t.yaml");
    ASSERT_FALSE(doc.error) << text;
    EXPECT_EQ(difference(text, YAML::Load(text), doc.root), "") << text;
  }
  // What students and instructors write: text in any script, empty values, comments, block
  // and flow styles mixed, folded and literal text, quoted keys, an anchor named again.
  for (const std::string text :
       {"student: Иванов\nanswers:\n  p1: {normal: [1/√3, −1/√3, 1/√3], z: 8}  # 注\n",
        "a:\n  - [1, 2]\n  - x:\n    y: 2\n  -\n  - ~\n",
        "t: >\n  folded\n  text\n\nu: |-\n  kept\n", "\"q k\": 'it''s'\n? complex\n: value\n",
        "a: &x 1\nb: &x 2\nc: *x\n", "p: plain text\n  over two lines\nq: \"quoted\n  over two\"\n",
        "e: 🙂 ✓\nf: Zバッファ\n", "- a\n- - b\n  - c\n-   d: 1\n    e: 2\n",
        "x: !!int 3\ny: !local v\nz: !<verbatim> w\n"}) {
    const YamlDocument doc = parse_yaml(text, "t.yaml");
    ASSERT_FALSE(doc.error) << text << doc.error->format();
    EXPECT_EQ(difference(text, YAML::Load(text), doc.root), "") << text;
  }
  // The alias is the anchored node itself (yaml-cpp shares it), as Load gives.
  const YamlDocument doc = parse_yaml("a: &x [1, 2]\nb: *x\n", "t.yaml");
  EXPECT_TRUE(doc.root["a"].is(doc.root["b"]));
}

TEST(YamlDocument, ControlCharactersAreReadAsReplacementCharacters) {
  // YAML text may not hold control characters other than tab and line breaks: an escape pasted
  // into an answer is replaced (and named), and the rest of the file is read.
  const YamlDocument doc = parse_yaml("student: s1\nz: 8\nw: \x1b[1m\n", "t.yaml");
  ASSERT_FALSE(doc.error);
  ASSERT_TRUE(doc.invalid_utf8);
  EXPECT_EQ(doc.invalid_utf8->format(),
            "t.yaml:3:4: character U+001B (a control character) is not read as text; it and any "
            "like it are read as U+FFFD");
  EXPECT_EQ(doc.root["student"].Scalar(), "s1");
  EXPECT_EQ(doc.root["w"].Scalar(), "\uFFFD[1m");
  // Invisible spacing — a form feed, a vertical tab, NEL and the Unicode line and paragraph
  // separators (which the YAML 1.1 reader would take for line ends although no editor shows a
  // break) — is read as a space: "8" and a form feed is still 8, a value stays one value.
  const YamlDocument nel = parse_yaml("z: 8\x0c\na: x\u0085y\nb: p\u2028q\u2029r\x0bs\n", "t.yaml");
  ASSERT_FALSE(nel.error) << nel.error->format();
  ASSERT_TRUE(nel.invalid_utf8);
  EXPECT_EQ(nel.invalid_utf8->format(),
            "t.yaml:1:5: character U+000C (invisible spacing YAML does not read as text) is read "
            "as a space, and any like it");
  EXPECT_EQ(nel.root["z"].Scalar(), "8");
  EXPECT_EQ(nel.root["a"].Scalar(), "x y");
  EXPECT_EQ(nel.root["b"].Scalar(), "p q r s");
  // Tab, CR LF and the no-break space are text.
  const YamlDocument kept = parse_yaml("a: \"x\ty\"\r\nb: c\u00A0d\n", "t.yaml");
  ASSERT_FALSE(kept.error) << kept.error->format();
  EXPECT_FALSE(kept.invalid_utf8);
  EXPECT_EQ(kept.root["a"].Scalar(), "x\ty");
  EXPECT_EQ(kept.root["b"].Scalar(), "c\u00A0d");
}

TEST(YamlDocument, StrictChecksRunWhileBuilding) {
  const auto error = [](const std::string& text) {
    const YamlDocument doc = parse_yaml(text, "t.yaml");
    return doc.error ? doc.error->format() : std::string("none");
  };
  EXPECT_EQ(error("x:\n  y: {p: 1, p: 2}\n"),
            "t.yaml:2:13: duplicate key 'p' (first on line 2): a mapping names each key once");
  // A duplicate before a syntax error is the one reported; a syntax error before it wins.
  EXPECT_EQ(error("a: 1\na: 2\nb: [\n"),
            "t.yaml:2:1: duplicate key 'a' (first on line 1): a mapping names each key once");
  EXPECT_EQ(error("b: [\na: 1\na: 2\n"),
            "t.yaml:3:2: invalid YAML: did not find expected \',\' or \']\' (while parsing a flow "
            "sequence that starts at line 1, column 4)");
  EXPECT_EQ(error("a: 1\n---\nb: 2\n"),
            "t.yaml:2:1: a second YAML document (after '---'): a file holds one document");
  // Ten aliases of ten aliases … of ten values: refused at the bound, before it is built.
  std::string laughs = "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n";
  std::string previous = "a";
  for (int i = 0; i < 6; ++i) {
    const std::string name = "b" + std::to_string(i);
    laughs += name + ": &" + name + " [";
    for (int k = 0; k < 10; ++k) laughs += (k ? ", *" : "*") + previous;
    laughs += "]\n";
    previous = name;
  }
  EXPECT_NE(error(laughs).find("expands to more than 1000000 values (through anchors and aliases)"),
            std::string::npos);
  // An alias inside its own anchor's node is a cycle: refused by the walk after the pass.
  EXPECT_NE(error("a: &a [*a]\n").find("expands to more than"), std::string::npos);
  EXPECT_EQ(error("{[a]: 1}\n"), "t.yaml:1:2: a key must be a name, not a list");
  // A refused document keeps no node.
  EXPECT_EQ(parse_yaml("a: 1\na: 2\n", "t.yaml").root.Type(), YAML::NodeType::Null);
}

// The id read for a class (top_scalar, no nodes built) is what parse_yaml's tree says, for
// every document parse_yaml accepts or refuses.
std::optional<std::string> scalar_of_tree(const std::string& text, const std::string& key) {
  const YamlDocument doc = parse_yaml(text, "t.yaml");
  if (doc.error || !doc.root.IsMap() || !doc.root[key].IsDefined() || !doc.root[key].IsScalar())
    return std::nullopt;
  return doc.root[key].Scalar();
}

TEST(YamlDocument, TopScalarIsTheTreesScalarWithoutBuildingIt) {
  std::vector<std::string> texts = {"a: &x [1, 2]\nb: *x\n",
                                    "&k student: 1\n*k : 2\n",
                                    "x: &s sc\nstudent: *s\n",
                                    "&e []: 1\n",
                                    "a: &e []\n*e : 2\n",
                                    "a: &a [*a]\n",
                                    "a: &a {x: *a}\n",
                                    "student: ~\n",
                                    "student:\n",
                                    "student: [1]\n",
                                    "- student\n",
                                    "student: a\n---\nb\n",
                                    "{[a]: 1, student: x}\n",
                                    "student: x\n{a: 1}: 2\n",
                                    "a: &n ~\n*n : 3\nstudent: q\n",
                                    "student: 'q'\n",
                                    "student: \"a\\tb\"\n",
                                    "student: !!str 12\n",
                                    "x: {student: 3}\n",
                                    "student: a\nstudent: b\n",
                                    "? student\n: v\n",
                                    "? [student]\n: v\n",
                                    "student: |\n  two\n  lines\n",
                                    "student: s1\nanswers: {p: [1, \n",
                                    "\xFF\xFEs\0"};
  for (const auto& file : shipped_yaml()) texts.push_back(file.second);
  for (const std::string& text : texts)
    for (const char* key : {"student", "title", "a", "x", "problems"})
      if (!parse_yaml(text, "t.yaml").error) {
        EXPECT_EQ(top_scalar(text, "t.yaml", key), scalar_of_tree(text, key))
            << key << " in " << text.substr(0, 200);
      }
}

// A text parse_yaml refuses still states its id when everything up to the value is valid: the
// pass stops there, so a broken answer below `student:` is the grader's to report, under the
// student the file names. Refused before the value: no id.
TEST(YamlDocument, TopScalarStopsAtTheValue) {
  const auto id = [](const std::string& text) { return top_scalar(text, "t.yaml", "student"); };
  EXPECT_EQ(id("student: s1\nanswers: {p: [1, \n"), "s1");
  EXPECT_EQ(id("student: a\nstudent: b\n"), "a");
  EXPECT_EQ(id("student: a\n---\nb\n"), "a");
  EXPECT_EQ(id("student: x\n{a: 1}: 2\n"), "x");
  EXPECT_EQ(id("x: &s sc\nstudent: *s\nbroken: [\n"), "sc");
  EXPECT_EQ(id("{[a]: 1, student: x}\n"), std::nullopt);
  EXPECT_EQ(id("a: 1\na: 2\nstudent: x\n"), std::nullopt);
  EXPECT_EQ(id("answers: {p: [1, \nstudent: s1\n"), std::nullopt);
  EXPECT_EQ(id("student: [s1]\nbroken: [\n"), std::nullopt);
  EXPECT_EQ(id("student:\nbroken: [\n"), std::nullopt);
  EXPECT_EQ(id("\xFF\xFEs\0"), std::nullopt);
}

// A first line `student: s00042` is read without the parser when what follows makes the parser's
// answer certain: over first lines and next lines built from pieces that sit on either side of
// that line (spaces and tabs, quotes, comments, YAML's nulls, continuation lines, control
// characters, line ends), the id is the parser's. A byte-order mark in front sends the same text
// through the parser, which skips the mark.
TEST(YamlDocument, TopScalarOfAPlainFirstLineIsTheParsersValue) {
  const std::vector<std::string> keys = {"student", "Student", "student ", "studentx", "a-b"};
  const std::vector<std::string> colons = {": ", ":  ", ":", ":\t", ": \t", " : "};
  const std::vector<std::string> words = {"s00042", "null",  "Null",     "NULL",      "~",   "true",
                                          "12",     "-1",    ".inf",     "a.b@c+d-e", "x#y", "a:b",
                                          "'q'",    "\"q\"", "\xc3\xa9", "a\x01",     "",    "_x",
                                          "a b",    "@a",    "a,b",      "[a]"};
  const std::vector<std::string> trails = {"", " ", "  ", "\t", " #c", "#c", " \x01"};
  const std::vector<std::string> ends = {"\n", "\r\n", "\r", "", "\n\n", "\x85"};
  const std::vector<std::string> nexts = {"",
                                          "answers:",
                                          "answers: {p: [1, \n",
                                          "  cont\n",
                                          "\tx\n",
                                          "#c\n",
                                          "- a\n",
                                          "1a: 2\n",
                                          "a:b\n",
                                          "a :\n",
                                          "abc\n",
                                          "abc\n\tx\n",
                                          "_k: v\n",
                                          "answers:\n  p: 1\n",
                                          "k:\t1\n",
                                          "student: b\n",
                                          "x: [\n",
                                          "k:\x01\n",
                                          "k: \xff\n",
                                          "a: 1\na: 2\n",
                                          "{a: 1}: 2\n",
                                          "---\nb\n",
                                          "...\n",
                                          "k:"};
  std::mt19937 rng(42);
  const auto pick = [&](const std::vector<std::string>& v) { return v[rng() % v.size()]; };
  int fast = 0;
  for (int i = 0; i < 20000; ++i) {
    const std::string text = pick(keys) + pick(colons) + pick(words) + pick(trails) + pick(ends) +
                             pick(nexts) + (rng() % 2 ? "" : pick(nexts));
    const std::optional<std::string> id = top_scalar(text, "t.yaml", "student");
    EXPECT_EQ(id, top_scalar("\xEF\xBB\xBF" + text, "t.yaml", "student"))
        << "text: " << ::testing::PrintToString(text);
    fast += id.has_value();
  }
  EXPECT_GT(fast, 1000);  // the pieces do make plain first lines
  EXPECT_EQ(top_scalar("student: s00042\nanswers:\n  p: 1\n", "t.yaml", "student"), "s00042");
  EXPECT_EQ(top_scalar("student: s1\r\nanswers: {p: [1, \n", "t.yaml", "student"), "s1");
  EXPECT_EQ(top_scalar("student: null\n", "t.yaml", "student"), std::nullopt);
  EXPECT_EQ(top_scalar("student: a\n  b\n", "t.yaml", "student"), "a b");
}

}  // namespace
}  // namespace frustum
