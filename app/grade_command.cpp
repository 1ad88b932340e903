// `frustum grade SET ANSWERS`: one answers file (text or JSON report, optional feedback files),
// or a class — a directory of answer files or a CSV roster — graded into a directory of
// outputs with a progress bar on a terminal.
#include "app/commands.hpp"
#include "app/variant_files.hpp"
#include "grader/atomic_file.hpp"
#include "grader/batch.hpp"
#include "grader/feedback.hpp"
#include "grader/gradescope.hpp"
#include "grader/report.hpp"
#include "solver/kinds/variants.hpp"
#include "solver/util/diagnostic.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>

namespace frustum::app {

namespace {

// The set a student is graded against: with --variants, the file `frustum generate` wrote for
// them; otherwise their own variant when the set varies.
ProblemSet set_for_student(const ProblemSet& set, const std::optional<std::string>& variants_dir,
                           const std::string& student, std::string& variant) {
  if (variants_dir) {
    const std::string file = variant_file(*variants_dir, set.file, variant_name(student));
    std::error_code ec;
    if (student.empty() || !std::filesystem::is_regular_file(file, ec)) {
      ProblemSet missing = set;
      missing.problems.clear();
      missing.errors.push_back(Diagnostic{SourceLocation{file, 0, 0}, "student",
                                          student.empty() ? "the answers need `student:` to find the student's generated set"
                                                          : "no generated set for student " + student + " in " + *variants_dir});
      return missing;
    }
    variant = "graded against " + file;
    return load_problem_set(file);
  }
  if (!set_varies(set)) return set;
  ProblemSet v = variant_for(set, student);
  if (v.variant)
    variant = fmt::format("graded against the variant of student {} (seed {:016x})", v.variant->student, v.variant->seed);
  return v;
}

// Text from files (ids, messages) on a terminal: control characters, escape sequences among
// them, are shown as '?' so that a student id cannot move the cursor or retitle the window.
std::string terminal_text(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    // C0 controls and DEL, and C1 controls (U+0080–U+009F, UTF-8 C2 80–C2 9F).
    if (c < 0x20 || c == 0x7F) {
      out += '?';
    } else if (c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(s[i + 1]) <= 0x9F) {
      out += '?';
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

std::string progress_bar(std::size_t done, std::size_t total, const std::string& who) {
  constexpr int kWidth = 30;
  const int filled = total ? static_cast<int>(kWidth * done / total) : kWidth;
  return fmt::format("\r[{}{}] {}/{} {:<24.24}", std::string(static_cast<std::size_t>(filled), '#'),
                     std::string(static_cast<std::size_t>(kWidth - filled), '.'), done, total, terminal_text(who));
}

int run_batch(const ProblemSet& set, const GradeOptions& g, const Output& o) {
  // NaN compares false with everything, so `--timeout nan` once meant no limit at all.
  if (!(g.timeout > 0 && g.timeout <= kMaxBatchTimeout)) {
    o.err << fmt::format("error: --timeout must be a number of seconds in (0, {}]\n", kMaxBatchTimeout);
    return 2;
  }
  std::vector<BatchEntry> entries;
  try {
    entries = collect_submissions(g.answers);
    if (g.roster) entries = apply_roster(std::move(entries), read_roster(*g.roster), *g.roster);
  } catch (const InputError& e) {
    o.err << "error: " << terminal_text(e.diagnostic().format()) << "\n";
    return 1;
  }
  BatchOptions options;
  options.out_dir = g.out_dir.value_or("grades");
  options.timeout_seconds = g.timeout;
  options.lang = g.lang;
  if (set_varies(set) || g.variants)
    options.set_for = [dir = g.variants](const ProblemSet& s, const std::string& student, std::string& variant) {
      return set_for_student(s, dir, student, variant);
    };
  if (o.progress)
    options.on_progress = [&](std::size_t done, std::size_t total, const std::string& who) {
      o.err << progress_bar(done, total, who) << std::flush;
      if (done == total) o.err << "\n";
    };
  BatchResult r;
  try {
    r = grade_batch(set, entries, options);
  } catch (const std::exception& e) {
    if (o.progress) o.err << "\n";
    o.err << "error: " << terminal_text(e.what()) << "\n"
          << "error: nothing was written; the outputs in " << terminal_text(options.out_dir)
          << " are as they were\n";
    return 1;
  }
  std::size_t graded = 0;
  double sum = 0;
  for (const BatchRow& row : r.rows) {
    if (row.status == "graded") {
      ++graded;
      sum += row.max_score > 0 ? row.score / row.max_score : 0;
      if (!row.message.empty() && g.roster)  // the file and the roster disagree
        o.err << terminal_text(fmt::format("{}: {} ({}): {}", row.source, row.status, row.student, row.message)) << "\n";
    } else {
      o.err << terminal_text(fmt::format("{}: {} ({}): {}", row.source, row.status, row.student, row.message)) << "\n";
    }
  }
  o.out << fmt::format("Graded {} of {} submissions{}; wrote {}/gradebook.csv, feedback/ and gradescope/\n", graded,
                       r.rows.size(), graded ? fmt::format(" (mean {:.1f}%)", 100.0 * sum / double(graded)) : "",
                       options.out_dir);
  for (const Diagnostic& d : set.all_errors()) o.err << terminal_text(d.format()) << "\n";
  return graded == r.rows.size() && set.all_errors().empty() ? 0 : 1;
}

}  // namespace

int run_grade(const GradeOptions& g, const Output& o) {
  const ProblemSet set = load_problem_set(g.set);
  std::error_code ec;
  const bool batch = std::filesystem::is_directory(g.answers, ec) ||
                     std::filesystem::path(g.answers).extension() == ".csv";
  if (batch) return run_batch(set, g, o);

  const Submission submission = load_submission(g.answers);
  // An answers file that could not be read has no `student:` to find a variant by: say why.
  if (g.variants && !submission.answers.IsDefined() && !submission.errors.empty()) {
    for (const Diagnostic& d : submission.errors) o.err << "error: " << terminal_text(d.format()) << "\n";
    return 1;
  }
  std::string variant;
  const ProblemSet graded = set_for_student(set, g.variants, submission.student, variant);
  GradeReport report = grade(graded, submission);
  report.variant = variant;
  if (g.format == Format::Json)
    o.out << json_text(render_grade_json(report)) << "\n";
  else
    o.out << render_grade_text(report, TextStyle{o.color, g.lang});
  try {
    if (g.gradescope) write_file_atomically(*g.gradescope, json_text(gradescope_results(report, g.lang)) + "\n");
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
