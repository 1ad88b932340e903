#include "server/sqlite_store.hpp"

#include <algorithm>
#include <mutex>
#include <vector>

#include "server/sqlite_migrations.hpp"
#include "server/sqlite_writer.hpp"

namespace frustum::server {

namespace {

constexpr const char* kSubmissionColumns =
    "id, student, set_id, set_version, variant, problem, answers, received, attempt, state, claims";

constexpr const char* kGradeColumns =
    "submission, result, score, max_score, set_version, graded_by, graded, failed";

GradeRecord grade_row(const SqliteStmt& s) {
  return GradeRecord{s.integer(0), s.text(1), s.real(2),    s.real(3),
                     s.text(4),    s.text(5), s.integer(6), s.integer(7) != 0};
}

void insert_grade(SqliteDb& db, const GradeRecord& g) {
  SqliteStmt(db, (std::string("INSERT INTO grades (") + kGradeColumns +
                  ") VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
                     .c_str())
      .bind(1, g.submission)
      .bind(2, g.result)
      .bind(3, g.score)
      .bind(4, g.max_score)
      .bind(5, g.set_version)
      .bind(6, g.graded_by)
      .bind(7, g.graded)
      .bind(8, g.failed ? 1 : 0)
      .run();
}

std::string role_text(Role role) { return role == Role::Instructor ? "instructor" : "student"; }

SubmissionRecord submission_row(const SqliteStmt& s) {
  SubmissionRecord r;
  r.id = s.integer(0);
  r.student = s.text(1);
  r.set = s.text(2);
  r.set_version = s.text(3);
  r.variant = s.text(4);
  r.problem = s.text(5);
  r.answers = s.text(6);
  r.received = s.integer(7);
  r.attempt = static_cast<int>(s.integer(8));
  r.state = static_cast<SubmissionState>(s.integer(9));
  r.claims = static_cast<int>(s.integer(10));
  return r;
}

// Read connections, each used by one thread at a time; WAL lets them read beside the writer.
class ReaderPool {
 public:
  explicit ReaderPool(std::string path) : path_(std::move(path)) {}
  template <class F>
  auto with(F&& read) {
    std::unique_ptr<SqliteDb> db = take();
    struct Back {
      ReaderPool& pool;
      std::unique_ptr<SqliteDb>& db;
      ~Back() { pool.give(std::move(db)); }
    } back{*this, db};
    return read(*db);
  }

 private:
  std::unique_ptr<SqliteDb> take() {
    {
      std::lock_guard lock(mutex_);
      if (!free_.empty()) {
        std::unique_ptr<SqliteDb> db = std::move(free_.back());
        free_.pop_back();
        return db;
      }
    }
    return std::make_unique<SqliteDb>(path_);
  }
  void give(std::unique_ptr<SqliteDb> db) {
    std::lock_guard lock(mutex_);
    free_.push_back(std::move(db));
  }
  std::string path_;
  std::mutex mutex_;
  std::vector<std::unique_ptr<SqliteDb>> free_;
};

class SqliteStore final : public Store {
 public:
  SqliteStore(const std::string& path, SqliteSync sync) : writer_(path, sync), readers_(path) {}

  int schema_version() override {
    return readers_.with([](SqliteDb& db) { return sqlite_schema_version(db); });
  }

  void put_student(const std::string& id, const std::string& token_hash) override {
    put_person(id, token_hash, Role::Student);
  }
  std::optional<std::string> student_by_token(const std::string& token_hash) override {
    return person_by_token(token_hash, Role::Student);
  }
  std::vector<std::string> students() override { return people(Role::Student); }
  void put_instructor(const std::string& id, const std::string& token_hash) override {
    put_person(id, token_hash, Role::Instructor);
  }
  std::optional<std::string> instructor_by_token(const std::string& token_hash) override {
    return person_by_token(token_hash, Role::Instructor);
  }
  std::vector<std::string> instructors() override { return people(Role::Instructor); }

  void put_session(const std::string& session_hash, const SessionRecord& r) override {
    writer_.run([&](SqliteDb& db) {
      SqliteStmt(db,
                 "INSERT INTO sessions (hash, student, csrf, expires, role) VALUES (?, ?, ?, ?, ?) "
                 "ON CONFLICT (hash) DO UPDATE SET student = excluded.student, "
                 "csrf = excluded.csrf, expires = excluded.expires, role = excluded.role")
          .bind(1, session_hash)
          .bind(2, r.student)
          .bind(3, r.csrf)
          .bind(4, r.expires)
          .bind(5, role_text(r.role))
          .run();
    });
  }

  std::optional<SessionRecord> session(const std::string& session_hash, Millis now) override {
    return readers_.with([&](SqliteDb& db) -> std::optional<SessionRecord> {
      SqliteStmt s(db,
                   "SELECT student, csrf, expires, role FROM sessions "
                   "WHERE hash = ? AND expires > ?");
      s.bind(1, session_hash).bind(2, now);
      if (!s.step()) return std::nullopt;
      return SessionRecord{s.text(0), s.text(1), s.integer(2),
                           s.text(3) == "instructor" ? Role::Instructor : Role::Student};
    });
  }

  void save_draft(const std::string& student, const Draft& d) override {
    writer_.run([&](SqliteDb& db) {
      SqliteStmt(db,
                 "INSERT INTO drafts (student, set_id, problem, answer, text, saved) "
                 "VALUES (?, ?, ?, ?, ?, ?) ON CONFLICT (student, set_id, problem, answer) "
                 "DO UPDATE SET text = excluded.text, saved = excluded.saved "
                 "WHERE excluded.saved >= drafts.saved")
          .bind(1, student)
          .bind(2, d.set)
          .bind(3, d.problem)
          .bind(4, d.answer)
          .bind(5, d.text)
          .bind(6, d.saved)
          .run();
    });
  }

  std::vector<Draft> drafts(const std::string& student, const std::string& set) override {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db,
                   "SELECT set_id, problem, answer, text, saved FROM drafts "
                   "WHERE student = ? AND set_id = ? ORDER BY problem, answer");
      s.bind(1, student).bind(2, set);
      std::vector<Draft> out;
      while (s.step())
        out.push_back(Draft{s.text(0), s.text(1), s.text(2), s.text(3), s.integer(4)});
      return out;
    });
  }

  SubmissionRecord submit(const NewSubmission& n) override {
    SubmissionRecord r;
    static_cast<NewSubmission&>(r) = n;
    writer_.run([&](SqliteDb& db) {
      SqliteStmt next(db,
                      "SELECT coalesce(max(attempt), 0) + 1 FROM submissions "
                      "WHERE student = ? AND set_id = ? AND problem = ?");
      next.bind(1, n.student).bind(2, n.set).bind(3, n.problem);
      r.attempt = next.step() ? static_cast<int>(next.integer(0)) : 1;
      SqliteStmt(db,
                 "INSERT INTO submissions (student, set_id, set_version, variant, problem, "
                 "answers, received, attempt) VALUES (?, ?, ?, ?, ?, ?, ?, ?)")
          .bind(1, n.student)
          .bind(2, n.set)
          .bind(3, n.set_version)
          .bind(4, n.variant)
          .bind(5, n.problem)
          .bind(6, n.answers)
          .bind(7, n.received)
          .bind(8, r.attempt)
          .run();
      r.id = sqlite3_last_insert_rowid(db.handle());
    });
    r.state = SubmissionState::Pending;
    return r;
  }

  std::vector<SubmissionRecord> claim_some(const std::string& worker, Millis now, Millis lease,
                                           std::size_t max) override {
    std::vector<SubmissionRecord> out;
    if (max == 0) return out;
    writer_.run([&](SqliteDb& db) {
      out.clear();  // a retried write starts again
      const auto claim_where = [&](const std::string& which, std::size_t limit) {
        SqliteStmt s(db, (std::string("UPDATE submissions SET claimed_by = ?, claimed_at = ?, "
                                      "claims = claims + 1 WHERE id IN (SELECT id FROM "
                                      "submissions WHERE state = 0 AND ") +
                          which + " ORDER BY id LIMIT ?) RETURNING " + kSubmissionColumns)
                             .c_str());
        s.bind(1, worker).bind(2, now);
        if (which.find('?') != std::string::npos)
          s.bind(3, now - lease).bind(4, static_cast<std::int64_t>(limit));
        else
          s.bind(3, static_cast<std::int64_t>(limit));
        while (s.step()) out.push_back(submission_row(s));
      };
      claim_where("claimed_by IS NOT NULL AND claimed_at <= ?", 1);
      if (out.empty()) claim_where("claimed_by IS NULL", max);
    });
    std::sort(out.begin(), out.end(),
              [](const SubmissionRecord& a, const SubmissionRecord& b) { return a.id < b.id; });
    return out;
  }

  void release(const std::vector<std::int64_t>& submissions, const std::string& worker) override {
    if (submissions.empty()) return;
    writer_.run([&](SqliteDb& db) {
      for (const std::int64_t id : submissions)
        SqliteStmt(db,
                   "UPDATE submissions SET claimed_by = NULL, claims = max(claims - 1, 0) "
                   "WHERE id = ? AND claimed_by = ? AND state = 0")
            .bind(1, id)
            .bind(2, worker)
            .run();
    });
  }

  std::vector<bool> record_grades(const std::vector<GradeRecord>& grades,
                                  const std::string& worker) override {
    std::vector<bool> recorded(grades.size(), false);
    if (grades.empty()) return recorded;
    writer_.run([&](SqliteDb& db) {
      for (std::size_t i = 0; i < grades.size(); ++i) {
        const GradeRecord& g = grades[i];
        SqliteStmt(db,
                   "UPDATE submissions SET state = ? WHERE id = ? AND claimed_by = ? AND state = 0")
            .bind(1, static_cast<int>(g.failed ? SubmissionState::Failed : SubmissionState::Graded))
            .bind(2, g.submission)
            .bind(3, worker)
            .run();
        recorded[i] = db.changes() == 1;
        if (recorded[i]) insert_grade(db, g);
      }
    });
    return recorded;
  }

  std::vector<SubmissionRecord> submissions(const std::string& student,
                                            const std::string& set) override {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db, (std::string("SELECT ") + kSubmissionColumns +
                        " FROM submissions WHERE student = ? AND set_id = ? ORDER BY id")
                           .c_str());
      s.bind(1, student).bind(2, set);
      std::vector<SubmissionRecord> out;
      while (s.step()) out.push_back(submission_row(s));
      return out;
    });
  }

  std::optional<SubmissionRecord> submission(const std::string& student, std::int64_t id) override {
    return readers_.with([&](SqliteDb& db) -> std::optional<SubmissionRecord> {
      SqliteStmt s(db, (std::string("SELECT ") + kSubmissionColumns +
                        " FROM submissions WHERE student = ? AND id = ?")
                           .c_str());
      s.bind(1, student).bind(2, id);
      if (!s.step()) return std::nullopt;
      return submission_row(s);
    });
  }

  std::optional<GradeRecord> latest_grade(std::int64_t submission) override {
    return readers_.with([&](SqliteDb& db) -> std::optional<GradeRecord> {
      SqliteStmt s(db, (std::string("SELECT ") + kGradeColumns +
                        " FROM grades WHERE submission = ? ORDER BY id DESC LIMIT 1")
                           .c_str());
      s.bind(1, submission);
      if (!s.step()) return std::nullopt;
      return grade_row(s);
    });
  }

  std::int64_t pending_count() override {
    return readers_.with([](SqliteDb& db) {
      SqliteStmt s(db, "SELECT count(*) FROM submissions WHERE state = 0");
      return s.step() ? s.integer(0) : 0;
    });
  }

  std::vector<SubmissionRecord> set_submissions(const std::string& set,
                                                std::size_t limit) override {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db, (std::string("SELECT ") + kSubmissionColumns +
                        " FROM submissions WHERE set_id = ? ORDER BY id LIMIT ?")
                           .c_str());
      s.bind(1, set).bind(2, static_cast<std::int64_t>(limit));
      std::vector<SubmissionRecord> out;
      while (s.step()) out.push_back(submission_row(s));
      return out;
    });
  }

  std::vector<GradeRecord> latest_grades(const std::string& set) override {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db,
                   "SELECT g.submission, g.result, g.score, g.max_score, g.set_version, "
                   "g.graded_by, g.graded, g.failed FROM grades g JOIN ("
                   "SELECT max(grades.id) AS id FROM grades JOIN submissions s "
                   "ON s.id = grades.submission WHERE s.set_id = ? GROUP BY grades.submission"
                   ") last ON last.id = g.id ORDER BY g.submission");
      s.bind(1, set);
      std::vector<GradeRecord> out;
      while (s.step()) out.push_back(grade_row(s));
      return out;
    });
  }

  std::vector<GradeRecord> grade_history(std::int64_t submission) override {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db, (std::string("SELECT ") + kGradeColumns +
                        " FROM grades WHERE submission = ? ORDER BY id")
                           .c_str());
      s.bind(1, submission);
      std::vector<GradeRecord> out;
      while (s.step()) out.push_back(grade_row(s));
      return out;
    });
  }

  void record_regrades(const std::vector<GradeRecord>& grades) override {
    writer_.run([&](SqliteDb& db) {
      for (const GradeRecord& g : grades) {
        SqliteStmt(db, "UPDATE submissions SET state = ? WHERE id = ?")
            .bind(1, static_cast<int>(g.failed ? SubmissionState::Failed : SubmissionState::Graded))
            .bind(2, g.submission)
            .run();
        if (db.changes() != 1)
          throw StoreError("regrade: no submission " + std::to_string(g.submission));
        insert_grade(db, g);
      }
    });
  }

  std::int64_t change_mark() override {
    return readers_.with([](SqliteDb& db) {
      SqliteStmt s(db,
                   "SELECT (SELECT coalesce(max(id), 0) FROM submissions) + "
                   "(SELECT coalesce(max(id), 0) FROM grades)");
      return s.step() ? s.integer(0) : 0;
    });
  }

 private:
  void put_person(const std::string& id, const std::string& token_hash, Role role) {
    writer_.run([&](SqliteDb& db) {
      SqliteStmt(db,
                 "INSERT INTO students (id, token_hash, role) VALUES (?, ?, ?) "
                 "ON CONFLICT (id) DO UPDATE SET token_hash = excluded.token_hash, "
                 "role = excluded.role")
          .bind(1, id)
          .bind(2, token_hash)
          .bind(3, role_text(role))
          .run();
    });
  }

  std::optional<std::string> person_by_token(const std::string& token_hash, Role role) {
    return readers_.with([&](SqliteDb& db) -> std::optional<std::string> {
      SqliteStmt s(db, "SELECT id FROM students WHERE token_hash = ? AND role = ?");
      s.bind(1, token_hash).bind(2, role_text(role));
      if (!s.step()) return std::nullopt;
      return s.text(0);
    });
  }

  std::vector<std::string> people(Role role) {
    return readers_.with([&](SqliteDb& db) {
      SqliteStmt s(db, "SELECT id FROM students WHERE role = ? ORDER BY id");
      s.bind(1, role_text(role));
      std::vector<std::string> out;
      while (s.step()) out.push_back(s.text(0));
      return out;
    });
  }

  SqliteWriter writer_;
  ReaderPool readers_;
};

}  // namespace

std::unique_ptr<Store> open_sqlite_store(const std::string& path, SqliteSync sync) {
  {
    SqliteDb db(path);
    migrate_sqlite(db, path);
  }
  return std::make_unique<SqliteStore>(path, sync);
}

}  // namespace frustum::server
