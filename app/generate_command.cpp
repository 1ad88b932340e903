// `frustum generate SET.yaml --student ID... | --seed N --count K [-o DIR]`: per-student or
// seeded variants of a problem set, each written as a complete problem set with its answer key
// (DIR/STEM-NAME.yaml and DIR/answers/STEM-NAME.yaml).
#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <unordered_map>

#include "app/commands.hpp"
#include "app/variant_files.hpp"
#include "grader/atomic_file.hpp"
#include "grader/paper.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::app {

namespace {

// Variant files made durable per sync (two files per variant).
constexpr std::size_t kFilesPerSync = 8192;

struct Named {
  std::string name;     // file name part
  std::string student;  // the answer key's student:
  ProblemSet variant;
};

// The paper route: DIR/STEM-exams.tex and DIR/STEM-key.tex, compiled to PDF with --format pdf.
int write_paper(const GenerateCommand& g, const ProblemSet& set, const std::vector<Named>& variants,
                const Output& o) {
  namespace fs = std::filesystem;
  std::vector<PaperSheet> sheets;
  for (const Named& v : variants)
    if (v.variant.all_errors().empty()) sheets.push_back({v.student, v.variant});
  const std::string stem = fs::path(g.set).stem().string();
  const std::string title = set.title.empty() ? stem : set.title.in(g.lang);
  int status = 0;
  for (const auto& [name, text] :
       {std::pair{stem + "-exams", exam_sheets_latex(sheets, title, g.lang)},
        std::pair{stem + "-key", answer_key_latex(sheets, title, g.lang)}}) {
    const std::string tex = (fs::path(g.out_dir) / (name + ".tex")).string();
    try {
      write_file_atomically(tex, text);
    } catch (const std::exception& e) {
      o.err << "error: " << e.what() << "\n";
      return 1;
    }
    if (g.format != "pdf") {
      o.out << tex << "\n";
      continue;
    }
    // Japanese text needs LuaLaTeX (latex_preamble says so in the first line).
    const std::string engine = text.rfind("% Japanese", 0) == 0 ? "lualatex" : "pdflatex";
    const std::string command = fmt::format(
        "{} -interaction=nonstopmode -halt-on-error -output-directory '{}' '{}' > '{}' 2>&1",
        engine, g.out_dir, tex, (fs::path(g.out_dir) / (name + ".build.log")).string());
    if (std::system(command.c_str()) != 0) {
      o.err << "error: " << engine << " could not compile " << tex << " (see " << name
            << ".build.log in " << g.out_dir
            << "; Debian: apt-get install texlive-latex-recommended texlive-pictures)\n";
      status = 1;
      continue;
    }
    o.out << (fs::path(g.out_dir) / (name + ".pdf")).string() << "\n";
  }
  return status;
}

}  // namespace

int run_generate(const GenerateCommand& g, const Output& o) {
  namespace fs = std::filesystem;
  const YamlDocument doc = load_yaml_file(g.set);
  const ProblemSet set = load_problem_set(g.set);
  if (!set.all_errors().empty()) {
    for (const Diagnostic& d : set.all_errors()) o.err << d.format() << "\n";
    return 1;
  }
  // What `check` refuses is refused here too, before any file is written: a problem that
  // cannot be solved (a placeholder that names no value, answers beyond a double's range).
  {
    bool unsolvable = false;
    for (const ProblemSpec& p : set.problems)
      if (const ProblemResult r = solve_problem(p, set.file, false); r.error) {
        o.err << r.error->format() << "\n";
        unsolvable = true;
      }
    if (unsolvable) return 1;
  }
  const bool vary_all = !set_varies(set);
  // A text stating a given value that no field explains would be stale in every variant.
  if (const std::vector<Diagnostic> stale = stale_text_errors(set, vary_all); !stale.empty()) {
    for (const Diagnostic& d : stale) o.err << d.format() << "\n";
    return 1;
  }
  if (vary_all)
    o.err << g.set
          << ": no problem has `vary` and the set does not say `variants: per_student`, so every "
          << "problem is drawn by its kind's default generator; grade against the generated files "
             "(or add "
          << "`variants: per_student` to grade against " << g.set << " itself)\n";
  const std::string stem = fs::path(g.set).stem().string();
  const std::string source = fs::path(g.set).filename().string();
  std::vector<std::string> students = g.students;
  if (g.roster) {
    try {
      const std::vector<std::string> listed = read_roster(*g.roster);
      students.insert(students.end(), listed.begin(), listed.end());
    } catch (const InputError& e) {
      o.err << "error: " << e.diagnostic().format() << "\n";
      return 1;
    }
  }
  const bool paper = g.format != "yaml";
  std::vector<Named> variants;  // kept only for the paper route
  bool redrawn = false;
  int status = 0;
  bool failed = false;  // an output could not be written
  // A variant's text (its FNV-1a hash: bodies are not kept) → the first variant that has it.
  std::unordered_map<std::uint64_t, std::string> seen;
  // Written in groups, each made durable by one sync (FileBatch); paths are printed once their
  // group is in place.
  FileBatch files;
  std::vector<std::string> written;
  const auto flush = [&] {
    files.commit();
    for (const std::string& line : written) o.out << line << "\n";
    written.clear();
  };
  const auto take = [&](Named&& v) {
    if (failed) return;
    if (!v.variant.all_errors().empty()) {
      for (const Diagnostic& d : v.variant.all_errors())
        o.err << v.name << ": " << d.format() << "\n";
      status = 1;
      return;
    }
    const std::string who =
        g.seed ? fmt::format("variant {} of seed {}", v.name, *g.seed) : "student " + v.student;
    const std::string set_file = stem + "-" + v.name + ".yaml";
    const int draw = v.variant.variant ? v.variant.variant->draw : 1;
    const std::string redraw_note =
        draw > 1 ? fmt::format(
                       "\nDraw {}: the earlier draws repeated another student's problem. Grade "
                       "this student "
                       "against this file: frustum grade {} ANSWERS --variants {}",
                       draw, source, g.out_dir)
                 : "";
    redrawn = redrawn || draw > 1;
    const std::string body = emit_variant_set(doc.root, v.variant, "");
    if (const auto [it, fresh] = seen.emplace(fnv1a64(body), v.name); !fresh)
      o.err << "warning: " << v.name << " has the same variant as " << it->second
            << " (the ranges leave few choices)\n";
    const std::string seed =
        fmt::format("{:016x}", v.variant.variant ? v.variant.variant->seed : 0);
    const std::string set_text =
        comment_lines(fmt::format("Variant of {} for {} (seed {}), drawn by `frustum "
                                  "generate`.\nAnswer key: answers/{}{}",
                                  source, who, seed, set_file, redraw_note)) +
        body;
    std::vector<Diagnostic> unsolved;
    const std::string key_text = emit_answer_key(
        v.variant, v.student, fmt::format("Answer key of {} ({}, seed {}).", set_file, who, seed),
        &unsolved);
    if (!unsolved
             .empty()) {  // a key without the problem would be a lost result: nothing is written
      for (const Diagnostic& d : unsolved) o.err << v.name << ": " << d.format() << "\n";
      status = 1;
      return;
    }
    try {
      const std::string set_path = variant_file(g.out_dir, g.set, v.name);
      const std::string key_path = variant_key_file(g.out_dir, g.set, v.name);
      files.stage(set_path, set_text);
      files.stage(key_path, key_text);
      written.push_back(set_path + "  " + key_path);
      if (files.staged() >= kFilesPerSync) flush();
    } catch (const std::exception& e) {
      o.err << "error: " << e.what() << "\n";
      failed = true;
      return;
    }
    if (paper) variants.push_back(std::move(v));
  };
  if (g.seed)
    for_each_variant_from_seed(set, *g.seed, g.count, vary_all, [&](int i, ProblemSet&& drawn) {
      const std::string name = fmt::format("seed{}-{}", *g.seed, i);
      take({name, name, std::move(drawn)});
    });
  // The class together: pairwise distinct, redrawing a student whose variant repeats another's.
  std::vector<ProblemSet> class_variants = variants_for_class(set, students, vary_all);
  for (std::size_t i = 0; i < students.size(); ++i)
    take({variant_name(students[i]), students[i], std::move(class_variants[i])});
  try {
    if (!failed) flush();
  } catch (const std::exception& e) {
    o.err << "error: " << e.what() << "\n";
    failed = true;
  }
  if (failed) return 1;
  if (g.format != "yaml") status = std::max(status, write_paper(g, set, variants, o));
  if (redrawn)
    o.err << "note: some students were drawn again so that no two share a problem; grade the class "
             "against these "
             "files: frustum grade "
          << g.set << " ANSWERS --variants " << g.out_dir << "\n";
  return status;
}

}  // namespace frustum::app
