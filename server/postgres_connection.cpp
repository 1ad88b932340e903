#include "server/postgres_connection.hpp"

#include <libpq-fe.h>
#include <poll.h>

#include <memory>

namespace frustum::server {

namespace {

// libpq's messages end in a newline and continue lines with "\n\t".
std::string one_line(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\t') {
      if (!out.empty() && out.back() != ' ') out += ' ';
    } else {
      out += c;
    }
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

std::string without(std::string text, const std::string& secret) {
  if (secret.empty()) return text;
  for (std::size_t at = text.find(secret); at != std::string::npos; at = text.find(secret, at))
    text.replace(at, secret.size(), "****");
  return text;
}

// The password written in a URL's user part ("scheme://user:PASSWORD@host…"), or "".
std::string url_password(const std::string& url) {
  const std::size_t scheme = url.find("://");
  if (scheme == std::string::npos) return "";
  const std::size_t start = scheme + 3;
  const std::size_t end = url.find_first_of("/?", start);
  const std::string authority = url.substr(start, end == std::string::npos ? end : end - start);
  const std::size_t at = authority.rfind('@');
  if (at == std::string::npos) return "";
  const std::size_t colon = authority.find(':');
  if (colon == std::string::npos || colon > at) return "";
  return authority.substr(colon + 1, at - colon - 1);
}

}  // namespace

std::string redact_postgres_url(const std::string& url) {
  const std::string password = url_password(url);
  if (password.empty()) return url;
  const std::size_t at = url.find(":" + password + "@");
  if (at == std::string::npos) return without(url, password);
  return url.substr(0, at) + url.substr(at + password.size() + 1);
}

PgConnection::PgConnection(const std::string& url) : password_(url_password(url)) {
  // What the URL names, for messages (the parse never connects).
  char* parse_error = nullptr;
  std::unique_ptr<PQconninfoOption, void (*)(PQconninfoOption*)> options(
      PQconninfoParse(url.c_str(), &parse_error), PQconninfoFree);
  if (!options) {
    std::string message = parse_error ? one_line(parse_error) : "out of memory";
    PQfreemem(parse_error);
    throw StoreError("invalid PostgreSQL URL " + redact_postgres_url(url) + ": " +
                     without(message, password_));
  }
  std::string host = "localhost", port = "5432", database, user;
  for (const PQconninfoOption* o = options.get(); o->keyword; ++o) {
    if (!o->val || !*o->val) continue;
    const std::string key = o->keyword;
    if (key == "host" || key == "hostaddr") host = o->val;
    if (key == "port") port = o->val;
    if (key == "dbname") database = o->val;
    if (key == "user") user = o->val;
    if (key == "password") password_ = o->val;
  }
  where_ = "the PostgreSQL server at " + host + ":" + port;
  if (!database.empty() || !user.empty())
    where_ += " (database " + (database.empty() ? user : database) +
              (user.empty() ? "" : ", user " + user) + ")";

  // Earlier keywords are defaults the URL (dbname, expanded) overrides.
  const char* keys[] = {"connect_timeout", "application_name", "dbname", nullptr};
  const char* values[] = {"10", "frustum serve", url.c_str(), nullptr};
  conn_ = PQconnectdbParams(keys, values, 1);
  if (!conn_ || PQstatus(conn_) != CONNECTION_OK) {
    std::string message = conn_ ? one_line(PQerrorMessage(conn_)) : "out of memory";
    PQfinish(conn_);
    conn_ = nullptr;
    throw StoreError("cannot connect to " + where_ + ": " + without(message, password_));
  }
  // The server's notices ("relation … already exists, skipping") are not for the terminal.
  PQsetNoticeProcessor(
      conn_, [](void*, const char*) {}, nullptr);
}

PgConnection::~PgConnection() { PQfinish(conn_); }

bool PgConnection::usable() const { return PQstatus(conn_) == CONNECTION_OK; }

bool PgConnection::alive() {
  // A server ending a session sends an error, then closes: each read takes one of them.
  for (int reads = 0; reads < 8 && usable(); ++reads) {
    pollfd ready{PQsocket(conn_), POLLIN, 0};
    if (::poll(&ready, 1, 0) != 1) break;
    if (PQconsumeInput(conn_) != 1) return false;
  }
  return usable();
}

bool PgConnection::wait_notification(int timeout_ms) {
  const auto take = [&] {
    bool any = false;
    while (PGnotify* n = PQnotifies(conn_)) {
      any = true;
      PQfreemem(n);
    }
    return any;
  };
  if (take()) return true;
  pollfd ready{PQsocket(conn_), POLLIN, 0};
  if (::poll(&ready, 1, timeout_ms) != 1) return false;
  if (PQconsumeInput(conn_) != 1) return false;
  return take();
}

namespace {

PgRows rows_of(PGresult* raw, const std::string& what, const std::string& where,
               const std::string& password, pg_conn* conn) {
  std::unique_ptr<PGresult, void (*)(PGresult*)> result(raw, PQclear);
  const ExecStatusType status = result ? PQresultStatus(result.get()) : PGRES_FATAL_ERROR;
  if (status != PGRES_TUPLES_OK && status != PGRES_COMMAND_OK) {
    const char* state = result ? PQresultErrorField(result.get(), PG_DIAG_SQLSTATE) : nullptr;
    const std::string message =
        one_line(result ? PQresultErrorMessage(result.get()) : PQerrorMessage(conn));
    throw PostgresError(what + " failed on " + where + ": " + without(message, password),
                        state ? state : "");
  }
  PgRows out;
  const int n = PQntuples(result.get()), columns = PQnfields(result.get());
  out.rows.reserve(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) {
    std::vector<std::string> row;
    row.reserve(static_cast<std::size_t>(columns));
    for (int c = 0; c < columns; ++c)
      row.emplace_back(PQgetvalue(result.get(), r, c),
                       static_cast<std::size_t>(PQgetlength(result.get(), r, c)));
    out.rows.push_back(std::move(row));
  }
  const char* changed = PQcmdTuples(result.get());
  if (changed && *changed) out.changed = std::stoull(changed);
  return out;
}

std::vector<const char*> pointers(const std::vector<std::string>& params) {
  std::vector<const char*> out;
  out.reserve(params.size());
  for (const std::string& p : params) out.push_back(p.c_str());
  return out;
}

}  // namespace

PgRows PgConnection::exec(const std::string& sql, const std::vector<std::string>& params) {
  // Without parameters: the simple protocol, which takes several statements (a migration).
  if (params.empty())
    return rows_of(PQexec(conn_, sql.c_str()), "a statement", where_, password_, conn_);
  const std::vector<const char*> values = pointers(params);
  return rows_of(PQexecParams(conn_, sql.c_str(), static_cast<int>(params.size()), nullptr,
                              values.data(), nullptr, nullptr, 0),
                 "a statement", where_, password_, conn_);
}

void PgConnection::prepare(const std::string& name, const std::string& sql) {
  rows_of(PQprepare(conn_, name.c_str(), sql.c_str(), 0, nullptr), "preparing statement " + name,
          where_, password_, conn_);
}

PgRows PgConnection::run(const std::string& name, const std::vector<std::string>& params) {
  const std::vector<const char*> values = pointers(params);
  return rows_of(PQexecPrepared(conn_, name.c_str(), static_cast<int>(params.size()), values.data(),
                                nullptr, nullptr, 0),
                 "statement " + name, where_, password_, conn_);
}

}  // namespace frustum::server
