// The answer types (grader/answer_types/): one per AnswerKind, each complete, every answer of
// every kind in exactly one row of its type's syntax, every example of the syntax read as its
// type, and docs/answers.md's answer-syntax table generated from them.
#include "grader/answer_type.hpp"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <regex>
#include <string>

#include "grader/answer_parser.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// The table under "## Answer syntax" in docs/answers.md, from its header row to its last row.
std::string docs_answer_table() {
  std::ifstream in(test::source_path("docs/answers.md"));
  std::string line, table;
  while (std::getline(in, line) && line.rfind("| type | answers (kind) |", 0) != 0) {
  }
  if (!in) return table;
  table = line + "\n";
  while (std::getline(in, line) && line.rfind("|", 0) == 0) table += line + "\n";
  return table;
}

TEST(AnswerTypes, DocsTableIsGeneratedFromTheTypes) {
  const std::string generated = answer_syntax_markdown(builtin_kinds());
  EXPECT_EQ(docs_answer_table(), generated)
      << "docs/answers.md's answer-syntax table differs from the answer types' rows; the table to "
         "paste (`frustum kinds --answer-syntax` prints it too):\n\n"
      << generated;
}

TEST(AnswerTypes, EachKindOfAnswerHasOneCompleteType) {
  const std::vector<AnswerType>& types = answer_types();
  ASSERT_EQ(types.size(), static_cast<std::size_t>(AnswerKind::Statements) + 1);
  for (std::size_t i = 0; i < types.size(); ++i) {
    const AnswerType& t = types[i];
    EXPECT_EQ(static_cast<std::size_t>(t.kind), i);
    EXPECT_FALSE(t.syntax.empty()) << i;
    EXPECT_TRUE(t.read && t.compare && t.quiz) << i;
    // What a platform's input needs: a hint to type by, or the words to choose from.
    if (t.input == TypedInput::Text) {
      EXPECT_NE(t.typed_hint, nullptr) << i;
    }
    if (t.input == TypedInput::Choice) {
      EXPECT_TRUE(t.choices && t.chosen) << i;
    }
  }
}

TEST(AnswerTypes, EveryAnswerOfEveryKindIsInExactlyOneRow) {
  int answers = 0;
  for (const KindInfo& k : builtin_kinds().all())
    for (const AnswerSpec& a : k.answers) {
      int rows = 0;
      for (const AnswerSyntax& row : answer_type(a.kind).syntax)
        rows += !row.covers || row.covers(a);
      EXPECT_EQ(rows, 1) << k.name << "." << a.name;
      ++answers;
    }
  EXPECT_GT(answers, 60);
}

// Every example of every row, read as an answer the row covers ("z: 8" gives the answer's name;
// a bare value is read as the row's first answer).
TEST(AnswerTypes, EveryExampleOfTheSyntaxIsRead) {
  int examples = 0;
  for (const AnswerType& t : answer_types())
    for (const AnswerSyntax& row : t.syntax) {
      const AnswerSpec* first = nullptr;
      for (const KindInfo& k : builtin_kinds().all())
        for (const AnswerSpec& a : k.answers)
          if (!first && a.kind == t.kind && (!row.covers || row.covers(a))) first = &a;
      ASSERT_NE(first, nullptr) << row.type << " covers no answer";
      const std::regex backticked("`([^`]+)`");
      for (auto m = std::sregex_iterator(row.examples.begin(), row.examples.end(), backticked);
           m != std::sregex_iterator(); ++m) {
        const std::string example = (*m)[1];
        YAML::Node node = YAML::Load(example);
        const AnswerSpec* spec = first;
        if (node.IsMap() && node.size() == 1 && example.find(": ") != std::string::npos &&
            example[0] != '{') {
          const std::string name = node.begin()->first.as<std::string>();
          for (const KindInfo& k : builtin_kinds().all())
            if (const AnswerSpec* a = k.answer(name); a && a->kind == t.kind) spec = a;
          node = node.begin()->second;  // "z: 8" → 8
        }
        const ParsedAnswer p = parse_answer(node, *spec, AngleUnit::Degrees);
        EXPECT_TRUE(p.ok) << row.type << ": `" << example << "`: " << p.error;
        ++examples;
      }
    }
  EXPECT_GE(examples, 20);
}

}  // namespace
}  // namespace frustum
