// `frustum solve SET.yaml|DIR [--id ID] [--format F] [--precision P] [--lang L]`: answers and
// derivations of every problem.
#include <algorithm>
#include <memory>
#include <ostream>
#include <vector>

#include "app/cli_options.hpp"
#include "app/set_files.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/problem/solve_precision.hpp"
#include "solver/problem/solve_set.hpp"

namespace frustum::app {

namespace {

bool failed(const SetResult& r) {
  return !r.errors.empty() ||
         std::any_of(r.problems.begin(), r.problems.end(),
                     [](const ProblemResult& p) { return p.error.has_value(); });
}

}  // namespace

int run_solve(const std::string& path, const std::optional<std::string>& id, Format format,
              const Output& o, std::optional<Precision> precision, std::optional<Lang> reading) {
  const std::vector<std::string> files = set_files(path);
  if (files.empty()) {
    o.err << path << ": no problem sets (*.yaml) here\n";
    return 1;
  }
  bool any_failed = false;
  nlohmann::ordered_json sets = nlohmann::ordered_json::array();
  for (const std::string& file : files) {
    const ProblemSet set = load_problem_set(file);
    const SetResult result =
        precision ? solve_set(set, true, id, *precision) : solve_set(set, true, id);
    // Without --lang each set is read in its own language (`lang:`).
    const Lang lang = reading.value_or(set.lang);
    any_failed = any_failed || failed(result);
    switch (format) {
      case Format::Json:
        sets.push_back(render_json(result, lang));
        break;
      case Format::Markdown:
        o.out << render_markdown(result, lang);
        break;
      case Format::Html: {
        const Figures figures = problem_figures(set, lang);
        o.out << render_html(result, lang, &figures);
        break;
      }
      case Format::Latex: {
        const Figures figures = problem_figures(set, lang);
        o.out << render_latex(result, lang, &figures);
        break;
      }
      case Format::Text:
        o.out << render_text(result, TextStyle{o.color, lang});
        break;
    }
    if (format != Format::Text)
      for (const ProblemResult& p : result.problems)
        if (p.error) o.err << p.error->format() << "\n";
  }
  // One set prints the object of problem-format.md §3; a directory prints {"sets": [...]}.
  if (format == Format::Json)
    o.out << json_text(sets.size() == 1 ? sets[0] : nlohmann::ordered_json{{"sets", sets}}) << "\n";
  return any_failed ? 1 : 0;
}

Command add_solve_command(CLI::App& cli) {
  struct Options {
    std::string set;
    std::optional<std::string> id;
    Format format = Format::Text;
    std::optional<Precision> precision;
    std::string lang;  // empty: each set's own
  };
  auto opt = std::make_shared<Options>();
  auto* solve = cli.add_subcommand("solve", "Solve a problem set, with derivations");
  solve->add_option("set", opt->set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  solve->add_option("--id", opt->id, "Solve only this problem");
  solve
      ->add_option("--format", opt->format,
                   "Output: text (default), markdown, json, html (a typeset, self-contained page) "
                   "or latex (for lualatex)")
      ->type_name("FORMAT")
      ->transform(choice<Format>({{"text", Format::Text},
                                  {"markdown", Format::Markdown},
                                  {"json", Format::Json},
                                  {"html", Format::Html},
                                  {"latex", Format::Latex}}));
  solve
      ->add_option("--precision", opt->precision,
                   "Arithmetic: exact (default, with derivations), or float, double, long-double")
      ->type_name("PRECISION")
      ->transform(choice<Precision>({{"exact", Precision::Exact},
                                     {"double", Precision::Double},
                                     {"float", Precision::Float},
                                     {"long-double", Precision::LongDouble}}));
  solve->footer(
      examples({"frustum solve problems/seeds/001_zbuffer_plane_method.yaml --id seed001-pixel-z",
                "frustum solve problems/seeds --format markdown > solutions.md"}));
  solve
      ->add_option("--lang", opt->lang,
                   "Language of the derivations and of the problems' texts (where the set gives "
                   "it): en, ja or ru (default: the set's own, its lang:)")
      ->check(language_check());
  return {solve, [opt](const Output& o) {
            return run_solve(opt->set, opt->id, opt->format, o, opt->precision,
                             parse_lang(opt->lang));
          }};
}

}  // namespace frustum::app
