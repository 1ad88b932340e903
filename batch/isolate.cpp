#include "batch/isolate.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <poll.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <exception>
#include <new>
#include <optional>
#include <thread>

namespace frustum {

namespace {

using Clock = std::chrono::steady_clock;

bool write_all(int fd, const char* p, std::size_t size) {
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = write(fd, p + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// One item's frame on the pipe: the 8-byte little-endian length of what follows it, the item's
// 8-byte little-endian index, a status byte ('O' ok, 'E' the work threw), then the text.
constexpr std::size_t kFrameHeader = 17;
constexpr int kPipeBytes = 1 << 20;
// After a round that read results, this process waits this long before it polls again, so that
// the children's results (small, and buffered by the pipes meanwhile) are taken many at a time:
// woken for each one, this process would cost a context switch per result, and where a wake-up
// is dear (a virtual machine) a shorter wait still leaves it a noticeable share of a batch's CPU
// time. The wait is never longer than the results so far say it takes the children to bring all
// but their last items (a flat wait would keep the end of a class waiting for results already
// in, every core idle). A time limit is still checked every round.
constexpr auto kCoalesce = std::chrono::milliseconds(8);
bool write_frame(int fd, std::size_t item, char status, const std::string& text) {
  const std::uint64_t size = text.size() + 9;
  unsigned char header[kFrameHeader];
  for (int i = 0; i < 8; ++i) {
    header[i] = static_cast<unsigned char>(size >> (8 * i));
    header[8 + i] = static_cast<unsigned char>(std::uint64_t(item) >> (8 * i));
  }
  header[16] = static_cast<unsigned char>(status);
  // One write for the frame, not one for the header and one for the text: a result is small,
  // and a system call costs more than copying it, most of all on a virtual machine.
  std::string frame(reinterpret_cast<const char*>(header), kFrameHeader);
  frame += text;
  return write_all(fd, frame.data(), frame.size());
}

std::uint64_t little_endian(const char* p) {
  std::uint64_t v = 0;
  for (int i = 0; i < 8; ++i) v |= std::uint64_t(static_cast<unsigned char>(p[i])) << (8 * i);
  return v;
}

// What the parent and its children share (one anonymous shared mapping): the caller's stop, the
// next item not yet taken (Shares::Dynamic) and, for each child, the item it took last.
struct Board {
  std::atomic<bool> stopping{false};
  std::atomic<std::size_t> next{0};
  // One slot per lane, placed right after the board in the mapping.
  std::atomic<std::size_t>& current(std::size_t lane) {
    return reinterpret_cast<std::atomic<std::size_t>*>(this + 1)[lane];
  }

  static constexpr std::size_t kNone = ~std::size_t(0);
  static Board* make(std::size_t lanes) {
    const std::size_t bytes = sizeof(Board) + sizeof(std::atomic<std::size_t>) * lanes;
    void* shared = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared == MAP_FAILED) return nullptr;
    Board* b = new (shared) Board;
    auto* slots = reinterpret_cast<std::atomic<std::size_t>*>(b + 1);
    for (std::size_t j = 0; j < lanes; ++j) new (&slots[j]) std::atomic<std::size_t>(kNone);
    return b;
  }
  static void release(Board* b, std::size_t lanes) {
    if (b) munmap(b, sizeof(Board) + sizeof(std::atomic<std::size_t>) * lanes);
  }
};

IsolatedResult run_in_process(const std::function<std::string()>& work) {
  IsolatedResult r;
  try {
    r.output = work();
    r.status = IsolatedResult::Status::Ok;
  } catch (const std::exception& e) {
    r.error = e.what();
  }
  return r;
}

// One child process working through items [next, end) of its share, and what it sent so far.
struct Lane {
  std::size_t next = 0, end = 0;  // the item being worked on, the end of the share
  pid_t pid = -1;
  int fd = -1;
  std::string data;
  std::size_t offset = 0;  // start of the frame being read
  bool broken = false;     // the child sent a frame it had no item for: what follows is not read
  Clock::time_point deadline;
};

// One run of run_isolated_each: its lanes (a child process each), the items handed so far and
// their results. The parts of the run are its methods; a child forked by start() runs take()
// and the caller's work in its own copy of the run.
class IsolatedRun {
 public:
  using Work = std::function<std::string(std::size_t)>;
  using OnResult = std::function<void(std::size_t, IsolatedResult&)>;

  IsolatedRun(std::size_t count, const Work& work, double seconds, const OnResult& on_result,
              std::size_t max_output, std::size_t jobs, const std::function<bool()>& stop,
              Shares shares)
      : count_(count),
        work_(work),
        seconds_(seconds),
        on_result_(on_result),
        max_output_(max_output),
        stop_(stop),
        results_(count),
        handed_(count, 0),
        jobs_(std::max<std::size_t>(1, std::min(jobs, count))),
        board_(Board::make(jobs_)),
        // Without the shared board, items cannot be taken one at a time: contiguous shares.
        dynamic_(shares == Shares::Dynamic && board_),
        limit_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds))),
        lanes_(jobs_) {
    // Contiguous shares, one per child: item i always lands in the same share for a given count
    // and jobs, so a rerun repeats every child's work item for item. Dynamic: every child takes
    // the next item nobody has taken (lane.next and lane.end are then unused).
    for (std::size_t j = 0; j < jobs_; ++j) {
      lanes_[j].next = dynamic_ ? 0 : count * j / jobs_;
      lanes_[j].end = dynamic_ ? 0 : count * (j + 1) / jobs_;
    }
  }
  ~IsolatedRun() { Board::release(board_, jobs_); }
  IsolatedRun(const IsolatedRun&) = delete;
  IsolatedRun& operator=(const IsolatedRun&) = delete;

  // Every lane's children until every item has a result (or the caller stopped the run).
  void run() {
    const Clock::time_point started = Clock::now();
    while (true) {
      std::vector<pollfd> polls;
      std::vector<std::size_t> polled;
      for (std::size_t j = 0; j < lanes_.size(); ++j) {
        keep_busy(j);
        if (lanes_[j].fd >= 0) {
          polls.push_back({lanes_[j].fd, POLLIN, 0});
          polled.push_back(j);
        }
      }
      if (polls.empty()) break;
      const bool read_some = poll_lanes(polls, polled);
      pace(read_some, started);
    }
  }

  // Items without a result: never started once the caller stopped, or (Dynamic) taken by a
  // child killed in the instant between taking an item and saying so — those run again, alone.
  std::vector<IsolatedResult> results(Reaper* reaper) {
    std::vector<std::size_t> left;
    for (std::size_t i = 0; i < count_; ++i)
      if (!handed_[i]) {
        if (stopped_by_caller_)
          results_[i].error = "not run";
        else
          left.push_back(i);
      }
    if (!left.empty()) {
      run_isolated_each(
          left.size(), [&](std::size_t k) { return work_(left[k]); }, seconds_,
          [&](std::size_t k, IsolatedResult& r) { finish(left[k], std::move(r)); }, max_output_, 1,
          [&] { return stopped_by_caller_; }, Shares::Contiguous, reaper);
      for (const std::size_t i : left)
        if (!handed_[i]) results_[i].error = "not run";
    }
    return std::move(results_);
  }

  Reaper* reaper = nullptr;

 private:
  // The child stopped: by a time limit, a result too big, or its pipe closing.
  enum class Stop { Timeout, TooBig, Eof };

  void finish(std::size_t i, IsolatedResult r) {
    handed_[i] = 1;
    ++handed_count_;
    if (on_result_) on_result_(i, r);
    results_[i] = std::move(r);
    if (stop_ && !stopped_by_caller_ && stop_()) {
      stopped_by_caller_ = true;
      if (board_) board_->stopping.store(true);
    }
  }

  // The lane's next item to work on, or nothing when its share (or the class) is done.
  std::optional<std::size_t> take(Lane& lane, std::size_t j) {
    if (board_ && board_->stopping.load()) return std::nullopt;
    if (!dynamic_)
      return lane.next < lane.end ? std::optional<std::size_t>(lane.next) : std::nullopt;
    const std::size_t i = board_->next.fetch_add(1);
    if (i >= count_) return std::nullopt;
    board_->current(j).store(i);
    return i;
  }

  bool work_left(const Lane& lane) const {
    if (stopped_by_caller_) return false;
    return dynamic_ ? board_->next.load() < count_ : lane.next < lane.end;
  }

  // Every lane with work left has a child; a lane whose child cannot be made works here,
  // without a time limit.
  void keep_busy(std::size_t j) {
    Lane& lane = lanes_[j];
    if (lane.fd < 0 && work_left(lane) && !start(lane, j))
      while (work_left(lane)) {
        const std::optional<std::size_t> i = take(lane, j);
        if (!i) break;
        if (!dynamic_) ++lane.next;
        finish(*i, run_in_process([&] { return work_(*i); }));
      }
  }

  // Starts a child on the rest of the lane's work; false when no child could be made.
  bool start(Lane& lane, std::size_t j) {
    if (board_) board_->current(j).store(Board::kNone);
    int fds[2];
    const pid_t parent = getpid();
    const pid_t pid = pipe(fds) == 0 ? fork() : -1;
    if (pid < 0) return false;
    if (pid == 0) {
      // The child dies with its parent (kill -9 of a batch once left it grading on): the
      // kernel sends SIGKILL when the parent goes; a parent already gone is caught here.
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(4);
      close(fds[0]);
      for (const Lane& other : lanes_)
        if (other.fd >= 0) close(other.fd);
      while (const std::optional<std::size_t> i = take(lane, j)) {
        std::string text;
        char status = 'O';
        try {
          text = work_(*i);
        } catch (const std::exception& e) {
          status = 'E';
          text = e.what();
        } catch (...) {
          status = 'E';
          text = "unknown error";
        }
        if (!write_frame(fds[1], *i, status, text)) _exit(3);
        ++lane.next;  // this process's copy of the lane
      }
      close(fds[1]);
      _exit(0);
    }
    close(fds[1]);
    // A pipe of 1 MiB (the default is 64 KiB) lets a child run ahead while this process is busy
    // (generate syncs and renames a group of files here): with 64 KiB a child stalled after a
    // few hundred results. Where the system allows less, the pipe stays as it is.
    fcntl(fds[0], F_SETPIPE_SZ, kPipeBytes);
    lane.pid = pid;
    lane.fd = fds[0];
    lane.data.clear();
    lane.offset = 0;
    lane.broken = false;
    lane.deadline = Clock::now() + limit_;
    return true;
  }

  // The child stopped (stop says why): the item it was on gets the reason, a fresh child
  // carries on after it.
  void stopped(Lane& lane, std::size_t j, Stop stop) {
    close(lane.fd);
    lane.fd = -1;
    if (stop != Stop::Eof) kill(lane.pid, SIGKILL);
    // The item the child was on: the one whose result it was sending, else the next of its
    // share or the last it took.
    std::size_t on = Board::kNone;
    if (!lane.broken && lane.data.size() - lane.offset >= kFrameHeader)
      on = little_endian(lane.data.data() + lane.offset + 8);
    else if (!dynamic_ && lane.next < lane.end)
      on = lane.next;
    else if (dynamic_)
      on = board_->current(j).load();
    const bool owed = on < count_ && !handed_[on];
    // A child that closed its pipe owing nothing is waited for by the reaper: it is unmapping
    // its memory, and its exit status says nothing about any item.
    if (stop == Stop::Eof && !owed && reaper) {
      reaper->adopt(lane.pid);
      lane.pid = -1;
      return;
    }
    int status = 0;
    while (waitpid(lane.pid, &status, 0) < 0 && errno == EINTR) {
    }
    lane.pid = -1;
    if (!owed) return;
    if (stopped_by_caller_ && stop == Stop::Eof && !WIFSIGNALED(status) && WEXITSTATUS(status) == 0)
      return;  // the child stopped before its next item, as asked
    IsolatedResult r;
    if (stop == Stop::Timeout) {
      r.status = IsolatedResult::Status::Timeout;
      r.error = fmt::format("time limit of {} s exceeded", seconds_);
    } else if (stop == Stop::TooBig) {
      r.error = fmt::format("result larger than {} bytes", max_output_);
    } else if (WIFSIGNALED(status)) {
      r.status = IsolatedResult::Status::Crashed;
      r.error = fmt::format("the grader crashed on this input (signal {}: {})", WTERMSIG(status),
                            strsignal(WTERMSIG(status)));
    } else {
      r.status = IsolatedResult::Status::Crashed;
      r.error =
          fmt::format("the grader stopped without a result (exit status {})", WEXITSTATUS(status));
    }
    if (!dynamic_) ++lane.next;
    finish(on, std::move(r));
  }

  // Hands over every complete frame the lane holds.
  void drain(Lane& lane) {
    while (!lane.broken && lane.data.size() - lane.offset >= kFrameHeader) {
      const std::uint64_t size = little_endian(lane.data.data() + lane.offset);
      if (lane.data.size() - lane.offset - 8 < size) break;
      const std::size_t i = little_endian(lane.data.data() + lane.offset + 8);
      IsolatedResult r;
      const char status = lane.data[lane.offset + 16];
      std::string text = lane.data.substr(lane.offset + kFrameHeader, size - 9);
      if (status == 'O') {
        r.status = IsolatedResult::Status::Ok;
        r.output = std::move(text);
      } else {
        r.error = std::move(text);
      }
      // A result for an item the child was not given: the child is killed, and the item it
      // was on fails as a crash when its pipe closes.
      if (i >= count_ || handed_[i] || (!dynamic_ && i != lane.next)) {
        kill(lane.pid, SIGKILL);
        lane.broken = true;
        break;
      }
      lane.offset += 8 + size;
      if (!dynamic_) ++lane.next;
      finish(i, std::move(r));
      lane.deadline = Clock::now() + limit_;
    }
    if (lane.offset > (1u << 20)) {
      lane.data.erase(0, lane.offset);
      lane.offset = 0;
    }
  }

  // Waits for the first lane with something to read or a deadline, and reads what is there;
  // whether anything was read.
  bool poll_lanes(std::vector<pollfd>& polls, const std::vector<std::size_t>& polled) {
    long long wait_ms = 1000;
    for (const std::size_t j : polled)
      wait_ms = std::min<long long>(wait_ms, std::chrono::duration_cast<std::chrono::milliseconds>(
                                                 lanes_[j].deadline - Clock::now())
                                                 .count());
    const int ready =
        poll(polls.data(), polls.size(), static_cast<int>(std::max<long long>(wait_ms, 0)));
    if (ready < 0) return false;  // EINTR: poll again
    bool read_some = false;
    for (std::size_t k = 0; k < polls.size(); ++k) {
      const std::size_t j = polled[k];
      Lane& lane = lanes_[j];
      if (ready > 0 && (polls[k].revents & (POLLIN | POLLHUP | POLLERR))) {
        const ssize_t n = read(lane.fd, buffer_, sizeof buffer_);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
          drain(lane);
          stopped(lane, j, Stop::Eof);
          continue;
        }
        lane.data.append(buffer_, static_cast<std::size_t>(n));
        read_some = true;
        drain(lane);
        if (!dynamic_ && lane.next >= lane.end) {
          stopped(lane, j, Stop::Eof);
          continue;
        }
        if (lane.data.size() - lane.offset > max_output_) {
          stopped(lane, j, Stop::TooBig);
          continue;
        }
      }
      if (lane.fd >= 0 && Clock::now() >= lane.deadline) stopped(lane, j, Stop::Timeout);
    }
    return read_some;
  }

  // At the rate so far (items a second, all children together), waits until only each open
  // child's last item is left, up to kCoalesce: results then arrive in larger reads.
  void pace(bool read_some, Clock::time_point started) {
    const auto open_lanes = static_cast<std::size_t>(
        std::count_if(lanes_.begin(), lanes_.end(), [](const Lane& l) { return l.fd >= 0; }));
    if (read_some && open_lanes > 0 && count_ - handed_count_ > open_lanes && handed_count_ > 0) {
      const auto per_item = (Clock::now() - started) / handed_count_;
      const auto until_last = per_item * (count_ - handed_count_ - open_lanes);
      std::this_thread::sleep_for(std::min<Clock::duration>(kCoalesce, until_last));
    }
  }

  const std::size_t count_;
  const Work& work_;
  const double seconds_;
  const OnResult& on_result_;
  const std::size_t max_output_;
  const std::function<bool()>& stop_;
  std::vector<IsolatedResult> results_;
  std::vector<char> handed_;  // the items whose result is in
  std::size_t handed_count_ = 0;
  bool stopped_by_caller_ = false;
  const std::size_t jobs_;
  Board* const board_;
  const bool dynamic_;
  const Clock::duration limit_;
  std::vector<Lane> lanes_;
  char buffer_[1 << 16];
};

}  // namespace

std::vector<IsolatedResult> run_isolated_each(
    std::size_t count, const std::function<std::string(std::size_t)>& work, double seconds,
    const std::function<void(std::size_t, IsolatedResult&)>& on_result, std::size_t max_output,
    std::size_t jobs, const std::function<bool()>& stop, Shares shares, Reaper* reaper) {
  IsolatedRun run(count, work, seconds, on_result, max_output, jobs, stop, shares);
  run.reaper = reaper;
  run.run();
  return run.results(reaper);
}

Reaper::~Reaper() {
  for (const int pid : pids_)
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
}

IsolatedResult run_isolated(const std::function<std::string()>& work, double seconds,
                            std::size_t max_output) {
  return run_isolated_each(
             1, [&](std::size_t) { return work(); }, seconds, {}, max_output)
      .at(0);
}

}  // namespace frustum
