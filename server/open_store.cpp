#include <algorithm>
#include <chrono>
#include <thread>

#include "server/postgres_connection.hpp"
#include "server/postgres_store.hpp"
#include "server/sqlite_migrations.hpp"
#include "server/sqlite_store.hpp"
#include "server/store.hpp"

namespace frustum::server {

std::unique_ptr<Store> open_store(const std::string& url, StoreRole role) {
  constexpr std::string_view kSqlite = "sqlite:";
  if (url.rfind(kSqlite, 0) == 0) {
    const std::string path = url.substr(kSqlite.size());
    if (path.empty()) throw StoreError("--db sqlite:PATH needs a file name after sqlite:");
    return open_sqlite_store(path,
                             role == StoreRole::Worker ? SqliteSync::Normal : SqliteSync::Full);
  }
  if (url.rfind("postgresql://", 0) == 0 || url.rfind("postgres://", 0) == 0) {
    PostgresOptions options;
    options.worker = role == StoreRole::Worker;
    return open_postgres_store(url, options);
  }
  throw StoreError("unknown database '" + redact_postgres_url(url) +
                   "': use sqlite:PATH or postgresql://USER@HOST/DATABASE");
}

std::int64_t Store::wait_for_change(std::int64_t mark, Millis timeout) {
  constexpr Millis kPoll = 250;
  for (Millis waited = 0;; waited += kPoll) {
    const std::int64_t now = change_mark();
    if (now != mark || waited >= timeout) return now;
    std::this_thread::sleep_for(std::chrono::milliseconds(std::min(kPoll, timeout - waited)));
  }
}

std::optional<SubmissionRecord> Store::claim(const std::string& worker, Millis now, Millis lease) {
  std::vector<SubmissionRecord> one = claim_some(worker, now, lease, 1);
  if (one.empty()) return std::nullopt;
  return std::move(one.front());
}

bool Store::record_grade(const GradeRecord& g, const std::string& worker) {
  return record_grades({g}, worker).front();
}

int latest_schema_version() { return sqlite_latest_version(); }

}  // namespace frustum::server
