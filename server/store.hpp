// What `frustum serve` keeps: students (by the hash of their link's token), sessions, drafts,
// submissions and their grades. One interface, two implementations (SQLite, PostgreSQL) held to
// the same conformance tests. Times come from the caller; no process-wide state.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace frustum::server {

using Millis = std::int64_t;  // ms since the epoch

// A store that cannot be opened, migrated or written; the message says which and why.
class StoreError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Who a link and its session belong to: a student on the roster, or an instructor of the
// course (instructors.csv), who sees the whole class and never a student's page.
enum class Role { Student, Instructor };

struct SessionRecord {
  std::string student;  // the id (an instructor's, for an instructor's session)
  std::string csrf;
  Millis expires = 0;
  Role role = Role::Student;
};

struct Draft {
  std::string set, problem, answer, text;
  Millis saved = 0;
};

struct NewSubmission {
  std::string student, set;
  std::string set_version;  // sha-256 hex of the set file
  std::string variant;      // the variant's seed (empty: the set as written)
  std::string problem;
  std::string answers;  // JSON object: answer name → text as written
  Millis received = 0;
};

enum class SubmissionState { Pending, Graded, Failed };

struct SubmissionRecord : NewSubmission {
  std::int64_t id = 0;
  int attempt = 0;  // 1, 2, … per (student, set, problem)
  SubmissionState state = SubmissionState::Pending;
  int claims = 0;  // times claimed, this claim included (a worker gives up on one that keeps
                   // killing its graders)
};

struct GradeRecord {  // many per submission (regrades keep history)
  std::int64_t submission = 0;
  std::string result;  // JSON of the problem's grade
  double score = 0, max_score = 0;
  std::string set_version, graded_by;
  Millis graded = 0;
  bool failed = false;  // grading itself failed (time limit, crash): the submission is Failed
};

class Store {
 public:
  virtual ~Store() = default;
  virtual int schema_version() = 0;

  // Students. The token is never stored, only its sha-256 hex; putting a student again
  // replaces the hash (the old link stops working).
  virtual void put_student(const std::string& id, const std::string& token_hash) = 0;
  virtual std::optional<std::string> student_by_token(const std::string& token_hash) = 0;
  virtual std::vector<std::string> students() = 0;  // every student with a token, sorted
  // Instructors, the same way (an id is a student's or an instructor's, never both).
  virtual void put_instructor(const std::string& id, const std::string& token_hash) = 0;
  virtual std::optional<std::string> instructor_by_token(const std::string& token_hash) = 0;
  virtual std::vector<std::string> instructors() = 0;

  virtual void put_session(const std::string& session_hash, const SessionRecord&) = 0;
  virtual std::optional<SessionRecord> session(const std::string& session_hash, Millis now) = 0;

  virtual void save_draft(const std::string& student, const Draft&) = 0;  // last write wins
  virtual std::vector<Draft> drafts(const std::string& student, const std::string& set) = 0;

  // Durable (committed) when it returns; attempt numbered per (student, set, problem).
  virtual SubmissionRecord submit(const NewSubmission&) = 0;
  // Pending submissions for `worker`, oldest first: one whose earlier claim's lease ran out,
  // alone (it may be the one that killed its grader: it must not take others down with it),
  // or else up to `max` that nobody has claimed. Each claim counts in `claims`.
  virtual std::vector<SubmissionRecord> claim_some(const std::string& worker, Millis now,
                                                   Millis lease, std::size_t max) = 0;
  std::optional<SubmissionRecord> claim(const std::string& worker, Millis now, Millis lease);
  // Claims given back unworked (a worker out of time for its batch): pending and unclaimed
  // again, this claim not counted. Only this worker's own pending claims are touched.
  virtual void release(const std::vector<std::int64_t>& submissions, const std::string& worker) = 0;
  // The grades of claimed submissions, in one transaction; each written only if its submission
  // is still this worker's claim and not graded — so a submission is graded exactly once.
  // Returns, per grade, whether it was written.
  virtual std::vector<bool> record_grades(const std::vector<GradeRecord>&,
                                          const std::string& worker) = 0;
  bool record_grade(const GradeRecord& g, const std::string& worker);

  // A student's own submissions to a set, oldest first; one by id only if it is theirs.
  virtual std::vector<SubmissionRecord> submissions(const std::string& student,
                                                    const std::string& set) = 0;
  virtual std::optional<SubmissionRecord> submission(const std::string& student,
                                                     std::int64_t id) = 0;
  virtual std::optional<GradeRecord> latest_grade(std::int64_t submission) = 0;
  virtual std::int64_t pending_count() = 0;

  // The instructor's reads of a whole class: every submission to a set (oldest first, at most
  // `limit`), the latest grade of each (by submission), and a submission's every grade, oldest
  // first (regrades keep the ones before).
  virtual std::vector<SubmissionRecord> set_submissions(const std::string& set,
                                                        std::size_t limit) = 0;
  virtual std::vector<GradeRecord> latest_grades(const std::string& set) = 0;
  virtual std::vector<GradeRecord> grade_history(std::int64_t submission) = 0;
  // A regrade: every grade written in one transaction, each submission marked by its grade
  // (graded or failed); all or nothing.
  virtual void record_regrades(const std::vector<GradeRecord>& grades) = 0;
  // A number that grows whenever a submission or a grade is written (by any instance).
  virtual std::int64_t change_mark() = 0;
  // Waits until change_mark() differs from `mark` or `timeout` passes; returns the mark then.
  // This one asks every quarter second; PostgreSQL's is woken by NOTIFY from any instance.
  virtual std::int64_t wait_for_change(std::int64_t mark, Millis timeout);
};

// Who opens a store. A grading worker's own writes (claims, grades) may be made durable less
// eagerly: one lost in a power failure leaves its submission pending, to be graded again (and
// still once). Submissions are always committed durably.
enum class StoreRole { Server, Worker };

// "sqlite:PATH" or "postgresql://…"; applies the embedded, numbered, forward-only migrations
// under a lock (exactly one of N instances starting at once migrates) and refuses a database
// whose schema is newer than the binary, with a clear error (StoreError).
std::unique_ptr<Store> open_store(const std::string& url, StoreRole role = StoreRole::Server);

// The schema version this binary's migrations reach (both stores share the numbering).
int latest_schema_version();

}  // namespace frustum::server
