#include "batch/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "batch/file_io.hpp"

namespace frustum {

namespace fs = std::filesystem;

namespace {

// Creates a fresh file `pattern` + a suffix, exclusively, with mode 0644 (less what the umask
// takes away, as for any file a program writes): the suffix mixes the process, the clock and the
// attempt, and a name already taken is passed over. No permissions are set afterwards.
int create_temporary(const std::string& pattern, std::string& name) {
  constexpr int kAttempts = 100;
  const std::uint64_t process = static_cast<std::uint64_t>(::getpid());
  for (int attempt = 0; attempt < kAttempts; ++attempt) {
    timespec now{};
    ::clock_gettime(CLOCK_MONOTONIC, &now);
    std::uint64_t mix = (process << 40) ^ static_cast<std::uint64_t>(now.tv_nsec) ^
                        (static_cast<std::uint64_t>(now.tv_sec) << 30) ^
                        (static_cast<std::uint64_t>(attempt) * 0x9e3779b97f4a7c15ULL);
    mix ^= mix >> 29;
    name = pattern + fmt::format("{:012x}", mix & 0xffffffffffffULL);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  errno = EEXIST;
  return -1;
}

// Writes `content` to a fresh temporary file beside `path` (synced when `sync`); returns its
// name. Nothing is left behind on failure.
std::string write_temporary(const std::string& path, const std::string& content, bool sync) {
  const fs::path target(path);
  const std::string pattern =
      (target.has_parent_path() ? target.parent_path() / ("." + target.filename().string())
                                : fs::path("." + target.filename().string()))
          .string() +
      ".";
  std::string tmp;
  int fd = create_temporary(pattern, tmp);
  if (fd < 0 && errno == ENOENT && target.has_parent_path()) {
    // The directory is made when it is missing, not looked up before every file.
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (ec) throw std::runtime_error(path + ": cannot create its directory: " + ec.message());
    fd = create_temporary(pattern, tmp);
  }
  if (fd < 0) fail(path, "cannot create a temporary file");
  try {
    write_all(fd, content, path);
    if (sync && fsync(fd) != 0) fail(path, "cannot flush");
  } catch (...) {
    ::close(fd);
    ::unlink(tmp.c_str());
    throw;
  }
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    fail(path, "cannot close", error);
  }
  return tmp;
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    fail(path, "cannot rename into place", error);
  }
}

// Flushes every file system change under `dir`'s file system (data and metadata) to disk.
void sync_file_system(const std::string& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) fail(dir, "cannot open to flush");
  const int r = ::syncfs(fd);
  const int error = errno;
  ::close(fd);
  if (r != 0) fail(dir, "cannot flush", error);
}

std::string parent_of(const std::string& path) {
  const fs::path p = fs::path(path).parent_path();
  return p.empty() ? std::string(".") : p.string();
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& content) {
  rename_into_place(write_temporary(path, content, true), path);
}

FileBatch::~FileBatch() {
  try {
    wait_commit();
  } catch (const std::exception&) {  // already reported by the caller's own wait, or moot
  }
  end_committer();
  for (const Pending& p : pending_) ::unlink(p.temporary.c_str());
}

namespace {

// The committing child's messages go through a socket pair: a write to a child that has ended
// is then an error (MSG_NOSIGNAL), where a pipe would end this process with SIGPIPE.
bool send_all(int fd, const std::string& data) {
  std::size_t sent = 0;
  while (sent < data.size()) {
    const ssize_t n = ::send(fd, data.data() + sent, data.size() - sent, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    sent += static_cast<std::size_t>(n);
  }
  return true;
}

bool read_exact(int fd, char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::read(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// Lengths in this machine's byte order: both ends are this program on this machine.
void put_length(std::string& out, std::uint64_t n) {
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
}

// Lengths and texts from the socket. Buffered at the committer's end, read in large blocks: a
// group of 8,192 files arrives as one message, which unbuffered reads would take in four system
// calls per file. Unbuffered at this process's end, which reads one reply at a time and nothing
// past it.
class MessageReader {
 public:
  MessageReader(int fd, bool buffered) : fd_(fd), buffered_(buffered) {}

  bool read_exact(char* data, std::size_t size) {
    if (!buffered_) return frustum::read_exact(fd_, data, size);
    while (size > 0) {
      if (at_ == buffer_.size() && !fill()) return false;
      const std::size_t n = std::min(size, buffer_.size() - at_);
      std::memcpy(data, buffer_.data() + at_, n);
      at_ += n;
      data += n;
      size -= n;
    }
    return true;
  }

  bool read_length(std::uint64_t& n) { return read_exact(reinterpret_cast<char*>(&n), sizeof n); }

  bool read_text(std::string& text) {
    std::uint64_t n = 0;
    if (!read_length(n) || n > (std::uint64_t(1) << 32)) return false;
    text.resize(n);
    return read_exact(text.data(), n);
  }

 private:
  static constexpr std::size_t kBlock = 1 << 16;

  bool fill() {
    buffer_.resize(kBlock);
    for (;;) {
      const ssize_t n = ::read(fd_, buffer_.data(), kBlock);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) return false;
      buffer_.resize(static_cast<std::size_t>(n));
      at_ = 0;
      return true;
    }
  }

  int fd_;
  bool buffered_;
  std::string buffer_;
  std::size_t at_ = 0;
};

}  // namespace

void FileBatch::serve_commits(int fd) {
  // A group: its count, then each file's temporary name and target. A count of 0 ends the
  // child, as does the end of the stream (this process gone).
  MessageReader in(fd, true);
  for (;;) {
    std::uint64_t count = 0;
    if (!in.read_length(count) || count == 0) ::_exit(0);
    std::vector<Pending> group(count);
    for (Pending& p : group)
      if (!in.read_text(p.temporary) || !in.read_text(p.target)) ::_exit(0);
    std::string message;
    try {
      commit_pending(group);
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
      message = "the files of a group could not be put in place";
    }
    for (const Pending& p : group) ::unlink(p.temporary.c_str());  // those not put in place
    std::string reply;
    put_length(reply, message.size());
    reply += message;
    if (!send_all(fd, reply)) ::_exit(0);
  }
}

void FileBatch::end_committer() {
  if (committer_ < 0) return;
  std::string quit;
  put_length(quit, 0);
  (void)send_all(committer_fd_, quit);
  ::close(committer_fd_);
  int status = 0;
  while (::waitpid(committer_, &status, 0) < 0 && errno == EINTR) {
  }
  committer_ = -1;
  committer_fd_ = -1;
}

bool FileBatch::start_committer() {
  if (committer_ >= 0) return true;
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) return false;
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return false;
  }
  if (pid == 0) {
    ::close(fds[0]);
    serve_commits(fds[1]);
  }
  ::close(fds[1]);
  committer_ = pid;
  committer_fd_ = fds[0];
  return true;
}

void FileBatch::commit_in_background() {
  wait_commit();
  if (pending_.empty()) return;
  if (!start_committer()) {
    commit();
    return;
  }
  std::string request;
  put_length(request, pending_.size());
  for (const Pending& p : pending_) {
    put_length(request, p.temporary.size());
    request += p.temporary;
    put_length(request, p.target.size());
    request += p.target;
  }
  if (!send_all(committer_fd_, request)) {  // the child has ended: the group is committed here
    end_committer();
    commit();
    return;
  }
  committing_ = true;
  pending_.clear();  // the child's to rename now
}

void FileBatch::wait_commit() {
  if (!committing_) return;
  committing_ = false;
  std::string message;
  if (!MessageReader(committer_fd_, false).read_text(message)) {
    end_committer();
    throw std::runtime_error(
        "the files of a group could not be put in place (the process that "
        "renames them stopped)");
  }
  if (!message.empty()) throw std::runtime_error(message);
}

void FileBatch::stage(const std::string& path, const std::string& content) {
  adopt(write_staged(path, content), path);
}

std::string FileBatch::write_staged(const std::string& path, const std::string& content) {
  return write_temporary(path, content, false);
}

void FileBatch::rewrite_staged(const std::string& temporary, const std::string& path,
                               const std::string& content) {
  // Written over, then cut to size: truncating to nothing first would free the file's blocks
  // only to take them again.
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CLOEXEC);
  if (fd < 0) fail(path, "cannot write its temporary file");
  try {
    write_all(fd, content, path);
    if (::ftruncate(fd, static_cast<off_t>(content.size())) != 0) fail(path, "cannot write");
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail(path, "cannot close");
}

void FileBatch::adopt(const std::string& temporary, const std::string& path) {
  pending_.push_back({temporary, path});
}

void FileBatch::discard(const std::string& temporary) { ::unlink(temporary.c_str()); }

void FileBatch::commit() {
  wait_commit();
  commit_pending(pending_);
}

// Syncs, then renames each file over its target, taking it off `pending` (what is left there
// on an error has not been put in place).
void FileBatch::commit_pending(std::vector<Pending>& pending) {
  if (pending.empty()) return;
  std::vector<std::string> dirs;
  for (const Pending& p : pending)
    if (std::find(dirs.begin(), dirs.end(), parent_of(p.target)) == dirs.end())
      dirs.push_back(parent_of(p.target));
  for (const std::string& d : dirs) sync_file_system(d);  // one sync per file system in practice
  while (!pending.empty()) {
    const Pending p = std::move(pending.back());
    pending.pop_back();
    rename_into_place(p.temporary, p.target);
  }
  for (const std::string& d : dirs) sync_directory(d);
}

}  // namespace frustum
