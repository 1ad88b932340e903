#include "app/commands.hpp"

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <vector>

#include "grader/file_names.hpp"
#include "grader/report.hpp"
#include "solver/derivation/render.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_precision.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::app {

namespace {

// A problem-set path, or every *.yaml directly inside a directory (answer files live in
// subdirectories), in name order.
std::vector<std::string> set_files(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return {path};
  std::vector<std::string> files;
  std::error_code type_ec;  // a symlink loop is listed, and then reported as unreadable
  for (const auto& entry : fs::directory_iterator(path, ec))
    if (!entry.is_directory(type_ec) && entry.path().extension() == ".yaml")
      files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

bool failed(const SetResult& r) {
  return !r.errors.empty() ||
         std::any_of(r.problems.begin(), r.problems.end(),
                     [](const ProblemResult& p) { return p.error.has_value(); });
}

}  // namespace

int run_solve(const std::string& path, const std::optional<std::string>& id, Format format,
              const Output& o, std::optional<Precision> precision, Lang lang) {
  const std::vector<std::string> files = set_files(path);
  if (files.empty()) {
    o.err << path << ": no problem sets (*.yaml) here\n";
    return 1;
  }
  bool any_failed = false;
  nlohmann::ordered_json sets = nlohmann::ordered_json::array();
  for (const std::string& file : files) {
    const SetResult result = precision ? solve_set(load_problem_set(file), true, id, *precision)
                                       : solve_set(load_problem_set(file), true, id);
    any_failed = any_failed || failed(result);
    switch (format) {
      case Format::Json:
        sets.push_back(render_json(result, lang));
        break;
      case Format::Markdown:
        o.out << render_markdown(result, lang);
        break;
      case Format::Html:
        o.out << render_html(result, lang);
        break;
      case Format::Latex:
        o.out << render_latex(result, lang);
        break;
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

int run_check(const std::string& path, const Output& o) {
  int errors = 0;
  for (const std::string& file : set_files(path)) {
    const ProblemSet set = load_problem_set(file);
    // `solve` can also fail on well-formed input (collinear points): check solves too.
    const SetResult result = solve_set(set, false);
    int here = 0;
    for (const Diagnostic& d : result.errors) {
      o.out << d.format() << "\n";
      ++here;
    }
    for (const ProblemResult& p : result.problems)
      if (p.error) {
        o.out << p.error->format() << "\n";
        ++here;
      }
    // A varied problem whose text states a given value that its variants cannot restate: an
    // error, as `generate` and per-student grading refuse it.
    for (const Diagnostic& d : stale_text_errors(set, false)) {
      o.out << d.format() << "\n";
      ++here;
    }
    // Ids a student may take for each other (not errors: every export keeps both).
    for (const Diagnostic& d : look_alike_problem_ids(set)) o.out << d.format() << "\n";
    if (here == 0)
      o.out << file << ": " << set.problems.size() << " problem"
            << (set.problems.size() == 1 ? "" : "s") << ", no errors\n";
    errors += here;
  }
  if (errors) o.out << errors << " error" << (errors == 1 ? "" : "s") << "\n";
  return errors == 0 ? 0 : 1;
}

int run_kinds(const Output& o, bool markdown) {
  if (markdown) {
    o.out << kinds_table_markdown(builtin_kinds());
    return 0;
  }
  for (const KindInfo& k : builtin_kinds().all()) {
    o.out << k.name << " — " << k.summary << "\n    given:";
    for (const std::string& f : k.given_fields) o.out << " " << f;
    o.out << "\n    answers:";
    for (const AnswerSpec& a : k.answers) o.out << " " << a.name;
    o.out << "\n";
  }
  return 0;
}

}  // namespace frustum::app
