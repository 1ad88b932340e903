// `frustum export FORMAT INPUT -o OUT`: a problem set as PrairieLearn questions, a Canvas QTI
// package or Moodle XML questions (with --count variants drawn from --seed), or a class's
// gradebook.csv as Canvas's or Moodle's gradebook import CSV.
#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "batch/atomic_file.hpp"
#include "batch/file_names.hpp"
#include "export/export_gradebook.hpp"
#include "export/export_moodle.hpp"
#include "export/export_prairielearn.hpp"
#include "export/export_qti.hpp"
#include "export/quiz_items.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/diagnostic.hpp"

namespace frustum::app {

namespace {

namespace fs = std::filesystem;

// The set itself when nothing varies and one is asked for, else `count` pairwise-distinct
// variants drawn from `seed` (named seedS-I, as `frustum generate --seed` names them).
std::vector<ProblemSet> drawn(const ProblemSet& set, const ExportOptions& e,
                              std::vector<std::string>& names) {
  if (e.count == 1 && !set_varies(set)) {
    names = {""};
    return {set};
  }
  std::vector<ProblemSet> out = variants_from_seed(set, e.seed, e.count, !set_varies(set));
  for (std::size_t i = 0; i < out.size(); ++i) names.push_back(fmt::format("seed{}-{}", e.seed, i));
  return out;
}

// The package's identifier: Canvas files a quiz under it, so two sets must never share one
// ("a b.yaml" and "a_b.yaml"): the batch's injective encoding of names.
std::string ident_of(const std::string& stem) { return "frustum_" + file_name_for(stem); }

int export_set(const ExportOptions& e, const Output& o) {
  const YamlDocument doc = load_yaml_file(e.input);
  const ProblemSet set = load_problem_set(doc, e.input);
  const Lang lang = e.lang.value_or(set.lang);  // without --lang: the set's own
  if (!set.all_errors().empty()) {
    for (const Diagnostic& d : set.all_errors()) o.err << d.format() << "\n";
    return 1;
  }
  std::vector<std::string> names;
  const std::vector<ProblemSet> variants = drawn(set, e, names);
  for (const ProblemSet& v : variants)
    if (!v.all_errors().empty()) {
      for (const Diagnostic& d : v.all_errors()) o.err << d.format() << "\n";
      return 1;
    }
  // A problem that cannot be solved has no key, and every export would leave its question out
  // (a set with a degenerate triangle once exported its other questions, exit status 0).
  int unsolved = 0;
  for (const ProblemSet& v : variants)
    for (const ProblemResult& p : solve_set(v, false).problems)
      if (p.error) {
        o.err << p.error->format() << "\n";
        ++unsolved;
      }
  if (unsolved) {
    o.err << "error: nothing was exported: every question needs its answer key\n";
    return 1;
  }
  const std::string stem = fs::path(e.input).stem().string();
  const std::string title = set.title.empty() ? stem : set.title.in(lang);
  std::map<std::string, std::string> files;  // path under e.out → contents
  if (e.format == "prairielearn") {
    PrairieLearnOptions options;
    options.image = e.image;
    options.lang = lang;
    for (const auto& [dir, content] : export_prairielearn(doc.root, set, variants, stem, options))
      for (const auto& [name, text] : content) files[dir + "/" + name] = text;
  } else {
    std::vector<QuizVariant> quiz;
    for (std::size_t i = 0; i < variants.size(); ++i)
      quiz.push_back({names[i], quiz_questions(variants[i], lang)});
    for (const QuizQuestion& q : quiz.front().questions)
      for (const std::string& l : q.left_out)
        o.err << "note: " << q.id << "." << l << " (left to frustum grade)\n";
    if (e.format == "qti")
      files = export_qti(quiz, title, ident_of(stem), lang);
    else
      files[""] = export_moodle(quiz, title, lang);
    // What the platforms cannot do as Frustum does, for the instructor.
    o.err << "note: " << (e.format == "qti" ? "Canvas" : "Moodle")
          << " credits each number of a vector or matrix on its own, where frustum grade gives "
             "an answer's points only when all its numbers are right\n";
  }
  try {
    for (const auto& [name, text] : files) {
      const fs::path path = name.empty() ? fs::path(e.out) : fs::path(e.out) / name;
      if (path.has_parent_path()) fs::create_directories(path.parent_path());
      write_file_atomically(path.string(), text);
      o.out << path.string() << "\n";
    }
  } catch (const std::exception& ex) {
    o.err << "error: " << ex.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int run_export(const ExportOptions& e, const Output& o) {
  if (e.format == "canvas-grades" || e.format == "moodle-grades") {
    try {
      std::ifstream in(e.input, std::ios::binary);
      std::stringstream text;
      text << in.rdbuf();
      std::vector<std::string> left_out;
      const std::string csv = export_gradebook(
          text.str(), e.input,
          e.format == "canvas-grades" ? GradebookFormat::Canvas : GradebookFormat::Moodle,
          e.assignment, e.sis_login ? StudentKey::SisLoginId : StudentKey::SisUserId, &left_out);
      for (const std::string& l : left_out) o.err << "note: " << l << "\n";
      if (e.out.empty() || e.out == "-")
        o.out << csv;
      else
        write_file_atomically(e.out, csv);
      return 0;
    } catch (const InputError& ex) {
      o.err << "error: " << ex.diagnostic().format() << "\n";
      return 1;
    } catch (const std::exception& ex) {
      o.err << "error: " << ex.what() << "\n";
      return 1;
    }
  }
  return export_set(e, o);
}

Command add_export_command(CLI::App& cli) {
  auto opt = std::make_shared<ExportOptions>();
  auto lang = std::make_shared<std::string>();  // empty: the set's own
  auto* exp = cli.add_subcommand("export",
                                 "A set as PrairieLearn questions, Canvas QTI or Moodle XML; a "
                                 "gradebook for Canvas or Moodle");
  exp->add_option("format", opt->format, "What to write")
      ->required()
      ->check(CLI::IsMember({"prairielearn", "qti", "moodle", "canvas-grades", "moodle-grades"}));
  exp->add_option("input", opt->input,
                  "Problem set (YAML); for *-grades, the gradebook.csv of `frustum grade`")
      ->required()
      ->check(CLI::ExistingFile);
  exp->add_option("-o,--out", opt->out,
                  "Directory (prairielearn, qti), .xml file (moodle) or .csv file (*-grades; "
                  "default: standard output)");
  exp->add_option("--count", opt->count,
                  "Variants to draw (default 1: the set itself when nothing varies)")
      ->check(CLI::Range(1, 1000));
  exp->add_option("--seed", opt->seed, "Seed of the variants (default 1)")
      ->check(whole_number(0, UINT64_MAX));
  exp->add_option("--assignment", opt->assignment,
                  "*-grades: the assignment's column name (default Frustum)");
  exp->add_flag("--sis-login", opt->sis_login,
                "canvas-grades: the student ids are SIS Login IDs (default SIS User IDs)");
  exp->add_option("--image", opt->image,
                  "prairielearn (required): the grader image as PrairieLearn pulls it, "
                  "ACCOUNT/NAME:TAG (docs/platforms.md: building and publishing it)");
  exp->add_option(
         "--lang", *lang,
         "Language of the questions' texts: en, ja or ru (default: the set's own, its lang:)")
      ->check(language_check());
  exp->footer(examples(
      {"frustum export prairielearn SET.yaml --count 20 --image ACCOUNT/frustum-grader:0.1.0 -o "
       "course/questions/",
       "frustum export qti SET.yaml --count 3 -o quiz/ && (cd quiz && zip -r ../quiz.zip .)",
       "frustum export moodle SET.yaml --count 20 -o questions.xml",
       "frustum export canvas-grades grades/gradebook.csv --assignment \"Homework 3\" -o "
       "canvas.csv"}));

  return {exp, [opt, lang](const Output& o) {
            if (opt->out.empty() && opt->format.find("grades") == std::string::npos) {
              o.err << "export " << opt->format << ": give -o OUT\n";
              return 2;
            }
            if (opt->format == "prairielearn" && opt->image.find('/') == std::string::npos) {
              o.err << "export prairielearn: give --image ACCOUNT/NAME:TAG, the grader image as "
                       "PrairieLearn pulls it from Docker Hub (build and push "
                       "tools/prairielearn/Dockerfile: docs/platforms.md)\n";
              return 2;
            }
            opt->lang = parse_lang(*lang);
            return run_export(*opt, o);
          }};
}

}  // namespace frustum::app
