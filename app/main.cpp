// frustum: solve, check and grade graphics-pipeline exercises. Thin: parse arguments, call
// the library, print.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "app/number_options.hpp"
#include "app/serve_command.hpp"

namespace {

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

// A seed: every value of 64 bits, and nothing beyond (CLI11 took -1 and 2^64 for 2^64 - 1).
CLI::Validator whole_number(std::uint64_t lo, std::uint64_t hi) {
  return CLI::Validator(
      [lo, hi](std::string& input) -> std::string {
        const auto n = frustum::app::parse_whole_number(input, lo, hi);
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

int run_command(int argc, char** argv) {
  using frustum::app::Format;
  CLI::App cli{"Frustum: solves, explains and grades exercises on the 3D graphics pipeline",
               "frustum"};
  cli.require_subcommand(1);
  cli.set_version_flag("--version", "frustum " FRUSTUM_VERSION, "Print the version and exit");
  cli.footer(
      examples({"frustum solve problems/seeds/001_zbuffer_plane_method.yaml",
                "frustum grade SET.yaml ANSWERS.yaml",
                "frustum SUBCOMMAND --help     (options and an example for each subcommand)"}));
  const std::vector<std::pair<std::string, Format>> formats = {{"text", Format::Text},
                                                               {"markdown", Format::Markdown},
                                                               {"json", Format::Json},
                                                               {"html", Format::Html},
                                                               {"latex", Format::Latex}};

  std::string set, answers;
  std::optional<std::string> id;
  Format format = Format::Text;

  auto* solve = cli.add_subcommand("solve", "Solve a problem set, with derivations");
  solve->add_option("set", set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  solve->add_option("--id", id, "Solve only this problem");
  solve
      ->add_option("--format", format,
                   "Output: text (default), markdown, json, html (a typeset, self-contained page) "
                   "or latex (for lualatex)")
      ->type_name("FORMAT")
      ->transform(choice(formats));
  std::optional<frustum::Precision> precision;
  solve
      ->add_option("--precision", precision,
                   "Arithmetic: exact (default, with derivations), or float, double, long-double")
      ->type_name("PRECISION")
      ->transform(choice<frustum::Precision>({{"exact", frustum::Precision::Exact},
                                              {"double", frustum::Precision::Double},
                                              {"float", frustum::Precision::Float},
                                              {"long-double", frustum::Precision::LongDouble}}));
  solve->footer(
      examples({"frustum solve problems/seeds/001_zbuffer_plane_method.yaml --id seed001-pixel-z",
                "frustum solve problems/seeds --format markdown > solutions.md"}));

  auto* check = cli.add_subcommand("check", "Report every error in a problem set; no solutions");
  check->add_option("set", set, "Problem set (YAML), or a directory of them")
      ->required()
      ->check(CLI::ExistingPath);
  check->footer(examples({"frustum check problems/seeds"}));

  std::string lang = "en", grade_lang = "en";
  solve
      ->add_option("--lang", lang,
                   "Language of the derivations and of the problems' texts (where the set gives "
                   "it): en, ja or ru")
      ->check(CLI::IsMember({"en", "ja", "ru"}));

  frustum::app::GradeOptions grade_opt;
  auto* grade =
      cli.add_subcommand("grade", "Grade a student's answers, or a class, against a problem set");
  grade->add_option("set", grade_opt.set, "Problem set (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  grade
      ->add_option(
          "answers", grade_opt.answers,
          "Answers (YAML); or a directory of answer files, or a CSV roster, to grade a class")
      ->required()
      ->check(CLI::ExistingPath);
  grade->add_option("--format", grade_opt.format, "Output: text (default) or json")
      ->type_name("FORMAT")
      ->transform(choice<Format>({{"text", Format::Text}, {"json", Format::Json}}));
  grade->add_option("--lang", grade_lang, "Language of the feedback: en, ja or ru")
      ->check(CLI::IsMember({"en", "ja", "ru"}));
  grade->add_option(
      "-o,--out", grade_opt.out_dir,
      "A class: directory for gradebook.csv, feedback/, gradescope/ (default grades)");
  grade
      ->add_option("--timeout", grade_opt.timeout,
                   "A class: seconds allowed per submission (default 10)")
      ->check(CLI::Range(0.1, 3600.0));
  grade
      ->add_option("-j,--jobs", grade_opt.jobs,
                   "A class: submissions graded at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  grade->add_option("--gradescope", grade_opt.gradescope,
                    "One student: write Gradescope's results.json here");
  grade->add_option("--prairielearn", grade_opt.prairielearn,
                    "One student: write PrairieLearn's external-grader results.json here");
  grade->add_option("--html", grade_opt.html,
                    "One student: write the feedback page (self-contained HTML) here");
  grade->add_option("--markdown", grade_opt.markdown,
                    "One student: write the feedback as Markdown here");
  grade
      ->add_option("--variants", grade_opt.variants,
                   "Grade each student against their set written by `frustum generate -o DIR` "
                   "(DIR/SET-STUDENT.yaml)")
      ->check(CLI::ExistingDirectory);
  grade
      ->add_option(
          "--roster", grade_opt.roster,
          "The class roster (CSV with a student column, or one id a line): says whose each file "
          "is, "
          "and grades each student against the variant `frustum generate --roster` drew (redraws "
          "included)")
      ->check(CLI::ExistingFile)
      ->excludes("--variants");
  grade->footer(examples(
      {"frustum grade problems/seeds/001_zbuffer_plane_method.yaml "
       "problems/seeds/answers/001_zbuffer_plane_method.yaml",
       "frustum grade SET.yaml submissions/ -o grades/      (a class: gradebook.csv, feedback/)",
       "frustum grade SET.yaml ANSWERS.yaml --gradescope results.json --lang ja"}));

  auto* kinds = cli.add_subcommand("kinds", "List the problem kinds and their answers");
  std::string kinds_format = "text";
  kinds
      ->add_option("--format", kinds_format,
                   "text, or markdown: the README's kinds table, generated from the kinds")
      ->check(CLI::IsMember({"text", "markdown"}));
  kinds->footer(examples({"frustum kinds", "frustum kinds --format markdown"}));

  frustum::app::GenerateCommand gen_opt;
  auto* generate =
      cli.add_subcommand("generate", "Per-student or seeded variants of a set, with answer keys");
  generate->add_option("set", gen_opt.set, "Problem set (YAML)")
      ->required()
      ->check(CLI::ExistingFile);
  auto* gen_student =
      generate->add_option("--student", gen_opt.students, "Student id(s): one variant each");
  auto* gen_seed =
      generate->add_option("--seed", gen_opt.seed, "Seed of --count variants (pairwise distinct)")
          ->check(whole_number(0, UINT64_MAX));
  generate->add_option("--count", gen_opt.count, "How many variants from --seed (default 1)")
      ->check(CLI::Range(1, 100000))
      ->needs(gen_seed);
  auto* gen_roster =
      generate
          ->add_option("--roster", gen_opt.roster,
                       "Class roster: a CSV with a student column, or one id per line")
          ->check(CLI::ExistingFile);
  gen_seed->excludes(gen_student);
  gen_seed->excludes(gen_roster);
  generate
      ->add_option("-j,--jobs", gen_opt.jobs,
                   "--count, --roster: variants drawn at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  generate->add_option("-o,--out", gen_opt.out_dir,
                       "Directory for the sets; keys go in its answers/ (default .)");
  generate
      ->add_option(
          "--format", gen_opt.format,
          "yaml (default: sets and keys), latex or pdf (also exam sheets and the answer key)")
      ->check(CLI::IsMember({"yaml", "latex", "pdf"}));
  std::string gen_lang = "en", export_lang = "en";
  generate
      ->add_option("--lang", gen_lang,
                   "latex, pdf: language of the exam sheets' texts: en, ja or ru")
      ->check(CLI::IsMember({"en", "ja", "ru"}));
  generate->footer(examples(
      {"frustum generate SET.yaml --roster roster.csv -o variants/",
       "frustum generate SET.yaml --seed 7 --count 30 -o drill/",
       "frustum generate SET.yaml --roster roster.csv -o exam/ --format pdf   (exams + key)"}));

  frustum::app::ExportOptions export_opt;
  auto* exp = cli.add_subcommand("export",
                                 "A set as PrairieLearn questions, Canvas QTI or Moodle XML; a "
                                 "gradebook for Canvas or Moodle");
  exp->add_option("format", export_opt.format, "What to write")
      ->required()
      ->check(CLI::IsMember({"prairielearn", "qti", "moodle", "canvas-grades", "moodle-grades"}));
  exp->add_option("input", export_opt.input,
                  "Problem set (YAML); for *-grades, the gradebook.csv of `frustum grade`")
      ->required()
      ->check(CLI::ExistingFile);
  exp->add_option("-o,--out", export_opt.out,
                  "Directory (prairielearn, qti), .xml file (moodle) or .csv file (*-grades; "
                  "default: standard output)");
  exp->add_option("--count", export_opt.count,
                  "Variants to draw (default 1: the set itself when nothing varies)")
      ->check(CLI::Range(1, 1000));
  exp->add_option("--seed", export_opt.seed, "Seed of the variants (default 1)")
      ->check(whole_number(0, UINT64_MAX));
  exp->add_option("--assignment", export_opt.assignment,
                  "*-grades: the assignment's column name (default Frustum)");
  exp->add_flag("--sis-login", export_opt.sis_login,
                "canvas-grades: the student ids are SIS Login IDs (default SIS User IDs)");
  exp->add_option("--image", export_opt.image,
                  "prairielearn: the grader image (default frustum-prairielearn)");
  exp->add_option("--lang", export_lang, "Language of the questions' texts: en, ja or ru")
      ->check(CLI::IsMember({"en", "ja", "ru"}));
  exp->footer(examples(
      {"frustum export prairielearn SET.yaml --count 20 -o course/questions/",
       "frustum export qti SET.yaml --count 3 -o quiz/ && (cd quiz && zip -r ../quiz.zip .)",
       "frustum export moodle SET.yaml --count 20 -o questions.xml",
       "frustum export canvas-grades grades/gradebook.csv --assignment \"Homework 3\" -o "
       "canvas.csv"}));

  frustum::app::ServeOptions serve_opt;
  CLI::App* serve = frustum::app::add_serve_command(cli, serve_opt);
  std::string draw_id, draw_output;
  int raster = 48;
  auto* draw =
      cli.add_subcommand("draw", "Draw one problem as SVG (hidden lines, painter vs z-buffer)");
  draw->add_option("set", set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  draw->add_option("--id", draw_id, "The problem to draw")->required();
  draw->add_option("-o,--output", draw_output, "SVG file to write (default: standard output)");
  draw->add_option("--raster", raster, "Painter vs z-buffer: window size in pixels (4 to 512)")
      ->check(CLI::Range(4, 512));
  draw->footer(
      examples({"frustum draw problems/seeds/003_polygons_backface.yaml --id "
                "seed003-ico-hidden-lines -o ico.svg"}));

  auto* bench = cli.add_subcommand("bench", "Benchmarks");
  bench->require_subcommand(1);
  std::string bench_dir = "docs";
  int bench_cases = 200;
  auto* accuracy =
      bench->add_subcommand("accuracy", "Speed against error of every numeric backend");
  accuracy->add_option("-o,--output", bench_dir, "Directory for accuracy.md and accuracy_plot.svg");
  accuracy->add_option("--cases", bench_cases, "Generated problems per kind")
      ->check(CLI::Range(1, 100000));
  std::string hard_dir = "problems/hard";
  accuracy->add_option("--hard", hard_dir, "Directory of the hard-case suite")
      ->check(CLI::ExistingDirectory);
  accuracy->footer(examples({"frustum bench accuracy -o docs --cases 200"}));
  bench->footer(examples({"frustum bench accuracy -o docs --cases 200"}));

  frustum::app::RenderOptions render_opt;
  std::string render_size;
  auto* render = cli.add_subcommand("render", "Render a scene (or a set's render problem) to PNG");
  render->add_option("file", render_opt.file, "Scene file (scene:) or problem set")
      ->required()
      ->check(CLI::ExistingFile);
  render->add_option("-o,--output", render_opt.output, "PNG file to write")->required();
  render->add_option("--depth", render_opt.depth, "Also write the depth buffer as a grey PNG");
  render->add_option("--size", render_size, "Image size WxH (default: the scene's viewport)");
  render->add_option("--id", render_opt.id,
                     "The render problem of a problem set (default: the first)");
  render
      ->add_option("--method", render_opt.method,
                   "zbuffer or scanline (default: the scene's method)")
      ->check(CLI::IsMember({"zbuffer", "scanline"}));
  render
      ->add_option(
          "--threads", render_opt.threads,
          "2 or more: the render shared by that many threads (a modelled scene's geometry "
          "in parts, then the frame in bands; a larger scene streamed, each thread drawing "
          "strips of rows), the same image; default 1")
      ->check(CLI::Range(1, 1024));
  render->footer(examples(
      {"frustum render problems/seeds/paperplane.yaml -o paperplane.png --depth depth.png"}));

  CLI11_PARSE(cli, argc, argv);
  // The last line of defence: whatever a command throws (a file system error, memory) ends in
  // a message and exit status 1, never in std::terminate.
  try {
    const frustum::app::Output out{std::cout, std::cerr, isatty(STDOUT_FILENO) != 0,
                                   isatty(STDERR_FILENO) != 0};
    if (solve->parsed())
      return frustum::app::run_solve(set, id, format, out, precision, *frustum::parse_lang(lang));
    if (accuracy->parsed())
      return frustum::app::run_bench_accuracy(bench_dir, hard_dir, bench_cases, out);
    if (check->parsed()) return frustum::app::run_check(set, out);
    if (grade->parsed()) {
      grade_opt.lang = *frustum::parse_lang(grade_lang);
      return frustum::app::run_grade(grade_opt, out);
    }
    if (kinds->parsed()) return frustum::app::run_kinds(out, kinds_format == "markdown");
    if (generate->parsed()) {
      if (gen_opt.students.empty() && !gen_opt.roster && !gen_opt.seed) {
        std::cerr << "generate: give --student ID, --roster FILE or --seed N [--count K]\n";
        return 2;
      }
      gen_opt.lang = *frustum::parse_lang(gen_lang);
      return frustum::app::run_generate(gen_opt, out);
    }
    if (exp->parsed()) {
      if (export_opt.out.empty() && export_opt.format.find("grades") == std::string::npos) {
        std::cerr << "export " << export_opt.format << ": give -o OUT\n";
        return 2;
      }
      export_opt.lang = *frustum::parse_lang(export_lang);
      return frustum::app::run_export(export_opt, out);
    }
    if (serve->parsed()) return frustum::app::run_serve(serve_opt, out);
    if (draw->parsed()) return frustum::app::run_draw(set, draw_id, draw_output, raster, out);
    if (render->parsed()) {
      if (!render_size.empty()) {
        const auto size = frustum::app::parse_size(render_size);
        if (const std::string* why = std::get_if<std::string>(&size)) {
          std::cerr << "--size: " << *why << "\n";
          return 2;
        }
        render_opt.size = std::get<std::pair<int, int>>(size);
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
// children, every page those destructors write to is a copy-on-write fault: they cost it about
// 4 ms, `solve` about 1.5 ms. Under AddressSanitizer the usual exit, so that leaks are reported.
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
