#include "grader/batch.hpp"

#include "grader/atomic_file.hpp"
#include "grader/csv.hpp"
#include "grader/feedback.hpp"
#include "grader/gradescope.hpp"
#include "grader/isolate.hpp"
#include "grader/report.hpp"
#include "solver/util/diagnostic.hpp"
#include "solver/util/exact_format.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace frustum {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// The student id written in an answers file, without grading it.
std::string student_in(const std::string& yaml) {
  try {
    const YAML::Node root = YAML::Load(yaml);
    if (root.IsMap() && root["student"].IsDefined() && root["student"].IsScalar()) return root["student"].Scalar();
  } catch (const std::exception&) {
  }
  return {};
}

std::vector<BatchEntry> from_directory(const fs::path& dir, std::size_t max_bytes) {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(dir)) {
    const std::string ext = lower(e.path().extension().string());
    if ((ext == ".yaml" || ext == ".yml") && !e.is_directory()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<BatchEntry> out;
  for (const fs::path& f : files) {
    BatchEntry b;
    b.source = f.string();
    std::error_code ec;
    const auto size = fs::file_size(f, ec);
    if (ec) {
      b.error = "cannot read: " + ec.message();
    } else if (size > max_bytes) {
      b.error = fmt::format("{} bytes: larger than the limit of {} bytes for one submission", size, max_bytes);
    } else {
      std::ifstream in(f, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      b.yaml = text.str();
      if (!in && !in.eof()) b.error = "cannot read the file";
    }
    b.student = b.error ? std::string() : student_in(b.yaml);
    if (b.student.empty()) b.student = f.stem().string();
    out.push_back(std::move(b));
  }
  return out;
}

// A CSV cell as a YAML value: lists ([1, 2, 3]) are read as YAML, everything else is a string,
// so that "x + y - z = -6" and "1/sqrt(3)" reach the answer parser as written.
YAML::Node cell_value(const std::string& cell) {
  const std::size_t start = cell.find_first_not_of(" \t");
  if (start != std::string::npos && cell[start] == '[') {
    try {
      const YAML::Node n = YAML::Load(cell);
      if (n.IsSequence()) return n;
    } catch (const std::exception&) {
    }
  }
  return YAML::Node(cell);
}

std::vector<BatchEntry> from_csv(const std::string& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const CsvTable table = parse_csv(text.str());
  if (table.error) throw InputError(Diagnostic{SourceLocation{path, 0, 0}, "", *table.error});
  if (table.rows.empty()) throw InputError(Diagnostic{SourceLocation{path, 1, 1}, "", "empty CSV: expected a header row"});
  const std::vector<std::string>& header = table.rows[0].fields;
  int student_col = -1;
  std::vector<std::pair<std::string, std::string>> columns(header.size());  // problem id, answer
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string h = header[i];
    if (lower(h) == "student") {
      student_col = static_cast<int>(i);
      continue;
    }
    const std::size_t dot = h.rfind('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == h.size())
      throw InputError(Diagnostic{SourceLocation{path, 1, 1}, "header",
                                  fmt::format("column {} is '{}': name answer columns problem-id.answer", i + 1, h)});
    columns[i] = {h.substr(0, dot), h.substr(dot + 1)};
  }
  if (student_col < 0) throw InputError(Diagnostic{SourceLocation{path, 1, 1}, "header", "no 'student' column"});
  std::vector<BatchEntry> out;
  for (std::size_t r = 1; r < table.rows.size(); ++r) {
    const CsvRow& row = table.rows[r];
    BatchEntry b;
    b.source = fmt::format("{} row {}", path, row.line);
    b.student = student_col < static_cast<int>(row.fields.size()) ? row.fields[static_cast<std::size_t>(student_col)] : "";
    if (b.student.empty()) b.student = fmt::format("row-{}", row.line);
    std::size_t bytes = 0;
    for (const std::string& f : row.fields) bytes += f.size();
    if (row.fields.size() > header.size()) {
      b.error = fmt::format("{} fields, but the header has {}", row.fields.size(), header.size());
    } else if (bytes > max_bytes) {
      b.error = fmt::format("{} bytes: larger than the limit of {} bytes for one submission", bytes, max_bytes);
    } else {
      YAML::Node answers(YAML::NodeType::Map);
      for (std::size_t i = 0; i < row.fields.size(); ++i) {
        if (static_cast<int>(i) == student_col || row.fields[i].empty()) continue;
        answers[columns[i].first][columns[i].second] = cell_value(row.fields[i]);
      }
      YAML::Node root(YAML::NodeType::Map);
      root["student"] = b.student;
      root["answers"] = answers;
      YAML::Emitter e;
      e << root;
      b.yaml = std::string(e.c_str()) + "\n";
    }
    out.push_back(std::move(b));
  }
  return out;
}

// A file name for a student id: letters, digits, '.', '-', '_' kept; anything else '_'.
std::string file_stem(const std::string& student) {
  std::string s;
  for (const char c : student) {
    const bool ok = std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.';
    s += ok ? c : '_';
  }
  if (s.empty() || s[0] == '.') s = "_" + s;
  return s.substr(0, 100);
}

std::string number_text(double v) { return format_approx(v, 6); }

}  // namespace

std::vector<BatchEntry> collect_submissions(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) return from_directory(path, max_bytes);
  if (fs::is_regular_file(path, ec) && lower(fs::path(path).extension().string()) == ".csv")
    return from_csv(path, max_bytes);
  throw InputError(Diagnostic{SourceLocation{path, 0, 0}, "",
                              "expected an answers file (.yaml), a directory of them, or a CSV roster"});
}

std::string gradebook_csv(const ProblemSet& set, const std::vector<BatchRow>& rows) {
  std::vector<std::string> header = {"student", "score", "max_score", "percent", "status"};
  for (const ProblemSpec& p : set.problems) header.push_back(p.id);
  header.insert(header.end(), {"source", "message"});
  std::string out = csv_row(header);
  for (const BatchRow& r : rows) {
    std::vector<std::string> f = {r.student, number_text(r.score), number_text(r.max_score),
                                  r.max_score > 0 ? fmt::format("{:.1f}", 100.0 * r.score / r.max_score) : "",
                                  r.status};
    for (std::size_t i = 0; i < set.problems.size(); ++i)
      f.push_back(i < r.problem_scores.size() ? number_text(r.problem_scores[i]) : "");
    f.push_back(r.source);
    f.push_back(r.message);
    out += csv_row(f);
  }
  return out;
}

BatchResult grade_batch(const ProblemSet& set, const std::vector<BatchEntry>& entries, const BatchOptions& options) {
  BatchResult result;
  // File stems, unique within the batch (two files claiming one id both get feedback).
  std::vector<std::string> stems;
  std::map<std::string, int> seen;
  for (const BatchEntry& e : entries) {
    std::string stem = file_stem(e.student);
    const int n = ++seen[stem];
    if (n > 1) stem += fmt::format("-{}", n);
    stems.push_back(stem);
  }
  // A set that does not vary per student is solved once, here: every child inherits it.
  std::optional<SolvedSet> solved;
  if (!options.set_for) solved = solve_for_grading(set);
  // The child grades and renders; the parent only writes what comes back.
  const auto work = [&](std::size_t i) -> std::string {
    const BatchEntry& e = entries[i];
    if (e.error) throw std::runtime_error(*e.error);
    const Submission sub = load_submission_from_string(e.yaml, e.source);
    std::string variant;
    const ProblemSet graded_set = options.set_for ? options.set_for(set, sub.student, variant) : set;
    // The student's own set could not be made (no `student:`, no generated file): an error row
    // that says why, not a score of 0.
    if (graded_set.errors.size() > set.errors.size()) throw std::runtime_error(graded_set.errors.back().format());
    GradeReport report = grade(graded_set, sub, solved ? &*solved : nullptr);
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
    j["markdown"] = render_feedback_markdown(report, options.lang);
    j["html"] = render_feedback_html(report, options.lang);
    j["gradescope"] = json_text(gradescope_results(report, options.lang)) + "\n";
    return json_text(j, -1);
  };
  const fs::path out(options.out_dir);
  const auto write = [&](const fs::path& p, const std::string& text) {
    write_file_atomically(p.string(), text);
    result.files_written.push_back(p.string());
  };
  const auto on_result = [&](std::size_t i, const IsolatedResult& r) {
    const BatchEntry& e = entries[i];
    BatchRow row;
    row.student = e.student;
    row.source = e.source;
    row.feedback_stem = stems[i];
    row.max_score = 0;
    for (const ProblemSpec& p : set.problems) row.max_score += p.max_score();
    std::string gradescope;
    if (r.status == IsolatedResult::Status::Ok) {
      const json j = json::parse(r.output);
      row.status = j["unreadable"].get<bool>() ? "error" : "graded";
      row.score = j["score"].get<double>();
      row.max_score = j["max_score"].get<double>();
      for (const auto& s : j["problem_scores"]) row.problem_scores.push_back(s.get<double>());
      row.message = j["message"].get<std::string>();
      write(out / "feedback" / (stems[i] + ".md"), j["markdown"].get<std::string>());
      write(out / "feedback" / (stems[i] + ".html"), j["html"].get<std::string>());
      gradescope = j["gradescope"].get<std::string>();
    } else {
      row.status = r.status == IsolatedResult::Status::Timeout   ? "timeout"
                   : r.status == IsolatedResult::Status::Crashed ? "crashed"
                                                                 : "error";
      row.message = r.error;
      const std::string md = fmt::format("# {}\n\nThis submission could not be graded: {}\n", e.student, r.error);
      write(out / "feedback" / (stems[i] + ".md"), md);
      gradescope = json_text(gradescope_failure(r.error)) + "\n";
    }
    write(out / "gradescope" / (stems[i] + ".json"), gradescope);
    result.rows.push_back(std::move(row));
    if (options.on_progress) options.on_progress(i + 1, entries.size(), e.student);
  };
  run_isolated_each(entries.size(), work, options.timeout_seconds, on_result);
  write(out / "gradebook.csv", gradebook_csv(set, result.rows));
  return result;
}

}  // namespace frustum
