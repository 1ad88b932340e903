#include "server/rate_limit.hpp"

#include <algorithm>
#include <cmath>

namespace frustum::server {

int RateLimiter::take(const std::string& key, Millis now) {
  std::lock_guard lock(mutex_);
  // Full buckets say nothing: dropped once a minute so that memory follows the active keys.
  if (now - last_sweep_ > 60'000) {
    std::erase_if(buckets_, [&](const auto& kv) {
      return kv.second.tokens + (now - kv.second.at) / 1000.0 * rate_ >= burst_;
    });
    last_sweep_ = now;
  }
  auto [it, fresh] = buckets_.try_emplace(key, Bucket{burst_, now});
  Bucket& b = it->second;
  b.tokens = std::min(burst_, b.tokens + std::max<Millis>(0, now - b.at) / 1000.0 * rate_);
  b.at = now;
  if (b.tokens >= 1) {
    b.tokens -= 1;
    return 0;
  }
  return std::max(1, static_cast<int>(std::ceil((1 - b.tokens) / rate_)));
}

}  // namespace frustum::server
