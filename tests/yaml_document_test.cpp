// parse_yaml reads a document in one pass: the strict checks (duplicate keys, the node bound
// with aliases expanded, one document) run on the parser's events while the nodes are built.
// The tree must be the one YAML::Load builds, marks included (every located message uses them).
#include "solver/input/yaml_document.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <string>

#include "test_util.hpp"

namespace frustum {
namespace {

// Type, tag, style, mark and text of every node, recursively ("" when alike, else where not).
std::string difference(const YAML::Node& a, const YAML::Node& b, const std::string& at = "root") {
  if (a.Type() != b.Type() || a.Tag() != b.Tag() || a.Style() != b.Style())
    return at + ": type, tag or style";
  if (a.Mark().line != b.Mark().line || a.Mark().column != b.Mark().column ||
      a.Mark().pos != b.Mark().pos)
    return at + ": mark";
  if (a.IsScalar()) return a.Scalar() == b.Scalar() ? "" : at + ": text";
  if (a.size() != b.size()) return at + ": size";
  std::size_t k = 0;
  for (auto i = a.begin(), j = b.begin(); i != a.end(); ++i, ++j, ++k) {
    const std::string where = at + "." + std::to_string(k);
    const std::string d = a.IsSequence() ? difference(*i, *j, where)
                                         : difference(i->first, j->first, where + ".key") +
                                               difference(i->second, j->second, where);
    if (!d.empty()) return d;
  }
  return "";
}

TEST(YamlDocument, OnePassBuildsTheTreeYamlLoadBuildsForEveryShippedFile) {
  std::size_t compared = 0;
  for (const char* dir : {"problems", "tests"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_path(dir))) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".yaml" && ext != ".yml")) continue;
      const std::string text = test::read_file(e.path());
      const YamlDocument doc = parse_yaml(text, e.path().string());
      if (doc.error || doc.invalid_utf8) continue;
      ++compared;
      EXPECT_EQ(difference(YAML::Load(text), doc.root), "") << e.path();
    }
  EXPECT_GT(compared, 100u);
}

TEST(YamlDocument, AnchorsAliasesAndStylesAsYamlLoadReadsThem) {
  for (const std::string text :
       {"a: &x [1, 2]\nb: *x\nc: {p: *x, q: \"s\", r: 'ok'}\n", "&k a: 1\n*k : 2\n",
        "- !!str 12\n- ~\n- |\n  two\n  lines\n- {? a}\n", "x: &s scalar\ny: *s\n", "",
        "# nothing\n"}) {
    const YamlDocument doc = parse_yaml(text, "t.yaml");
    ASSERT_FALSE(doc.error) << text;
    EXPECT_EQ(difference(YAML::Load(text), doc.root), "") << text;
  }
  // The alias is the anchored node itself (yaml-cpp shares it), as Load gives.
  const YamlDocument doc = parse_yaml("a: &x [1, 2]\nb: *x\n", "t.yaml");
  EXPECT_TRUE(doc.root["a"].is(doc.root["b"]));
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
            "t.yaml:3:2: invalid YAML: end of sequence flow not found");
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
  for (const char* dir : {"problems", "tests"})
    for (const auto& e : std::filesystem::recursive_directory_iterator(test::source_path(dir)))
      if (e.is_regular_file() &&
          (e.path().extension() == ".yaml" || e.path().extension() == ".yml"))
        texts.push_back(test::read_file(e.path()));
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

}  // namespace
}  // namespace frustum
