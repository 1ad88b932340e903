#include "app/cli_options.hpp"

#include <variant>

#include "app/number_options.hpp"

namespace frustum::app {

CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& input) -> std::string {
        const auto n = parse_whole_number(input, lo, hi);
        const std::string* why = std::get_if<std::string>(&n);
        return why ? *why : std::string();
      },
      "");
}

std::string examples(std::initializer_list<const char*> lines) {
  std::string s = lines.size() == 1 ? "\nExample:\n" : "\nExamples:\n";
  for (const char* line : lines) s += std::string("  ") + line + "\n";
  return s;
}

CLI::Validator language_check() { return CLI::IsMember({"en", "ja", "ru"}); }

}  // namespace frustum::app
