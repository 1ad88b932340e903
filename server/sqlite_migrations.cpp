#include "server/sqlite_migrations.hpp"

#include <array>

namespace frustum::server {

namespace {

// Migration i + 1 is kMigrations[i]. Append only.
constexpr std::array<const char*, 2> kMigrations = {
    R"SQL(
CREATE TABLE students (id TEXT PRIMARY KEY, token_hash TEXT NOT NULL UNIQUE);
CREATE TABLE sessions (hash TEXT PRIMARY KEY, student TEXT NOT NULL REFERENCES students(id),
                       csrf TEXT NOT NULL, expires INTEGER NOT NULL);
CREATE TABLE drafts (student TEXT NOT NULL, set_id TEXT NOT NULL, problem TEXT NOT NULL,
                     answer TEXT NOT NULL, text TEXT NOT NULL, saved INTEGER NOT NULL,
                     PRIMARY KEY (student, set_id, problem, answer));
CREATE TABLE submissions (id INTEGER PRIMARY KEY AUTOINCREMENT, student TEXT NOT NULL,
                          set_id TEXT NOT NULL, set_version TEXT NOT NULL, variant TEXT NOT NULL,
                          problem TEXT NOT NULL, answers TEXT NOT NULL, received INTEGER NOT NULL,
                          attempt INTEGER NOT NULL, state INTEGER NOT NULL DEFAULT 0,
                          claimed_by TEXT, claimed_at INTEGER, claims INTEGER NOT NULL DEFAULT 0,
                          UNIQUE (student, set_id, problem, attempt));
CREATE INDEX submissions_pending ON submissions (state, id);
CREATE TABLE grades (id INTEGER PRIMARY KEY AUTOINCREMENT,
                     submission INTEGER NOT NULL REFERENCES submissions(id), result TEXT NOT NULL,
                     score REAL NOT NULL, max_score REAL NOT NULL, set_version TEXT NOT NULL,
                     graded_by TEXT NOT NULL, graded INTEGER NOT NULL, failed INTEGER NOT NULL);
CREATE INDEX grades_submission ON grades (submission, id);
)SQL",
    // 2: instructors (a role beside each id and each session) and the class read by set.
    R"SQL(
ALTER TABLE students ADD COLUMN role TEXT NOT NULL DEFAULT 'student';
ALTER TABLE sessions ADD COLUMN role TEXT NOT NULL DEFAULT 'student';
CREATE INDEX submissions_set ON submissions (set_id, id);
)SQL"};

}  // namespace

int sqlite_latest_version() { return static_cast<int>(kMigrations.size()); }

int sqlite_schema_version(SqliteDb& db) {
  SqliteStmt s(db, "SELECT coalesce(max(version), 0) FROM schema_migrations");
  return s.step() ? static_cast<int>(s.integer(0)) : 0;
}

void migrate_sqlite(SqliteDb& db, const std::string& path) {
  db.exec("BEGIN EXCLUSIVE");
  try {
    db.exec(
        "CREATE TABLE IF NOT EXISTS schema_migrations (version INTEGER PRIMARY KEY, "
        "applied INTEGER NOT NULL)");
    const int have = sqlite_schema_version(db);
    if (have > sqlite_latest_version())
      throw StoreError("the database " + path + " has schema version " + std::to_string(have) +
                       ", newer than this frustum's (" + std::to_string(sqlite_latest_version()) +
                       "): it was written by a newer frustum; run that one, or a copy of the "
                       "database made before it");
    for (int v = have; v < sqlite_latest_version(); ++v) {
      db.exec(kMigrations[static_cast<std::size_t>(v)]);
      SqliteStmt mark(db,
                      "INSERT INTO schema_migrations (version, applied) "
                      "VALUES (?, CAST((julianday('now') - 2440587.5) * 86400000 AS INTEGER))");
      mark.bind(1, v + 1).run();
    }
    db.exec("COMMIT");
  } catch (...) {
    sqlite3_exec(db.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

}  // namespace frustum::server
