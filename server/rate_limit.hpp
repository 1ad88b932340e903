// Per-key token buckets (a key is a session's hash): `rate` requests a second on average,
// `burst` at once. A refused request learns how long to wait (HTTP 429 with Retry-After).
#pragma once

#include <map>
#include <mutex>
#include <string>

#include "server/store.hpp"

namespace frustum::server {

class RateLimiter {
 public:
  RateLimiter(double rate, double burst) : rate_(rate), burst_(burst) {}
  // 0 when allowed (and counted); else the seconds to wait, at least 1.
  int take(const std::string& key, Millis now);

 private:
  struct Bucket {
    double tokens;
    Millis at;
  };
  double rate_, burst_;
  std::mutex mutex_;
  std::map<std::string, Bucket> buckets_;
  Millis last_sweep_ = 0;
};

}  // namespace frustum::server
