#include "batch/batch.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <thread>
#include <unordered_set>
#include <utility>

#include "batch/csv.hpp"
#include "batch/file_names.hpp"
#include "batch/gradebook.hpp"
#include "batch/isolate.hpp"
#include "batch/output_transaction.hpp"
#include "grader/student_id.hpp"
#include "report/feedback.hpp"
#include "report/gradescope.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/problem_figure.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/words.hpp"

namespace frustum {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

// The student id of an answers file, without grading it: what it states under `student:`
// (through the same bounded, strict reader as grading, which stops at the id), or else its
// file's name. A refused id (read_student_id) makes the entry an error, located at the value.
void read_id(BatchEntry& b, const std::string& text, const std::string& stem) {
  const std::optional<std::string> stated = top_scalar(text, b.source, "student");
  const StudentId id = read_student_id(stated ? *stated : stem);
  if (!id.problem) {
    b.student = id.id;
    if (stated) b.claimed = id.id;
    return;
  }
  if (!stated) {
    b.error =
        Diagnostic{SourceLocation{b.source, 0, 0}, "file name",
                   "the file has no `student:` and its name cannot be the id: " + *id.problem +
                       " (or add `student:` to the file)"}
            .format();
    return;
  }
  // Grading's reader refuses the id with the same words, at its line and column.
  for (const Diagnostic& d : load_submission_from_string(text, b.source).errors)
    if (d.field == "student") {
      b.error = d.format();
      return;
    }
  b.error = Diagnostic{SourceLocation{b.source, 0, 0}, "student", *id.problem}.format();
}

// Files that claim a student another file also claims: each row names the other files, so the
// instructor sees the two submissions (and two gradebook rows) before importing grades.
// Ids that differ only in case, the spaces around them or their Unicode form are one student
// (student_id_key): each such file names the others with the id it states.
void note_shared_students(std::vector<BatchEntry>& entries) {
  std::map<std::string, std::vector<std::size_t>> by_student;
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (!entries[i].error) by_student[student_id_key(entries[i].student)].push_back(i);
  for (const auto& [key, files] : by_student) {
    if (files.size() < 2) continue;
    for (const std::size_t i : files) {
      const std::string& student = entries[i].student;
      std::string others;
      for (const std::size_t j : files)
        if (j != i)
          others +=
              (others.empty() ? "" : ", ") + entries[j].source +
              (entries[j].student == student ? ""
                                             : " (as " + quote_excerpt(entries[j].student) + ")");
      entries[i].note =
          fmt::format("{} also claim{} student {}: each file is graded; keep the one that counts",
                      others, files.size() > 2 ? "" : "s", quote_excerpt(student));
    }
  }
}

// The files are read one after another, in this process: a thread here would leave the process
// multi-threaded for good, and every child forked from it afterwards would then count every shared
// reference (yaml-cpp's nodes, GiNaC's numbers) with atomic instructions (a quarter more CPU per
// student). Reading is cheap: top_scalar stops at the student's id.
std::vector<BatchEntry> from_directory(const fs::path& dir, std::size_t max_bytes,
                                       std::vector<Diagnostic>* not_graded) {
  std::vector<fs::path> files;
  std::vector<std::pair<fs::path, std::string>> passed_over;
  std::error_code ec;
  fs::directory_iterator it(dir, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    const std::string ext = ascii_lower(it->path().extension().string());
    std::error_code type_ec;  // a symlink loop is an entry that cannot be read, not an abort
    const bool directory = it->is_directory(type_ec);
    if ((ext == ".yaml" || ext == ".yml") && !directory)
      files.push_back(it->path());
    else if (it->path().filename().string().rfind('.', 0) != 0)  // hidden files are the system's
      passed_over.emplace_back(it->path(), directory
                                               ? "a directory: not graded (grade it on its own)"
                                               : "not an answers file (.yaml or .yml): not graded");
  }
  if (ec)
    throw InputError(Diagnostic{SourceLocation{dir.string(), 0, 0}, "",
                                "cannot list the directory: " + ec.message()});
  std::sort(files.begin(), files.end());
  std::vector<BatchEntry> out(files.size());
  std::string text;  // each file's, in turn: kept only as its length and digest
  for (std::size_t i = 0; i < files.size(); ++i) {
    BatchEntry& b = out[i];
    b.source = files[i].string();
    text.clear();
    if (const std::optional<Diagnostic> d = read_text_file(b.source, max_bytes, text))
      b.error = d->message;
    if (b.error)
      b.student = read_student_id(files[i].stem().string()).id;  // "" when it cannot be one
    else
      read_id(b, text, files[i].stem().string());
    if (!b.error) {
      b.read_when_graded = true;
      b.length = text.size();
      b.digest = text_digest(text);
    }
  }
  note_shared_students(out);
  if (not_graded) {
    std::sort(passed_over.begin(), passed_over.end());
    for (const auto& [path, why] : passed_over)
      not_graded->push_back(Diagnostic{SourceLocation{path.string(), 0, 0}, "", why});
  }
  return out;
}

// A CSV cell as a YAML value: lists ([1, 2, 3]) are read as YAML, everything else is a string,
// so that "x + y - z = -6" and "1/sqrt(3)" reach the answer parser as written.
YAML::Node cell_value(const std::string& cell) {
  const std::size_t start = cell.find_first_not_of(" \t");
  if (start != std::string::npos && cell[start] == '[') {
    // Read as every YAML file is read (parse_yaml: libyaml, bounded, strict).
    const YamlDocument doc = parse_yaml(cell, "");
    if (!doc.error && doc.root.IsSequence()) return doc.root;
  }
  return YAML::Node(cell);
}

std::vector<BatchEntry> from_csv(const std::string& path, std::size_t max_bytes) {
  std::string text;
  if (const std::optional<Diagnostic> d = read_text_file(path, kMaxRosterBytes, text))
    throw InputError(*d);
  const CsvRoster roster = parse_csv_roster(path, text);
  const CsvTable& table = roster.table;
  const std::vector<std::string>& header = table.rows[0].fields;
  const int header_line = table.rows[0].line;
  const int student_col =
      roster.student_columns.empty() ? -1 : static_cast<int>(roster.student_columns[0]);
  std::vector<std::pair<std::string, std::string>> columns(header.size());  // problem id, answer
  // Looked up, not searched: checking every pair of columns is quadratic in the header, which
  // may have kMaxCsvColumns of them.
  std::map<std::pair<std::string, std::string>, std::size_t> first_column;
  std::map<std::string, std::size_t> problem_at;  // problem id → its place below
  std::vector<std::pair<std::string, std::vector<std::size_t>>> by_problem;  // in header order
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string h = header[i];
    const int column = static_cast<int>(i) + 1;
    if (ascii_lower(h) == "student") {
      if (static_cast<int>(i) != student_col)
        throw InputError(Diagnostic{
            SourceLocation{path, header_line, column}, "header",
            fmt::format("a second 'student' column (the first is column {})", student_col + 1)});
      continue;
    }
    const std::size_t dot = h.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == h.size())
      throw InputError(
          Diagnostic{SourceLocation{path, header_line, column}, "header",
                     fmt::format("column {} is {}: name answer columns problem-id.answer", column,
                                 quote_excerpt(h))});
    columns[i] = {h.substr(0, dot), h.substr(dot + 1)};
    if (const auto [first, fresh] = first_column.emplace(columns[i], i); !fresh)
      throw InputError(Diagnostic{SourceLocation{path, header_line, column}, "header",
                                  fmt::format("column {} repeats column {} ({})", column,
                                              first->second + 1, quote_excerpt(h))});
    const auto [at, fresh] = problem_at.emplace(columns[i].first, by_problem.size());
    if (fresh) by_problem.emplace_back(columns[i].first, std::vector<std::size_t>());
    by_problem[at->second].second.push_back(i);
  }
  require_student_column(path, roster);
  // Each row's answers file, priced before any is built: its answers, each under its problem's
  // and its own name (a long header repeated on every row), all rows at most
  // kMaxRosterAnswerBytes together.
  std::vector<std::size_t> row_bytes(table.rows.size(), 0);
  std::size_t all_bytes = 0;
  for (std::size_t r = 1; r < table.rows.size(); ++r) {
    const CsvRow& row = table.rows[r];
    std::size_t& bytes = row_bytes[r];
    for (std::size_t i = 0; i < row.fields.size(); ++i)
      if (!row.fields[i].empty())
        bytes += row.fields[i].size() +
                 (i < columns.size() ? columns[i].first.size() + columns[i].second.size() : 0);
    all_bytes += std::min(bytes, max_bytes + 1);  // a row over max_bytes is an error row
    if (all_bytes > kMaxRosterAnswerBytes)
      throw InputError(Diagnostic{
          SourceLocation{path, row.line, 1}, "",
          fmt::format("the rows up to this one hold more than {} bytes of answers with their "
                      "column names (the limit is {} bytes for a roster)",
                      kMaxRosterAnswerBytes, kMaxRosterAnswerBytes)});
  }
  std::vector<BatchEntry> out;
  for (std::size_t r = 1; r < table.rows.size(); ++r) {
    const CsvRow& row = table.rows[r];
    BatchEntry b;
    b.source = fmt::format("{} row {}", path, row.line);
    b.csv_file = path;
    const StudentId id = read_student_id(student_col < static_cast<int>(row.fields.size())
                                             ? row.fields[static_cast<std::size_t>(student_col)]
                                             : "");
    b.student = id.id;
    const std::size_t bytes = row_bytes[r];
    if (id.problem) {
      b.error = Diagnostic{SourceLocation{path, row.line, student_col + 1}, "student", *id.problem}
                    .format();
    } else if (row.fields.size() > header.size()) {
      b.error = fmt::format("line {}: {} fields, but the header has {}", row.line,
                            row.fields.size(), header.size());
    } else if (bytes > max_bytes) {
      b.error = fmt::format("{} bytes: larger than the limit of {} bytes for one submission", bytes,
                            max_bytes);
    } else {
      // Keys inserted without yaml-cpp's search for an existing one (linear in the map's
      // size): the header's columns are distinct, so each key is new.
      YAML::Node answers(YAML::NodeType::Map);
      for (const auto& [problem, in_order] : by_problem) {
        YAML::Node given(YAML::NodeType::Map);
        for (const std::size_t i : in_order) {
          if (i >= row.fields.size() || row.fields[i].empty()) continue;
          given.force_insert(columns[i].second, cell_value(row.fields[i]));
          const std::pair<int, int> cell{row.line, static_cast<int>(i) + 1};
          b.cells.emplace("answers." + problem + "." + columns[i].second, cell);
          b.cells.emplace("answers." + problem, cell);  // the first cell of that problem
        }
        if (given.size() > 0) answers.force_insert(problem, given);
      }
      YAML::Node root(YAML::NodeType::Map);
      root["student"] = b.student;
      root["answers"] = answers;
      YAML::Emitter e;
      e << root;
      b.yaml = std::string(e.c_str()) + "\n";
      b.claimed = b.student;
    }
    out.push_back(std::move(b));
  }
  note_shared_students(out);  // two rows of one student, as two files
  return out;
}

// Messages about a CSV row's answers, moved from the YAML the row became to its cells.
void relocate(Diagnostic& d, const BatchEntry& e) {
  if (e.csv_file.empty()) return;
  for (std::string field = d.field; !field.empty();
       field = field.substr(0, std::min(field.size(), field.rfind('.')))) {
    if (const auto it = e.cells.find(field); it != e.cells.end()) {
      d.where = SourceLocation{e.csv_file, it->second.first, it->second.second};
      return;
    }
    if (field.find('.') == std::string::npos) break;
  }
  d.where = SourceLocation{e.csv_file, 0, 0};
}

// The shared copy of KaTeX in the output directory, beside feedback/.
constexpr const char* kKatexDir = "katex";

}  // namespace

std::uint64_t text_digest(std::string_view text) { return std::hash<std::string_view>{}(text); }

std::string submission_text(const BatchEntry& e) {
  if (!e.read_when_graded) return e.yaml;
  std::string text;
  if (const std::optional<Diagnostic> d =
          read_text_file(e.source, std::max(kMaxSubmissionBytes, e.length), text))
    throw std::runtime_error(d->message);
  if (text.size() != e.length || text_digest(text) != e.digest)
    throw std::runtime_error(
        "the answers file changed while the class was being graded, so it was not graded; "
        "grading the class again grades the file as it is now");
  return text;
}

std::vector<BatchEntry> collect_submissions(const std::string& path, std::size_t max_bytes,
                                            std::vector<Diagnostic>* not_graded) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return from_directory(path, max_bytes, not_graded);
  if (ascii_lower(fs::path(path).extension().string()) == ".csv") return from_csv(path, max_bytes);
  throw InputError(
      Diagnostic{SourceLocation{path, 0, 0}, "",
                 "expected an answers file (.yaml), a directory of them, or a CSV roster"});
}

std::vector<BatchEntry> apply_roster(std::vector<BatchEntry> entries,
                                     const std::vector<std::string>& roster,
                                     const std::string& roster_file) {
  std::map<std::string, std::size_t> by_stem;  // file stem → entry
  for (std::size_t i = 0; i < entries.size(); ++i)
    by_stem.emplace(fs::path(entries[i].source).stem().string(), i);
  std::vector<bool> used(entries.size(), false);
  std::vector<BatchEntry> out;
  for (const std::string& id : roster) {
    const std::string stem = file_name_for(id);
    const auto it = by_stem.find(stem);
    if (it == by_stem.end()) {
      BatchEntry missing;
      missing.student = id;
      missing.source = roster_file;
      missing.from_roster = true;
      missing.error = "no answers file " + stem + ".yaml for this student of the roster";
      out.push_back(std::move(missing));
      continue;
    }
    BatchEntry e = entries[it->second];
    e.note.clear();  // the roster decides whose file it is: another file's claim does not matter
    used[it->second] = true;
    if (!e.claimed.empty() && e.claimed != id)
      e.note = fmt::format(
          "the file says student {}, but the roster gives this file to {}: graded as {}",
          quote_excerpt(e.claimed), quote_excerpt(id), quote_excerpt(id));
    e.student = id;
    e.from_roster = true;
    out.push_back(std::move(e));
  }
  for (std::size_t i = 0; i < entries.size(); ++i)
    if (!used[i]) {
      BatchEntry e = std::move(entries[i]);
      e.error = "not on the roster " + roster_file + " (its answers are not graded)";
      out.push_back(std::move(e));
    }
  return out;
}

bool write_back_due(std::size_t done, std::size_t n) {
  if (n < kWriteBackClass || done == 0 || done >= n) return false;
  // Each eighth of the class.
  if (done * kWriteBacks / n != (done - 1) * kWriteBacks / n) return true;
  // Fewer than n/16, n/32 and n/64 rows left, for the first time.
  for (std::size_t part = 2 * kWriteBacks; part <= kLastWriteBack; part *= 2)
    if ((n - done) * part < n && (n - done + 1) * part >= n) return true;
  return false;
}

BatchResult grade_batch(const ProblemSet& set, const std::vector<BatchEntry>& entries,
                        const BatchOptions& options) {
  // The children, once done, end while the class is published; waited for last of all.
  Reaper reaper;
  BatchResult result;
  // File names, one per student and never shared (two files claiming one id both get theirs).
  std::vector<std::string> ids;
  for (const BatchEntry& e : entries) ids.push_back(e.student);
  const std::vector<std::string> stems = unique_file_names(ids);
  // Taken first: a locked or unwritable output directory stops the batch before any grading.
  // KaTeX once for the class (katex/, linked by every feedback page), not ~0.7 MB in each page;
  // where KaTeX is absent the pages show the formulas' Unicode forms and link nothing.
  const std::vector<std::pair<std::string, std::string>> katex = katex_files();
  std::vector<std::string> names = {"gradebook.csv", "feedback", "gradescope"};
  if (!katex.empty()) names.push_back(kKatexDir);
  // Every file the run may write, so that grading the class again writes over the run before
  // (OutputTransaction) instead of deleting one run's files and creating another's.
  std::unordered_set<std::string> files{"gradebook.csv"};
  for (const std::string& stem : stems)
    files.insert(
        {"feedback/" + stem + ".md", "feedback/" + stem + ".html", "gradescope/" + stem + ".json"});
  for (const auto& [relative, bytes] : katex) files.insert(std::string(kKatexDir) + "/" + relative);
  OutputTransaction out(options.out_dir, names, std::move(files));
  // A set that does not vary per student is solved once, here: every child inherits it.
  std::optional<SolvedSet> solved;
  if (!options.set_for) solved = solve_for_grading(set);
  const std::string math_head =
      katex.empty() ? std::string() : html_math_head_linked(std::string("../") + kKatexDir + "/");
  // The child grades, renders and writes the student's three files into this run (so that
  // -j children share the writing); the parent gets the row back. A file the child could not
  // write stops the batch, as the parent's own writes do.
  const auto work = [&](std::size_t i) -> std::string {
    const BatchEntry& e = entries[i];
    if (e.error) throw std::runtime_error(*e.error);
    Submission sub = load_submission_from_string(submission_text(e), e.source);
    for (Diagnostic& d : sub.errors) relocate(d, e);
    // A file that could not be read is reported as such, not as a file without `student:`.
    if (options.set_for && !sub.answers.IsDefined() && !sub.errors.empty())
      throw std::runtime_error(sub.errors[0].format());
    // With a roster, the roster says whose answers these are (and so whose variant applies).
    if (e.from_roster) sub.student = e.student;
    std::string variant;
    const ProblemSet graded_set =
        options.set_for ? options.set_for(set, sub.student, variant) : set;
    // The student's own set could not be made (no `student:`, no generated file): an error row
    // that says why, not a score of 0.
    if (graded_set.errors.size() > set.errors.size())
      throw std::runtime_error(graded_set.errors.back().format());
    GradeReport report = grade(graded_set, sub, solved ? &*solved : nullptr);
    for (Diagnostic& d : report.errors) relocate(d, e);
    if (report.student.empty()) report.student = e.student;
    if (!variant.empty()) report.variant = variant;
    json j;
    j["score"] = report.score;
    j["max_score"] = report.max_score;
    json scores = json::array();
    for (const ProblemGrade& p : report.problems) scores.push_back(p.score);
    j["problem_scores"] = scores;
    j["message"] = !sub.errors.empty() ? sub.errors[0].format() : std::string();
    // No answers could be read at all: the row says so (the feedback still lists the problems).
    j["unreadable"] = !sub.answers.IsDefined() || !sub.answers.IsMap();
    try {
      const std::vector<std::string> parts = problem_feedback_markdown(report, options.lang);
      out.write("feedback/" + stems[i] + ".md",
                render_feedback_markdown(report, options.lang, parts));
      const Figures figures = student_figures(graded_set, report, options.lang);
      out.write("feedback/" + stems[i] + ".html",
                render_feedback_html(report, options.lang, math_head, &figures));
      out.write("gradescope/" + stems[i] + ".json",
                json_text(gradescope_results(report, parts)) + "\n");
    } catch (const std::exception& x) {
      j["write_error"] = x.what();
    }
    return json_text(j, -1);
  };
  double max_score = 0;
  for (const ProblemSpec& p : set.problems) max_score += p.max_score();
  // Rows in the class's order whatever order the children finish them in, written to the
  // gradebook as they come (the class's rows are not all held: BatchOptions::keep_rows).
  GradebookStream gradebook(set, out, "gradebook.csv", [&](BatchRow&& row) {
    if (options.on_row) options.on_row(row);
    if (options.keep_rows) result.rows.push_back(std::move(row));
  });
  const auto failed_row = [&](BatchRow& row, std::string status, const std::string& reason) {
    row.status = std::move(status);
    row.message = reason;
    row.score = 0;
    row.problem_scores.clear();
    out.remove("feedback/" + row.feedback_stem + ".html");  // a child stopped after writing it
    out.write("feedback/" + row.feedback_stem + ".md",
              fmt::format("# {}\n\nThis submission could not be graded: {}\n",
                          markdown_escape(row.student), markdown_escape(reason)));
    out.write("gradescope/" + row.feedback_stem + ".json",
              json_text(gradescope_failure(reason)) + "\n");
  };
  for (const auto& [relative, bytes] : katex)
    out.write(std::string(kKatexDir) + "/" + relative, bytes);
  std::size_t done = 0;
  const auto on_result = [&](std::size_t i, IsolatedResult& r) {
    const BatchEntry& e = entries[i];
    BatchRow row;
    row.student = e.student;
    row.source = e.source;
    row.feedback_stem = stems[i];
    row.max_score = max_score;
    if (r.status == IsolatedResult::Status::Ok) {
      // What the child sent is checked like any input: a malformed result is this row's error.
      try {
        const json j = json::parse(r.output);
        if (j.contains("write_error"))
          throw std::runtime_error(j["write_error"].get<std::string>());
        row.status = j.at("unreadable").get<bool>() ? "error" : "graded";
        row.score = j.at("score").get<double>();
        row.max_score = j.at("max_score").get<double>();
        for (const auto& s : j.at("problem_scores")) row.problem_scores.push_back(s.get<double>());
        row.message = j.at("message").get<std::string>();
      } catch (const nlohmann::json::exception& x) {
        failed_row(row, "error", std::string("the grader's result could not be read: ") + x.what());
      }
    } else {
      failed_row(row,
                 r.status == IsolatedResult::Status::Timeout   ? "timeout"
                 : r.status == IsolatedResult::Status::Crashed ? "crashed"
                                                               : "error",
                 r.error);
    }
    if (!e.note.empty()) row.message = e.note + (row.message.empty() ? "" : "; " + row.message);
    gradebook.add(i, std::move(row));
    ++done;
    // The disk writes the class's files while the children grade (write_back_due): the one
    // sync before publishing then has only the last few students' files left, not the whole
    // class with every core idle. This process only waits there; the children go on.
    if (write_back_due(done, entries.size())) out.write_back();
    if (options.on_progress) options.on_progress(done, entries.size(), e.student);
  };
  const std::size_t jobs =
      options.jobs ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  // Students are independent: each child takes the next student not yet taken, so the children
  // finish together on a loaded machine (rows and files are kept by student, not by arrival).
  run_isolated_each(entries.size(), work, options.timeout_seconds, on_result, 64u << 20, jobs, {},
                    Shares::Dynamic, &reaper);
  gradebook.finish();
  out.commit();
  result.set_aside = out.set_aside();
  return result;
}

}  // namespace frustum
