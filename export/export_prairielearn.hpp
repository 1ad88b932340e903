// A problem set as PrairieLearn questions: one question directory per problem, each with
// info.json (v3, external grading by Frustum's image), question.html (pl-string-input for
// numbers, vectors, matrices, points, planes, bit strings and label lists, read by Frustum so
// exact forms and `none` are accepted, with the accepted window stated; pl-multiple-choice for
// words and true/false; pl-checkbox for true statements, with a "none is true" option; the
// feedback as HTML in the submission panel and the derivation in the answer panel) and
// server.py, whose generate() picks one of the variants Frustum drew, puts that variant's
// one-problem set and language in params and its key in correct_answers;
// tools/prairielearn/frustum-pl-grade grades it with `frustum grade --prairielearn`.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "solver/problem/problem_set.hpp"

namespace frustum {

struct PrairieLearnOptions {
  // The grader image (built from tools/prairielearn/Dockerfile) as PrairieLearn pulls it:
  // ACCOUNT/NAME:TAG on Docker Hub (or a registry's host/path); no default, since a name only
  // the instructor's machine knows cannot be pulled.
  std::string image;
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

// The input element an answer is entered with: string (text Frustum reads), choice or checkbox.
std::string prairielearn_input(const AnswerSpec& spec);

}  // namespace frustum
