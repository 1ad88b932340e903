// frustum: solve, check and grade graphics-pipeline exercises. Only assembles the subcommands,
// each registered from its own file (app/cli_options.hpp), and flushes what they print.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

#include "app/cli_options.hpp"
#include "app/command_line_secrets.hpp"

namespace {

namespace app = frustum::app;

int run_command(int argc, char** argv) {
  CLI::App cli{"Frustum: solves, explains and grades exercises on the 3D graphics pipeline",
               "frustum"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "frustum " FRUSTUM_VERSION, "Print the version and exit");
  cli.footer(app::examples(
      {"frustum solve problems/seeds/001_zbuffer_plane_method.yaml",
       "frustum grade SET.yaml ANSWERS.yaml",
       "frustum SUBCOMMAND --help     (options and an example for each subcommand)"}));
  const std::vector<app::Command> commands = {
      app::add_solve_command(cli), app::add_check_command(cli),    app::add_grade_command(cli),
      app::add_kinds_command(cli), app::add_generate_command(cli), app::add_export_command(cli),
      app::add_serve_command(cli), app::add_draw_command(cli),     app::add_bench_command(cli),
      app::add_render_command(cli)};
  CLI11_PARSE(cli, argc, argv);
  app::hide_passwords(argc, argv, std::cerr);  // parsed: argv's copy of a secret is not needed
  // The last line of defence: whatever a command throws (a file system error, memory) ends in
  // a message and exit status 1, never in std::terminate.
  try {
    const app::Output out{std::cout, std::cerr, isatty(STDOUT_FILENO) != 0,
                          isatty(STDERR_FILENO) != 0};
    for (const app::Command& command : commands)
      if (command.app->parsed()) return command.run(out);
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}

// Standard output written to the end: a command whose output could not be written (a full
// disk under `> page.html`) says so and fails, instead of ending with status 0 and a page cut
// short.
int flush_output(int status) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (!std::cout || !flushed || std::ferror(stdout)) {
    std::cerr << "error: standard output could not be written in full"
              << (!flushed && error != 0 ? std::string(": ") + std::strerror(error) : "") << "\n";
    if (status == 0) status = 1;
  }
  std::cerr.flush();
  std::fflush(nullptr);
  return status;
}

}  // namespace

// The process ends once the command's output is flushed, without the static destructors: the
// command's files are written and closed by then, and what the destructors would free (the
// registry of kinds, GiNaC's tables) the kernel frees at once. After `grade` forked its
// children, every page those destructors write to is a copy-on-write fault, and even without
// children they are milliseconds of a short command's time. Under AddressSanitizer the usual
// exit, so that leaks are reported.
#if defined(__SANITIZE_ADDRESS__)
#define FRUSTUM_LEAK_CHECK 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FRUSTUM_LEAK_CHECK 1
#endif
#endif
int main(int argc, char** argv) {
  const int status = flush_output(run_command(argc, argv));
#if defined(FRUSTUM_LEAK_CHECK)
  return status;
#else
  std::_Exit(status);
#endif
}
