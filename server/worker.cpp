#include "server/worker.hpp"

#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <stdexcept>

#include "server/clock.hpp"
#include "server/grade_job.hpp"
#include "server/live_course.hpp"
#include "server/tokens.hpp"

extern char** environ;

namespace frustum::server {

Millis claim_lease(const WorkerOptions& o) { return (o.seconds + 5) * Millis{1000}; }

namespace {

GradeRecord gave_up(const SubmissionRecord& s, const std::string& name) {
  GradeRecord g;
  g.submission = s.id;
  g.result = R"({"error":"grading did not finish in time"})";
  g.set_version = s.set_version;
  g.graded_by = name;
  g.graded = now_ms();
  g.failed = true;
  return g;
}

}  // namespace

int run_worker(Course course, Store& store, const std::string& name, const WorkerOptions& options,
               const std::atomic<bool>& stop) {
  std::mutex exact_math;  // one thread: LiveCourse's lock is never contended here
  LiveCourse live(std::move(course), exact_math, 1000, [](const std::vector<Diagnostic>& errors) {
    for (const Diagnostic& d : errors) std::fprintf(stderr, "%s\n", d.format().c_str());
  });
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);  // the server gone (even by kill -9): stop too
  const pid_t parent = ::getppid();
  SolvedCache cache;
  const Millis lease = claim_lease(options);
  while (!stop.load() && ::getppid() == parent) {
    // A read first: an idle worker takes no write lock.
    const std::vector<SubmissionRecord> claimed =
        store.pending_count() > 0
            ? store.claim_some(name, now_ms(), lease, static_cast<std::size_t>(options.batch))
            : std::vector<SubmissionRecord>{};
    if (claimed.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(options.idle_ms));
      continue;
    }
    // Graded in turn, their grades written together: two write transactions a batch, not two a
    // submission (the database has one writer, which the server's submissions need too).
    const Millis started = now_ms();
    std::vector<GradeRecord> grades;
    std::size_t next = 0;
    for (; next < claimed.size(); ++next) {
      const SubmissionRecord& s = claimed[next];
      if (s.claims > options.max_claims) {
        grades.push_back(gave_up(s, name));
        continue;
      }
      // Half the lease gone: the rest go back, unworked, before another worker would take them.
      if (next > 0 && now_ms() - started > lease / 2) break;
      // The grader's own limits bound its work; this bounds its time: SIGALRM ends the process,
      // the pool starts another, and the claims run out and count against their submissions
      // (each then claimed alone, so one that kills its graders fails alone).
      ::alarm(static_cast<unsigned>(options.seconds));
      grades.push_back(grade_submission(*live.at(now_ms()), cache, s, name, now_ms()));
      ::alarm(0);
    }
    std::vector<std::int64_t> unworked;
    for (std::size_t i = next; i < claimed.size(); ++i) unworked.push_back(claimed[i].id);
    store.release(unworked, name);
    store.record_grades(grades, name);
  }
  return 0;
}

WorkerPool::WorkerPool(std::vector<std::string> argv_tail, int count,
                       std::vector<std::string> environment)
    : argv_tail_(std::move(argv_tail)), prefix_("w" + random_token(4)) {
  const auto named = [&](std::string_view entry) {
    const std::size_t equals = entry.find('=');
    if (equals == std::string_view::npos) return false;
    const std::string_view name = entry.substr(0, equals + 1);
    return std::any_of(environment.begin(), environment.end(),
                       [&](const std::string& e) { return e.rfind(name, 0) == 0; });
  };
  for (char** e = environ; *e != nullptr; ++e)
    if (!named(*e)) environment_.emplace_back(*e);
  environment_.insert(environment_.end(), environment.begin(), environment.end());
  for (int i = 0; i < count; ++i) pids_.push_back(spawn(i));
  watcher_ = std::thread([this] { watch(); });
}

WorkerPool::~WorkerPool() {
  stopping_ = true;
  watcher_.join();
  std::lock_guard lock(mutex_);
  for (const pid_t pid : pids_)
    if (pid > 0) ::kill(pid, SIGTERM);
  for (const pid_t pid : pids_)
    if (pid > 0) ::waitpid(pid, nullptr, 0);
}

pid_t WorkerPool::spawn(int index) {
  std::vector<std::string> args{"/proc/self/exe"};
  args.insert(args.end(), argv_tail_.begin(), argv_tail_.end());
  args.push_back("--worker");
  args.push_back(prefix_ + "-" + std::to_string(index));
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<char*> envp;
  for (std::string& e : environment_) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = -1;
  if (::posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), envp.data()) != 0)
    return -1;
  return pid;
}

void WorkerPool::watch() {
  while (!stopping_.load()) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < pids_.size(); ++i) {
      if (pids_[i] > 0 && ::waitpid(pids_[i], nullptr, WNOHANG) == 0) continue;
      if (stopping_.load()) break;
      pids_[i] = spawn(static_cast<int>(i));
      ++restarts_;
    }
  }
}

}  // namespace frustum::server
