// A thin RAII layer over libsqlite3: a connection and prepared statements with typed binds and
// columns. Errors throw StoreError with SQLite's message and the statement's text.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <string>

#include "server/store.hpp"

namespace frustum::server {

class SqliteStmt;

// synchronous=FULL: a commit is on disk when it returns. NORMAL (WAL): it survives the process
// being killed, and a power failure may lose the last commits.
enum class SqliteSync { Full, Normal };

class SqliteDb {
 public:
  // Opens (creating) the file in WAL mode with synchronous=FULL and a busy timeout.
  explicit SqliteDb(const std::string& path, SqliteSync sync = SqliteSync::Full);
  ~SqliteDb();
  SqliteDb(const SqliteDb&) = delete;
  SqliteDb& operator=(const SqliteDb&) = delete;

  void exec(const std::string& sql);  // statements without results
  sqlite3* handle() const { return db_; }
  std::int64_t changes() const { return sqlite3_changes64(db_); }
  [[noreturn]] void fail(const std::string& what) const;

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

class SqliteStmt {
 public:
  SqliteStmt(SqliteDb& db, const char* sql);
  ~SqliteStmt();
  SqliteStmt(const SqliteStmt&) = delete;
  SqliteStmt& operator=(const SqliteStmt&) = delete;

  SqliteStmt& bind(int i, const std::string& v);
  SqliteStmt& bind(int i, std::int64_t v);
  SqliteStmt& bind(int i, double v);
  SqliteStmt& bind(int i, int v) { return bind(i, static_cast<std::int64_t>(v)); }
  bool step();  // true: a row is ready; false: done
  void run();   // steps to the end
  std::string text(int col) const;
  std::int64_t integer(int col) const;
  double real(int col) const;

 private:
  SqliteDb& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

// Runs `body` inside BEGIN IMMEDIATE … COMMIT (ROLLBACK when it throws).
template <class F>
auto sqlite_transaction(SqliteDb& db, F&& body) {
  db.exec("BEGIN IMMEDIATE");
  try {
    if constexpr (std::is_void_v<decltype(body())>) {
      body();
      db.exec("COMMIT");
    } else {
      auto result = body();
      db.exec("COMMIT");
      return result;
    }
  } catch (...) {
    sqlite3_exec(db.handle(), "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
}

}  // namespace frustum::server
