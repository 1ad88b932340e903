// What the authoring page shows of a set as its author writes it: `check`'s errors and warnings
// at their lines and columns, each sample answer graded against the key, and for every problem
// its statement as students read it in each of the set's languages, its givens and answer key
// typeset, its derivation and its figure — of the set itself or of one student's variant.
// Made from text no one has checked, so the server runs it in a child process (`frustum
// author-preview`), bounded in time and output: a hostile set costs that process only.
#pragma once

#include <string>
#include <vector>

namespace frustum::server {

// A set an author edits in the browser: many times the largest bundled set, far below what
// would make a request slow to receive.
inline constexpr std::size_t kMaxAuthoredSetBytes = 1024 * 1024;

struct AuthorPreviewRequest {
  std::string yaml;
  std::string name;                 // the set's file name, for errors ("week1.yaml")
  std::vector<std::string> roster;  // the class, whose variants `generate --roster` draws
  std::string student;              // whose variant to show; "" for the set as written
  bool check_only = false;          // errors and samples only (what a save needs)
};

// The preview as JSON: {ok, errors: [{line, column, field, message}], warnings, samples:
// [{problem, field, line, expected, verdict, credit, ok, message}], langs, student,
// student_error, problems: [{id, kind, texts: [{lang, text}], given: [{name, tex, plain}],
// key: [{name, html}], derivation_html, figure_svg, error}]}.
std::string author_preview_json(const AuthorPreviewRequest& request);

}  // namespace frustum::server
