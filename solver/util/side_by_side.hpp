// Work in parts, side by side: part 0 on the calling thread, the others on threads of their own
// (where the system gives no more threads, the parts left run on the calling thread). For work
// that a caller splits itself and merges in order, so that its result does not depend on the
// number of parts that ran at once. No state outlives the call.
#pragma once

#include <system_error>
#include <thread>
#include <vector>

namespace frustum {

// Calls work(k) once for every k in 0 … parts − 1 and returns when all have returned. `work`
// must not throw (catch inside it and keep the error with the part).
template <typename Work>
void side_by_side(int parts, const Work& work) {
  std::vector<std::thread> pool;
  int started = 1;
  for (; started < parts; ++started) {
    try {
      pool.emplace_back([&work, started] { work(started); });
    } catch (const std::system_error&) {
      break;
    }
  }
  work(0);
  for (int k = started; k < parts; ++k) work(k);
  for (std::thread& t : pool) t.join();
}

}  // namespace frustum
