// `frustum draw SET.yaml --id ID [-o FILE.svg] [--raster N] [--lang L]`: the picture of one
// problem.
#include <fstream>
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "solver/input/given_reader.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/visibility/pictures.hpp"

namespace frustum::app {

namespace {

std::string drawable_kinds() {
  std::string s;
  for (const KindInfo& k : builtin_kinds().all())
    if (k.drawable) s += (s.empty() ? "" : ", ") + k.name;
  return s;
}

}  // namespace

int run_draw(const std::string& set_file, const std::string& id, const std::string& output,
             int raster, const Output& o, std::optional<Lang> lang) {
  const ProblemSet set = load_problem_set(set_file);
  for (const Diagnostic& d : set.errors) o.err << d.format() << "\n";
  const ProblemSpec* spec = set.find(id);
  if (!spec) {
    o.err << set_file << ": no problem with id '" << id << "'\n";
    return 1;
  }
  if (spec->error) {
    o.err << spec->error->format() << "\n";
    return 1;
  }
  if (!spec->info->drawable) {
    o.err << set_file << ": problem '" << id << "' is of kind " << spec->kind
          << ", which cannot be drawn (kinds that can: " << drawable_kinds() << ")\n";
    return 1;
  }
  // Solve first: a problem that cannot be solved (an open mesh) is reported as `solve` would.
  const ProblemResult solved = solve_problem(*spec, set.file, false);
  if (solved.error) {
    o.err << solved.error->format() << "\n";
    return 1;
  }
  Picture picture;
  try {
    PictureOptions options;
    options.api = spec->conventions.api;
    options.title = spec->id + " (" + spec->kind + ")";
    options.raster = raster;
    options.lang = lang.value_or(set.lang);
    picture = draw_picture(spec->info->drawable(spec->given), options);
  } catch (const DomainError& e) {
    o.err << GivenReader(spec->given_node, set.file, spec->field + ".given", {})
                 .locate(e.field(), e.what())
                 .format()
          << "\n";
    return 1;
  }
  if (output.empty() || output == "-") {
    o.out << picture.svg;
  } else {
    std::ofstream file(output, std::ios::binary);
    file << picture.svg;
    if (!file) {
      o.err << output << ": cannot write the picture\n";
      return 1;
    }
    o.out << output << ": " << picture.summary << "\n";
  }
  return 0;
}

Command add_draw_command(CLI::App& cli) {
  struct Options {
    std::string set, id, output;
    int raster = 48;
    std::string lang;  // empty: the set's own
  };
  auto opt = std::make_shared<Options>();
  auto* draw =
      cli.add_subcommand("draw", "Draw one problem as SVG (hidden lines, painter vs z-buffer)");
  draw->add_option("set", opt->set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  draw->add_option("--id", opt->id, "The problem to draw")->required();
  draw->add_option("-o,--output", opt->output, "SVG file to write (default: standard output)");
  draw->add_option("--raster", opt->raster, "Painter vs z-buffer: window size in pixels (4 to 512)")
      ->check(CLI::Range(4, 512));
  draw->add_option("--lang", opt->lang,
                   "Language of the picture's captions: en, ja or ru (default: the set's own, "
                   "its lang:)")
      ->check(language_check());
  draw->footer(
      examples({"frustum draw problems/seeds/003_polygons_backface.yaml --id "
                "seed003-ico-hidden-lines -o ico.svg"}));

  return {draw, [opt](const Output& o) {
            return run_draw(opt->set, opt->id, opt->output, opt->raster, o, parse_lang(opt->lang));
          }};
}

}  // namespace frustum::app
