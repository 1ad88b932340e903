#include "grader/isolate.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <exception>

#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

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
  return write_all(fd, reinterpret_cast<const char*>(header), 9) && write_all(fd, text.data(), text.size());
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

}  // namespace

std::vector<IsolatedResult> run_isolated_each(
    std::size_t count, const std::function<std::string(std::size_t)>& work, double seconds,
    const std::function<void(std::size_t, const IsolatedResult&)>& on_result, std::size_t max_output) {
  std::vector<IsolatedResult> results;
  results.reserve(count);
  const auto finish = [&](IsolatedResult r) {
    results.push_back(std::move(r));
    if (on_result) on_result(results.size() - 1, results.back());
  };
  const auto limit = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  while (results.size() < count) {
    const std::size_t first = results.size();
    int fds[2];
    const pid_t parent = getpid();
    const pid_t pid = pipe(fds) == 0 ? fork() : -1;
    if (pid < 0) {  // no child process: grade here, without a time limit
      for (std::size_t i = first; i < count; ++i) finish(run_in_process([&] { return work(i); }));
      break;
    }
    if (pid == 0) {
      // The child dies with its parent (kill -9 of a batch once left it grading on): the
      // kernel sends SIGKILL when the parent goes; a parent already gone is caught here.
      prctl(PR_SET_PDEATHSIG, SIGKILL);
      if (getppid() != parent) _exit(4);
      close(fds[0]);
      for (std::size_t i = first; i < count; ++i) {
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
    std::string data;
    std::size_t offset = 0;  // start of the frame being read
    auto deadline = Clock::now() + limit;
    enum class Stop { None, Timeout, TooBig, Eof } stop = Stop::None;
    char buffer[1 << 16];
    while (results.size() < count) {
      // Hand over every complete frame.
      while (data.size() - offset >= 9) {
        std::uint64_t size = 0;
        for (int i = 0; i < 8; ++i) size |= std::uint64_t(static_cast<unsigned char>(data[offset + i])) << (8 * i);
        if (data.size() - offset - 8 < size) break;
        IsolatedResult r;
        const char status = data[offset + 8];
        std::string text = data.substr(offset + 9, size - 1);
        if (status == 'O') {
          r.status = IsolatedResult::Status::Ok;
          r.output = std::move(text);
        } else {
          r.error = std::move(text);
        }
        offset += 8 + size;
        finish(std::move(r));
        deadline = Clock::now() + limit;
      }
      if (offset > (1u << 20)) {
        data.erase(0, offset);
        offset = 0;
      }
      if (results.size() >= count) break;
      if (data.size() - offset > max_output) {
        stop = Stop::TooBig;
        break;
      }
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
      if (left <= 0) {
        stop = Stop::Timeout;
        break;
      }
      pollfd p{fds[0], POLLIN, 0};
      const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (ready < 0 && errno == EINTR) continue;
      if (ready <= 0) continue;
      const ssize_t n = read(fds[0], buffer, sizeof buffer);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        stop = Stop::Eof;
        break;
      }
      data.append(buffer, static_cast<std::size_t>(n));
    }
    close(fds[0]);
    if (stop == Stop::Timeout || stop == Stop::TooBig) kill(pid, SIGKILL);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (results.size() >= count) break;
    // The item being worked on when the child stopped gets the reason; the next child
    // starts after it.
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
      r.error = fmt::format("the grader stopped without a result (exit status {})", WEXITSTATUS(status));
    }
    finish(std::move(r));
  }
  return results;
}

IsolatedResult run_isolated(const std::function<std::string()>& work, double seconds, std::size_t max_output) {
  return run_isolated_each(1, [&](std::size_t) { return work(); }, seconds, {}, max_output).at(0);
}

}  // namespace frustum
