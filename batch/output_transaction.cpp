#include "batch/output_transaction.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>

#include "batch/file_io.hpp"

namespace frustum {

namespace fs = std::filesystem;

namespace {

constexpr const char* kStateDir = ".frustum";
constexpr const char* kSetAsideDir = "set-aside";

// The number of a run directory ("run-7" → 7), or nothing for another name.
std::optional<unsigned long> run_number(const std::string& name) {
  if (name.rfind("run-", 0) != 0 || name.size() == 4) return std::nullopt;
  char* end = nullptr;
  const unsigned long n = std::strtoul(name.c_str() + 4, &end, 10);
  if (*end != '\0') return std::nullopt;
  return n;
}

// Every directory the files of a run lie in ("katex/fonts/f.woff2" → "katex", "katex/fonts"),
// and the names published as directories.
std::unordered_set<std::string> directories_of(const std::unordered_set<std::string>& files,
                                               const std::vector<std::string>& names) {
  std::unordered_set<std::string> dirs;
  for (const std::string& f : files)
    for (std::size_t slash = f.find('/'); slash != std::string::npos;
         slash = f.find('/', slash + 1))
      dirs.insert(f.substr(0, slash));
  for (const std::string& name : names)
    if (fs::path(name).extension().empty()) dirs.insert(name);
  return dirs;
}

// A run's file names as sorted hashes (has_file): what the kept run and, once published, the
// replaced run are cleared against, held through the batch in a few pages instead of a set of
// strings.
std::vector<std::uint64_t> name_hashes(const std::unordered_set<std::string>& files) {
  std::vector<std::uint64_t> hashes;
  hashes.reserve(files.size());
  for (const std::string& f : files) hashes.push_back(std::hash<std::string>{}(f));
  std::sort(hashes.begin(), hashes.end());
  return hashes;
}

// Where a published run's record of its files is kept: dir/.frustum/files-N for run-N.
fs::path record_of(const fs::path& run) {
  return run.parent_path() / ("files-" + run.filename().string().substr(4));
}

// The sorted name hashes a run recorded (empty when it has no record: an older Frustum's run).
std::vector<std::uint64_t> read_record(const fs::path& run) {
  std::vector<std::uint64_t> hashes;
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(record_of(run), ec);
  if (ec || size % sizeof(std::uint64_t) != 0) return hashes;
  hashes.resize(size / sizeof(std::uint64_t));
  const int fd = ::open(record_of(run).c_str(), O_RDONLY | O_CLOEXEC);
  const ssize_t n = fd < 0 ? -1 : ::read(fd, hashes.data(), size);
  if (fd >= 0) ::close(fd);
  if (n != static_cast<ssize_t>(size)) hashes.clear();
  std::sort(hashes.begin(), hashes.end());
  return hashes;
}

// Walks the run `dir` (the part `prefix` of it): a plain file that `keep` says this run writes,
// and the directories in `dirs`, stay; every other entry goes to `drop` (files, symlinks, and
// what is neither; a directory not in `dirs` is walked with nothing kept, then removed if empty).
// A symlink is never followed.
using Keep = std::function<bool(const std::string&)>;
using Drop = std::function<void(const fs::path&, const std::string&)>;

void keep_only(const fs::path& dir, const std::string& prefix, const Keep& keep,
               const std::unordered_set<std::string>& dirs, const Drop& drop) {
  std::error_code ec;
  std::vector<std::pair<fs::path, std::string>> dropped, walked;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const std::string relative = prefix.empty() ? name : prefix + "/" + name;
    // The type from the directory listing, a symlink not followed.
    if (!it->is_symlink() && it->is_directory())
      walked.emplace_back(it->path(), relative);
    else if (it->is_symlink() || !(it->is_regular_file() && keep(relative)))
      dropped.emplace_back(it->path(), relative);
  }
  for (const auto& [path, relative] : dropped) drop(path, relative);
  static const Keep nothing = [](const std::string&) { return false; };
  for (const auto& [path, relative] : walked) {
    const bool kept = dirs.count(relative) > 0;
    keep_only(path, relative, kept ? keep : nothing, dirs, drop);
    if (!kept) fs::remove(path, ec);  // only when empty: what was moved aside is gone from it
  }
}

// Writes a run's record: the sorted name hashes of the files it may write.
void write_record(const fs::path& run, const std::vector<std::uint64_t>& hashes) {
  const std::string record = record_of(run).string();
  const int fd = ::open(record.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(record, "cannot create");
  try {
    write_all(fd,
              std::string(reinterpret_cast<const char*>(hashes.data()),
                          hashes.size() * sizeof(std::uint64_t)),
              record);
  } catch (...) {
    ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail(record, "cannot close");
}

// Writes `content` over the file `fd` from its start, the last block in full (zeros after the
// content: a block only partly written would have to be read from the disk first when it is not
// in memory), then cuts the file to the content's length.
void overwrite_in_place(int fd, const std::string& content, std::size_t block, off_t old_size,
                        const std::string& path) {
  static const std::array<char, 1 << 16> kZeros{};
  const std::size_t pad =
      std::min((block - content.size() % block) % block, static_cast<std::size_t>(kZeros.size()));
  std::array<iovec, 2> parts{iovec{const_cast<char*>(content.data()), content.size()},
                             iovec{const_cast<char*>(kZeros.data()), pad}};
  std::size_t first = 0;
  while (first < parts.size()) {
    const ssize_t n = ::writev(fd, parts.data() + first, static_cast<int>(parts.size() - first));
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) fail(path, "cannot write");
    for (std::size_t left = static_cast<std::size_t>(n); first < parts.size(); ++first) {
      if (left < parts[first].iov_len) {
        parts[first].iov_base = static_cast<char*>(parts[first].iov_base) + left;
        parts[first].iov_len -= left;
        break;
      }
      left -= parts[first].iov_len;
    }
  }
  if ((pad > 0 || old_size > static_cast<off_t>(content.size())) &&
      ::ftruncate(fd, static_cast<off_t>(content.size())) != 0)
    fail(path, "cannot write");
}

}  // namespace

OutputTransaction::OutputTransaction(std::string dir, std::vector<std::string> names,
                                     std::optional<std::unordered_set<std::string>> files)
    : dir_(std::move(dir)), names_(std::move(names)) {
  const fs::path state = fs::path(dir_) / kStateDir;
  std::error_code ec;
  fs::create_directories(state, ec);
  if (ec) throw std::runtime_error(dir_ + ": cannot create the output directory: " + ec.message());
  const std::string lock = (state / "lock").string();
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0) fail(lock, "cannot open the lock file");
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    char pid[32] = {};
    const ssize_t n = ::pread(lock_fd_, pid, sizeof pid - 1, 0);
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw std::runtime_error(
        dir_ + ": another batch is writing here" +
        (n > 0 ? fmt::format(" (process {})", std::string(pid, static_cast<std::size_t>(n)))
               : std::string()) +
        "; wait for it to finish or choose another output directory");
  }
  const std::string me = std::to_string(::getpid());
  if (::ftruncate(lock_fd_, 0) == 0) (void)::pwrite(lock_fd_, me.data(), me.size(), 0);
  // The run directories but the published one: the newest is kept (the run before the
  // published one, or what a killed run left), the others are what killed runs left.
  std::error_code read_ec;
  const fs::path current = fs::read_symlink(state / "current", read_ec);
  unsigned long next = 1;
  std::optional<std::pair<unsigned long, fs::path>> kept;
  std::vector<fs::path> left;
  for (const fs::directory_entry& e : fs::directory_iterator(state, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("run-", 0) != 0) continue;
    const std::optional<unsigned long> n = run_number(name);
    if (n) next = std::max(next, *n + 1);
    if (!read_ec && e.path().filename() == current.filename()) continue;
    if (n && !e.is_symlink() && e.is_directory() && (!kept || *n > kept->first)) {
      if (kept) left.push_back(kept->second);
      kept = std::pair{*n, e.path()};
    } else {
      left.push_back(e.path());
    }
  }
  for (const fs::path& p : left) {
    // A run that was never published holds only what Frustum wrote; one that was (its record
    // is there) may hold what was put in through the published names.
    if (fs::exists(record_of(p), ec)) clear_run(p, [](const std::string&) { return false; });
    fs::remove_all(p, ec);
    fs::remove(record_of(p), ec);
  }
  // Records of runs that are no longer there.
  for (const fs::directory_entry& e : fs::directory_iterator(state, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind("files-", 0) == 0 && !fs::exists(state / ("run-" + name.substr(6)), ec))
      fs::remove(e.path(), ec);
  }
  run_ = (state / ("run-" + std::to_string(next))).string();
  if (files) {
    dirs_ = directories_of(*files, names_);
    file_hashes_ = name_hashes(*files);
    files_named_ = true;
  }
  if (kept && files_named_) {
    // The kept run is cleared of what this run does not write (what Frustum did not write there
    // moved aside), then becomes this one; its record is of both runs' files until this one is
    // published (a kill in between leaves a run whose every file is recorded).
    std::vector<std::uint64_t> both = read_record(kept->second);
    clear_run(kept->second, [this](const std::string& f) { return has_file(f); });
    fs::rename(kept->second, run_, ec);
    reused_ = !ec;
    if (reused_) {
      both.insert(both.end(), file_hashes_.begin(), file_hashes_.end());
      std::sort(both.begin(), both.end());
      write_record(run_, both);
      fs::remove(record_of(kept->second), ec);
    }
  }
  if (kept && !reused_) {
    clear_run(kept->second, [](const std::string&) { return false; });
    fs::remove_all(kept->second, ec);
    fs::remove(record_of(kept->second), ec);
  }
  fs::create_directories(run_, ec);
  if (ec) throw std::runtime_error(run_ + ": cannot create: " + ec.message());
  if (files_named_ && !reused_) write_record(run_, file_hashes_);
  run_fd_ = ::open(run_.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (run_fd_ < 0) fail(run_, "cannot open");
  for (const std::string& name : names_)
    if (fs::path(name).extension().empty()) fs::create_directories(fs::path(run_) / name, ec);
}

OutputTransaction::~OutputTransaction() {
  std::error_code ec;
  if (!committed_ && !run_.empty()) fs::remove_all(run_, ec);
  if (run_fd_ >= 0) ::close(run_fd_);
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

void OutputTransaction::write(const std::string& relative, const std::string& content) {
  put(relative, content, O_TRUNC);
  if (!files_named_) written_.push_back(std::hash<std::string>{}(relative));
}

void OutputTransaction::append(const std::string& relative, const std::string& content) {
  put(relative, content, O_APPEND);
  if (!files_named_) written_.push_back(std::hash<std::string>{}(relative));
}

// Opened from the run's directory, not by the whole path: the kernel then looks up only the
// name's own one or two parts, not every directory above the run, for each of a class's files.
// A symlink is not followed.
int OutputTransaction::open_file(const std::string& relative, int flags) const {
  const int how = O_WRONLY | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | flags;
  int fd = ::openat(run_fd_, relative.c_str(), how, 0644);
  if (fd < 0 && errno == ENOENT) {  // a file in a subdirectory of a name ("katex/fonts/…")
    std::error_code ec;
    fs::create_directories((fs::path(run_) / relative).parent_path(), ec);
    fd = ::openat(run_fd_, relative.c_str(), how, 0644);
  }
  if (fd < 0) fail(published_path(relative), "cannot create");
  return fd;
}

void OutputTransaction::put(const std::string& relative, const std::string& content, int flags) {
  // In a kept run, a file is written over where it lies (overwrite): truncating it would free
  // its blocks, and ext4 mounted with `discard` waits for the disk to discard them, file by file.
  const bool in_place = reused_ && flags == O_TRUNC;
  int fd = -1;
  if (in_place) {
    // A file of the kept run that cannot be opened for writing (made read-only by hand, or a
    // directory, symlink or pipe put there since) gives way to a new file.
    fd = ::openat(run_fd_, relative.c_str(), O_WRONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0 && errno != ENOENT) {
      std::error_code ec;
      fs::remove_all(fs::path(run_) / relative, ec);
    }
  }
  if (fd < 0) fd = open_file(relative, in_place ? 0 : flags);
  try {
    struct stat st {};
    if (in_place && ::fstat(fd, &st) != 0) fail(published_path(relative), "cannot read");
    if (in_place && (st.st_nlink > 1 || !S_ISREG(st.st_mode))) {
      // A file also linked elsewhere (a copy made with hard links) keeps what it holds there,
      // and what is not a plain file is not written to: this run's file is a new one.
      ::close(fd);
      fd = -1;
      if (::unlinkat(run_fd_, relative.c_str(), 0) != 0)
        fail(published_path(relative), "cannot replace");
      fd = open_file(relative, O_EXCL);
      st.st_size = 0;
    }
    if (in_place && st.st_size > 0)
      overwrite_in_place(fd, content, st.st_blksize > 0 ? st.st_blksize : 4096, st.st_size,
                         published_path(relative));
    else
      write_all(fd, content, published_path(relative));
  } catch (...) {
    if (fd >= 0) ::close(fd);
    throw;
  }
  if (::close(fd) != 0) fail(published_path(relative), "cannot close");
}

void OutputTransaction::remove(const std::string& relative) {
  if (::unlinkat(run_fd_, relative.c_str(), 0) != 0 && errno != ENOENT)
    fail(published_path(relative), "cannot remove");
}

std::string OutputTransaction::published_path(const std::string& relative) const {
  return (fs::path(dir_) / relative).string();
}

void OutputTransaction::write_back() {
  if (::syncfs(run_fd_) != 0 && write_back_error_ == 0) write_back_error_ = errno;
}

void OutputTransaction::commit() {
  const fs::path state = fs::path(dir_) / kStateDir;
  // One sync for the whole run (its files and directories), not one per file; what write_back()
  // met counts as this sync's error.
  if (write_back_error_ != 0) fail(run_, "cannot flush", write_back_error_);
  // Without the files named up front, the record is of what this process wrote.
  if (!files_named_) {
    std::sort(written_.begin(), written_.end());
    write_record(run_, written_);
  }
  if (::syncfs(run_fd_) != 0) fail(run_, "cannot flush");
  // Each published name is a fixed symlink into `current`. Anything else there (a file written
  // by hand, or by an older Frustum that wrote in place) is moved aside first, never deleted.
  for (const std::string& name : names_) {
    const fs::path link = fs::path(dir_) / name;
    const fs::path target = fs::path(kStateDir) / "current" / name;
    std::error_code ec;
    const fs::file_status st = fs::symlink_status(link, ec);
    if (fs::is_symlink(st) && fs::read_symlink(link, ec) == target) continue;
    if (fs::exists(st) || fs::is_symlink(st)) move_aside(link, name);
    fs::create_symlink(target, link, ec);
    if (ec) throw std::runtime_error(link.string() + ": cannot create: " + ec.message());
  }
  // The one step that publishes: a new symlink renamed over `current`. The run it replaces is
  // kept, for the next run to be written into.
  std::error_code ec;
  const fs::path replaced = fs::read_symlink(state / "current", ec);
  const fs::path fresh = state / "current.new";
  fs::remove(fresh, ec);
  fs::create_symlink(fs::path(run_).filename(), fresh, ec);
  if (ec) throw std::runtime_error(fresh.string() + ": cannot create: " + ec.message());
  if (std::rename(fresh.c_str(), (state / "current").c_str()) != 0)
    fail((state / "current").string(), "cannot publish");
  sync_directory(state.string());
  committed_ = true;
  // The replaced run keeps only the files this run also has: the feedback of a student no
  // longer in the class (another section graded into the same directory) does not stay behind
  // in a directory that is shared or archived as a whole.
  if (files_named_ && !replaced.empty() && replaced.filename() != fs::path(run_).filename())
    clear_run(state / replaced.filename(), [this](const std::string& f) { return has_file(f); });
}

void OutputTransaction::clear_run(const fs::path& run,
                                  const std::function<bool(const std::string&)>& keep) {
  const std::vector<std::uint64_t> wrote = read_record(run);
  keep_only(run, "", keep, dirs_, [&](const fs::path& path, const std::string& relative) {
    std::error_code ec;
    if (std::binary_search(wrote.begin(), wrote.end(), std::hash<std::string>{}(relative)))
      fs::remove_all(path, ec);
    else
      move_aside(path, relative);
  });
}

void OutputTransaction::move_aside(const fs::path& path, const std::string& relative) {
  const fs::path base = fs::path(dir_) / kSetAsideDir / relative;
  fs::path to = base;
  std::error_code ec;
  for (int n = 2; fs::exists(fs::symlink_status(to, ec)); ++n)
    to = base.parent_path() /
         (base.stem().string() + "~" + std::to_string(n) + base.extension().string());
  fs::create_directories(to.parent_path(), ec);
  fs::rename(path, to, ec);
  if (ec)
    throw std::runtime_error(path.string() + " was not written by Frustum and cannot be moved to " +
                             to.string() + ": " + ec.message() + "; nothing was deleted");
  set_aside_.emplace_back((fs::path(dir_) / relative).string(), to.string());
}

bool OutputTransaction::has_file(const std::string& relative) const {
  return std::binary_search(file_hashes_.begin(), file_hashes_.end(),
                            std::hash<std::string>{}(relative));
}

}  // namespace frustum
