#include "solver/util/thread_team.hpp"

#include <algorithm>
#include <system_error>

namespace frustum {

ThreadTeam::ThreadTeam(int threads) {
  for (int k = 1; k < threads; ++k) {
    try {
      helpers_.emplace_back([this, k] { serve(k); });
    } catch (const std::system_error&) {
      break;  // the parts past the last helper run on the calling thread
    }
  }
}

ThreadTeam::~ThreadTeam() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    ending_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void ThreadTeam::run(int parts, const std::function<void(int)>& work) {
  const int helped = std::min(parts, threads()) - 1;  // parts on helpers
  if (helped > 0) {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      work_ = &work;
      parts_ = helped + 1;
      left_ = helped;
      ++round_;
    }
    wake_.notify_all();
  }
  work(0);
  for (int k = helped + 1; k < parts; ++k) work(k);  // more parts than threads: here
  if (helped > 0) {
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return left_ == 0; });
    work_ = nullptr;
  }
}

void ThreadTeam::serve(int helper) {
  std::uint64_t seen = 0;
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return ending_ || round_ != seen; });
    if (ending_) return;
    seen = round_;
    if (helper >= parts_) continue;  // a round with fewer parts than helpers
    const std::function<void(int)>* work = work_;
    lock.unlock();
    (*work)(helper);
    lock.lock();
    if (--left_ == 0) done_.notify_one();
  }
}

}  // namespace frustum
