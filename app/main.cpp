// frustum: solve, check and grade graphics-pipeline exercises. Thin: parse arguments, call
// the library, print.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <map>
#include <unistd.h>

int main(int argc, char** argv) {
  using frustum::app::Format;
  CLI::App cli{"Frustum: solves, explains and grades exercises on the 3D graphics pipeline"};
  cli.require_subcommand(1);
  const std::map<std::string, Format> formats = {
      {"text", Format::Text}, {"markdown", Format::Markdown}, {"json", Format::Json}};

  std::string set, answers;
  std::optional<std::string> id;
  Format format = Format::Text;

  auto* solve = cli.add_subcommand("solve", "Solve a problem set, with derivations");
  solve->add_option("set", set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  solve->add_option("--id", id, "Solve only this problem");
  solve->add_option("--format", format, "text, markdown or json")
      ->transform(CLI::CheckedTransformer(formats, CLI::ignore_case));

  auto* check = cli.add_subcommand("check", "Report every error in a problem set; no solutions");
  check->add_option("set", set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);

  auto* grade = cli.add_subcommand("grade", "Grade a student's answers against a problem set");
  grade->add_option("set", set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  grade->add_option("answers", answers, "Answers (YAML)")->required()->check(CLI::ExistingFile);
  grade->add_option("--format", format, "text or json")
      ->transform(CLI::CheckedTransformer(std::map<std::string, Format>{{"text", Format::Text},
                                                                       {"json", Format::Json}},
                                          CLI::ignore_case));

  auto* kinds = cli.add_subcommand("kinds", "List the problem kinds and their answers");

  CLI11_PARSE(cli, argc, argv);
  const frustum::app::Output out{std::cout, std::cerr, isatty(STDOUT_FILENO) != 0};
  if (solve->parsed()) return frustum::app::run_solve(set, id, format, out);
  if (check->parsed()) return frustum::app::run_check(set, out);
  if (grade->parsed()) return frustum::app::run_grade(set, answers, format, out);
  if (kinds->parsed()) return frustum::app::run_kinds(out);
  return 2;
}
