// Every declared dependency of every kind (AnswerSpec::depends_on) and whether the kind
// recomputes the answer from the student's own earlier value (error carried forward), as
// docs/grading.md lists them: the list is generated here from the kinds and the document must
// match it, so it cannot drift. Each recomputation is checked on the first problem of the
// kind's verdict corpus: from the key's own earlier answers it gives the key.
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <string>

#include "grader/grade.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// The corpus's first problem of a kind, as a one-problem set.
ProblemSet corpus_problem(const std::string& kind) {
  const YAML::Node root = YAML::LoadFile(test::source_path("tests/verdicts/" + kind + ".yaml"));
  YAML::Node p = YAML::Clone(root["problems"][0]);
  p.remove("cases");
  p["id"] = "p";
  p["kind"] = kind;
  YAML::Node set;
  set["problems"].push_back(p);
  YAML::Emitter out;
  out << set;
  return load_problem_set_from_string(out.c_str(), kind + ".yaml");
}

// The dependencies' table of docs/grading.md, and whether each answer is recomputed.
std::string dependencies_table() {
  std::string table =
      "| kind | answer | computed from | carried credit (recomputed from the student's own "
      "value) |\n| --- | --- | --- | --- |\n";
  for (const KindInfo& kind : builtin_kinds().all()) {
    std::optional<ProblemSet> set;
    std::optional<ProblemResult> solved;
    for (const AnswerSpec& a : kind.answers) {
      if (a.depends_on.empty()) continue;
      if (!set) {
        set = corpus_problem(kind.name);
        EXPECT_TRUE(set->all_errors().empty()) << kind.name;
        solved = solve_for_grading(*set).results[0];
      }
      bool recomputed = false;
      if (kind.carry_forward && !solved->error) {
        Answers inputs;
        for (const std::string& d : a.depends_on)
          if (const Value* v = solved->answers.find(d)) inputs.set(d, *v);
        const Answers carried = kind.carry_forward(set->problems[0].given, inputs);
        if (const Value* v = carried.find(a.name)) {
          recomputed = true;
          // From the key's own earlier answers, the recomputation is the key.
          const ProblemJudging judging = prepare_judging(set->problems[0], solved->answers);
          AnswerRules rules = judging.rules(set->problems[0], a.name);
          EXPECT_EQ(compare(*solved->answers.find(a.name), *v, rules).verdict, Verdict::Correct)
              << kind.name << "." << a.name;
        }
      }
      std::string from;
      for (const std::string& d : a.depends_on) from += (from.empty() ? "`" : ", `") + d + "`";
      table += "| " + kind.name + " | `" + a.name + "` | " + from + " | " +
               (recomputed ? "yes" : "no: only a named mistake is recognised") + " |\n";
    }
  }
  return table;
}

std::string documented_table() {
  std::ifstream in(test::source_path("docs/grading.md"));
  std::string line, table;
  while (std::getline(in, line) && line.rfind("| kind | answer | computed from |", 0) != 0) {
  }
  if (!in) return table;
  table = line + "\n";
  while (std::getline(in, line) && line.rfind("|", 0) == 0) table += line + "\n";
  return table;
}

TEST(GraderDependencies, DocsListEveryDependencyOfEveryKind) {
  const std::string generated = dependencies_table();
  EXPECT_EQ(documented_table(), generated)
      << "docs/grading.md's table of dependencies differs from the kinds' AnswerSpecs and "
         "carry_forward; the table to paste:\n\n"
      << generated;
}

}  // namespace
}  // namespace frustum
