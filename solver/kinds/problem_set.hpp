// Loading a problem set (problem-format.md §1): conventions, tolerance defaults, problems with
// `ask`, `points` and `given`. Loading never throws: every mistake becomes a Diagnostic on the
// set or on its problem, and one broken problem never stops the rest.
#pragma once

#include "solver/kinds/kind.hpp"
#include "solver/util/diagnostic.hpp"

#include <yaml-cpp/yaml.h>

#include <any>
#include <optional>
#include <string>
#include <vector>

namespace frustum {

// Grading defaults (problem-format.md: relative 1e-3 like WeBWorK, with an absolute floor).
inline constexpr double kRelTolDefault = 1e-3;
inline constexpr double kAbsTolDefault = 1e-6;

struct Tolerance {
  double rel = kRelTolDefault;
  double abs = kAbsTolDefault;
};

struct ProblemSpec {
  std::string id;
  std::string kind;
  std::string text;
  Conventions conventions;
  Tolerance tolerance;
  std::vector<std::string> ask;   // every answer of the kind when the file has no `ask`
  std::optional<double> points;   // total weight; default 1 per asked answer
  SourceLocation where;           // the problem's mapping
  std::string field;              // "problems[2]"
  const KindInfo* info = nullptr;
  std::any given;                 // the kind's parsed Given
  YAML::Node given_node;
  std::optional<Diagnostic> error;

  double max_score() const { return points ? *points : static_cast<double>(ask.size()); }
};

struct ProblemSet {
  std::string file;
  std::string title;
  Conventions conventions;
  Tolerance tolerance;
  std::vector<ProblemSpec> problems;
  std::vector<Diagnostic> errors;  // of the file as a whole

  const ProblemSpec* find(const std::string& id) const;
  // Every diagnostic: the file's and each problem's.
  std::vector<Diagnostic> all_errors() const;
};

ProblemSet load_problem_set(const std::string& path);
// `name` stands for the file in messages.
ProblemSet load_problem_set_from_string(const std::string& yaml, const std::string& name);

// Reads `conventions:` / `tolerance:` mappings (also used by the answer loader).
Conventions read_conventions(const YAML::Node& n, const std::string& file,
                             const std::string& field, Conventions base);
Tolerance read_tolerance(const YAML::Node& n, const std::string& file, const std::string& field,
                         Tolerance base);

}  // namespace frustum
