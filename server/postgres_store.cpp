#include "server/postgres_store.hpp"

#include <algorithm>
#include <charconv>
#include <condition_variable>
#include <mutex>
#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "server/postgres_connection.hpp"

namespace frustum::server {

namespace {

constexpr const char* kSubmissionColumns =
    "id, student, set_id, set_version, variant, problem, answers, received, attempt, state, "
    "claims";

// Every statement, prepared on each connection when it opens. Orders use the C collation so
// that both stores sort alike, whatever the database's locale.
const std::pair<const char*, std::string> kStatements[] = {
    {"schema_version", "SELECT coalesce(max(version), 0) FROM schema_migrations"},
    {"put_person",
     "INSERT INTO students (id, token_hash, role) VALUES ($1, $2, $3) "
     "ON CONFLICT (id) DO UPDATE SET token_hash = excluded.token_hash, role = excluded.role"},
    {"person_by_token", "SELECT id FROM students WHERE token_hash = $1 AND role = $2"},
    {"people", "SELECT id FROM students WHERE role = $1 ORDER BY id COLLATE \"C\""},
    {"put_session",
     "INSERT INTO sessions (hash, student, csrf, expires, role) VALUES ($1, $2, $3, $4, $5) "
     "ON CONFLICT (hash) DO UPDATE SET student = excluded.student, csrf = excluded.csrf, "
     "expires = excluded.expires, role = excluded.role"},
    {"session",
     "SELECT student, csrf, expires, role FROM sessions WHERE hash = $1 AND expires > $2"},
    {"save_draft",
     "INSERT INTO drafts (student, set_id, problem, answer, text, saved) "
     "VALUES ($1, $2, $3, $4, $5, $6) ON CONFLICT (student, set_id, problem, answer) "
     "DO UPDATE SET text = excluded.text, saved = excluded.saved "
     "WHERE excluded.saved >= drafts.saved"},
    {"drafts",
     "SELECT set_id, problem, answer, text, saved FROM drafts WHERE student = $1 AND set_id = $2 "
     "ORDER BY problem COLLATE \"C\", answer COLLATE \"C\""},
    // One statement, committed when it returns; the attempt comes from the row of `attempts`,
    // locked by the upsert until the commit, so submissions at once are numbered in turn.
    {"submit",
     "WITH next AS (INSERT INTO attempts AS a (student, set_id, problem, last) "
     "VALUES ($1, $2, $5, 1) ON CONFLICT (student, set_id, problem) "
     "DO UPDATE SET last = a.last + 1 RETURNING last) "
     "INSERT INTO submissions (student, set_id, set_version, variant, problem, answers, "
     "received, attempt) SELECT $1, $2, $3, $4, $5, $6, $7, last FROM next "
     "RETURNING id, attempt"},
    // A pending submission whose holder's lease ran out, alone; else up to $4 that nobody
    // holds, oldest first. Rows another instance is claiming this instant are skipped, not
    // waited for.
    {"reclaim",
     std::string("UPDATE submissions SET claimed_by = $1, claimed_at = $2, claims = claims + 1 "
                 "WHERE id = (SELECT id FROM submissions WHERE state = 0 AND claimed_by IS NOT "
                 "NULL AND claimed_at <= $3 ORDER BY id LIMIT 1 FOR UPDATE SKIP LOCKED) "
                 "RETURNING ") +
         kSubmissionColumns},
    {"claim",
     std::string("UPDATE submissions SET claimed_by = $1, claimed_at = $2, claims = claims + 1 "
                 "WHERE id IN (SELECT id FROM submissions WHERE state = 0 AND claimed_by IS NULL "
                 "ORDER BY id LIMIT $3 FOR UPDATE SKIP LOCKED) RETURNING ") +
         kSubmissionColumns},
    {"release",
     "UPDATE submissions SET claimed_by = NULL, claims = greatest(claims - 1, 0) "
     "WHERE id = ANY($1::bigint[]) AND claimed_by = $2 AND state = 0"},
    // Each grade is written only if its submission is still pending and this worker's claim,
    // in the same statement that marks it graded: a submission is graded exactly once.
    {"record_grades",
     "WITH g AS (SELECT (e->>'submission')::bigint AS submission, e->>'result' AS result, "
     "(e->>'score')::double precision AS score, (e->>'max_score')::double precision AS max_score, "
     "e->>'set_version' AS set_version, e->>'graded_by' AS graded_by, "
     "(e->>'graded')::bigint AS graded, (e->>'failed')::boolean AS failed "
     "FROM jsonb_array_elements($1::jsonb) e), "
     "mine AS (UPDATE submissions s SET state = CASE WHEN g.failed THEN 2 ELSE 1 END "
     "FROM g WHERE s.id = g.submission AND s.claimed_by = $2 AND s.state = 0 RETURNING s.id) "
     "INSERT INTO grades (submission, result, score, max_score, set_version, graded_by, graded, "
     "failed) SELECT submission, result, score, max_score, set_version, graded_by, graded, failed "
     "FROM g WHERE submission IN (SELECT id FROM mine) RETURNING submission"},
    {"submissions", std::string("SELECT ") + kSubmissionColumns +
                        " FROM submissions WHERE student = $1 AND set_id = $2 ORDER BY id"},
    {"submission", std::string("SELECT ") + kSubmissionColumns +
                       " FROM submissions WHERE student = $1 AND id = $2"},
    {"latest_grade",
     "SELECT submission, result, score, max_score, set_version, graded_by, graded, failed "
     "FROM grades WHERE submission = $1 ORDER BY id DESC LIMIT 1"},
    {"pending_count", "SELECT count(*) FROM submissions WHERE state = 0"},
    {"set_submissions", std::string("SELECT ") + kSubmissionColumns +
                            " FROM submissions WHERE set_id = $1 ORDER BY id LIMIT $2"},
    {"latest_grades",
     "SELECT DISTINCT ON (g.submission) g.submission, g.result, g.score, g.max_score, "
     "g.set_version, g.graded_by, g.graded, g.failed FROM grades g JOIN submissions s "
     "ON s.id = g.submission WHERE s.set_id = $1 ORDER BY g.submission, g.id DESC"},
    {"grade_history",
     "SELECT submission, result, score, max_score, set_version, graded_by, graded, failed "
     "FROM grades WHERE submission = $1 ORDER BY id"},
    // A regrade in one statement (so one transaction): the grades as a JSON array.
    {"record_regrades",
     "WITH g AS (SELECT (e->>'submission')::bigint AS submission, e->>'result' AS result, "
     "(e->>'score')::double precision AS score, (e->>'max_score')::double precision AS max_score, "
     "e->>'set_version' AS set_version, e->>'graded_by' AS graded_by, "
     "(e->>'graded')::bigint AS graded, (e->>'failed')::boolean AS failed "
     "FROM jsonb_array_elements($1::jsonb) e), "
     "marked AS (UPDATE submissions s SET state = CASE WHEN g.failed THEN 2 ELSE 1 END "
     "FROM g WHERE s.id = g.submission RETURNING s.id), "
     // A submission that is not there fails the whole statement (division by zero, 22012).
     "whole AS (SELECT 1 / (CASE WHEN (SELECT count(*) FROM marked) = (SELECT count(*) FROM g) "
     "THEN 1 ELSE 0 END) AS one) "
     "INSERT INTO grades (submission, result, score, max_score, set_version, graded_by, graded, "
     "failed) SELECT submission, result, score, max_score, set_version, graded_by, graded, failed "
     "FROM g, whole WHERE whole.one = 1 AND submission IN (SELECT id FROM marked)"},
    {"change_mark",
     "SELECT (SELECT coalesce(max(id), 0) FROM submissions) + "
     "(SELECT coalesce(max(id), 0) FROM grades)"},
};

// Grades as the JSON array the batch statements read with jsonb_array_elements.
std::string grades_json(const std::vector<GradeRecord>& grades) {
  nlohmann::json all = nlohmann::json::array();
  for (const GradeRecord& g : grades)
    all.push_back({{"submission", g.submission},
                   {"result", g.result},
                   {"score", g.score},
                   {"max_score", g.max_score},
                   {"set_version", g.set_version},
                   {"graded_by", g.graded_by},
                   {"graded", g.graded},
                   {"failed", g.failed}});
  return all.dump();
}

std::int64_t integer(const std::string& text) {
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size())
    throw StoreError("PostgreSQL returned '" + text + "' where a whole number belongs");
  return value;
}

double real(const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0')
    throw StoreError("PostgreSQL returned '" + text + "' where a number belongs");
  return value;
}

SubmissionRecord submission_row(const std::vector<std::string>& row) {
  SubmissionRecord r;
  r.id = integer(row.at(0));
  r.student = row.at(1);
  r.set = row.at(2);
  r.set_version = row.at(3);
  r.variant = row.at(4);
  r.problem = row.at(5);
  r.answers = row.at(6);
  r.received = integer(row.at(7));
  r.attempt = static_cast<int>(integer(row.at(8)));
  r.state = static_cast<SubmissionState>(integer(row.at(9)));
  r.claims = static_cast<int>(integer(row.at(10)));
  return r;
}

GradeRecord grade_row(const std::vector<std::string>& row) {
  return GradeRecord{integer(row.at(0)), row.at(1), real(row.at(2)),    real(row.at(3)),
                     row.at(4),          row.at(5), integer(row.at(6)), row.at(7) == "t"};
}

// Open connections, each used by one thread at a time; at most `limit` exist.
class ConnectionPool {
 public:
  ConnectionPool(std::string url, int limit, bool worker)
      : url_(std::move(url)), limit_(limit < 1 ? 1 : limit), worker_(worker) {}

  // Runs the prepared statement `name` on a free connection. A connection the server has
  // closed while it was idle (restart, failover) is replaced before the statement is sent, so
  // no statement is ever sent twice; one that breaks while a statement runs is closed and the
  // error reported (whether that statement committed cannot be known).
  PgRows run(const char* name, const std::vector<std::string>& params) {
    std::unique_ptr<PgConnection> db = take();
    try {
      PgRows rows = db->run(name, params);
      give(std::move(db));
      return rows;
    } catch (const StoreError&) {
      if (db->usable()) {
        give(std::move(db));
      } else {
        db.reset();
        forget();
      }
      throw;
    }
  }

 private:
  std::unique_ptr<PgConnection> take() {
    {
      std::unique_lock lock(mutex_);
      freed_.wait(lock, [&] { return !free_.empty() || open_ < limit_; });
      while (!free_.empty()) {
        std::unique_ptr<PgConnection> db = std::move(free_.back());
        free_.pop_back();
        if (db->alive()) return db;
        --open_;
      }
      ++open_;
    }
    try {
      auto db = std::make_unique<PgConnection>(url_);
      // A commit returns once it is on disk, whatever the server's default: a submission is
      // acknowledged only after its commit. A worker submits nothing (PostgresOptions::worker).
      db->exec(worker_ ? "SET synchronous_commit TO off" : "SET synchronous_commit TO on");
      for (const auto& [name, sql] : kStatements) db->prepare(name, sql);
      return db;
    } catch (...) {
      forget();
      throw;
    }
  }
  void give(std::unique_ptr<PgConnection> db) {
    {
      std::lock_guard lock(mutex_);
      free_.push_back(std::move(db));
    }
    freed_.notify_one();
  }
  void forget() {
    {
      std::lock_guard lock(mutex_);
      --open_;
    }
    freed_.notify_one();
  }

  std::string url_;
  int limit_;
  bool worker_;
  std::mutex mutex_;
  std::condition_variable freed_;
  std::vector<std::unique_ptr<PgConnection>> free_;
  int open_ = 0;
};

class PostgresStore final : public Store {
 public:
  PostgresStore(const std::string& url, const PostgresOptions& options)
      : url_(url), pool_(url, options.connections, options.worker) {}

  int schema_version() override {
    return static_cast<int>(integer(pool_.run("schema_version", {}).rows.at(0).at(0)));
  }

  void put_student(const std::string& id, const std::string& token_hash) override {
    pool_.run("put_person", {id, token_hash, "student"});
  }
  std::optional<std::string> student_by_token(const std::string& token_hash) override {
    return person_by_token(token_hash, "student");
  }
  std::vector<std::string> students() override { return people("student"); }
  void put_instructor(const std::string& id, const std::string& token_hash) override {
    pool_.run("put_person", {id, token_hash, "instructor"});
  }
  std::optional<std::string> instructor_by_token(const std::string& token_hash) override {
    return person_by_token(token_hash, "instructor");
  }
  std::vector<std::string> instructors() override { return people("instructor"); }

  void put_session(const std::string& session_hash, const SessionRecord& r) override {
    pool_.run("put_session", {session_hash, r.student, r.csrf, std::to_string(r.expires),
                              r.role == Role::Instructor ? "instructor" : "student"});
  }

  std::optional<SessionRecord> session(const std::string& session_hash, Millis now) override {
    PgRows r = pool_.run("session", {session_hash, std::to_string(now)});
    if (r.rows.empty()) return std::nullopt;
    return SessionRecord{r.rows[0][0], r.rows[0][1], integer(r.rows[0][2]),
                         r.rows[0][3] == "instructor" ? Role::Instructor : Role::Student};
  }

  void save_draft(const std::string& student, const Draft& d) override {
    pool_.run("save_draft", {student, d.set, d.problem, d.answer, d.text, std::to_string(d.saved)});
  }

  std::vector<Draft> drafts(const std::string& student, const std::string& set) override {
    std::vector<Draft> out;
    for (const auto& row : pool_.run("drafts", {student, set}).rows)
      out.push_back(Draft{row[0], row[1], row[2], row[3], integer(row[4])});
    return out;
  }

  SubmissionRecord submit(const NewSubmission& n) override {
    const std::vector<std::string> params = {n.student,
                                             n.set,
                                             n.set_version,
                                             n.variant,
                                             n.problem,
                                             n.answers,
                                             std::to_string(n.received)};
    const PgRows r = pool_.run("submit", params);
    SubmissionRecord out;
    static_cast<NewSubmission&>(out) = n;
    out.id = integer(r.rows.at(0).at(0));
    out.attempt = static_cast<int>(integer(r.rows.at(0).at(1)));
    out.state = SubmissionState::Pending;
    return out;
  }

  std::vector<SubmissionRecord> claim_some(const std::string& worker, Millis now, Millis lease,
                                           std::size_t max) override {
    std::vector<SubmissionRecord> out;
    if (max == 0) return out;
    PgRows r = pool_.run("reclaim", {worker, std::to_string(now), std::to_string(now - lease)});
    if (r.rows.empty()) r = pool_.run("claim", {worker, std::to_string(now), std::to_string(max)});
    for (const auto& row : r.rows) out.push_back(submission_row(row));
    std::sort(out.begin(), out.end(),
              [](const SubmissionRecord& a, const SubmissionRecord& b) { return a.id < b.id; });
    return out;
  }

  void release(const std::vector<std::int64_t>& submissions, const std::string& worker) override {
    if (submissions.empty()) return;
    std::string ids = "{";
    for (const std::int64_t id : submissions)
      ids += (ids.size() > 1 ? "," : "") + std::to_string(id);
    pool_.run("release", {ids + "}", worker});
  }

  std::vector<bool> record_grades(const std::vector<GradeRecord>& grades,
                                  const std::string& worker) override {
    std::vector<bool> recorded(grades.size(), false);
    if (grades.empty()) return recorded;
    const PgRows r = pool_.run("record_grades", {grades_json(grades), worker});
    for (const auto& row : r.rows) {
      const std::int64_t id = integer(row.at(0));
      for (std::size_t i = 0; i < grades.size(); ++i)
        if (grades[i].submission == id) recorded[i] = true;
    }
    return recorded;
  }

  std::vector<SubmissionRecord> submissions(const std::string& student,
                                            const std::string& set) override {
    std::vector<SubmissionRecord> out;
    for (const auto& row : pool_.run("submissions", {student, set}).rows)
      out.push_back(submission_row(row));
    return out;
  }

  std::optional<SubmissionRecord> submission(const std::string& student, std::int64_t id) override {
    PgRows r = pool_.run("submission", {student, std::to_string(id)});
    if (r.rows.empty()) return std::nullopt;
    return submission_row(r.rows[0]);
  }

  std::optional<GradeRecord> latest_grade(std::int64_t submission) override {
    PgRows r = pool_.run("latest_grade", {std::to_string(submission)});
    if (r.rows.empty()) return std::nullopt;
    return grade_row(r.rows[0]);
  }

  std::int64_t pending_count() override {
    return integer(pool_.run("pending_count", {}).rows.at(0).at(0));
  }

  std::vector<SubmissionRecord> set_submissions(const std::string& set,
                                                std::size_t limit) override {
    std::vector<SubmissionRecord> out;
    for (const auto& row : pool_.run("set_submissions", {set, std::to_string(limit)}).rows)
      out.push_back(submission_row(row));
    return out;
  }

  std::vector<GradeRecord> latest_grades(const std::string& set) override {
    std::vector<GradeRecord> out;
    for (const auto& row : pool_.run("latest_grades", {set}).rows) out.push_back(grade_row(row));
    return out;
  }

  std::vector<GradeRecord> grade_history(std::int64_t submission) override {
    std::vector<GradeRecord> out;
    for (const auto& row : pool_.run("grade_history", {std::to_string(submission)}).rows)
      out.push_back(grade_row(row));
    return out;
  }

  void record_regrades(const std::vector<GradeRecord>& grades) override {
    try {
      pool_.run("record_regrades", {grades_json(grades)});
    } catch (const PostgresError& e) {
      if (e.sqlstate != "22012") throw;
      throw StoreError("regrade: one of its submissions is not in the database; nothing written");
    }
  }

  std::int64_t change_mark() override {
    return integer(pool_.run("change_mark", {}).rows.at(0).at(0));
  }

  // Woken by the NOTIFY that every instance's writes send (migration 2's triggers), on one
  // listening connection shared by the waiting requests.
  std::int64_t wait_for_change(std::int64_t mark, Millis timeout) override {
    const std::int64_t now = change_mark();
    if (now != mark) return now;
    {
      // One request listens; any other waiting at once asks every quarter second.
      std::unique_lock lock(listen_mutex_, std::try_to_lock);
      if (!lock.owns_lock()) return Store::wait_for_change(mark, timeout);
      if (!listener_ || !listener_->usable()) {
        listener_ = std::make_unique<PgConnection>(url_);
        listener_->exec("LISTEN frustum_class");
        const std::int64_t again = change_mark();  // a write between the two reads
        if (again != mark) return again;
      }
      listener_->wait_notification(static_cast<int>(timeout));
    }
    return change_mark();
  }

 private:
  std::optional<std::string> person_by_token(const std::string& token_hash, const char* role) {
    PgRows r = pool_.run("person_by_token", {token_hash, role});
    if (r.rows.empty()) return std::nullopt;
    return r.rows[0][0];
  }
  std::vector<std::string> people(const char* role) {
    std::vector<std::string> out;
    for (auto& row : pool_.run("people", {role}).rows) out.push_back(std::move(row[0]));
    return out;
  }

  std::string url_;
  ConnectionPool pool_;
  std::mutex listen_mutex_;
  std::unique_ptr<PgConnection> listener_;
};

}  // namespace

std::unique_ptr<Store> open_postgres_store(const std::string& url, PostgresOptions options) {
  migrate_postgres(url);
  return std::make_unique<PostgresStore>(url, options);
}

}  // namespace frustum::server
