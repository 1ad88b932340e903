// Group commit for SQLite's single writer: request threads queue their writes, one thread
// runs every write waiting at that moment inside one transaction (each in a savepoint, so one
// failing write fails alone), commits once, and only then tells each caller. Under load one
// fsync serves many submissions; alone, a write waits only for its own commit.
#pragma once

#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <mutex>
#include <thread>

#include "server/sqlite_db.hpp"

namespace frustum::server {

class SqliteWriter {
 public:
  SqliteWriter(const std::string& path, SqliteSync sync);
  ~SqliteWriter();  // finishes the queued writes, then stops

  // Runs `write` on the writer's connection inside a transaction and returns once it is
  // committed; rethrows what `write` threw (its changes then rolled back).
  void run(std::function<void(SqliteDb&)> write);

 private:
  struct Job {
    std::function<void(SqliteDb&)> write;
    std::promise<void> done;
  };
  void loop();
  void commit_batch(std::deque<Job>& batch);

  SqliteDb db_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Job> queue_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace frustum::server
