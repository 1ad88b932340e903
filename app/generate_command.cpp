// `frustum generate SET.yaml --student ID... | --seed N --count K [-o DIR] [-j N]`: per-student or
// seeded variants of a problem set, each written as a complete problem set with its answer key
// (DIR/STEM-NAME.yaml and DIR/answers/STEM-NAME.yaml).
#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <thread>
#include <unordered_map>

#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "batch/atomic_file.hpp"
#include "batch/isolate.hpp"
#include "batch/run_program.hpp"
#include "batch/variant_files.hpp"
#include "export/paper.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_set.hpp"
#include "solver/problem/variants.hpp"

namespace frustum::app {

namespace {

// Variant files made durable per sync (two files per variant).
constexpr std::size_t kFilesPerSync = 8192;
// With fewer variants than this, -j does not pay for its processes: they are drawn here.
constexpr std::size_t kMinParallelVariants = 64;
// A worker's time for one variant (one that finds no acceptable draw takes the longest).
constexpr double kVariantSeconds = 600;
// A LaTeX compiler's time for one document of exam sheets or keys.
constexpr double kLatexSeconds = 300;

struct Named {
  std::string name;     // file name part
  std::string student;  // the answer key's student:
  ProblemSet variant;
};

// A LaTeX document compiled to `pdf`, the compiler's output in `log`; "" when it worked, else
// why not. The compiler runs from an argument vector in a private directory beside the PDF on a
// fixed file name, so neither a shell nor TeX ever reads the set's or the directory's name (a set
// saved as `w';touch x;'.yaml` or `O'Brien.yaml` is only a name), and with \write18 off.
std::string compile_latex(const std::string& engine, const std::string& text,
                          const std::filesystem::path& pdf, const std::string& log) {
  namespace fs = std::filesystem;
  std::string work = (pdf.parent_path().empty() ? fs::path(".") : pdf.parent_path()).string() +
                     "/.frustum-latex-XXXXXX";
  if (!::mkdtemp(work.data()))
    return std::string("cannot make a directory: ") + std::strerror(errno);
  struct Cleanup {
    std::string dir;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(dir, ec);
    }
  } cleanup{work};
  try {
    write_file_atomically(work + "/sheet.tex", text);
  } catch (const std::exception& e) {
    return e.what();
  }
  RunOptions options;
  options.cwd = work;
  options.out = OutputTo::File;
  options.err = OutputTo::File;
  options.log_file = fs::absolute(log).string();
  options.seconds = kLatexSeconds;
  std::error_code ec;
  const ProgramRun run = run_program(
      {engine, "-no-shell-escape", "-interaction=nonstopmode", "-halt-on-error", "sheet.tex"},
      options);
  fs::rename(fs::path(work) / "sheet.log", fs::path(pdf).replace_extension(".log"), ec);
  if (!run.started) return run.start_error;
  if (run.timed_out) return fmt::format("stopped after {:g} s", kLatexSeconds);
  if (run.status != 0) return fmt::format("exit status {}", run.status);
  fs::rename(fs::path(work) / "sheet.pdf", pdf, ec);
  return ec ? pdf.string() + ": " + ec.message() : "";
}

// The paper route: DIR/STEM-exams.tex and DIR/STEM-key.tex, compiled to PDF with --format pdf.
int write_paper(const GenerateCommandOptions& g, const ProblemSet& set,
                const std::vector<Named>& variants, const Output& o) {
  namespace fs = std::filesystem;
  std::vector<PaperSheet> sheets;
  for (const Named& v : variants)
    if (v.variant.all_errors().empty()) sheets.push_back({v.student, v.variant});
  const std::string stem = fs::path(g.set).stem().string();
  const Lang lang = g.lang.value_or(set.lang);  // without --lang: the set's own
  const std::string title = set.title.empty() ? stem : set.title.in(lang);
  int status = 0;
  for (const auto& [name, text] :
       {std::pair{stem + "-exams", exam_sheets_latex(sheets, title, lang)},
        std::pair{stem + "-key", answer_key_latex(sheets, title, lang)}}) {
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
    // Japanese and Russian text need LuaLaTeX (latex_preamble says so in the first line).
    const std::string engine = text.rfind("% LuaLaTeX", 0) == 0 ? "lualatex" : "pdflatex";
    const std::string log = (fs::path(g.out_dir) / (name + ".build.log")).string();
    const std::string why = compile_latex(engine, text, fs::path(g.out_dir) / (name + ".pdf"), log);
    if (!why.empty()) {
      o.err << "error: " << engine << " could not compile " << tex << ": " << why << " (see "
            << name << ".build.log in " << g.out_dir
            << "; Debian: apt-get install texlive-latex-recommended texlive-pictures)\n";
      status = 1;
      continue;
    }
    o.out << (fs::path(g.out_dir) / (name + ".pdf")).string() << "\n";
  }
  return status;
}

// One variant's files as text, or why it has none: what a worker process hands back, less
// the texts themselves (it writes them to temporary files beside their targets).
struct Rendered {
  std::string variant_errors;  // stderr lines: the variant has a problem that was not drawn
  std::string unsolved;        // stderr lines: a problem of the key could not be solved
  std::uint64_t body_hash = 0;
  int draw = 1;
  std::string set_text, key_text;
};

Rendered render(const GenerateCommandOptions& g, const YamlDocument& doc,
                const std::string& fingerprint, const Named& v) {
  namespace fs = std::filesystem;
  Rendered out;
  if (!v.variant.all_errors().empty()) {
    for (const Diagnostic& d : v.variant.all_errors())
      out.variant_errors += v.name + ": " + d.format() + "\n";
    return out;
  }
  const std::string stem = fs::path(g.set).stem().string();
  const std::string source = fs::path(g.set).filename().string();
  const std::string who =
      g.seed ? fmt::format("variant {} of seed {}", v.name, *g.seed) : "student " + v.student;
  const std::string set_file = stem + "-" + v.name + ".yaml";
  out.draw = v.variant.variant ? v.variant.variant->draw : 1;
  const std::string redraw_note =
      out.draw > 1 ? fmt::format(
                         "\nDraw {}: the earlier draws repeated another student's problem. Grade "
                         "this student "
                         "against this file: frustum grade {} ANSWERS --variants {}",
                         out.draw, source, g.out_dir)
                   : "";
  const std::string body = emit_variant_set(doc.root, v.variant, "");
  out.body_hash = fnv1a64(body);
  const std::string seed = fmt::format("{:016x}", v.variant.variant ? v.variant.variant->seed : 0);
  out.set_text =
      comment_lines(fmt::format("Variant of {} for {} (seed {}), drawn by `frustum "
                                "generate`.\nAnswer key: answers/{}{}",
                                source, who, seed, set_file, redraw_note)) +
      drawn_from_line(DrawnFrom{source, fingerprint, g.seed ? "" : v.student, out.draw}) + body;
  std::vector<Diagnostic> unsolved;
  out.key_text = emit_answer_key(
      v.variant, v.student, fmt::format("Answer key of {} ({}, seed {}).", set_file, who, seed),
      &unsolved);
  // A key without the problem would be a lost result: nothing is written.
  for (const Diagnostic& d : unsolved) out.unsolved += v.name + ": " + d.format() + "\n";
  return out;
}

// ---- a worker's record of one variant, sent through the pipe ----

void put(std::string& out, const std::string& text) {
  const std::uint64_t size = text.size();
  out.append(reinterpret_cast<const char*>(&size), sizeof size);
  out += text;
}

std::string get(const std::string& in, std::size_t& at) {
  std::uint64_t size = 0;
  if (in.size() - at < sizeof size) throw std::runtime_error("truncated worker record");
  std::memcpy(&size, in.data() + at, sizeof size);
  at += sizeof size;
  if (in.size() - at < size) throw std::runtime_error("truncated worker record");
  std::string text = in.substr(at, size);
  at += size;
  return text;
}

// What the parent needs of a variant a worker drew: its givens (to check it against every
// earlier variant), its messages, and the temporary files holding its texts.
struct Record {
  VariantGivens givens;
  Rendered rendered;                         // without its texts
  std::string set_temporary, key_temporary;  // empty: not written
  std::string write_error;                   // the worker could not write its files
};

std::string encode(const Record& r) {
  std::string out;
  put(out, std::to_string(r.givens.given.size()));
  put(out, r.givens.complete ? "1" : "0");
  for (std::size_t p = 0; p < r.givens.given.size(); ++p) {
    put(out, r.givens.given[p] ? "1" + *r.givens.given[p] : "0");
    put(out, std::to_string(r.givens.repeated[p].size()));
    for (const std::string& text : r.givens.repeated[p]) put(out, text);
  }
  put(out, r.rendered.variant_errors);
  put(out, r.rendered.unsolved);
  put(out, std::to_string(r.rendered.body_hash));
  put(out, std::to_string(r.rendered.draw));
  put(out, r.set_temporary);
  put(out, r.key_temporary);
  put(out, r.write_error);
  return out;
}

Record decode(const std::string& in) {
  Record r;
  std::size_t at = 0;
  const std::size_t problems = std::stoul(get(in, at));
  r.givens.complete = get(in, at) == "1";
  r.givens.given.resize(problems);
  r.givens.repeated.resize(problems);
  for (std::size_t p = 0; p < problems; ++p) {
    const std::string given = get(in, at);
    if (!given.empty() && given[0] == '1') r.givens.given[p] = given.substr(1);
    const std::size_t repeated = std::stoul(get(in, at));
    for (std::size_t k = 0; k < repeated; ++k) r.givens.repeated[p].push_back(get(in, at));
  }
  r.rendered.variant_errors = get(in, at);
  r.rendered.unsolved = get(in, at);
  r.rendered.body_hash = std::stoull(get(in, at));
  r.rendered.draw = std::stoi(get(in, at));
  r.set_temporary = get(in, at);
  r.key_temporary = get(in, at);
  r.write_error = get(in, at);
  return r;
}

void discard(const Record& r) {
  if (!r.set_temporary.empty()) FileBatch::discard(r.set_temporary);
  if (!r.key_temporary.empty()) FileBatch::discard(r.key_temporary);
}

// What `check` refuses is refused here too, before any file is written: errors of the set, a
// problem that cannot be solved (a placeholder that names no value, answers beyond a double's
// range), a text stating a given value that no field explains (stale in every variant). Each
// is printed; false when the set is refused.
bool set_can_vary(const ProblemSet& set, bool vary_all, const Output& o) {
  if (!set.all_errors().empty()) {
    for (const Diagnostic& d : set.all_errors()) o.err << d.format() << "\n";
    return false;
  }
  bool unsolvable = false;
  for (const ProblemSpec& p : set.problems)
    if (const ProblemResult r = solve_problem(p, set.file, false); r.error) {
      o.err << r.error->format() << "\n";
      unsolvable = true;
    }
  if (unsolvable) return false;
  if (const std::vector<Diagnostic> stale = stale_text_errors(set, vary_all); !stale.empty()) {
    for (const Diagnostic& d : stale) o.err << d.format() << "\n";
    return false;
  }
  return true;
}

// The students named with --student and in --roster; nothing (after printing why) when the
// roster cannot be read.
std::optional<std::vector<std::string>> students_of(const GenerateCommandOptions& g,
                                                    const Output& o) {
  std::vector<std::string> students = g.students;
  if (g.roster) {
    try {
      const std::vector<std::string> listed = read_roster(*g.roster);
      students.insert(students.end(), listed.begin(), listed.end());
    } catch (const InputError& e) {
      o.err << "error: " << e.diagnostic().format() << "\n";
      return std::nullopt;
    }
  }
  return students;
}

// One run's variants on their way to disk, in variant order: their messages, and their files
// written in groups, each made durable by one sync (FileBatch); paths are printed once their
// group is in place. A group is synced and renamed by a child process while this one goes on
// taking variants (the workers' results would otherwise wait in their pipes).
class VariantWriter {
 public:
  using Stage = std::function<void(const std::string& set_path, const std::string& key_path)>;

  VariantWriter(const GenerateCommandOptions& g, const YamlDocument& doc, std::string fingerprint,
                const Output& o, bool paper)
      : g_(g), doc_(doc), fingerprint_(std::move(fingerprint)), o_(o), paper_(paper) {}

  // More than one group: the process that commits them is made now, while this one is small.
  void expect(std::size_t items) {
    if (!paper_ && 2 * items > kFilesPerSync) files_.start_committer();
  }

  // A variant's messages and files; `stage` puts its two files in the batch (writing them, or
  // adopting what a worker wrote). False when it has none.
  bool take(const std::string& name, const Rendered& r, const Stage& stage) {
    if (failed) return false;
    if (!r.variant_errors.empty()) {
      o_.err << r.variant_errors;
      status = 1;
      return false;
    }
    redrawn = redrawn || r.draw > 1;
    if (const auto [it, fresh] = seen_.emplace(r.body_hash, name); !fresh)
      o_.err << "warning: " << name << " has the same variant as " << it->second
             << " (the ranges leave few choices)\n";
    if (!r.unsolved.empty()) {
      o_.err << r.unsolved;
      status = 1;
      return false;
    }
    try {
      const std::string set_path = variant_file(g_.out_dir, g_.set, name);
      const std::string key_path = variant_key_file(g_.out_dir, g_.set, name);
      stage(set_path, key_path);
      written_.push_back(set_path + "  " + key_path);
      if (files_.staged() >= kFilesPerSync) flush();
    } catch (const std::exception& e) {
      o_.err << "error: " << e.what() << "\n";
      failed = true;
      return false;
    }
    return true;
  }

  // A variant drawn in this process, rendered and taken; `reuse` (when given) holds a worker's
  // temporary files for it, written again here (removing and creating files costs more than
  // rewriting them).
  void take_here(Named&& v, Record* reuse = nullptr) {
    if (failed) return;
    const Rendered r = render(g_, doc_, fingerprint_, v);
    const auto stage_one = [&](std::string* temporary, const std::string& path,
                               const std::string& text) {
      if (!temporary || temporary->empty()) return files_.stage(path, text);
      FileBatch::rewrite_staged(*temporary, path, text);
      files_.adopt(*temporary, path);
      temporary->clear();
    };
    const bool staged =
        take(v.name, r, [&](const std::string& set_path, const std::string& key_path) {
          stage_one(reuse ? &reuse->set_temporary : nullptr, set_path, r.set_text);
          stage_one(reuse ? &reuse->key_temporary : nullptr, key_path, r.key_text);
        });
    if (staged && paper_) variants.push_back(std::move(v));
  }

  // A worker's files for a variant, put in the batch under their names.
  void adopt(const std::string& temporary, const std::string& path) {
    files_.adopt(temporary, path);
  }

  // The last group put in place; false when an output could not be written.
  bool finish() {
    try {
      if (!failed) {
        flush();
        group_done();
      }
    } catch (const std::exception& e) {
      o_.err << "error: " << e.what() << "\n";
      failed = true;
    }
    return !failed;
  }

  int status = 0;
  bool failed = false;          // an output could not be written
  bool redrawn = false;         // some variant was drawn again to stay distinct
  std::vector<Named> variants;  // kept only for the paper route

 private:
  void group_done() {
    files_.wait_commit();
    for (const std::string& line : committing_) o_.out << line << "\n";
    committing_.clear();
  }
  void flush() {
    group_done();
    files_.commit_in_background();
    committing_ = std::move(written_);
    written_.clear();
  }

  const GenerateCommandOptions& g_;
  const YamlDocument& doc_;
  const std::string fingerprint_;
  const Output& o_;
  const bool paper_;
  // A variant's text (its FNV-1a hash: bodies are not kept) → the first variant that has it.
  std::unordered_map<std::uint64_t, std::string> seen_;
  FileBatch files_;
  std::vector<std::string> written_;     // staged since the last group
  std::vector<std::string> committing_;  // the group being put in place
};

// The variants drawn, solved and written by worker processes (GiNaC is not thread-safe), each
// taking the next that nobody has taken (so that they finish together, and the variants arrive
// nearly in order: their groups are synced and renamed while the workers go on). A worker knows
// only the givens of the variants it drew itself, all earlier than the one it draws, so this
// process takes their variants in order and draws again, itself, any that repeats a given it
// did not know (SeedVariants::take): the files are those of one process whatever -j is.
// Returns the problems that ran out of variants (--allow-repeats).
std::vector<std::string> draw_in_workers(VariantWriter& w, const GenerateCommandOptions& g,
                                         const YamlDocument& doc, const std::string& fingerprint,
                                         const ProblemSet& set,
                                         const std::vector<std::string>& students, bool vary_all,
                                         std::size_t items, std::size_t jobs, const Output& o) {
  namespace fs = std::filesystem;
  std::optional<SeedVariants> seeds, seeds_apart;
  std::optional<ClassVariants> classes, classes_apart;
  if (g.seed) {
    seeds.emplace(set, *g.seed, g.count, vary_all);
    seeds_apart.emplace(set, *g.seed, g.count, vary_all);
  } else {
    classes.emplace(set, vary_all, g.allow_repeats);
    classes_apart.emplace(set, vary_all, g.allow_repeats);
  }
  const auto name_of = [&](std::size_t i) {
    return g.seed ? fmt::format("seed{}-{}", *g.seed, i) : variant_name(students[i]);
  };
  const auto work = [&](std::size_t i) {
    Record r;
    if (g.seed && seeds_apart->exhausted()) {
      // This worker found the ranges used up: the rest is left to this process's own draws,
      // which stop where the ranges are used up.
      r.givens.complete = false;
      return encode(r);
    }
    const Named v{name_of(i), g.seed ? name_of(i) : students[i],
                  g.seed ? seeds_apart->draw(static_cast<int>(i), &r.givens)
                         : classes_apart->first_draw(students[i], &r.givens)};
    Rendered rendered = render(g, doc, fingerprint, v);
    try {
      if (rendered.variant_errors.empty() && rendered.unsolved.empty()) {
        r.set_temporary =
            FileBatch::write_staged(variant_file(g.out_dir, g.set, v.name), rendered.set_text);
        r.key_temporary =
            FileBatch::write_staged(variant_key_file(g.out_dir, g.set, v.name), rendered.key_text);
      }
    } catch (const std::exception& e) {
      discard(r);
      r.set_temporary.clear();
      r.key_temporary.clear();
      r.write_error = e.what();
    }
    r.rendered = std::move(rendered);
    r.rendered.set_text.clear();
    r.rendered.key_text.clear();
    return encode(r);
  };
  std::vector<std::optional<IsolatedResult>> arrived(items);
  std::size_t next = 0;
  bool stopped = false;  // a seed's ranges are used up: no variant after it
  const auto settle = [&](std::size_t i, IsolatedResult& result) {
    if (result.status != IsolatedResult::Status::Ok) {
      o.err << "error: " << name_of(i) << ": " << result.error << "\n";
      w.status = 1;
      return;
    }
    Record r;
    try {
      r = decode(result.output);
    } catch (const std::exception& e) {
      o.err << "error: " << name_of(i) << ": " << e.what() << "\n";
      w.status = 1;
      return;
    }
    if (stopped || w.failed) {
      discard(r);
      return;
    }
    if (!r.write_error.empty()) {
      o.err << "error: " << r.write_error << "\n";
      w.failed = true;
      return;
    }
    if (g.seed ? seeds->take(r.givens) : classes->take(r.givens)) {
      if (!w.take(name_of(i), r.rendered,
                  [&](const std::string& set_path, const std::string& key_path) {
                    w.adopt(r.set_temporary, set_path);
                    r.set_temporary.clear();
                    w.adopt(r.key_temporary, key_path);
                    r.key_temporary.clear();
                  }))
        discard(r);
      return;
    }
    if (g.seed) {
      w.take_here({name_of(i), name_of(i), seeds->draw(static_cast<int>(i))}, &r);
      stopped = seeds->exhausted();
    } else {
      w.take_here({name_of(i), students[i], classes->draw(students[i])}, &r);
    }
    discard(r);  // what was not written again
  };
  std::error_code ec;
  fs::create_directories(fs::path(variant_key_file(g.out_dir, g.set, "x")).parent_path(), ec);
  run_isolated_each(
      items, work, kVariantSeconds,
      [&](std::size_t i, IsolatedResult& result) {
        arrived[i] = std::move(result);
        for (; next < items && arrived[next]; ++next) {
          settle(next, *arrived[next]);
          arrived[next].reset();
        }
      },
      64u << 20, jobs, [&] { return stopped || w.failed; }, Shares::Dynamic);
  // Once stopped, what arrived beyond a share that was not run is never taken: its files go.
  for (std::optional<IsolatedResult>& result : arrived)
    if (result && result->status == IsolatedResult::Status::Ok) try {
        discard(decode(result->output));
      } catch (const std::exception&) {
      }
  return classes ? classes->exhausted() : std::vector<std::string>{};
}

// The variants drawn in this process, in order; the class together, pairwise distinct,
// redrawing a student whose variant repeats another's. Returns the problems that ran out of
// variants (--allow-repeats).
std::vector<std::string> draw_here(VariantWriter& w, const GenerateCommandOptions& g,
                                   const ProblemSet& set, const std::vector<std::string>& students,
                                   bool vary_all) {
  if (g.seed) {
    for_each_variant_from_seed(set, *g.seed, g.count, vary_all, [&](int i, ProblemSet&& drawn) {
      const std::string name = fmt::format("seed{}-{}", *g.seed, i);
      w.take_here({name, name, std::move(drawn)});
    });
    return {};
  }
  ClassVariants drawn(set, vary_all, g.allow_repeats);
  for (const std::string& student : students)
    w.take_here({variant_name(student), student, drawn.draw(student)});
  return drawn.exhausted();
}

}  // namespace

int run_generate(const GenerateCommandOptions& g, const Output& o) {
  const YamlDocument doc = load_yaml_file(g.set);
  const ProblemSet set = load_problem_set(doc, g.set);
  const bool vary_all = !set_varies(set);
  if (!set_can_vary(set, vary_all, o)) return 1;
  if (vary_all)
    o.err << g.set
          << ": no problem has `vary` and the set does not say `variants: per_student`, so every "
          << "problem is drawn by its kind's default generator; grade against the generated files "
             "(or add "
          << "`variants: per_student` to grade against " << g.set << " itself)\n";
  const std::optional<std::vector<std::string>> students = students_of(g, o);
  if (!students) return 1;
  const bool paper = g.format != "yaml";
  // What every variant file records as drawn from (grade --variants checks it).
  const std::string fingerprint = set_fingerprint(doc.root);
  VariantWriter w(g, doc, fingerprint, o, paper);
  const std::size_t items = g.seed ? static_cast<std::size_t>(g.count) : students->size();
  const std::size_t jobs = std::min<std::size_t>(
      g.jobs ? g.jobs : std::max(1u, std::thread::hardware_concurrency()), items);
  w.expect(items);
  const std::vector<std::string> repeating =
      jobs > 1 && !paper && items >= kMinParallelVariants
          ? draw_in_workers(w, g, doc, fingerprint, set, *students, vary_all, items, jobs, o)
          : draw_here(w, g, set, *students, vary_all);
  if (!w.finish()) return 1;
  int status = w.status;
  if (paper) status = std::max(status, write_paper(g, set, w.variants, o));
  if (g.allow_repeats)
    for (const std::string& id : repeating)
      o.err << "note: problem '" << id
            << "' has fewer variants than the class: it repeats among students (--allow-repeats)\n";
  if (w.redrawn)
    o.err << "note: some students were drawn again so that no two share a problem"
          << (g.allow_repeats && !repeating.empty() ? " (but those named above)" : "")
          << "; grade the class against these files: frustum grade " << g.set
          << " ANSWERS --variants " << g.out_dir << "\n";
  return status;
}

Command add_generate_command(CLI::App& cli) {
  auto opt = std::make_shared<GenerateCommandOptions>();
  auto lang = std::make_shared<std::string>();  // empty: the set's own
  auto* generate =
      cli.add_subcommand("generate", "Per-student or seeded variants of a set, with answer keys");
  generate->add_option("set", opt->set, "Problem set (YAML)")->required()->check(CLI::ExistingFile);
  auto* gen_student =
      generate->add_option("--student", opt->students, "Student id(s): one variant each");
  auto* gen_seed =
      generate->add_option("--seed", opt->seed, "Seed of --count variants (pairwise distinct)")
          ->check(whole_number(0, UINT64_MAX));
  generate->add_option("--count", opt->count, "How many variants from --seed (default 1)")
      ->check(CLI::Range(1, 100000))
      ->needs(gen_seed);
  auto* gen_roster =
      generate
          ->add_option("--roster", opt->roster,
                       "Class roster: a CSV with a student column, or one id per line")
          ->check(CLI::ExistingFile);
  gen_seed->excludes(gen_student);
  gen_seed->excludes(gen_roster);
  generate
      ->add_option("-j,--jobs", opt->jobs,
                   "--count, --roster: variants drawn at once (default: one per core)")
      ->check(CLI::Range(1, 1024));
  generate->add_flag("--allow-repeats", opt->allow_repeats,
                     "--roster, --student: a problem with fewer variants than the class repeats "
                     "among students instead of leaving the rest without a variant");
  generate->add_option("-o,--out", opt->out_dir,
                       "Directory for the sets; keys go in its answers/ (default .)");
  generate
      ->add_option(
          "--format", opt->format,
          "yaml (default: sets and keys), latex or pdf (also exam sheets and the answer key)")
      ->check(CLI::IsMember({"yaml", "latex", "pdf"}));
  generate
      ->add_option(
          "--lang", *lang,
          "latex, pdf: language of the exam sheets' texts: en, ja or ru (default: the set's own)")
      ->check(language_check());
  generate->footer(examples(
      {"frustum generate SET.yaml --roster roster.csv -o variants/",
       "frustum generate SET.yaml --seed 7 --count 30 -o drill/",
       "frustum generate SET.yaml --roster roster.csv -o exam/ --format pdf   (exams + key)"}));

  return {generate, [opt, lang](const Output& o) {
            if (opt->students.empty() && !opt->roster && !opt->seed) {
              o.err << "generate: give --student ID, --roster FILE or --seed N [--count K]\n";
              return 2;
            }
            opt->lang = parse_lang(*lang);
            return run_generate(*opt, o);
          }};
}

}  // namespace frustum::app
