// Grading a whole class: every submission in a directory of answer files (or every row of a
// CSV roster) against one problem set, each in an isolated child process under a time limit,
// with a CSV gradebook, per-student feedback (Markdown and HTML pages that share one copy of
// KaTeX in the output directory, which works offline as a whole) and Gradescope results.json
// files written atomically. A broken, empty, huge or slow submission gets its own
// error row; the batch always finishes and the gradebook lists every submission.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grader/grade.hpp"
#include "solver/derivation/i18n.hpp"

namespace frustum {

constexpr double kBatchTimeoutDefault = 10.0;          // seconds per submission
constexpr double kMaxBatchTimeout = 3600.0;            // an hour for one submission
constexpr std::size_t kMaxSubmissionBytes = 1u << 20;  // 1 MiB of answers per student

constexpr std::size_t kMaxRosterBytes = 64u << 20;  // a CSV roster of answers
// The answers files a CSV roster becomes, all rows together: each names its answers by the
// header's column names, so a long header repeated on every row could make gigabytes of a
// 64 MiB file (a row's own file is at most max_bytes, kMaxSubmissionBytes).
constexpr std::size_t kMaxRosterAnswerBytes = 256u << 20;

// One submission, before grading.
struct BatchEntry {
  std::string source;   // the file, or "roster.csv row 12"
  std::string student;  // from the answers, the CSV, or the file name
  std::string claimed;  // the id the answers file states ("" if none or unreadable)
  std::string yaml;     // the answers as YAML text (CSV rows are converted)
  // A file of a directory is not kept in memory (a class's files would all be, and memory would
  // grow with the size of the answers, not only with the class): `yaml` stays empty, and the
  // file is read again when it is graded. `length` and `digest` are those of the text its id
  // was read from; a file that no longer has them is an error row (it changed while the class
  // was graded), never graded under an id read from other text.
  bool read_when_graded = false;
  std::size_t length = 0;
  std::uint64_t digest = 0;
  std::optional<std::string> error;  // could not be read at all (too big, unreadable)
  // A CSV row: where each answer ("answers.ID.NAME") was in the CSV (line, column), so that
  // messages point at the cell, not at the YAML the row was converted to.
  std::string csv_file;
  std::map<std::string, std::pair<int, int>> cells;
  // Set by apply_roster: `student` is the roster's id, not the file's claim, and `note` says
  // where they disagree.
  bool from_roster = false;
  std::string note;
};

// The digest BatchEntry keeps of a file's text (a change detector, not a cryptographic hash).
std::uint64_t text_digest(std::string_view text);
// A submission's answers text: `yaml`, or the file read again (read_when_graded); throws
// std::runtime_error when it cannot be read or is not the text its id was read from.
std::string submission_text(const BatchEntry& e);

// Answer files (*.yaml, *.yml) directly in a directory, in name order; or the rows of a CSV
// whose header has `student` and one column per answer named `problem-id.answer`. A file that
// cannot be read (a symlink loop, a FIFO, too big) is an entry with its error. Every id is read
// by read_student_id: one it refuses (empty, a control character, not UTF-8) makes its file or
// row an error entry with no student, located at the id. Two files (or rows) that claim the
// same student — the same student_id_key — are both graded, and each one's note names the
// others.
// Everything else in the directory that is not hidden (other files, subdirectories) is not
// graded: `not_graded`, when given, receives a located line for each, so nothing a student
// handed in is passed over in silence.
// Throws InputError for a path that is neither, an unreadable directory, or a CSV without a
// `student` column (located in the CSV: line and column).
// The files of a directory are read and their ids parsed one after another, in the calling
// thread (so that grade_batch's children are forked from a single-threaded process). The id is
// what a file
// states under `student:`, read up to that value only (top_scalar): a file whose answers below
// it are broken is still that student's (an error row under their id).
std::vector<BatchEntry> collect_submissions(const std::string& path,
                                            std::size_t max_bytes = kMaxSubmissionBytes,
                                            std::vector<Diagnostic>* not_graded = nullptr);

// The roster is the authority for who a file belongs to: the answers of roster id R are the
// file file_name_for(R).yaml (or .yml) in the directory, whatever its `student:` says (a file
// that claims another id is graded as R and the row says so). A roster id without a file is an
// error row; a file that no roster id names is an error row "not on the roster". Rows follow
// the roster's order, then the files not on it.
std::vector<BatchEntry> apply_roster(std::vector<BatchEntry> entries,
                                     const std::vector<std::string>& roster,
                                     const std::string& roster_file);

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

struct BatchOptions {
  std::string out_dir = "grades";
  double timeout_seconds = kBatchTimeoutDefault;
  Lang lang = Lang::En;
  // Child processes grading at once (each a contiguous share of the class); 0: one per core.
  // The outputs are the same bytes whatever the number.
  std::size_t jobs = 0;
  // The set a student is graded against (per-student variants); the set itself when empty.
  std::function<ProblemSet(const ProblemSet& set, const std::string& student, std::string& variant)>
      set_for;
  // Called after each submission: how many are done, of how many, and whose it was.
  std::function<void(std::size_t done, std::size_t total, const std::string& student)> on_progress;
  // Each row once it is final, in the class's order (the gradebook's), while the class is graded.
  std::function<void(const BatchRow&)> on_row;
  // Whether BatchResult::rows keeps every row. A caller that takes the rows through on_row and
  // keeps none holds memory that does not grow with the class but for its list of files.
  bool keep_rows = true;
};

struct BatchResult {
  std::vector<BatchRow> rows;  // in input order (when BatchOptions::keep_rows)
  // Files and directories in the output directory that Frustum did not write, moved to
  // out_dir/set-aside/ instead of being deleted: (where they were, where they are now).
  std::vector<std::pair<std::string, std::string>> set_aside;
};

// Classes of kWriteBackClass students or more are written back to disk while they are graded
// (OutputTransaction::write_back: the disk writes, nothing is published): after each eighth of
// the class, then when fewer than a sixteenth, a thirty-second and a sixty-fourth are left, so
// that the sync before publishing, with every core idle, has about a sixty-fourth of the files
// to write, not an eighth. write_back_due says whether the row that made `done` rows of a class
// of `n` is such a point.
inline constexpr std::size_t kWriteBackClass = 64;
inline constexpr std::size_t kWriteBacks = 8;
inline constexpr std::size_t kLastWriteBack = 64;
bool write_back_due(std::size_t done, std::size_t n);

// Grades and writes every output under options.out_dir as one transaction (OutputTransaction:
// locked, staged, published by one rename):
//   gradebook.csv, feedback/<file>.md, feedback/<file>.html, gradescope/<file>.json,
//   katex/ (KaTeX's script, stylesheet and fonts, linked by the HTML pages as ../katex/)
// with <file> = unique_file_names of the student ids (the gradebook's `file` column). Never
// aborts on a submission: every failure is that student's row. Throws std::runtime_error only
// when the outputs cannot be written at all (not writable, locked by another batch, disk
// full); the previous outputs are then unchanged.
BatchResult grade_batch(const ProblemSet& set, const std::vector<BatchEntry>& entries,
                        const BatchOptions& options);

}  // namespace frustum
