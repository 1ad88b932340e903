#include "grader/isolate.hpp"

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

// One item's frame on the pipe: 8-byte little-endian length, a status byte ('O' ok, 'E' the
// work threw), then the text.
bool write_frame(int fd, char status, const std::string& text) {
  const std::uint64_t size = text.size() + 1;
  unsigned char header[9];
  for (int i = 0; i < 8; ++i) header[i] = static_cast<unsigned char>(size >> (8 * i));
  header[8] = static_cast<unsigned char>(status);
  return write_all(fd, reinterpret_cast<const char*>(header), 9) &&
         write_all(fd, text.data(), text.size());
}

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
  Clock::time_point deadline;
};

}  // namespace

std::vector<IsolatedResult> run_isolated_each(
    std::size_t count, const std::function<std::string(std::size_t)>& work, double seconds,
    const std::function<void(std::size_t, IsolatedResult&)>& on_result, std::size_t max_output,
    std::size_t jobs, const std::function<bool()>& stop) {
  std::vector<IsolatedResult> results(count);
  // Set when `stop` says so; shared with the children, which look at it before each item.
  std::atomic<bool>* stopping = nullptr;
  if (stop) {
    void* shared = mmap(nullptr, sizeof(std::atomic<bool>), PROT_READ | PROT_WRITE,
                        MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (shared != MAP_FAILED) stopping = new (shared) std::atomic<bool>(false);
  }
  bool stopped_by_caller = false;
  const auto finish = [&](std::size_t i, IsolatedResult r) {
    if (on_result) on_result(i, r);
    results[i] = std::move(r);
    if (stop && !stopped_by_caller && stop()) {
      stopped_by_caller = true;
      if (stopping) stopping->store(true);
    }
  };
  // The items of a share never started once the caller stopped the run.
  const auto not_run = [&](std::size_t from, std::size_t to) {
    for (std::size_t i = from; i < to; ++i) results[i].error = "not run";
  };
  const auto limit =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  // Contiguous shares, one per child: item i always lands in the same share for a given count
  // and jobs, so a rerun repeats every child's work item for item.
  jobs = std::max<std::size_t>(1, std::min(jobs, count));
  std::vector<Lane> lanes(jobs);
  for (std::size_t j = 0; j < jobs; ++j) {
    lanes[j].next = count * j / jobs;
    lanes[j].end = count * (j + 1) / jobs;
  }
  // Starts a child on the rest of the lane's share; false when no child could be made.
  const auto start = [&](Lane& lane) {
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
      for (const Lane& other : lanes)
        if (other.fd >= 0) close(other.fd);
      for (std::size_t i = lane.next; i < lane.end; ++i) {
        if (stopping && stopping->load()) break;
        std::string text;
        char status = 'O';
        try {
          text = work(i);
        } catch (const std::exception& e) {
          status = 'E';
          text = e.what();
        } catch (...) {
          status = 'E';
          text = "unknown error";
        }
        if (!write_frame(fds[1], status, text)) _exit(3);
      }
      close(fds[1]);
      _exit(0);
    }
    close(fds[1]);
    lane.pid = pid;
    lane.fd = fds[0];
    lane.data.clear();
    lane.offset = 0;
    lane.deadline = Clock::now() + limit;
    return true;
  };
  // The child stopped (stop says why): the item it was on gets the reason, a fresh child
  // carries on after it.
  enum class Stop { Timeout, TooBig, Eof };
  const auto stopped = [&](Lane& lane, Stop stop) {
    close(lane.fd);
    lane.fd = -1;
    if (stop != Stop::Eof) kill(lane.pid, SIGKILL);
    int status = 0;
    while (waitpid(lane.pid, &status, 0) < 0 && errno == EINTR) {
    }
    lane.pid = -1;
    if (lane.next >= lane.end) return;
    if (stopped_by_caller) {  // the child stopped before its next item, as asked
      not_run(lane.next, lane.end);
      lane.next = lane.end;
      return;
    }
    IsolatedResult r;
    if (stop == Stop::Timeout) {
      r.status = IsolatedResult::Status::Timeout;
      r.error = fmt::format("time limit of {} s exceeded", seconds);
    } else if (stop == Stop::TooBig) {
      r.error = fmt::format("result larger than {} bytes", max_output);
    } else if (WIFSIGNALED(status)) {
      r.status = IsolatedResult::Status::Crashed;
      r.error = fmt::format("the grader crashed on this input (signal {}: {})", WTERMSIG(status),
                            strsignal(WTERMSIG(status)));
    } else {
      r.status = IsolatedResult::Status::Crashed;
      r.error =
          fmt::format("the grader stopped without a result (exit status {})", WEXITSTATUS(status));
    }
    finish(lane.next++, std::move(r));
  };
  // Hands over every complete frame the lane holds.
  const auto drain = [&](Lane& lane) {
    while (lane.data.size() - lane.offset >= 9 && lane.next < lane.end) {
      std::uint64_t size = 0;
      for (int i = 0; i < 8; ++i)
        size |= std::uint64_t(static_cast<unsigned char>(lane.data[lane.offset + i])) << (8 * i);
      if (lane.data.size() - lane.offset - 8 < size) break;
      IsolatedResult r;
      const char status = lane.data[lane.offset + 8];
      std::string text = lane.data.substr(lane.offset + 9, size - 1);
      if (status == 'O') {
        r.status = IsolatedResult::Status::Ok;
        r.output = std::move(text);
      } else {
        r.error = std::move(text);
      }
      lane.offset += 8 + size;
      finish(lane.next++, std::move(r));
      lane.deadline = Clock::now() + limit;
    }
    if (lane.offset > (1u << 20)) {
      lane.data.erase(0, lane.offset);
      lane.offset = 0;
    }
  };
  char buffer[1 << 16];
  while (true) {
    // Every lane with work left has a child (a lane whose child cannot be made works here,
    // without a time limit).
    std::vector<pollfd> polls;
    std::vector<Lane*> polled;
    for (Lane& lane : lanes) {
      if (lane.fd < 0 && lane.next < lane.end && stopped_by_caller) {
        not_run(lane.next, lane.end);
        lane.next = lane.end;
      }
      if (lane.fd < 0 && lane.next < lane.end && !start(lane))
        while (lane.next < lane.end) {
          if (stopped_by_caller) {
            not_run(lane.next, lane.end);
            lane.next = lane.end;
            break;
          }
          const std::size_t i = lane.next++;
          finish(i, run_in_process([&] { return work(i); }));
        }
      if (lane.fd >= 0) {
        polls.push_back({lane.fd, POLLIN, 0});
        polled.push_back(&lane);
      }
    }
    if (polls.empty()) break;
    long long wait_ms = 1000;
    for (const Lane* lane : polled)
      wait_ms = std::min<long long>(wait_ms, std::chrono::duration_cast<std::chrono::milliseconds>(
                                                 lane->deadline - Clock::now())
                                                 .count());
    const int ready =
        poll(polls.data(), polls.size(), static_cast<int>(std::max<long long>(wait_ms, 0)));
    if (ready < 0) continue;  // EINTR: poll again
    for (std::size_t k = 0; k < polls.size(); ++k) {
      Lane& lane = *polled[k];
      if (ready > 0 && (polls[k].revents & (POLLIN | POLLHUP | POLLERR))) {
        const ssize_t n = read(lane.fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
          drain(lane);
          stopped(lane, Stop::Eof);
          continue;
        }
        lane.data.append(buffer, static_cast<std::size_t>(n));
        drain(lane);
        if (lane.next >= lane.end) {
          stopped(lane, Stop::Eof);
          continue;
        }
        if (lane.data.size() - lane.offset > max_output) {
          stopped(lane, Stop::TooBig);
          continue;
        }
      }
      if (lane.fd >= 0 && Clock::now() >= lane.deadline) stopped(lane, Stop::Timeout);
    }
  }
  if (stopping) munmap(stopping, sizeof(std::atomic<bool>));
  return results;
}

IsolatedResult run_isolated(const std::function<std::string()>& work, double seconds,
                            std::size_t max_output) {
  return run_isolated_each(
             1, [&](std::size_t) { return work(); }, seconds, {}, max_output)
      .at(0);
}

}  // namespace frustum
