// Grading a student's answer file against a problem set: parse → compare → verdict, per
// answer, with the derivation kept for every wrong answer. A broken answer or problem is
// reported and never stops the rest.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "grader/compare.hpp"
#include "grader/trivial.hpp"
#include "solver/derivation/problem_result.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {

struct Submission {
  std::string file;
  std::string student;
  YAML::Node answers;  // id → {answer name → value}
  std::vector<Diagnostic> errors;
};

Submission load_submission(const std::string& path);
Submission load_submission_from_string(const std::string& yaml, const std::string& name);

struct AnswerGrade {
  std::string name;
  Verdict verdict = Verdict::Missing;
  double score = 0;
  double max_score = 0;
  Value expected;
  std::optional<Value> got;  // parsed
  std::string got_text;      // as written
  Said feedback;
  Said misconception;            // the common mistake the answer matches, if any
  Said wrong_step;               // the derivation step where that mistake happens
  bool carried_forward = false;  // credit given for following the student's earlier answer
  std::vector<Step> derivation;  // the steps that lead to this answer, for wrong answers
};

struct ProblemGrade {
  std::string id;
  std::string kind;
  double score = 0;
  double max_score = 0;
  std::vector<AnswerGrade> answers;
  std::optional<Diagnostic> error;  // the problem itself could not be solved
};

struct GradeReport {
  std::string set_file;
  std::string answers_file;
  std::string student;
  // Which generated variant was graded, when the set varies per student: the instructor's note
  // (terminal and JSON reports, the gradebook); feedback a student reads leaves it out, since it
  // names the instructor's files.
  std::string variant;
  double score = 0;
  double max_score = 0;
  std::vector<ProblemGrade> problems;
  std::vector<Diagnostic> errors;  // of the set or the answer file, and unknown ids
};

// What judging a problem's answers needs besides the key, made once per problem: the kind's
// scales and each answer's trivial answers (trivial.hpp).
struct ProblemJudging {
  AnswerScales scales;
  std::vector<std::pair<std::string, std::vector<TrivialAnswer>>> trivial;
  std::vector<AlsoRight> also_right;  // answers as right as the key's (KindInfo::also_right)
  AnswerRules rules(const ProblemSpec& spec, const std::string& name) const;
};
ProblemJudging prepare_judging(const ProblemSpec& spec, const Answers& key);

// The set solved once (with derivations), to grade many submissions against: results[i] is
// set.problems[i]'s.
struct SolvedSet {
  std::vector<ProblemResult> results;
  std::vector<std::vector<Misconception>> mistakes;  // what common mistakes give, per problem
  std::vector<ProblemJudging> judging;               // per problem
};
SolvedSet solve_for_grading(const ProblemSet& set);

// Grades one submission; `solved` (from solve_for_grading on the same set) saves solving the
// set again for every student of a class.
GradeReport grade(const ProblemSet& set, const Submission& submission,
                  const SolvedSet* solved = nullptr);

}  // namespace frustum
