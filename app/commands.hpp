// The subcommands of `frustum`: each maps its options to library calls and prints.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "solver/derivation/i18n.hpp"
#include "solver/numeric/precision.hpp"
#include "solver/raster/scene.hpp"
#include "solver/raster/zbuffer.hpp"
#include "solver/shared/scene_reader.hpp"
#include "solver/util/thread_team.hpp"

namespace frustum {
struct Frame;
}

namespace frustum::app {

enum class Format { Text, Markdown, Json, Html, Latex };

struct Output {
  std::ostream& out;
  std::ostream& err;
  bool color;             // stdout is a terminal
  bool progress = false;  // stderr is a terminal: progress bars
};

// Exit status: 0 all good, 1 some problem or answer had an error (the rest is still printed).
int run_solve(const std::string& set, const std::optional<std::string>& id, Format format,
              const Output& o, std::optional<Precision> precision = std::nullopt,
              std::optional<Lang> lang = std::nullopt);
int run_check(const std::string& set, const Output& o);
// frustum grade (app/grade_command.cpp): `answers` is one answers file, a directory of them, or
// a CSV roster (a batch, written under out_dir).
struct GradeOptions {
  std::string set;
  std::string answers;
  Format format = Format::Text;
  std::optional<Lang> lang;               // --lang; none: the set's own (`lang:`), set by run_grade
  std::optional<std::string> out_dir;     // batch outputs (default "grades")
  double timeout = 10;                    // seconds per submission in a batch
  std::size_t jobs = 0;                   // batch: child processes at once (0: one per core)
  std::optional<std::string> gradescope;  // single: results.json
  std::optional<std::string> prairielearn;  // single: PrairieLearn's external-grader results.json
  std::optional<std::string> html;          // single: feedback page
  std::optional<std::string> markdown;      // single: feedback Markdown
  std::optional<std::string> variants;      // --variants DIR: the sets `frustum generate` wrote
  std::optional<std::string>
      roster;  // --roster FILE: whose each file is; the class `generate --roster` drew
};
int run_grade(const GradeOptions& options, const Output& o);
int run_kinds(const Output& o, bool markdown = false);
// frustum generate (app/generate_command.cpp): variants for `students`, or `count` variants
// from `seed`, written with their answer keys under out_dir.
struct GenerateCommandOptions {
  std::string set;
  std::vector<std::string> students;
  std::optional<std::string> roster;  // --roster: a CSV with a student column, or one id per line
  std::optional<std::uint64_t> seed;
  int count = 1;
  std::size_t jobs = 0;  // worker processes drawing --count or --roster variants (0: one per core)
  std::string out_dir = ".";
  std::string format = "yaml";  // also latex (exam sheets + answer key) or pdf (compiled)
  std::optional<Lang> lang;     // the exam sheets' texts (none: the set's own `lang:`)
  bool allow_repeats = false;   // a problem whose ranges run out may repeat among the class
};
int run_generate(const GenerateCommandOptions& options, const Output& o);

// frustum export (app/export_command.cpp): a set as PrairieLearn questions, a Canvas QTI
// package or Moodle XML (format prairielearn | qti | moodle, `input` a set), or a gradebook.csv
// for Canvas's or Moodle's gradebook import (canvas-grades | moodle-grades, `input` the CSV).
struct ExportOptions {
  std::string format;
  std::string input;
  std::string out;  // a directory (prairielearn, qti) or a file
  int count = 1;    // variants drawn
  std::uint64_t seed = 1;
  std::string assignment = "Frustum";  // the gradebook column
  bool sis_login = false;              // canvas-grades: ids are SIS Login IDs
  std::string image;                   // prairielearn: required (ACCOUNT/NAME:TAG)
  std::optional<Lang> lang;            // the questions' texts (none: the set's own `lang:`)
};
int run_export(const ExportOptions& options, const Output& o);

// frustum render (app/render_command.cpp).
struct RenderOptions {
  std::string file;                         // scene file or problem set
  std::string output;                       // PNG
  std::optional<std::string> depth;         // depth PNG
  std::optional<std::pair<int, int>> size;  // --size WxH
  std::optional<std::string> id;            // the render problem of a set
  std::optional<std::string> method;        // zbuffer | scanline
  // ≥ 2: threaded_zbuffer.hpp's render_zbuffer (and the PNG's colour scan) share the work.
  int threads = 1;
};
// The threads a render with --threads N shares between its steps and its PNG writer, started
// now (so that they start while the scene is read): none for one thread, at most 64 (--threads
// allows 1024; a 1920 × 1080 frame has 34 bands to fill and 17 pieces to compress).
std::optional<ThreadTeam> render_team(int threads);
// target: a frame the caller keeps from one render to the next, reused when the size is the
// same (bench/render_race.cpp, as llvmpipe's context keeps its framebuffer); none: a new one.
int run_render(const RenderOptions& options, const Output& o, Frame* target = nullptr);
// The scene `frustum render` draws (--size and --method applied), or the exit status after
// printing why not; its PNG writer is solver/raster_fast/png_writer.hpp. bench/render_race.cpp
// races the same steps through llvmpipe.
std::variant<Scene, int> load_render_scene(const RenderOptions& options, const Output& o);
// The same with its exact inputs and the exact projection · camera (--size applied): what
// `frustum render` certifies its frame against (certified_frame.hpp).
struct RenderScene {
  SceneSpec spec;
  Mat4<Exact> clip_from_world;
};
std::variant<RenderScene, int> load_render_spec(const RenderOptions& options, const Output& o);
// `frustum bench accuracy`: speed against error of every numeric path and backend, on generated
// and hard cases (every *.yaml in hard_dir); writes accuracy_results.md and the plots into out_dir
// (bench_command.cpp).
int run_bench_accuracy(const std::string& out_dir, const std::string& hard_dir, int cases,
                       const Output& o);
// `frustum draw`: an SVG picture of one problem (hidden lines, painter vs z-buffer); written
// to `output`, or to o.out when it is empty or "-". `raster` is the painter/z-buffer size;
// `lang` the language of the picture's captions and of the summary printed (none: the set's
// own, its `lang:`).
int run_draw(const std::string& set, const std::string& id, const std::string& output, int raster,
             const Output& o, std::optional<Lang> lang = std::nullopt);

}  // namespace frustum::app
