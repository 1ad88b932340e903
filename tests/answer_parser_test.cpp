// The symbols a student may write before `=` for each answer (AnswerSpec::symbols, the ones
// the derivations use: "D_f = 27", "s = −415.7"), as docs/grading.md §1 lists them: the table
// is generated here from the kinds, so the document cannot drift; and each symbol is read.
#include "grader/answer_parser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

std::string symbols_table() {
  std::string table = "| kind | answer: symbols besides its name |\n| --- | --- |\n";
  for (const KindInfo& kind : builtin_kinds().all()) {
    std::string row;
    for (const AnswerSpec& a : kind.answers) {
      if (a.symbols.empty()) continue;
      std::string list;
      for (const std::string& s : a.symbols) list += (list.empty() ? "" : ", ") + s;
      row += (row.empty() ? "" : "; ") + ("`" + a.name + "`: " + list);
    }
    if (!row.empty()) table += "| " + kind.name + " | " + row + " |\n";
  }
  return table;
}

std::string documented_table() {
  std::ifstream in(test::source_path("docs/grading.md"));
  std::string line, table;
  while (std::getline(in, line) && line.rfind("| kind | answer: symbols", 0) != 0) {
  }
  if (!in) return table;
  table = line + "\n";
  while (std::getline(in, line) && line.rfind("|", 0) == 0) table += line + "\n";
  return table;
}

TEST(AnswerSymbols, DocsListEverySymbolOfEveryAnswer) {
  const std::string generated = symbols_table();
  EXPECT_EQ(documented_table(), generated)
      << "docs/grading.md's table of answer symbols differs from the kinds' AnswerSpecs; the "
         "table to paste:\n\n"
      << generated;
}

// Every symbol, in its ASCII spelling too, is read before `=`; a name that is none of them is
// not (the answer is then unreadable, never judged under another name).
TEST(AnswerSymbols, EverySymbolIsReadBeforeEquals) {
  for (const KindInfo& kind : builtin_kinds().all())
    for (const AnswerSpec& a : kind.answers)
      for (const std::string& s : a.symbols) {
        const bool scalar = a.kind == AnswerKind::Scalar || a.kind == AnswerKind::Angle;
        const std::string value = scalar ? "2" : "(1, 2, 3)";
        const ParsedAnswer p = parse_answer(YAML::Node(s + " = " + value), a, AngleUnit::Degrees);
        if (a.kind == AnswerKind::Transform) continue;  // a matrix is no one-line text
        EXPECT_TRUE(p.ok) << kind.name << "." << a.name << ": " << s << ": " << p.error;
      }
  AnswerSpec df{.name = "df", .kind = AnswerKind::Scalar, .symbols = {"D_f"}};
  for (const char* written : {"D_f = 27", "Df = 27", "D_{f} = 27", "d_f=27", "df = 27"}) {
    const ParsedAnswer p = parse_answer(YAML::Node(written), df, AngleUnit::Degrees);
    ASSERT_TRUE(p.ok) << written << ": " << p.error;
    EXPECT_EQ(p.value.numbers[0], 27) << written;
  }
  EXPECT_FALSE(parse_answer(YAML::Node("D = 27"), df, AngleUnit::Degrees).ok);
  EXPECT_FALSE(parse_answer(YAML::Node("n = 27"), df, AngleUnit::Degrees).ok);
}

// A number times a tuple is read as the vector it means, and bounded like any expression.
TEST(AnswerForms, ScalarTimesTupleIsTheVector) {
  const AnswerSpec u{.name = "unit_normal", .kind = AnswerKind::UnitVector};
  for (const char* written : {"(1/√21)(−2, 1, 4)", "1/sqrt(21)*(-2,1,4)", "(-2,1,4)/sqrt(21)"}) {
    const ParsedAnswer p = parse_answer(YAML::Node(written), u, AngleUnit::Degrees);
    ASSERT_TRUE(p.ok) << written << ": " << p.error;
    ASSERT_EQ(p.value.numbers.size(), 3u) << written;
    EXPECT_NEAR(p.value.numbers[0], -2 / std::sqrt(21.0), 1e-15) << written;
    EXPECT_NEAR(p.value.numbers[2], 4 / std::sqrt(21.0), 1e-15) << written;
  }
  EXPECT_FALSE(parse_answer(YAML::Node("(6, 3, 2)/0"), u, AngleUnit::Degrees).ok);
  EXPECT_FALSE(parse_answer(YAML::Node("(6, 3, 2) + 7"), u, AngleUnit::Degrees).ok);
  EXPECT_FALSE(parse_answer(YAML::Node("2^2^2^2^2^2^2^2^2(1, 2, 3)"), u, AngleUnit::Degrees).ok);
}

}  // namespace
}  // namespace frustum
