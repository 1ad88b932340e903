// frustum: solve, check and grade graphics-pipeline exercises. Thin: parse arguments, call
// the library, print.
#include "app/commands.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
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
  std::optional<frustum::Precision> precision;
  const std::map<std::string, frustum::Precision> precisions = {
      {"float", frustum::Precision::Float}, {"double", frustum::Precision::Double},
      {"long-double", frustum::Precision::LongDouble}, {"exact", frustum::Precision::Exact}};
  solve->add_option("--precision", precision, "float, double, long-double or exact (default)")
      ->transform(CLI::CheckedTransformer(precisions, CLI::ignore_case));

  auto* check = cli.add_subcommand("check", "Report every error in a problem set; no solutions");
  check->add_option("set", set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);

  std::string lang = "en", grade_lang = "en";
  solve->add_option("--lang", lang, "Language of the derivations: en or ja")->check(CLI::IsMember({"en", "ja"}));

  frustum::app::GradeOptions grade_opt;
  auto* grade = cli.add_subcommand("grade", "Grade a student's answers, or a class, against a problem set");
  grade->add_option("set", grade_opt.set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  grade->add_option("answers", grade_opt.answers,
                    "Answers (YAML); or a directory of answer files, or a CSV roster, to grade a class")
      ->required()
      ->check(CLI::ExistingPath);
  grade->add_option("--format", grade_opt.format, "text or json")
      ->transform(CLI::CheckedTransformer(std::map<std::string, Format>{{"text", Format::Text},
                                                                       {"json", Format::Json}},
                                          CLI::ignore_case));
  grade->add_option("--lang", grade_lang, "Language of the feedback: en or ja")->check(CLI::IsMember({"en", "ja"}));
  grade->add_option("-o,--out", grade_opt.out_dir, "A class: directory for gradebook.csv, feedback/, gradescope/ (default grades)");
  grade->add_option("--timeout", grade_opt.timeout, "A class: seconds allowed per submission (default 10)")
      ->check(CLI::Range(0.1, 3600.0));
  grade->add_option("--gradescope", grade_opt.gradescope, "One student: write Gradescope's results.json here");
  grade->add_option("--html", grade_opt.html, "One student: write the feedback page (self-contained HTML) here");
  grade->add_option("--markdown", grade_opt.markdown, "One student: write the feedback as Markdown here");
  grade->add_option("--roster", grade_opt.roster,
                    "A class directory: the roster (CSV with a student column, or one id a line) that says whose each file is");
  grade->add_option("--variants", grade_opt.variants,
                    "Grade each student against their set written by `frustum generate -o DIR` (DIR/SET-STUDENT.yaml)")
      ->check(CLI::ExistingDirectory);

  auto* kinds = cli.add_subcommand("kinds", "List the problem kinds and their answers");

  frustum::app::GenerateCommand gen_opt;
  auto* generate = cli.add_subcommand("generate", "Per-student or seeded variants of a set, with answer keys");
  generate->add_option("set", gen_opt.set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  auto* gen_student = generate->add_option("--student", gen_opt.students, "Student id(s): one variant each");
  auto* gen_seed = generate->add_option("--seed", gen_opt.seed, "Seed of --count variants (pairwise distinct)");
  generate->add_option("--count", gen_opt.count, "How many variants from --seed (default 1)")
      ->check(CLI::Range(1, 100000))
      ->needs(gen_seed);
  auto* gen_roster = generate->add_option("--roster", gen_opt.roster,
                                          "Class roster: a CSV with a student column, or one id per line")
                         ->check(CLI::ExistingFile);
  gen_seed->excludes(gen_student);
  gen_seed->excludes(gen_roster);
  generate->add_option("-o,--out", gen_opt.out_dir, "Directory for the sets; keys go in its answers/ (default .)");

  std::string draw_id, draw_output;
  int raster = 48;
  auto* draw = cli.add_subcommand("draw", "Draw one problem as SVG (hidden lines, painter vs z-buffer)");
  draw->add_option("set", set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  draw->add_option("--id", draw_id, "The problem to draw")->required();
  draw->add_option("-o,--output", draw_output, "SVG file to write (default: standard output)");
  draw->add_option("--raster", raster, "Painter vs z-buffer: window size in pixels (4 to 512)")
      ->check(CLI::Range(4, 512));

  auto* bench = cli.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  std::string bench_dir = "docs";
  int bench_cases = 200;
  auto* accuracy = bench->add_subcommand("accuracy", "Speed against error of every numeric backend");
  accuracy->add_option("-o,--output", bench_dir, "Directory for accuracy.md and accuracy_plot.svg");
  accuracy->add_option("--cases", bench_cases, "Generated problems per kind")->check(CLI::Range(1, 100000));
  std::string hard_dir = "problems/hard";
  accuracy->add_option("--hard", hard_dir, "Directory of the hard-case suite")->check(CLI::ExistingDirectory);

  frustum::app::RenderOptions render_opt;
  std::string render_size;
  auto* render = cli.add_subcommand("render", "Render a scene (or a set's render problem) to PNG");
  render->add_option("file", render_opt.file, "Scene file (scene:) or problem set")->required()->check(CLI::ExistingFile);
  render->add_option("-o,--output", render_opt.output, "PNG file to write")->required();
  render->add_option("--depth", render_opt.depth, "Also write the depth buffer as a grey PNG");
  render->add_option("--size", render_size, "Image size WxH (default: the scene's viewport)");
  render->add_option("--id", render_opt.id, "The render problem of a problem set (default: the first)");
  render->add_option("--method", render_opt.method, "zbuffer or scanline (default: the scene's method)")
      ->check(CLI::IsMember({"zbuffer", "scanline"}));

  CLI11_PARSE(cli, argc, argv);
  // The last line of defence: whatever a command throws (a file system error, memory) ends in
  // a message and exit status 1, never in std::terminate.
  try {
  const frustum::app::Output out{std::cout, std::cerr, isatty(STDOUT_FILENO) != 0, isatty(STDERR_FILENO) != 0};
  if (solve->parsed())
    return frustum::app::run_solve(set, id, format, out, precision, *frustum::parse_lang(lang));
  if (accuracy->parsed()) return frustum::app::run_bench_accuracy(bench_dir, hard_dir, bench_cases, out);
  if (check->parsed()) return frustum::app::run_check(set, out);
  if (grade->parsed()) {
    grade_opt.lang = *frustum::parse_lang(grade_lang);
    return frustum::app::run_grade(grade_opt, out);
  }
  if (kinds->parsed()) return frustum::app::run_kinds(out);
  if (generate->parsed()) {
    if (gen_opt.students.empty() && !gen_opt.roster && !gen_opt.seed) {
      std::cerr << "generate: give --student ID, --roster FILE or --seed N [--count K]\n";
      return 2;
    }
    return frustum::app::run_generate(gen_opt, out);
  }
  if (draw->parsed()) return frustum::app::run_draw(set, draw_id, draw_output, raster, out);
  if (render->parsed()) {
    if (!render_size.empty()) {
      int w = 0, h = 0;
      char x = 0, extra = 0;
      if (std::sscanf(render_size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 ||
          h < 1 || w > 16384 || h > 16384) {
        std::cerr << "--size: expected WxH with 1 ≤ W, H ≤ 16384, got '" << render_size << "'\n";
        return 2;
      }
      render_opt.size = std::pair{w, h};
    }
    return frustum::app::run_render(render_opt, out);
  }
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 2;
}
