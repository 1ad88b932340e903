// The subcommands of `frustum`: each maps its options to library calls and prints.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

namespace frustum::app {

enum class Format { Text, Markdown, Json };

struct Output {
  std::ostream& out;
  std::ostream& err;
  bool color;  // stdout is a terminal
};

// Exit status: 0 all good, 1 some problem or answer had an error (the rest is still printed).
int run_solve(const std::string& set, const std::optional<std::string>& id, Format format,
              const Output& o);
int run_check(const std::string& set, const Output& o);
int run_grade(const std::string& set, const std::string& answers, Format format, const Output& o);
int run_kinds(const Output& o);

}  // namespace frustum::app
