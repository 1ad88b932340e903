// The wall clock in ms since the epoch: the one place the server reads it (handlers take times
// as arguments, so tests choose them).
#pragma once

#include <chrono>
#include <cstdint>

namespace frustum::server {

inline std::int64_t now_ms() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace frustum::server
