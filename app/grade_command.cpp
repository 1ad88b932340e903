// `frustum grade SET ANSWERS`: one answers file (text or JSON report, optional feedback files),
// or a class — a directory of answer files or a CSV roster — graded into a directory of
// outputs with a progress bar on a terminal.
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <memory>
#include <ostream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "batch/atomic_file.hpp"
#include "batch/batch.hpp"
#include "batch/class_variants.hpp"
#include "batch/variant_files.hpp"
#include "grader/visible_text.hpp"
#include "report/feedback.hpp"
#include "report/gradescope.hpp"
#include "report/prairielearn.hpp"
#include "report/report.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::app {

namespace {

VariantSource variant_source(const GradeOptions& g) { return {g.variants, g.roster}; }

// With --roster: the class's variants, or false after printing why the roster cannot be read.
bool read_class(const ProblemSet& set, const GradeOptions& g, const Output& o,
                std::optional<RosterVariants>& out) {
  try {
    out = read_class_variants(set, variant_source(g));
    return true;
  } catch (const InputError& e) {
    o.err << "error: " << e.diagnostic().format() << "\n";
    return false;
  }
}

// Text from files (ids, messages) on a terminal: visible text, so that an id or a file name
// cannot move the cursor, retitle the window or hide a line.
std::string terminal_text(const std::string& s) { return visible_text(s); }

std::string progress_bar(std::size_t done, std::size_t total, const std::string& who) {
  constexpr int kWidth = 30;
  const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
  return fmt::format("\r[{}{}] {}/{} {:<24.24}", std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(kWidth - filled), '.'), done, total,
                     terminal_text(who));
}

int run_batch(const ProblemSet& set, const GradeOptions& g, const Output& o) {
  // NaN compares false with everything, so `--timeout nan` once meant no limit at all.
  if (!(g.timeout > 0 && g.timeout <= kMaxBatchTimeout)) {
    o.err << fmt::format("error: --timeout must be a number of seconds in (0, {}]\n",
                         kMaxBatchTimeout);
    return 2;
  }
  std::vector<BatchEntry> entries;
  std::vector<Diagnostic> not_graded;  // other files and folders beside the answers
  try {
    entries = collect_submissions(g.answers, kMaxSubmissionBytes, &not_graded);
    if (g.roster) entries = apply_roster(std::move(entries), read_roster(*g.roster), *g.roster);
  } catch (const InputError& e) {
    o.err << "error: " << terminal_text(e.diagnostic().format()) << "\n";
    return 1;
  }
  BatchOptions options;
  options.out_dir = g.out_dir.value_or("grades");
  options.timeout_seconds = g.timeout;
  options.jobs = g.jobs;
  options.lang = *g.lang;
  std::optional<RosterVariants> roster;
  if (!read_class(set, g, o, roster)) return 1;
  const std::vector<std::string> shared = !g.roster && !g.variants && set_varies(set)
                                              ? shared_draws(set, entries)
                                              : std::vector<std::string>{};
  if (set_varies(set) || g.variants || roster)
    options.set_for = [&](const ProblemSet& s, const std::string& student, std::string& variant) {
      return set_for_student(s, variant_source(g), roster ? &*roster : nullptr, student, variant);
    };
  if (o.progress)
    options.on_progress = [&](std::size_t done, std::size_t total, const std::string& who) {
      o.err << progress_bar(done, total, who) << std::flush;
      if (done == total) o.err << "\n";
    };
  // The rows as they come, in the class's order: counted, and the few with something to say
  // kept for after the batch; none of the class's rows is held (memory flat in its size).
  std::size_t rows = 0, graded = 0;
  double sum = 0;
  std::vector<std::string> said;
  options.keep_rows = false;
  options.on_row = [&](const BatchRow& row) {
    ++rows;
    if (row.status == "graded") {
      ++graded;
      sum += row.max_score > 0 ? row.score / row.max_score : 0;
    }
    // Not graded, or graded with a note (the file and the roster disagree, two files claim one
    // student).
    if (row.status != "graded" || !row.message.empty())
      said.push_back(
          fmt::format("{}: {} ({}): {}", row.source, row.status, row.student, row.message));
  };
  BatchResult result;
  try {
    result = grade_batch(set, entries, options);
  } catch (const std::exception& e) {
    if (o.progress) o.err << "\n";
    o.err << "error: " << terminal_text(e.what()) << "\n"
          << "error: nothing was written; the outputs in " << terminal_text(options.out_dir)
          << " are as they were\n";
    return 1;
  }
  for (const std::string& line : said) o.err << terminal_text(line) << "\n";
  o.out << fmt::format(
      "Graded {} of {} submissions{}; wrote {}/gradebook.csv, feedback/ and gradescope/\n", graded,
      rows, graded ? fmt::format(" (mean {:.1f}%)", 100.0 * sum / double(graded)) : "",
      options.out_dir);
  for (const Diagnostic& d : not_graded) o.err << "warning: " << terminal_text(d.format()) << "\n";
  for (const std::string& line : shared) o.err << "warning: " << terminal_text(line) << "\n";
  for (const auto& [from, to] : result.set_aside)
    o.err << "note: " << terminal_text(from) << " was not written by Frustum: moved to "
          << terminal_text(to) << " (nothing of yours is deleted)\n";
  for (const Diagnostic& d : set.all_errors()) o.err << terminal_text(d.format()) << "\n";
  return graded == rows && set.all_errors().empty() ? 0 : 1;
}

}  // namespace

int run_grade(const GradeOptions& given, const Output& o) {
  const ProblemSet set = load_problem_set(given.set);
  // Without --lang the feedback is in the set's own language (`lang:`).
  GradeOptions g = given;
  g.lang = given.lang.value_or(set.lang);
  std::error_code ec;
  const bool batch = std::filesystem::is_directory(g.answers, ec) ||
                     std::filesystem::path(g.answers).extension() == ".csv";
  if (batch) return run_batch(set, g, o);

  const Submission submission = load_submission(g.answers);
  // A file that could not be read at all (not a regular file, too large, not YAML) is one
  // error, said once: not every problem's derivation under "missing". It has no `student:` to
  // find a variant by, so it is scored (nothing earned) against the set itself, and the
  // --gradescope/--prairielearn/--html/--markdown outputs still carry the located reason.
  const bool unreadable = !submission.answers.IsMap() && !submission.errors.empty();
  std::string variant;
  std::optional<RosterVariants> roster;
  if (!read_class(set, g, o, roster)) return 1;
  const ProblemSet graded =
      unreadable ? set
                 : set_for_student(set, variant_source(g), roster ? &*roster : nullptr,
                                   submission.student, variant);
  GradeReport report = grade(graded, submission);
  report.variant = variant;
  if (g.format == Format::Json)
    o.out << json_text(render_grade_json(report)) << "\n";
  else if (unreadable)
    for (const Diagnostic& d : submission.errors)
      o.err << "error: " << terminal_text(d.format()) << " — nothing was graded\n";
  else
    o.out << render_grade_text(report, TextStyle{o.color, *g.lang});
  try {
    if (g.gradescope)
      write_file_atomically(*g.gradescope, json_text(gradescope_results(report, *g.lang)) + "\n");
    if (g.prairielearn)
      write_file_atomically(*g.prairielearn,
                            json_text(prairielearn_results(report, *g.lang)) + "\n");
    if (g.html) {
      const Figures figures = student_figures(graded, report, *g.lang);
      write_file_atomically(*g.html,
                            render_feedback_html(report, *g.lang, html_math_head(), &figures));
    }
    if (g.markdown) write_file_atomically(*g.markdown, render_feedback_markdown(report, *g.lang));
  } catch (const std::exception& e) {
    o.err << "error: " << e.what() << "\n";
    return 1;
  }
  bool failed = !report.errors.empty();
  for (const ProblemGrade& p : report.problems) failed = failed || p.error.has_value();
  return failed ? 1 : 0;
}

Command add_grade_command(CLI::App& cli) {
  auto opt = std::make_shared<GradeOptions>();
  auto lang = std::make_shared<std::string>();  // empty: the set's own
  auto* grade =
      cli.add_subcommand("grade", "Grade a student's answers, or a class, against a problem set");
  grade->add_option("set", opt->set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  grade
      ->add_option(
          "answers", opt->answers,
          "Answers (YAML); or a directory of answer files, or a CSV roster, to grade a class")
      ->required()
      ->check(CLI::ExistingPath);
  grade->add_option("--format", opt->format, "Output: text (default) or json")
      ->type_name("FORMAT")
      ->transform(choice<Format>({{"text", Format::Text}, {"json", Format::Json}}));
  grade
      ->add_option("--lang", *lang,
                   "Language of the feedback: en, ja or ru (default: the set's own, its lang:)")
      ->check(language_check());
  grade->add_option(
      "-o,--out", opt->out_dir,
      "A class: directory for gradebook.csv, feedback/, gradescope/ (default grades)");
  grade
      ->add_option("--timeout", opt->timeout,
                   "A class: seconds allowed per submission (default 10)")
      ->check(CLI::Range(0.1, 3600.0));
  grade
      ->add_option("-j,--jobs", opt->jobs,
                   "A class: submissions graded at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  grade->add_option("--gradescope", opt->gradescope,
                    "One student: write Gradescope's results.json here");
  grade->add_option("--prairielearn", opt->prairielearn,
                    "One student: write PrairieLearn's external-grader results.json here");
  grade->add_option("--html", opt->html,
                    "One student: write the feedback page (self-contained HTML) here");
  grade->add_option("--markdown", opt->markdown,
                    "One student: write the feedback as Markdown here");
  grade
      ->add_option("--variants", opt->variants,
                   "Grade each student against their set written by `frustum generate -o DIR` "
                   "(DIR/SET-STUDENT.yaml)")
      ->check(CLI::ExistingDirectory);
  grade
      ->add_option(
          "--roster", opt->roster,
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

  return {grade, [opt, lang](const Output& o) {
            opt->lang = parse_lang(*lang);
            return run_grade(*opt, o);
          }};
}

}  // namespace frustum::app
