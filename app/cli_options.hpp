// What every subcommand's registration shares: a subcommand with the function that runs it
// once its options are parsed, and CLI11 validators for words and whole numbers.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "app/commands.hpp"

namespace frustum::app {

// A subcommand added to the command line; `run` is called when it was the one given. Its
// options' values live in what `run` holds.
struct Command {
  CLI::App* app = nullptr;
  std::function<int(const Output&)> run;
};

// An option's words and the values they stand for (case ignored); only the words are accepted,
// and the help lists them as they are typed ({text,markdown,json}), not CLI11's mapping.
template <class T>
CLI::Validator choice(std::vector<std::pair<std::string, T>> words) {
  std::string list;
  for (const auto& [word, value] : words) list += (list.empty() ? "" : ",") + word;
  return CLI::Validator(
      [words, list](std::string& input) -> std::string {
        for (const auto& [word, value] : words)
          if (CLI::detail::to_lower(input) == word) {
            input = std::to_string(static_cast<int>(value));
            return {};
          }
        return "'" + input + "' is not one of " + list;
      },
      "{" + list + "}");
}

// A whole number in [lo, hi], read exactly (CLI11 took -1 and 2^64 for 2^64 - 1).
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi);

// A help footer: "Example:" or "Examples:" and the lines, indented.
std::string examples(std::initializer_list<const char*> lines);

// The languages' option check (en, ja, ru).
CLI::Validator language_check();

// The subcommands, in the order `frustum --help` lists them (each in its own file).
Command add_solve_command(CLI::App& cli);
Command add_check_command(CLI::App& cli);
Command add_grade_command(CLI::App& cli);
Command add_kinds_command(CLI::App& cli);
Command add_generate_command(CLI::App& cli);
Command add_export_command(CLI::App& cli);
Command add_serve_command(CLI::App& cli);
Command add_draw_command(CLI::App& cli);
Command add_bench_command(CLI::App& cli);
Command add_render_command(CLI::App& cli);
Command add_serve_command(CLI::App& cli);

}  // namespace frustum::app
