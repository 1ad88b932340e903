// Threads kept for several rounds of work in parts. side_by_side starts a thread for each part of
// each round and ends it after, at a cost to the calling thread that is a noticeable share of a
// short round, paid again by a caller that runs several short rounds in a row (a render: its
// geometry, its fill, then the PNG's colour scan and compression, four rounds of a few
// milliseconds). A team starts its helpers once, when it is made (a render makes it before it
// reads its scene, so that the start overlaps the reading), and each round only wakes them.
// A team belongs to the one caller that made it and ends with it: no state outlives it.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace frustum {

class ThreadTeam {
 public:
  // threads − 1 helpers (fewer where the system gives no more threads; none for threads ≤ 1).
  explicit ThreadTeam(int threads);
  ~ThreadTeam();  // ends the helpers
  ThreadTeam(const ThreadTeam&) = delete;
  ThreadTeam& operator=(const ThreadTeam&) = delete;

  // The calling thread and the helpers.
  int threads() const { return 1 + static_cast<int>(helpers_.size()); }
  // work(k) for every k in 0 … parts − 1 (parts ≤ threads()): part 0 on the calling thread, part
  // k on helper k; returns when every part has returned. `work` must not throw (side_by_side
  // catches each part's exception). One round at a time, from the thread that made the team.
  void run(int parts, const std::function<void(int)>& work);

 private:
  void serve(int helper);

  std::mutex mutex_;
  std::condition_variable wake_, done_;
  std::uint64_t round_ = 0;  // counts the rounds: a helper works once per new value
  int parts_ = 0;            // this round's
  int left_ = 0;             // helpers' parts of this round not yet returned
  bool ending_ = false;
  const std::function<void(int)>* work_ = nullptr;
  std::vector<std::thread> helpers_;
};

}  // namespace frustum
