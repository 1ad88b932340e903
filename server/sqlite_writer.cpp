#include "server/sqlite_writer.hpp"

#include <vector>

namespace frustum::server {

SqliteWriter::SqliteWriter(const std::string& path, SqliteSync sync)
    : db_(path, sync), thread_([this] { loop(); }) {}

SqliteWriter::~SqliteWriter() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  ready_.notify_one();
  thread_.join();
}

void SqliteWriter::run(std::function<void(SqliteDb&)> write) {
  Job job{std::move(write), {}};
  std::future<void> done = job.done.get_future();
  {
    std::lock_guard lock(mutex_);
    queue_.push_back(std::move(job));
  }
  ready_.notify_one();
  done.get();
}

void SqliteWriter::loop() {
  for (;;) {
    std::deque<Job> batch;
    {
      std::unique_lock lock(mutex_);
      ready_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;
      batch.swap(queue_);
    }
    commit_batch(batch);
  }
}

void SqliteWriter::commit_batch(std::deque<Job>& batch) {
  std::vector<std::exception_ptr> errors(batch.size());
  try {
    sqlite_transaction(db_, [&] {
      for (std::size_t i = 0; i < batch.size(); ++i) {
        db_.exec("SAVEPOINT job");
        try {
          batch[i].write(db_);
          db_.exec("RELEASE job");
        } catch (...) {
          errors[i] = std::current_exception();
          db_.exec("ROLLBACK TO job");
          db_.exec("RELEASE job");
        }
      }
    });
  } catch (...) {
    // The commit itself failed: nothing of the batch is stored, and every caller hears it.
    for (auto& e : errors) e = std::current_exception();
  }
  for (std::size_t i = 0; i < batch.size(); ++i) {
    if (errors[i])
      batch[i].done.set_exception(errors[i]);
    else
      batch[i].done.set_value();
  }
}

}  // namespace frustum::server
