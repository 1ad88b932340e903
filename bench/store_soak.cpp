// The processes of the store-level soak (bench/serve_cluster_soak.sh --store): clients that
// submit and print each submission once the store has committed it, and grading workers that
// claim, "grade" (a pause standing in for the grader) and record, printing what they do. The
// script kills a worker with SIGKILL mid-run and then checks, in SQL, that every acknowledged
// submission is stored and graded exactly once.
//   frustum_store_soak submit URL COUNT CLIENTS
//       prints "ack ID" for each of COUNT submissions (CLIENTS threads, 13 students)
//   frustum_store_soak work URL NAME LEASE_MS GRADE_MS IDLE_EXIT_MS
//       prints "claim ID" and "graded ID" (or "late ID": the claim had been taken again);
//       exits once nothing has been pending for IDLE_EXIT_MS
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/postgres_store.hpp"
#include "server/store.hpp"

namespace {

using frustum::server::Millis;

Millis now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

std::mutex out_mutex;
// One line, flushed at once: a line on the output is a fact even if the process dies next.
void say(const char* what, std::int64_t id) {
  std::lock_guard lock(out_mutex);
  std::printf("%s %lld\n", what, static_cast<long long>(id));
  std::fflush(stdout);
}

int submit(const std::string& url, int count, int clients) {
  frustum::server::PostgresOptions options;
  options.connections = clients;
  const std::unique_ptr<frustum::server::Store> store =
      frustum::server::open_postgres_store(url, options);
  std::atomic<int> next = 0;
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c)
    threads.emplace_back([&] {
      for (int i = next++; i < count; i = next++) {
        const std::string student = "s" + std::to_string(i % 13);
        const frustum::server::SubmissionRecord r = store->submit(
            {student, "soak", "sha-soak", std::to_string(i), "p" + std::to_string(i % 3),
             R"({"z":")" + std::to_string(i) + R"("})", now_ms()});
        say("ack", r.id);
      }
    });
  for (std::thread& t : threads) t.join();
  return 0;
}

int work(const std::string& url, const std::string& name, Millis lease, Millis grade_ms,
         Millis idle_exit) {
  frustum::server::PostgresOptions options;
  options.connections = 1;
  options.worker = true;
  const std::unique_ptr<frustum::server::Store> store =
      frustum::server::open_postgres_store(url, options);
  Millis idle_since = now_ms();
  while (now_ms() - idle_since < idle_exit) {
    const std::optional<frustum::server::SubmissionRecord> s = store->claim(name, now_ms(), lease);
    if (!s) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    say("claim", s->id);
    std::this_thread::sleep_for(std::chrono::milliseconds(grade_ms));
    const bool recorded = store->record_grade(
        {s->id, R"({"answers":)" + s->answers + "}", 1, 1, s->set_version, name, now_ms(), false},
        name);
    say(recorded ? "graded" : "late", s->id);
    idle_since = now_ms();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.size() == 4 && args[0] == "submit")
      return submit(args[1], std::stoi(args[2]), std::stoi(args[3]));
    if (args.size() == 6 && args[0] == "work")
      return work(args[1], args[2], std::stoll(args[3]), std::stoll(args[4]), std::stoll(args[5]));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "frustum_store_soak: %s\n", e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: frustum_store_soak submit URL COUNT CLIENTS\n"
               "       frustum_store_soak work URL NAME LEASE_MS GRADE_MS IDLE_EXIT_MS\n");
  return 2;
}
