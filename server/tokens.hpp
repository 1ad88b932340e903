// Secrets of `frustum serve`: 128-bit tokens from the OS random source, and the SHA-256 hashes
// that the store keeps in their place (a stolen database opens no link and no session).
#pragma once

#include <string>
#include <string_view>

namespace frustum::server {

// `bytes` random bytes from getrandom(2), as lower-case hex (32 characters for 16 bytes).
std::string random_token(std::size_t bytes = 16);
std::string sha256_hex(std::string_view data);
// Whether `a` and `b` are equal, in time that depends only on their lengths.
bool constant_time_equal(std::string_view a, std::string_view b);

}  // namespace frustum::server
