// The reviewed verdict corpus (docs/grading.md): tests/verdicts/*.yaml hold problems, each with
// cases of (a student's answers, the verdict a careful instructor gives each, the reason). One
// test reads them all and grades every case; a rule that changes a verdict changes the corpus.
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "grader/grade.hpp"
#include "solver/problem/registry.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

struct Expected {
  Verdict verdict;
  std::optional<double> credit;  // fraction of the answer's points
};

std::optional<Verdict> verdict_named(const std::string& word) {
  for (const Verdict v : {Verdict::Correct, Verdict::Incorrect, Verdict::Partial,
                          Verdict::Unparseable, Verdict::Missing})
    if (to_string(v) == word) return v;
  return std::nullopt;
}

// "correct", "partial 0.5": a verdict and, optionally, the credit.
std::optional<Expected> expected_of(const std::string& text) {
  std::istringstream in(text);
  std::string word;
  in >> word;
  const auto v = verdict_named(word);
  if (!v) return std::nullopt;
  Expected e{*v, std::nullopt};
  double credit = 0;
  if (in >> credit) e.credit = credit;
  return e;
}

std::string where(const std::string& file, const YAML::Node& n) {
  return file + ":" + std::to_string(n.Mark().line + 1);
}

TEST(VerdictCorpus, EveryCaseGetsTheInstructorsVerdict) {
  const std::filesystem::path dir =
      std::filesystem::path(FRUSTUM_SOURCE_DIR) / "tests" / "verdicts";
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".yaml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  std::size_t cases = 0;
  std::set<std::string> kinds;
  for (const std::string& file : files) {
    const YAML::Node root = YAML::LoadFile(file);
    const std::string kind = root["kind"].as<std::string>();
    kinds.insert(kind);
    for (const YAML::Node& problem : root["problems"]) {
      YAML::Node p = YAML::Clone(problem);
      p.remove("cases");
      p["id"] = "p";
      p["kind"] = kind;
      YAML::Node set;
      set["problems"].push_back(p);
      YAML::Emitter set_text;
      set_text << set;
      const ProblemSet s = load_problem_set_from_string(set_text.c_str(), file);
      ASSERT_TRUE(s.all_errors().empty())
          << where(file, problem) << ": " << s.all_errors()[0].format();
      const SolvedSet solved = solve_for_grading(s);
      for (const YAML::Node& c : problem["cases"]) {
        ++cases;
        const std::string at = where(file, c);
        const std::string reason = c["reason"] ? c["reason"].as<std::string>() : "";
        EXPECT_FALSE(reason.empty()) << at << ": every case says why";
        YAML::Node sub;
        sub["student"] = "corpus";
        sub["answers"]["p"] = c["answers"];
        YAML::Emitter sub_text;
        sub_text << sub;
        const GradeReport r = grade(s, load_submission_from_string(sub_text.c_str(), at), &solved);
        EXPECT_TRUE(r.errors.empty())
            << at << ": " << (r.errors.empty() ? "" : r.errors[0].format());
        const auto graded = [&](const std::string& name) -> const AnswerGrade* {
          for (const AnswerGrade& a : r.problems[0].answers)
            if (a.name == name) return &a;
          return nullptr;
        };
        for (auto it = c["expect"].begin(); it != c["expect"].end(); ++it) {
          const std::string name = it->first.as<std::string>();
          const auto e = expected_of(it->second.as<std::string>());
          ASSERT_TRUE(e) << at << ": bad expectation '" << it->second.as<std::string>() << "'";
          const AnswerGrade* a = graded(name);
          ASSERT_NE(a, nullptr) << at << ": " << name << " is not asked";
          EXPECT_EQ(to_string(a->verdict), to_string(e->verdict))
              << at << ": " << name << " = " << a->got_text << " (" << reason
              << "); feedback: " << a->feedback;
          if (e->credit) {
            EXPECT_NEAR(a->score / a->max_score, *e->credit, 1e-9)
                << at << ": " << name << " (" << reason << ")";
          }
        }
        for (auto it = c["mistake"].begin(); c["mistake"] && it != c["mistake"].end(); ++it) {
          const AnswerGrade* a = graded(it->first.as<std::string>());
          ASSERT_NE(a, nullptr) << at;
          EXPECT_EQ(a->misconception.en(), it->second.as<std::string>())
              << at << ": " << a->name << " (" << reason << ")";
        }
        // What the feedback says (a phrase it holds, one it must not hold: a form or a mistake
        // the student did not write), and the answer as shown (in the student's own form).
        for (const char* field : {"says", "never_says", "shown"})
          for (auto it = c[field].begin(); c[field] && it != c[field].end(); ++it) {
            const AnswerGrade* a = graded(it->first.as<std::string>());
            ASSERT_NE(a, nullptr) << at;
            const std::string text = it->second.as<std::string>();
            const std::string& in = std::string(field) == "shown" ? a->got_text : a->feedback.en();
            if (std::string(field) == "shown") {
              EXPECT_EQ(in, text) << at << ": " << a->name << " (" << reason << ")";
            } else {
              EXPECT_EQ(in.find(text) != std::string::npos, std::string(field) == "says")
                  << at << ": " << a->name << " " << field << " '" << text << "' (" << reason
                  << "); feedback: " << in;
            }
          }
        for (const YAML::Node& n : c["carried"]) {
          const AnswerGrade* a = graded(n.as<std::string>());
          ASSERT_NE(a, nullptr) << at;
          EXPECT_TRUE(a->carried_forward) << at << ": " << a->name << " (" << reason << ")";
        }
      }
    }
  }
  EXPECT_GE(cases, 300u) << "the corpus keeps at least 300 reviewed cases";
  for (const std::string& k : builtin_kinds().names())
    EXPECT_TRUE(kinds.count(k)) << "no corpus file for kind " << k;
}

}  // namespace
}  // namespace frustum
