// A problem set as PrairieLearn questions: one question directory per problem, each with
// info.json (v3, external grading by Frustum's image), question.html (pl-number-input for
// numbers, pl-matrix-input for vectors and matrices, pl-multiple-choice for words and true/false,
// pl-string-input for planes, bit strings and label lists, pl-external-grader-results for the
// feedback) and server.py, whose generate() picks one of the variants Frustum drew and puts that
// variant's one-problem set in params; tools/prairielearn/frustum-pl-grade grades it with
// `frustum grade --prairielearn`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "solver/problem/problem_set.hpp"

namespace frustum {

struct PrairieLearnOptions {
  std::string image = "frustum-prairielearn";  // built from tools/prairielearn/Dockerfile
  std::string entrypoint = "/usr/local/bin/frustum-pl-grade";
  int timeout = 30;      // seconds per grading job
  Lang lang = Lang::En;  // the questions' texts (the set's own where not given)
};

// Question directory name → file name → contents. `source_root` is the set file's YAML (its
// fields are kept in each one-problem set); `variants` holds at least one drawn set (or the set
// itself when nothing varies).
std::map<std::string, std::map<std::string, std::string>> export_prairielearn(
    const YAML::Node& source_root, const ProblemSet& set, const std::vector<ProblemSet>& variants,
    const std::string& stem, const PrairieLearnOptions& options = {});

// The input element an answer is entered with: number, vector, matrix, choice or string.
std::string prairielearn_input(const AnswerSpec& spec);

}  // namespace frustum
