// Grading workers. `frustum serve` starts them as processes of its own binary (posix_spawn of
// /proc/self/exe with `serve COURSE --db URL --worker NAME`: never fork from the threaded
// server), restarts one that dies, and stops them with itself. Each claims pending submissions
// from the store a few at a time, so a submission left pending by a restart is graded then.
#pragma once

#include <sys/types.h>

#include <atomic>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/course.hpp"
#include "server/store.hpp"

namespace frustum::server {

struct WorkerOptions {
  int seconds = 10;    // one submission's grading; the worker is killed beyond it
  int max_claims = 3;  // a submission claimed this often (its graders died) is failed
  int idle_ms = 10;    // pause when nothing is pending
  int batch = 16;      // submissions claimed at once (a lease run out: one, alone)
};

// How long a claim holds: past it, another worker takes the submission again.
Millis claim_lease(const WorkerOptions& o);

// The worker's loop, until `stop` or its parent dies. Returns the exit status. Each submission
// is graded against its set as the file is then (live_course.hpp), as the server serves it.
int run_worker(Course course, Store& store, const std::string& name, const WorkerOptions& options,
               const std::atomic<bool>& stop);

class WorkerPool {
 public:
  // `argv_tail` follows the binary's path: {"serve", COURSE, "--db", URL}; each worker adds
  // "--worker NAME".
  // `environment`: NAME=VALUE entries the workers get on top of (in place of) this process's
  // own — how a secret such as the database URL reaches them without showing in `ps`.
  WorkerPool(std::vector<std::string> argv_tail, int count,
             std::vector<std::string> environment = {});
  ~WorkerPool();  // SIGTERM to every worker, then waits for them
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;
  std::size_t restarts() const { return restarts_.load(); }

 private:
  pid_t spawn(int index);
  void watch();

  std::vector<std::string> argv_tail_;
  std::vector<std::string> environment_;  // the workers' whole environment
  std::string prefix_;                    // worker names: PREFIX-INDEX
  std::mutex mutex_;
  std::vector<pid_t> pids_;
  std::atomic<bool> stopping_{false};
  std::atomic<std::size_t> restarts_{0};
  std::thread watcher_;
};

}  // namespace frustum::server
