#include "server/sqlite_db.hpp"

#include <unistd.h>

namespace frustum::server {

namespace {
// A writer waits this long for another process's transaction (a grading worker's) to finish.
constexpr int kBusyTimeoutMs = 10000;
// ...retrying every this many microseconds. SQLite's own busy_timeout backs off to 100 ms
// sleeps, and a writer sleeping that long starves behind workers that commit many short
// transactions: the server's submissions wait.
constexpr int kBusyRetryUs = 250;

int retry_soon(void*, int tries) {
  if (tries * kBusyRetryUs >= kBusyTimeoutMs * 1000) return 0;
  ::usleep(kBusyRetryUs);
  return 1;
}
}  // namespace

SqliteDb::SqliteDb(const std::string& path, SqliteSync sync) : path_(path) {
  const int flags = SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string why = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    db_ = nullptr;
    throw StoreError("cannot open the database " + path + ": " + why);
  }
  sqlite3_busy_handler(db_, retry_soon, nullptr);
  // Switching to WAL takes an exclusive lock, and when several instances open a new database at
  // once SQLite may answer SQLITE_BUSY without calling the busy handler (a lock it cannot wait
  // for without deadlock): retried here within the same time bound.
  for (int waited_us = 0;; waited_us += kBusyRetryUs) {
    const int rc = sqlite3_exec(db_, "PRAGMA journal_mode=WAL", nullptr, nullptr, nullptr);
    if (rc == SQLITE_OK) break;
    if ((rc != SQLITE_BUSY && rc != SQLITE_LOCKED) || waited_us >= kBusyTimeoutMs * 1000)
      exec("PRAGMA journal_mode=WAL");  // throws, naming the error
    ::usleep(kBusyRetryUs);
  }
  exec(sync == SqliteSync::Full ? "PRAGMA synchronous=FULL" : "PRAGMA synchronous=NORMAL");
  exec("PRAGMA foreign_keys=ON");
}

SqliteDb::~SqliteDb() { sqlite3_close(db_); }

void SqliteDb::fail(const std::string& what) const {
  throw StoreError("database " + path_ + ": " + what + ": " + sqlite3_errmsg(db_));
}

void SqliteDb::exec(const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string why = error ? error : "unknown error";
    sqlite3_free(error);
    throw StoreError("database " + path_ + ": " + why + " (in: " + sql.substr(0, 80) + ")");
  }
}

SqliteStmt::SqliteStmt(SqliteDb& db, const char* sql) : db_(db) {
  if (sqlite3_prepare_v2(db.handle(), sql, -1, &stmt_, nullptr) != SQLITE_OK)
    db.fail(std::string("cannot prepare ") + sql);
}

SqliteStmt::~SqliteStmt() { sqlite3_finalize(stmt_); }

SqliteStmt& SqliteStmt::bind(int i, const std::string& v) {
  if (sqlite3_bind_text(stmt_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT) !=
      SQLITE_OK)
    db_.fail("bind");
  return *this;
}

SqliteStmt& SqliteStmt::bind(int i, std::int64_t v) {
  if (sqlite3_bind_int64(stmt_, i, v) != SQLITE_OK) db_.fail("bind");
  return *this;
}

SqliteStmt& SqliteStmt::bind(int i, double v) {
  if (sqlite3_bind_double(stmt_, i, v) != SQLITE_OK) db_.fail("bind");
  return *this;
}

bool SqliteStmt::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  db_.fail(std::string("cannot run ") + sqlite3_sql(stmt_));
}

void SqliteStmt::run() {
  while (step()) {
  }
}

std::string SqliteStmt::text(int col) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, col));
  return p ? std::string(p, static_cast<std::size_t>(sqlite3_column_bytes(stmt_, col))) : "";
}

std::int64_t SqliteStmt::integer(int col) const { return sqlite3_column_int64(stmt_, col); }
double SqliteStmt::real(int col) const { return sqlite3_column_double(stmt_, col); }

}  // namespace frustum::server
