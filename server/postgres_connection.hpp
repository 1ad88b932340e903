// One libpq connection to PostgreSQL, for the PostgreSQL store and its tests: statements with
// parameters (text format), named prepared statements, errors as StoreError that name the server
// (host, port, database, user) and never the password.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "server/store.hpp"

struct pg_conn;

namespace frustum::server {

// A failed statement; `sqlstate` is PostgreSQL's five-character code (23505: unique violation).
class PostgresError : public StoreError {
 public:
  PostgresError(const std::string& message, std::string sqlstate)
      : StoreError(message), sqlstate(std::move(sqlstate)) {}
  std::string sqlstate;
};

// A statement's rows as text (NULL reads as ""), and how many rows it changed.
struct PgRows {
  std::vector<std::vector<std::string>> rows;
  std::size_t changed = 0;
};

// "postgresql://frustum@127.0.0.1:5432/frustum" for "postgresql://frustum:SECRET@127.0.0.1…":
// a URL fit for messages and logs.
std::string redact_postgres_url(const std::string& url);

class PgConnection {
 public:
  // Connects (10 s time-out unless the URL sets connect_timeout); throws StoreError naming the
  // server when it cannot.
  explicit PgConnection(const std::string& url);
  ~PgConnection();
  PgConnection(const PgConnection&) = delete;
  PgConnection& operator=(const PgConnection&) = delete;

  // Without parameters, `sql` may hold several statements (the last one's rows are returned).
  PgRows exec(const std::string& sql, const std::vector<std::string>& params = {});
  void prepare(const std::string& name, const std::string& sql);
  PgRows run(const std::string& name, const std::vector<std::string>& params);
  // False once the server has gone (restarted, killed); such a connection is dropped.
  bool usable() const;
  // usable(), after reading what the server sent an idle connection: a server that ended the
  // session (restart, pg_terminate_backend) has closed it, and this sees so before any
  // statement is sent on it.
  bool alive();
  // After LISTEN on this connection: waits up to `timeout_ms` for a notification; true when one
  // (or more; all are taken) came.
  bool wait_notification(int timeout_ms);

 private:
  pg_conn* conn_ = nullptr;
  std::string where_;  // "the PostgreSQL server at 127.0.0.1:5432 (database …, user …)"
  std::string password_;
};

}  // namespace frustum::server
