// docs/answers.md's answer-syntax table is checked against the code: every answer of every kind is
// in the row of its answer type, and every example in the table parses as that type.
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "grader/answer_parser.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

struct Row {
  std::string type;
  std::set<std::pair<std::string, std::string>> answers;  // (kind, answer)
  std::vector<std::string> examples;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::istringstream in(s + sep);  // a trailing separator keeps a final empty field
  for (std::string field; std::getline(in, field, sep);) out.push_back(field);
  return out;
}

std::vector<std::string> backticked(const std::string& s) {
  std::vector<std::string> out;
  for (std::size_t open = s.find('`'); open != std::string::npos; open = s.find('`', open)) {
    const std::size_t close = s.find('`', open + 1);
    if (close == std::string::npos) break;
    out.push_back(s.substr(open + 1, close - open - 1));
    open = close + 1;
  }
  return out;
}

// The rows of the table under "## Answer syntax" in docs/answers.md.
std::vector<Row> docs_rows() {
  std::ifstream in(test::source_path("docs/answers.md"));
  std::string line;
  while (std::getline(in, line) && line != "## Answer syntax") {
  }
  std::vector<Row> rows;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.rfind("| ", 0) != 0) {
      if (in_table) break;
      continue;
    }
    in_table = true;
    const std::vector<std::string> cells =
        split(line, '|');  // "", type, answers, forms, example, ""
    if (cells.size() < 6 || cells[1] == " type " || cells[1].find("---") != std::string::npos)
      continue;
    Row row;
    row.type = cells[1].substr(1, cells[1].size() - 2);
    // "`dot`, `area` (vectors); `z` (depth_at_pixel)": names, then their kinds in parentheses.
    for (const std::string& group : split(cells[2], ';')) {
      const std::size_t open = group.find('('), close = group.find(')');
      const std::vector<std::string> names = backticked(group.substr(0, open));
      const std::string kinds =
          open == std::string::npos ? "" : group.substr(open + 1, close - open - 1);
      for (std::string kind : kinds.empty() ? std::vector<std::string>{} : split(kinds, ',')) {
        kind.erase(0, kind.find_first_not_of(' '));
        kind = kind.substr(0, kind.find_first_of(": "));
        for (const std::string& name : names) row.answers.insert({kind, name});
      }
      if (kinds.empty())  // every kind that has these answers
        for (const KindInfo& k : builtin_kinds().all())
          for (const std::string& name : names)
            if (k.answer(name)) row.answers.insert({k.name, name});
    }
    row.examples = backticked(cells[4]);
    rows.push_back(row);
  }
  return rows;
}

TEST(AnswerSyntax, DocsTableCoversEveryAnswerOfEveryKind) {
  const std::vector<Row> rows = docs_rows();
  ASSERT_GE(rows.size(), 10u);
  std::map<std::pair<std::string, std::string>, std::string> row_of;
  for (const Row& r : rows)
    for (const auto& a : r.answers) {
      EXPECT_TRUE(row_of.emplace(a, r.type).second)
          << a.first << "." << a.second << " is in two rows";
      const KindInfo* k = builtin_kinds().find(a.first);
      EXPECT_TRUE(k && k->answer(a.second))
          << r.type << ": " << a.first << " has no answer " << a.second;
    }
  // Answers of one row share one comparison (AnswerKind).
  for (const Row& r : rows) {
    std::set<int> kinds;
    for (const auto& [kind, name] : r.answers)
      if (const KindInfo* k = builtin_kinds().find(kind))
        if (const AnswerSpec* spec = k->answer(name)) kinds.insert(static_cast<int>(spec->kind));
    EXPECT_EQ(kinds.size(), 1u) << r.type << " mixes answer types";
  }
  for (const KindInfo& k : builtin_kinds().all())
    for (const AnswerSpec& a : k.answers)
      EXPECT_TRUE(row_of.count({k.name, a.name}))
          << k.name << "." << a.name << " is missing from docs/answers.md's table";
}

TEST(AnswerSyntax, EveryExampleInTheDocsParses) {
  int examples = 0;
  for (const Row& r : docs_rows()) {
    ASSERT_FALSE(r.answers.empty()) << r.type;
    const auto& [kind, name] = *r.answers.begin();
    const AnswerSpec* spec = builtin_kinds().find(kind)->answer(name);
    ASSERT_NE(spec, nullptr);
    for (const std::string& example : r.examples) {
      YAML::Node node = YAML::Load(example);
      if (node.IsMap() && node.size() == 1 && example.find(": ") != std::string::npos &&
          example[0] != '{')
        node = node.begin()->second;  // "z: 8" → 8
      const ParsedAnswer p = parse_answer(node, *spec, AngleUnit::Degrees);
      EXPECT_TRUE(p.ok) << r.type << ": `" << example << "`: " << p.error;
      ++examples;
    }
  }
  EXPECT_GE(examples, 20);
}

}  // namespace
}  // namespace frustum
