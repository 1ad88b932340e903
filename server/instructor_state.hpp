// What the instructors' side of `frustum serve` keeps between requests (part of StudentApp,
// never process-wide): the class's solved variants for the copy check, and how many requests
// wait for the class to change.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "server/copy_signals.hpp"
#include "server/grade_job.hpp"

namespace frustum::server {

struct InstructorState {
  std::mutex mutex;  // guards `solved` and `copies` (taken before StudentApp::exact_math)
  SolvedCache solved{1024};
  // The last copy check of each set, with the class's change mark it was made at.
  std::map<std::string, std::pair<std::int64_t, CopyReport>> copies;
  std::atomic<int> waiting{0};  // requests in wait_for_change
};

}  // namespace frustum::server
