// Grading a whole class: every submission in a directory of answer files (or every row of a
// CSV roster) against one problem set, each in an isolated child process under a time limit,
// with a CSV gradebook, per-student feedback (Markdown and self-contained HTML) and Gradescope
// results.json files written atomically. A broken, empty, huge or slow submission gets its own
// error row; the batch always finishes and the gradebook lists every submission.
#pragma once

#include "grader/grade.hpp"
#include "solver/derivation/i18n.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace frustum {

constexpr double kBatchTimeoutDefault = 10.0;                  // seconds per submission
constexpr std::size_t kMaxSubmissionBytes = 1u << 20;          // 1 MiB of answers per student

// One submission, before grading.
struct BatchEntry {
  std::string source;   // the file, or "roster.csv row 12"
  std::string student;  // from the answers, the CSV, or the file name
  std::string yaml;     // the answers as YAML text (CSV rows are converted)
  std::optional<std::string> error;  // could not be read at all (too big, unreadable)
};

// Answer files (*.yaml, *.yml) directly in a directory, in name order; or the rows of a CSV
// whose header has `student` and one column per answer named `problem-id.answer`.
// Throws InputError for a path that is neither, or a CSV without a `student` column.
std::vector<BatchEntry> collect_submissions(const std::string& path,
                                            std::size_t max_bytes = kMaxSubmissionBytes);

struct BatchOptions {
  std::string out_dir = "grades";
  double timeout_seconds = kBatchTimeoutDefault;
  Lang lang = Lang::En;
  // The set a student is graded against (per-student variants); the set itself when empty.
  std::function<ProblemSet(const ProblemSet& set, const std::string& student, std::string& variant)> set_for;
  // Called after each submission: how many are done, of how many, and whose it was.
  std::function<void(std::size_t done, std::size_t total, const std::string& student)> on_progress;
};

struct BatchRow {
  std::string student;
  std::string source;
  std::string status;   // graded, error, timeout, crashed
  std::string message;  // why it is not graded, or the first problem with the answers file
  double score = 0;
  double max_score = 0;
  std::vector<double> problem_scores;  // in the set's order (graded rows)
  std::string feedback_stem;           // feedback/<stem>.md|.html, gradescope/<stem>.json
};

struct BatchResult {
  std::vector<BatchRow> rows;  // in input order
  std::vector<std::string> files_written;
};

// Grades and writes every output under options.out_dir:
//   gradebook.csv, feedback/<student>.md, feedback/<student>.html, gradescope/<student>.json
BatchResult grade_batch(const ProblemSet& set, const std::vector<BatchEntry>& entries, const BatchOptions& options);

// The gradebook's CSV text (header + one row per submission).
std::string gradebook_csv(const ProblemSet& set, const std::vector<BatchRow>& rows);

}  // namespace frustum
