// Work in parts, side by side: part 0 on the calling thread, the others on threads of their own
// (where the system gives no more threads, the parts left run on the calling thread). For work
// that a caller splits itself and merges in order, so that its result does not depend on the
// number of parts that ran at once. No state outlives the call.
#pragma once

#include <atomic>
#include <exception>
#include <functional>
#include <system_error>
#include <thread>
#include <vector>

#include "solver/util/thread_team.hpp"

namespace frustum {

// Calls work(k) once for every k in 0 … parts − 1 and returns when all have returned. An
// exception from a part is rethrown here once every part has ended (the lowest part's, when
// several threw), never lost on its thread. With a team (thread_team.hpp), the parts run on its
// threads instead of threads started for them.
template <typename Work>
void side_by_side(int parts, const Work& work, ThreadTeam* team = nullptr) {
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(parts > 0 ? parts : 0));
  const auto run = [&](int k) {
    try {
      work(k);
    } catch (...) {
      errors[static_cast<std::size_t>(k)] = std::current_exception();
    }
  };
  if (team && parts > 1) {
    team->run(parts, std::function<void(int)>(run));
    for (const std::exception_ptr& e : errors)
      if (e) std::rethrow_exception(e);
    return;
  }
  std::vector<std::thread> pool;
  int started = 1;
  for (; started < parts; ++started) {
    try {
      pool.emplace_back(run, started);
    } catch (const std::system_error&) {
      break;
    }
  }
  run(0);
  for (int k = started; k < parts; ++k) run(k);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

// Items 0 … items − 1 shared by `workers` side by side, each worker taking the next item not yet
// taken as it finishes one (for items of uneven cost: a frame's rows are not alike). work(w, next)
// runs once on each worker w; next() gives it its next item, or −1 when none is left, so that
// what a worker keeps from one item to the next (a compressor, a buffer, its counts) lives in
// work's own frame.
template <typename Work>
void in_turn(int workers, int items, const Work& work, ThreadTeam* team = nullptr) {
  std::atomic<int> taken{0};
  const auto next = [&]() {
    const int k = taken.fetch_add(1, std::memory_order_relaxed);
    return k < items ? k : -1;
  };
  side_by_side(
      workers, [&](int w) { work(w, next); }, team);
}

}  // namespace frustum
