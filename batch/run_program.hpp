// Running another program: always from an argument vector (posix_spawnp), never through a
// shell, so no file name, id or option value is ever read as a command.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace frustum {

// Where one of the child's output streams goes.
enum class OutputTo {
  Capture,  // into ProgramRun::output (stdout and stderr captured together when both say so)
  File,     // into RunOptions::log_file (created or emptied)
  Null,     // /dev/null
  Inherit,  // this process's own stream
};

struct RunOptions {
  std::optional<std::string> cwd;         // the child's working directory
  std::vector<std::string> environment;   // "NAME=value" set over this process's environment
  std::optional<std::string> stdin_file;  // read from this file (default: /dev/null)
  OutputTo out = OutputTo::Capture;
  OutputTo err = OutputTo::Capture;
  std::string log_file;              // for OutputTo::File
  double seconds = 600;              // killed (SIGKILL, its whole process group) after this
  std::size_t max_output = 1 << 26;  // captured bytes kept; the rest is read and dropped
};

struct ProgramRun {
  int status = -1;         // exit status; -1 when it did not exit normally or did not start
  bool started = false;    // false: the program could not be started (start_error says why)
  bool timed_out = false;  // killed after RunOptions::seconds
  std::string start_error;
  std::string output;  // what it wrote to the captured streams
};

// Runs argv[0] (looked up on PATH when it has no '/') with exactly these arguments. Never throws
// for the child's failures: they are in the result.
ProgramRun run_program(const std::vector<std::string>& argv, const RunOptions& options = {});

}  // namespace frustum
