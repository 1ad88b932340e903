// The random numbers of generated variants: splitmix64 (Steele, Lea, Flood 2014) with our own
// mapping to ranges, so that a seed gives the same variant on every machine, compiler and
// standard library (std:: distributions differ between libraries). Seeds are FNV-1a 64 hashes
// of text (variant_seed).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace frustum {

// FNV-1a, 64 bits: offset basis 0xcbf29ce484222325, prime 0x100000001b3, over the bytes.
constexpr std::uint64_t fnv1a64(std::string_view bytes,
                                std::uint64_t hash = 0xcbf29ce484222325ULL) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : state_(seed) {}

  // splitmix64: the state advances by the golden-ratio increment, the output is mixed.
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

  // Uniform in [0, n), n ≥ 1, by rejection: outputs below 2^64 mod n are redrawn, so every
  // residue has the same number of preimages (no modulo bias).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t limit = (0 - n) % n;  // (2^64 − n) mod n = 2^64 mod n
    for (;;) {
      const std::uint64_t r = next();
      if (r >= limit) return r % n;
    }
  }

  // Uniform integer in [lo, hi] (inclusive; lo ≤ hi).
  std::int64_t integer(std::int64_t lo, std::int64_t hi) {
    const auto span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo);
    return lo + static_cast<std::int64_t>(span == UINT64_MAX ? next() : below(span + 1));
  }

  // Uniform integer in [lo, hi] other than 0.
  std::int64_t nonzero(std::int64_t lo, std::int64_t hi) {
    for (;;)
      if (const std::int64_t v = integer(lo, hi); v != 0) return v;
  }

  // True with probability num/den.
  bool chance(std::uint64_t num, std::uint64_t den) { return below(den) < num; }

  template <typename T>
  const T& pick(const std::vector<T>& items) {
    return items[static_cast<std::size_t>(below(items.size()))];
  }

 private:
  std::uint64_t state_;
};

}  // namespace frustum
