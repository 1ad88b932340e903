// The few system calls every writer of outputs shares (atomic files, file batches, a batch's
// output transaction), each failure turned into one sentence naming the path.
#pragma once

#include <cerrno>
#include <string>

namespace frustum {

// Throws std::runtime_error "PATH: WHAT: strerror(error)".
[[noreturn]] void fail(const std::string& path, const std::string& what, int error = errno);

// Writes all of `content` to `fd` (a short write is continued); `path` names it in the error.
void write_all(int fd, const std::string& content, const std::string& path);

// Flushes a directory's entries (a rename inside it) to disk.
void sync_directory(const std::string& dir);

}  // namespace frustum
