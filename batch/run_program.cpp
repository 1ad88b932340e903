#include "batch/run_program.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <string_view>

extern char** environ;

namespace frustum {

namespace {

// Closes what it holds when it goes out of scope.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
  void reset() {
    if (fd >= 0) ::close(fd);
    fd = -1;
  }
};

struct SpawnActions {
  posix_spawn_file_actions_t actions;
  SpawnActions() { posix_spawn_file_actions_init(&actions); }
  ~SpawnActions() { posix_spawn_file_actions_destroy(&actions); }
};

struct SpawnAttributes {
  posix_spawnattr_t attr;
  SpawnAttributes() { posix_spawnattr_init(&attr); }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attr); }
};

// Points the child's descriptor `target` where `to` says (the capture pipe's write end is `pipe`).
int route(posix_spawn_file_actions_t* a, int target, OutputTo to, const RunOptions& o, int pipe) {
  switch (to) {
    case OutputTo::Capture:
      return posix_spawn_file_actions_adddup2(a, pipe, target);
    case OutputTo::File:
      return posix_spawn_file_actions_addopen(a, target, o.log_file.c_str(),
                                              O_WRONLY | O_CREAT | O_TRUNC, 0644);
    case OutputTo::Null:
      return posix_spawn_file_actions_addopen(a, target, "/dev/null", O_WRONLY, 0);
    case OutputTo::Inherit:
      return 0;
  }
  return 0;
}

}  // namespace

ProgramRun run_program(const std::vector<std::string>& argv, const RunOptions& options) {
  ProgramRun run;
  if (argv.empty()) {
    run.start_error = "no program named";
    return run;
  }
  const bool capture = options.out == OutputTo::Capture || options.err == OutputTo::Capture;
  std::array<int, 2> pipe_fds{-1, -1};
  if (capture && ::pipe2(pipe_fds.data(), O_CLOEXEC) != 0) {
    run.start_error = std::string("cannot make a pipe: ") + std::strerror(errno);
    return run;
  }
  Fd read_end{pipe_fds[0]}, write_end{pipe_fds[1]};

  SpawnActions actions;
  posix_spawn_file_actions_t* a = &actions.actions;
  int rc = posix_spawn_file_actions_addopen(
      a, 0, options.stdin_file ? options.stdin_file->c_str() : "/dev/null", O_RDONLY, 0);
  if (rc == 0) rc = route(a, 1, options.out, options, write_end.fd);
  if (rc == 0 && options.err == OutputTo::File && options.out == OutputTo::File)
    rc = posix_spawn_file_actions_adddup2(a, 1, 2);  // one log for both, in order
  else if (rc == 0)
    rc = route(a, 2, options.err, options, write_end.fd);
  if (rc == 0 && options.cwd) rc = posix_spawn_file_actions_addchdir_np(a, options.cwd->c_str());
  // Its own process group, so that a time-out ends whatever it started too.
  SpawnAttributes attributes;
  if (rc == 0) rc = posix_spawnattr_setpgroup(&attributes.attr, 0);
  if (rc == 0) rc = posix_spawnattr_setflags(&attributes.attr, POSIX_SPAWN_SETPGROUP);
  if (rc != 0) {
    run.start_error = std::string("cannot prepare the program: ") + std::strerror(rc);
    return run;
  }
  // The environment: this process's, with `environment`'s names set over it.
  std::vector<std::string> env_strings = options.environment;
  for (char** e = environ; *e; ++e) {
    const std::string_view entry(*e);
    const std::string_view name = entry.substr(0, entry.find('='));
    bool replaced = false;
    for (const std::string& set : options.environment)
      replaced = replaced || std::string_view(set).substr(0, set.find('=')) == name;
    if (!replaced) env_strings.emplace_back(entry);
  }
  std::vector<char*> envp;
  for (std::string& s : env_strings) envp.push_back(s.data());
  envp.push_back(nullptr);
  std::vector<char*> args;
  for (const std::string& s : argv) args.push_back(const_cast<char*>(s.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  rc = posix_spawnp(&pid, args[0], a, &attributes.attr, args.data(), envp.data());
  write_end.reset();
  if (rc != 0) {
    run.start_error = argv[0] + ": " + std::strerror(rc);
    return run;
  }
  run.started = true;

  // Wait for its end (and read what it writes) until the deadline; then kill its group.
  Fd exited{static_cast<int>(::syscall(SYS_pidfd_open, pid, 0))};
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                            std::chrono::duration<double>(options.seconds));
  std::array<char, 65536> buf;
  bool ended = false;
  while (read_end.fd >= 0 || !ended) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0 && !run.timed_out) {
      ::kill(-pid, SIGKILL);
      run.timed_out = true;
    }
    std::array<pollfd, 2> fds{pollfd{read_end.fd, POLLIN, 0}, pollfd{exited.fd, POLLIN, 0}};
    const int wait_ms = run.timed_out ? 100 : static_cast<int>(std::min<long long>(left, 1000));
    const int n =
        ::poll(fds.data(), fds.size(), exited.fd < 0 && !ended ? std::min(wait_ms, 10) : wait_ms);
    if (n < 0 && errno != EINTR) break;
    if (read_end.fd >= 0 && (fds[0].revents & (POLLIN | POLLHUP | POLLERR))) {
      const ssize_t got = ::read(read_end.fd, buf.data(), buf.size());
      if (got > 0) {
        const std::size_t room =
            options.max_output - std::min(options.max_output, run.output.size());
        run.output.append(buf.data(), std::min<std::size_t>(room, static_cast<std::size_t>(got)));
      } else if (got == 0 || errno != EINTR) {
        read_end.reset();
      }
    }
    if (!ended) {
      int status = 0;
      const pid_t done = ::waitpid(pid, &status, WNOHANG);
      if (done == pid) {
        ended = true;
        run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      } else if (done < 0 && errno != EINTR) {
        ended = true;
      }
    }
    // A grandchild that keeps the pipe open after the program ended is not waited for past the
    // deadline.
    if (ended && run.timed_out) break;
    if (ended && read_end.fd >= 0 && std::chrono::steady_clock::now() > deadline) break;
  }
  return run;
}

}  // namespace frustum
