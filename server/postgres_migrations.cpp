// The PostgreSQL store's schema as numbered, forward-only migrations embedded in the binary
// (migration i brings the schema from version i to i + 1; none is edited once released). The
// numbering is the SQLite store's: version N has the same tables and meaning in both (and here
// the table `attempts`, which SQLite's single writer does not need).
#include <array>
#include <string>

#include "server/postgres_connection.hpp"
#include "server/postgres_store.hpp"

namespace frustum::server {

namespace {

// Migration i + 1 is kMigrations[i]. Append only.
constexpr std::array<const char*, 2> kMigrations = {
    R"SQL(
CREATE TABLE students (id TEXT PRIMARY KEY, token_hash TEXT NOT NULL UNIQUE);
CREATE TABLE sessions (hash TEXT PRIMARY KEY, student TEXT NOT NULL REFERENCES students(id),
                       csrf TEXT NOT NULL, expires BIGINT NOT NULL);
CREATE TABLE drafts (student TEXT NOT NULL, set_id TEXT NOT NULL, problem TEXT NOT NULL,
                     answer TEXT NOT NULL, text TEXT NOT NULL, saved BIGINT NOT NULL,
                     PRIMARY KEY (student, set_id, problem, answer));
CREATE TABLE submissions (id BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
                          student TEXT NOT NULL, set_id TEXT NOT NULL, set_version TEXT NOT NULL,
                          variant TEXT NOT NULL, problem TEXT NOT NULL, answers TEXT NOT NULL,
                          received BIGINT NOT NULL, attempt INTEGER NOT NULL,
                          state SMALLINT NOT NULL DEFAULT 0, claimed_by TEXT, claimed_at BIGINT,
                          claims INTEGER NOT NULL DEFAULT 0,
                          UNIQUE (student, set_id, problem, attempt));
CREATE INDEX submissions_pending ON submissions (id) WHERE state = 0;
-- The last attempt of each student's problem: submit takes the next one by an upsert, whose row
-- lock makes two submissions at once take two numbers (max(attempt) + 1 could take one twice).
CREATE TABLE attempts (student TEXT NOT NULL, set_id TEXT NOT NULL, problem TEXT NOT NULL,
                       last INTEGER NOT NULL, PRIMARY KEY (student, set_id, problem));
CREATE TABLE grades (id BIGINT GENERATED ALWAYS AS IDENTITY PRIMARY KEY,
                     submission BIGINT NOT NULL REFERENCES submissions(id), result TEXT NOT NULL,
                     score DOUBLE PRECISION NOT NULL, max_score DOUBLE PRECISION NOT NULL,
                     set_version TEXT NOT NULL, graded_by TEXT NOT NULL, graded BIGINT NOT NULL,
                     failed BOOLEAN NOT NULL);
CREATE INDEX grades_submission ON grades (submission, id);
)SQL",
    // 2: instructors (a role beside each id and each session), the class read by set, and a
    // NOTIFY on frustum_class whenever a submission or a grade is written, so that every
    // instance's dashboards hear of it.
    R"SQL(
ALTER TABLE students ADD COLUMN role TEXT NOT NULL DEFAULT 'student';
ALTER TABLE sessions ADD COLUMN role TEXT NOT NULL DEFAULT 'student';
CREATE INDEX submissions_set ON submissions (set_id, id);
CREATE FUNCTION frustum_class_changed() RETURNS trigger LANGUAGE plpgsql AS $$
BEGIN
  PERFORM pg_notify('frustum_class', TG_TABLE_NAME);
  RETURN NULL;
END $$;
CREATE TRIGGER submissions_notify AFTER INSERT ON submissions
  FOR EACH STATEMENT EXECUTE FUNCTION frustum_class_changed();
CREATE TRIGGER grades_notify AFTER INSERT ON grades
  FOR EACH STATEMENT EXECUTE FUNCTION frustum_class_changed();
)SQL"};

// The advisory lock that serializes migrations (any constant; it reads "frustmig").
constexpr const char* kMigrationLock = "7382360734245743975";

}  // namespace

int postgres_latest_version() { return static_cast<int>(kMigrations.size()); }

int migrate_postgres(const std::string& url) {
  PgConnection db(url);
  // One transaction under a transaction-scoped advisory lock: a second instance waits here,
  // then (READ COMMITTED: each statement sees what committed before it) finds the work done.
  // The lock goes with the transaction, whatever ends it.
  db.exec("BEGIN");
  try {
    db.exec("SELECT pg_advisory_xact_lock(" + std::string(kMigrationLock) + ")");
    db.exec(
        "CREATE TABLE IF NOT EXISTS schema_migrations (version INTEGER PRIMARY KEY, "
        "applied BIGINT NOT NULL, applied_by INTEGER NOT NULL)");
    const PgRows have_rows = db.exec("SELECT coalesce(max(version), 0) FROM schema_migrations");
    const int have = std::stoi(have_rows.rows.at(0).at(0));
    const int latest = postgres_latest_version();
    if (have > latest)
      throw StoreError("the database " + redact_postgres_url(url) + " has schema version " +
                       std::to_string(have) + ", newer than this frustum's (" +
                       std::to_string(latest) +
                       "): it was written by a newer frustum; run that one, or a copy of the "
                       "database made before it");
    for (int v = have; v < latest; ++v) {
      db.exec(kMigrations[static_cast<std::size_t>(v)]);
      db.exec(
          "INSERT INTO schema_migrations (version, applied, applied_by) VALUES ($1, "
          "(extract(epoch FROM clock_timestamp()) * 1000)::bigint, pg_backend_pid())",
          {std::to_string(v + 1)});
    }
    db.exec("COMMIT");
    return latest - have;
  } catch (...) {
    if (db.usable()) {
      try {
        db.exec("ROLLBACK");
      } catch (const StoreError&) {  // the first error is the one to report
      }
    }
    throw;
  }
}

}  // namespace frustum::server
