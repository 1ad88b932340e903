// `frustum grade SET ANSWERS`: one answers file (text or JSON report, optional feedback files),
// or a class — a directory of answer files or a CSV roster — graded into a directory of
// outputs with a progress bar on a terminal.
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <ostream>

#include "app/commands.hpp"
#include "app/variant_files.hpp"
#include "grader/atomic_file.hpp"
#include "grader/batch.hpp"
#include "grader/feedback.hpp"
#include "grader/gradescope.hpp"
#include "grader/prairielearn.hpp"
#include "grader/report.hpp"
#include "grader/visible_text.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::app {

namespace {

// The sets of a class as `frustum generate --roster` drew them (redraws included), by student.
using ClassVariants = std::map<std::string, ProblemSet>;

// A set that does not vary is every student's set: the roster then says only whose each file
// is. (Variants that `generate` drew from such a set are graded against its files, --variants.)
ClassVariants class_variants(const ProblemSet& set, const std::vector<std::string>& roster) {
  ClassVariants out;
  if (!set_varies(set)) {
    for (const std::string& student : roster) out.emplace(student, set);
    return out;
  }
  const std::vector<ProblemSet> drawn = variants_for_class(set, roster, false);
  for (std::size_t i = 0; i < roster.size(); ++i) out.emplace(roster[i], drawn[i]);
  return out;
}

// With --roster: the class's variants, or false after printing why the roster cannot be read.
bool read_class(const ProblemSet& set, const GradeOptions& g, const Output& o,
                std::optional<ClassVariants>& out) {
  if (!g.roster) return true;
  try {
    out = class_variants(set, read_roster(*g.roster));
    return true;
  } catch (const InputError& e) {
    o.err << "error: " << e.diagnostic().format() << "\n";
    return false;
  }
}

ProblemSet refused(const ProblemSet& set, const std::string& where, const std::string& why) {
  ProblemSet none = set;
  none.problems.clear();
  none.errors.push_back(Diagnostic{SourceLocation{where, 0, 0}, "student", why});
  return none;
}

const char* kRedrawHint =
    "grade the class against the files `frustum generate -o DIR` wrote (--variants DIR) or against "
    "the roster it "
    "was generated from (--roster ROSTER)";

// A class of a varying set graded without --variants or --roster: each student is graded against
// the variant drawn from their own id (as `generate --student` draws it), so each result depends
// on that student's file alone. When two students' variants from their ids share a problem and the
// class was generated together (`generate --roster`), one of them was drawn again, and which
// depends on the roster: those pairs are named to the instructor (never in a student's result).
std::vector<std::string> shared_draws(const ProblemSet& set,
                                      const std::vector<BatchEntry>& entries) {
  std::vector<std::string> said;
  std::map<std::string, std::string> first;  // problem id + given → the first student with it
  for (const BatchEntry& e : entries) {
    if (e.student.empty() || e.error) continue;
    const ProblemSet v = variant_for(set, e.student);
    for (std::size_t i = 0; i < v.problems.size() && i < set.problems.size(); ++i) {
      const ProblemSpec& p = v.problems[i];
      if (!problem_varies(set, set.problems[i]) || p.error) continue;
      const auto [it, fresh] = first.emplace(p.id + "\x1f" + emit_flow(p.given_node), e.student);
      if (!fresh && it->second != e.student)
        said.push_back(fmt::format(
            "the variants of {} and {} drawn from their ids share problem {}; each was graded "
            "against the variant from their own id, which is right if the class was generated "
            "with `frustum generate --student`; if it was generated with --roster, one of them "
            "was drawn again: {}",
            it->second, e.student, p.id, kRedrawHint));
    }
  }
  return said;
}

// The set a student is graded against: with --variants, the file `frustum generate` wrote for
// them; with --roster, their variant in the class drawn from that roster; otherwise their own
// variant when the set varies.
ProblemSet set_for_student(const ProblemSet& set, const GradeOptions& g,
                           const ClassVariants* roster, const std::string& student,
                           std::string& variant) {
  if (g.variants) {
    const std::string file = variant_file(*g.variants, set.file, variant_name(student));
    std::error_code ec;
    if (student.empty() || !std::filesystem::is_regular_file(file, ec))
      return refused(set, file,
                     student.empty()
                         ? "the answers need `student:` to find the student's generated set"
                         : "no generated set for student " + student + " in " + *g.variants);
    variant = "graded against " + file;
    return load_problem_set(file);
  }
  if (roster) {
    const auto it = roster->find(student);
    if (it == roster->end())
      return refused(set, *g.roster,
                     student.empty()
                         ? "the answers need `student:` to find the student in the roster"
                         : "student " + student + " is not in the roster " + *g.roster);
    const ProblemSet& v = it->second;
    if (v.variant)
      variant = fmt::format(
          "graded against the variant of student {} in the class of {} (draw {}, seed {:016x})",
          student, *g.roster, v.variant->draw, v.variant->seed);
    return v;
  }
  if (!set_varies(set)) return set;
  ProblemSet v = variant_for(set, student);
  if (v.variant)
    variant = fmt::format(
        "graded against the variant of student {} (seed {:016x}) drawn from the id, as "
        "`frustum generate --student` draws it; a class generated with --roster may have drawn "
        "this "
        "student again: then {}",
        v.variant->student, v.variant->seed, kRedrawHint);
  return v;
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
  options.lang = g.lang;
  std::optional<ClassVariants> roster;
  if (!read_class(set, g, o, roster)) return 1;
  const std::vector<std::string> shared = !g.roster && !g.variants && set_varies(set)
                                              ? shared_draws(set, entries)
                                              : std::vector<std::string>{};
  if (set_varies(set) || g.variants || roster)
    options.set_for = [&](const ProblemSet& s, const std::string& student, std::string& variant) {
      return set_for_student(s, g, roster ? &*roster : nullptr, student, variant);
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

int run_grade(const GradeOptions& g, const Output& o) {
  const ProblemSet set = load_problem_set(g.set);
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
  std::optional<ClassVariants> roster;
  if (!read_class(set, g, o, roster)) return 1;
  const ProblemSet graded = unreadable ? set
                                       : set_for_student(set, g, roster ? &*roster : nullptr,
                                                         submission.student, variant);
  GradeReport report = grade(graded, submission);
  report.variant = variant;
  if (g.format == Format::Json)
    o.out << json_text(render_grade_json(report)) << "\n";
  else if (unreadable)
    for (const Diagnostic& d : submission.errors)
      o.err << "error: " << terminal_text(d.format()) << " — nothing was graded\n";
  else
    o.out << render_grade_text(report, TextStyle{o.color, g.lang});
  try {
    if (g.gradescope)
      write_file_atomically(*g.gradescope, json_text(gradescope_results(report, g.lang)) + "\n");
    if (g.prairielearn)
      write_file_atomically(*g.prairielearn,
                            json_text(prairielearn_results(report, g.lang)) + "\n");
    if (g.html) write_file_atomically(*g.html, render_feedback_html(report, g.lang));
    if (g.markdown) write_file_atomically(*g.markdown, render_feedback_markdown(report, g.lang));
  } catch (const std::exception& e) {
    o.err << "error: " << e.what() << "\n";
    return 1;
  }
  bool failed = !report.errors.empty();
  for (const ProblemGrade& p : report.problems) failed = failed || p.error.has_value();
  return failed ? 1 : 0;
}

}  // namespace frustum::app
