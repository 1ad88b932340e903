// `frustum kinds [--format text|markdown] [--answer-syntax]`: the problem kinds, their givens
// and answers; or how each type of answer may be written.
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "grader/answer_type.hpp"
#include "solver/problem/registry.hpp"

namespace frustum::app {

int run_kinds(const Output& o, bool markdown, bool answer_syntax) {
  if (answer_syntax) {
    o.out << answer_syntax_markdown(builtin_kinds());
    return 0;
  }
  if (markdown) {
    o.out << kinds_table_markdown(builtin_kinds());
    return 0;
  }
  for (const KindInfo& k : builtin_kinds().all()) {
    o.out << k.name << " — " << k.summary.en() << "\n    given:";
    for (const std::string& f : k.given_fields) o.out << " " << f;
    o.out << "\n    answers:";
    for (const AnswerSpec& a : k.answers) o.out << " " << a.name;
    o.out << "\n";
  }
  return 0;
}

Command add_kinds_command(CLI::App& cli) {
  auto format = std::make_shared<std::string>("text");
  auto answer_syntax = std::make_shared<bool>(false);
  auto* kinds = cli.add_subcommand("kinds", "List the problem kinds and their answers");
  kinds
      ->add_option("--format", *format,
                   "text, or markdown: the manual's kinds table, generated from the kinds")
      ->check(CLI::IsMember({"text", "markdown"}));
  kinds->add_flag("--answer-syntax", *answer_syntax,
                  "How each type of answer may be written: the manual's answer-syntax table "
                  "(Markdown), generated from the answer types");
  kinds->footer(examples(
      {"frustum kinds", "frustum kinds --format markdown", "frustum kinds --answer-syntax"}));
  return {kinds, [format, answer_syntax](const Output& o) {
            return run_kinds(o, *format == "markdown", *answer_syntax);
          }};
}

}  // namespace frustum::app
