// Bounds on a command's total work, not only on each item: a frame's rasterization, the hidden
// lines of a picture, a CSV roster's rows, columns and fields, an answers file's values, and
// the numbers of the command line. Each test builds the input just past a bound and checks the
// error names it, and the input at the bound is accepted. No test is timed: a refused input is
// refused by its error, before (or within) the bound's work.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "app/number_options.hpp"
#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "grader/grade.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/raster/fill.hpp"
#include "solver/raster/frame_work.hpp"
#include "solver/raster/scanline.hpp"
#include "solver/visibility/edge_classes.hpp"
#include "solver/visibility/hidden_lines.hpp"
#include "solver/visibility/mesh.hpp"
#include "test_util.hpp"

extern char** environ;

namespace frustum {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int status = -1;
  std::string output;  // stdout and stderr
};

// `frustum ARGS...` run with an argument vector (no shell), its output captured.
CliRun frustum_cli(const std::vector<std::string>& args) {
  std::vector<std::string> argv_strings = {FRUSTUM_BINARY};
  argv_strings.insert(argv_strings.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_strings) argv.push_back(a.data());
  argv.push_back(nullptr);
  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return {};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 1);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[1], 2);
  posix_spawn_file_actions_addclose(&actions, pipe_fds[0]);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fds[1]);
  CliRun r;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_fds[0], buffer, sizeof buffer)) > 0;)
    r.output.append(buffer, static_cast<std::size_t>(n));
  ::close(pipe_fds[0]);
  if (spawned != 0) return r;
  int status = 0;
  waitpid(pid, &status, 0);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// ------------------------------------------------------------------ numbers of the command line

TEST(NumberOptions, WholeNumbersAreComparedWithTheirRangeBeforeConversion) {
  using app::parse_whole_number;
  EXPECT_EQ(std::get<std::uint64_t>(parse_whole_number("18446744073709551615", 0, UINT64_MAX)),
            UINT64_MAX);
  EXPECT_EQ(std::get<std::uint64_t>(parse_whole_number("7", 1, 10)), 7u);
  const auto over = parse_whole_number("18446744073709551616", 0, UINT64_MAX);
  ASSERT_TRUE(std::holds_alternative<std::string>(over));
  EXPECT_TRUE(has(std::get<std::string>(over), "out of range")) << std::get<std::string>(over);
  for (const char* bad : {"-1", "", " 1", "1e3", "0x10", "+1", "1 ", "١"})
    EXPECT_TRUE(std::holds_alternative<std::string>(parse_whole_number(bad, 0, UINT64_MAX))) << bad;
  EXPECT_TRUE(std::holds_alternative<std::string>(parse_whole_number("11", 1, 10)));
}

TEST(NumberOptions, ASizeThatOverflowsIsRefusedNotWrapped) {
  using app::parse_size;
  // 2³² + 1 was read by sscanf's %d as 1: a 1 × 1 render.
  for (const char* bad : {"4294967297x1", "1x4294967297", "18446744073709551617x2", "16385x1",
                          "0x5", "10x", "x10", "1x1x1", "-5x5", "5 x5", "5x5 "}) {
    const auto size = parse_size(bad);
    ASSERT_TRUE(std::holds_alternative<std::string>(size)) << bad;
    EXPECT_TRUE(has(std::get<std::string>(size), "1 ≤ W, H ≤ 16384")) << bad;
  }
  using Size = std::pair<int, int>;
  EXPECT_EQ(std::get<Size>(parse_size("16384x1")), Size(16384, 1));
  EXPECT_EQ(std::get<Size>(parse_size("640X480")), Size(640, 480));
}

TEST(NumberOptions, TheCommandLineRefusesOverflowingSizesAndSeeds) {
  const std::string paperplane = test::source_path("problems/seeds/paperplane.yaml");
  const std::string out = (fs::path(::testing::TempDir()) / "bounds.png").string();
  const CliRun size = frustum_cli({"render", paperplane, "-o", out, "--size", "4294967297x1"});
  EXPECT_EQ(size.status, 2) << size.output;
  EXPECT_TRUE(has(size.output, "--size: expected WxH with 1 ≤ W, H ≤ 16384")) << size.output;
  const std::string set = test::source_path("problems/seeds/001_zbuffer_plane_method.yaml");
  const fs::path dir = test::scratch_dir("bounds_seed");
  for (const char* seed : {"18446744073709551616", "-1", "99999999999999999999999"}) {
    const CliRun g = frustum_cli({"generate", set, "--seed", seed, "-o", dir.string()});
    EXPECT_NE(g.status, 0) << seed;
    EXPECT_TRUE(has(g.output, "from 0 to 18446744073709551615")) << g.output;
    const CliRun e =
        frustum_cli({"export", "moodle", set, "--seed", seed, "-o", (dir / "m.xml").string()});
    EXPECT_NE(e.status, 0) << seed;
    EXPECT_TRUE(has(e.output, "from 0 to 18446744073709551615")) << e.output;
  }
  // The other numbers are compared with their ranges as written, so 2³² + 1 is not 1.
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"generate", set, "--seed", "1", "--count", "4294967297", "-o", dir.string()},
           {"generate", set, "--seed", "1", "-j", "18446744073709551617", "-o", dir.string()},
           {"render", paperplane, "-o", out, "--threads", "4294967297"},
           {"export", "qti", set, "--count", "4294967297", "-o", dir.string()}}) {
    const CliRun r = frustum_cli(args);
    EXPECT_NE(r.status, 0) << args[args.size() - 3];
    EXPECT_TRUE(has(r.output, "not in range")) << r.output;
  }
  const CliRun largest =
      frustum_cli({"generate", set, "--seed", "18446744073709551615", "-o", (dir / "g").string()});
  EXPECT_EQ(largest.status, 0) << largest.output;
  fs::remove_all(dir);
}

// ------------------------------------------------------------------ CSV rosters

std::string repeated(const std::string& item, std::size_t n, const std::string& sep) {
  std::string s;
  s.reserve((item.size() + sep.size()) * n);
  for (std::size_t k = 0; k < n; ++k) s += (k ? sep : "") + item;
  return s;
}

TEST(CsvLimits, ColumnsRowsAndFieldBytesAreBoundedWhereTheyArePassed) {
  // At each limit: read.
  EXPECT_FALSE(parse_csv(repeated("a", kMaxCsvColumns, ",") + "\n").error);
  EXPECT_FALSE(parse_csv(std::string(kMaxCsvCellBytes, 'x') + "\n").error);
  const CsvTable rows = parse_csv(repeated("s", kMaxCsvRows, "\n"));
  EXPECT_FALSE(rows.error);
  EXPECT_EQ(rows.rows.size(), kMaxCsvRows);
  // One past: refused at the field or row that passes it, naming the limit; no row is kept.
  const CsvTable wide = parse_csv("ok\n" + repeated("ab", kMaxCsvColumns + 1, ","));
  ASSERT_TRUE(wide.error);
  EXPECT_TRUE(has(*wide.error, "(the limit is 10000 columns)")) << *wide.error;
  EXPECT_EQ(wide.error_line, 2);
  EXPECT_EQ(wide.error_column, static_cast<int>(3 * kMaxCsvColumns + 1));
  EXPECT_TRUE(wide.rows.empty());
  const CsvTable tall = parse_csv(repeated("s", kMaxCsvRows + 1, "\n"));
  ASSERT_TRUE(tall.error);
  EXPECT_TRUE(has(*tall.error, "(the limit is 100000 rows)")) << *tall.error;
  EXPECT_EQ(tall.error_line, static_cast<int>(kMaxCsvRows + 1));
  const CsvTable big = parse_csv("a,\"" + std::string(kMaxCsvCellBytes + 1, 'x') + "\"\n");
  ASSERT_TRUE(big.error);
  EXPECT_TRUE(has(*big.error, "(the limit is 65536 bytes a field)")) << *big.error;
  EXPECT_EQ(big.error_line, 1);
  EXPECT_EQ(big.error_column, 3);
  const CsvTable last = parse_csv("a," + std::string(kMaxCsvCellBytes + 1, 'x'));  // no newline
  ASSERT_TRUE(last.error);
  EXPECT_TRUE(has(*last.error, "bytes a field")) << *last.error;
}

TEST(CsvLimits, FieldsInAllAreBounded) {
  // 401 rows of 10 000 empty fields: 4 010 000 fields, each 32 bytes kept.
  const std::string row = repeated("", kMaxCsvColumns, ",") + "\n";
  std::string text;
  for (std::size_t r = 0; r * kMaxCsvColumns <= kMaxCsvCells; ++r) text += row;
  const CsvTable t = parse_csv(text);
  ASSERT_TRUE(t.error);
  EXPECT_TRUE(has(*t.error, "(the limit is 4000000 cells)")) << *t.error;
  EXPECT_EQ(t.error_line, static_cast<int>(kMaxCsvCells / kMaxCsvColumns + 1));
}

fs::path write_file(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

TEST(CsvLimits, AWideRosterIsReadInOnePassAndARepeatedColumnNamesTheFirst) {
  const fs::path dir = test::scratch_dir("bounds_roster");
  // 9 999 answer columns (checked for repeats by lookup: every pair would be quadratic).
  std::string header = "student", row = "s1";
  for (std::size_t i = 0; i + 1 < kMaxCsvColumns; ++i) {
    header += ",p" + std::to_string(i % 100) + ".a" + std::to_string(i);
    row += "," + std::to_string(i);
  }
  const std::vector<BatchEntry> entries =
      collect_submissions(write_file(dir, "wide.csv", header + "\n" + row + "\n").string());
  ASSERT_EQ(entries.size(), 1u);
  ASSERT_FALSE(entries[0].error) << *entries[0].error;
  const Submission s = load_submission_from_string(entries[0].yaml, "wide");
  ASSERT_TRUE(s.errors.empty()) << s.errors[0].format();
  EXPECT_EQ(s.answers["p7"]["a9907"].Scalar(), "9907");
  EXPECT_EQ(s.answers.size(), 100u);
  // The answers of a problem keep the header's order.
  EXPECT_EQ(s.answers["p0"].begin()->first.Scalar(), "a0");
  try {
    collect_submissions(
        write_file(dir, "twice.csv", "student,p.a,q.b,p.c,r.d,q.b\ns,1,2,3,4,5\n").string());
    ADD_FAILURE() << "a repeated column was read";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.diagnostic().format(), "twice.csv:1:6: header: column 6 repeats column 3"))
        << e.diagnostic().format();
  }
  fs::remove_all(dir);
}

TEST(CsvLimits, TheAnswersARosterBecomesAreBoundedBeforeAnyIsBuilt) {
  const fs::path dir = test::scratch_dir("bounds_roster_total");
  // 1 000 answer columns of 1 000-byte names: every row of "1"s is an answers file of about
  // 1 MB, within one submission's limit; 269 of them pass the roster's 256 MiB.
  std::string header = "student", cells;
  for (int i = 0; i < 1000; ++i) {
    header += ",p" + std::to_string(i) + "." + std::string(990, 'a');
    cells += ",1";
  }
  std::string text = header + "\n";
  // A row's answers file: each "1" under its problem's and its own name, and the student.
  std::size_t names = 0;
  for (int i = 0; i < 1000; ++i) names += 1 + ("p" + std::to_string(i)).size() + 990;
  std::size_t rows = 0;
  for (std::size_t all = 0; all <= kMaxRosterAnswerBytes; ++rows) {
    const std::string id = "s" + std::to_string(rows);
    all += names + id.size();
    text += id + cells + "\n";
  }
  try {
    collect_submissions(write_file(dir, "long.csv", text).string());
    ADD_FAILURE() << "the roster was read";
  } catch (const InputError& e) {
    EXPECT_TRUE(has(e.diagnostic().message, "(the limit is 268435456 bytes for a roster)"))
        << e.diagnostic().format();
    EXPECT_EQ(e.diagnostic().where.line, static_cast<int>(rows + 1));
  }
  // The first rows alone are within it, and each is its student's answers.
  std::string fewer = header + "\n";
  for (std::size_t r = 0; r < 3; ++r) fewer += "s" + std::to_string(r) + cells + "\n";
  const std::vector<BatchEntry> entries =
      collect_submissions(write_file(dir, "fewer.csv", fewer).string());
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_FALSE(entries[2].error);
  fs::remove_all(dir);
}

TEST(CsvLimits, ARosterOfStudentIdsIsBoundedAsAFileAndInRows) {
  const fs::path dir = test::scratch_dir("bounds_id_roster");
  std::string ids;
  for (std::size_t k = 0; k <= kMaxCsvRows; ++k) ids += "s" + std::to_string(k) + "\n";
  const std::string set = test::source_path("problems/seeds/001_zbuffer_plane_method.yaml");
  const CliRun r =
      frustum_cli({"generate", set, "--roster", write_file(dir, "ids.txt", ids).string(), "-o",
                   (dir / "out").string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output,
                  "ids.txt:100001:1: student: more than 100000 students (the limit is "
                  "100000 rows)"))
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "out" / "001_zbuffer_plane_method-s0.yaml"));
  fs::remove_all(dir);
}

// ------------------------------------------------------------------ answers files

std::string answers_of(std::size_t values) {
  return "student: s\nanswers:\n  seed001-pixel-z:\n    z: [" + repeated("1", values, ", ") + "]\n";
}

TEST(AnswerLimits, AnAnswersFileHoldsAtMostItsBoundOfValues) {
  // The document's own nodes: the root, student, answers and its mapping, the list: five.
  const Submission under = load_submission_from_string(answers_of(kMaxAnswerNodes - 10), "a");
  EXPECT_TRUE(under.errors.empty()) << under.errors[0].format();
  const Submission over = load_submission_from_string(answers_of(kMaxAnswerNodes), "a");
  ASSERT_FALSE(over.errors.empty());
  EXPECT_TRUE(has(over.errors[0].format(), "(the limit is 50000 values)"))
      << over.errors[0].format();
  EXPECT_EQ(over.errors[0].where.line, 4);
  // Aliases count as what they expand to.
  const Submission laughs = load_submission_from_string(
      "student: s\nanswers:\n  p:\n    a: &a [" + repeated("1", 1000, ", ") + "]\n    b: [" +
          repeated("*a", 60, ", ") + "]\n",
      "a");
  ASSERT_FALSE(laughs.errors.empty());
  EXPECT_TRUE(has(laughs.errors[0].format(), "(the limit is 50000 values)"))
      << laughs.errors[0].format();
  // A problem set keeps its own, larger bound.
  const YamlDocument set = parse_yaml(answers_of(kMaxAnswerNodes * 2), "set.yaml");
  EXPECT_FALSE(set.error);
}

// ------------------------------------------------------------------ problem sets

std::string vectors_set(std::size_t problems) {
  std::string s = "problems:\n";
  for (std::size_t k = 0; k < problems; ++k)
    s += "  - {id: p" + std::to_string(k) + ", kind: vectors, given: {a: [1, 2, " +
         std::to_string(k) + "], b: [0, 1, 1]}}\n";
  return s;
}

TEST(SetLimits, ASetHoldsAtMostItsBoundOfProblems) {
  const ProblemSet at = load_problem_set_from_string(vectors_set(kMaxSetProblems), "at.yaml");
  EXPECT_TRUE(at.errors.empty()) << at.errors[0].format();
  EXPECT_EQ(at.problems.size(), kMaxSetProblems);
  const ProblemSet over =
      load_problem_set_from_string(vectors_set(kMaxSetProblems + 1), "over.yaml");
  ASSERT_EQ(over.errors.size(), 1u);
  EXPECT_EQ(over.errors[0].format(),
            "over.yaml:2:3: problems: 1001 problems (the limit is 1000 problems a set): split the "
            "set");
  EXPECT_TRUE(over.problems.empty());
}

// ------------------------------------------------------------------ a frame's work

// Half of a side × side frame, corner to corner (what an ortho view of [−1, 1]² gives).
WindowTriangle half_frame(int side) {
  WindowTriangle t;
  t.v = {Vec3d(0, 0, 0.5), Vec3d(side, 0, 0.5), Vec3d(side, side, 0.5)};
  return t;
}

TEST(FrameWork, ATrianglesPriceIsItsRowsAndThePixelsItCanCover) {
  WindowTriangle t;
  t.v = {Vec3d(10.2, 20.7, 0), Vec3d(14.9, 20.1, 0), Vec3d(12, 25.5, 0)};
  // Rows 19 … 26 (a pixel of margin each way) and A + 1.02·(w + h) + 3 = 11.82 + 10.30 + 3.
  EXPECT_EQ(triangle_price(t, 100, 100), 8 + 25);
  // A thin triangle: its box (64²) is far more than it can cover (16 + 130.56 + 3).
  t.v = {Vec3d(0, 0, 0), Vec3d(64, 64, 0), Vec3d(64, 63.5, 0)};
  EXPECT_EQ(triangle_price(t, 64, 64), 64 + 149);
  // A large one: its box within the frame, clamped however far its corners are.
  t.v = {Vec3d(-1e300, -5, 0), Vec3d(1e300, 3, 0), Vec3d(0, 1e308, 0)};
  EXPECT_EQ(triangle_price(t, 30, 20), 20 + 30 * 20);
  t.v = {Vec3d(-50, -50, 0), Vec3d(-40, -50, 0), Vec3d(-45, -40, 0)};
  EXPECT_EQ(triangle_price(t, 30, 20), 0);
  t.v[0](0) = std::nan("");
  EXPECT_EQ(triangle_price(t, 30, 20), 0);
  // The pixels a fill covers are never more than the price.
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> u(-20, 84);
  for (int k = 0; k < 2000; ++k) {
    WindowTriangle r;
    const double size = k % 3 == 0 ? 60 : (k % 3 == 1 ? 4 : 0.7);
    const double cx = u(rng), cy = u(rng);
    for (Vec3d& v : r.v)
      v = Vec3d(std::round((cx + size * (u(rng) - 32) / 52) * 256) / 256,
                std::round((cy + size * (u(rng) - 32) / 52) * 256) / 256, 0.5);
    FillStats stats;
    render_zbuffer({r}, 64, 64, Rgb{}, &stats);
    ASSERT_LE(stats.fragments, triangle_price(r, 64, 64)) << k;
  }
}

TEST(FrameWork, AFrameIsDrawnUpToItsBoundAndRefusedPastItBeforeAnyPixel) {
  std::vector<WindowTriangle> tris(4, half_frame(256));
  std::int64_t price = 0;
  for (const WindowTriangle& t : tris) price += triangle_price(t, 256, 256);
  EXPECT_NO_THROW(render_zbuffer(tris, 256, 256, Rgb{}, nullptr, price));
  EXPECT_NO_THROW(render_scanline(tris, 256, 256, Rgb{}, nullptr, nullptr, price));
  const std::string bound = fmt::format("(the limit is {} pixel tests a frame)", price - 1);
  try {
    render_zbuffer(tris, 256, 256, Rgb{}, nullptr, price - 1);
    ADD_FAILURE() << "drawn";
  } catch (const DomainError& e) {
    EXPECT_EQ(e.field(), "scene.objects");
    EXPECT_TRUE(has(e.what(), bound)) << e.what();
  }
  try {
    render_scanline(tris, 256, 256, Rgb{}, nullptr, nullptr, price - 1);
    ADD_FAILURE() << "drawn";
  } catch (const DomainError& e) {
    EXPECT_TRUE(has(e.what(), bound)) << e.what();
  }
  // The bound itself: 128 halves of a 4096² frame pass 2³⁰, refused before a frame is made.
  const std::vector<WindowTriangle> poster(128, half_frame(4096));
  try {
    render_zbuffer(poster, 4096, 4096, Rgb{});
    ADD_FAILURE() << "drawn";
  } catch (const DomainError& e) {
    EXPECT_TRUE(has(e.what(),
                    "(the limit is 1073741824 pixel tests a frame: 64 layers of a "
                    "4096 × 4096 frame)"))
        << e.what();
  }
}

// A scene file of halves of a side × side viewport, one behind the other: `copies` of them, or
// [x, y, z] copies in a nested repeat (at most 100 001 a side).
std::string layers_scene(int side, long copies, const std::string& method = "zbuffer",
                         std::array<long, 3> to = {0, 0, -1}) {
  if (to[2] < 0) to[2] = copies - 1;
  return fmt::format(
      "scene:\n  viewport: {{width: {0}, height: {0}}}\n"
      "  camera: {{eye: [0, 0, 5], center: [0, 0, 0], up: [0, 1, 0]}}\n"
      "  ortho: {{left: -1, right: 1, bottom: -1, top: 1, near: 1, far: 10}}\n"
      "  method: {2}\n  objects:\n"
      "    - triangle: [[-1, -1, 0], [1, -1, 0], [1, 1, 0]]\n"
      "      repeat: {{from: [0, 0, 0], to: [{3}, {4}, {1}], step: [0, 0, -0.0001]}}\n",
      side, to[2], method, to[0], to[1]);
}

// How many halves of a side² frame kMaxFrameWork pays for.
long layers_at_the_bound(int side) {
  return static_cast<long>(kMaxFrameWork / triangle_price(half_frame(side), side, side));
}

TEST(FrameWork, RenderRefusesAFrameOverItsBoundOnEveryPathAndDrawsOneAtIt) {
  const fs::path dir = test::scratch_dir("bounds_render");
  const std::string png = (dir / "out.png").string();
  const long n = layers_at_the_bound(1024);
  ASSERT_GT(n, 1000);
  const std::string at = write_file(dir, "at.yaml", layers_scene(1024, n)).string();
  const std::string over = write_file(dir, "over.yaml", layers_scene(1024, n + 1)).string();
  const std::string scan =
      write_file(dir, "scan.yaml", layers_scene(1024, n + 1, "scanline")).string();
  for (const std::vector<std::string>& extra :
       std::vector<std::vector<std::string>>{{}, {"--threads", "2"}}) {
    std::vector<std::string> args = {"render", at, "-o", png};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun drawn = frustum_cli(args);
    EXPECT_EQ(drawn.status, 0) << drawn.output;
    args[1] = over;
    const CliRun refused = frustum_cli(args);
    EXPECT_EQ(refused.status, 1) << refused.output;
    EXPECT_TRUE(has(refused.output, over + ": scene: the frame's triangles need more than "
                                           "1073741824 pixel tests and row steps in all (the "
                                           "limit is 1073741824 pixel tests a frame"))
        << refused.output;
  }
  const CliRun scanline = frustum_cli({"render", scan, "-o", png});
  EXPECT_EQ(scanline.status, 1);
  EXPECT_TRUE(has(scanline.output, "(the limit is 1073741824 pixel tests a frame"))
      << scanline.output;
  // Ten million of them at 4096² (each triangle within its limits, about 44 hours of filling
  // without the bound) stop at the bound.
  const std::string huge =
      write_file(dir, "huge.yaml", layers_scene(4096, 0, "zbuffer", {99, 99, 999})).string();
  const CliRun h = frustum_cli({"render", huge, "-o", png});
  EXPECT_EQ(h.status, 1);
  EXPECT_TRUE(has(h.output, "(the limit is 1073741824 pixel tests a frame")) << h.output;
  fs::remove_all(dir);
}

std::string render_problem(int side, long copies) {
  std::string scene = layers_scene(side, copies);
  std::string indented;
  for (std::size_t at = 0, next; at < scene.size(); at = next + 1) {
    next = scene.find('\n', at);
    indented += "      " + scene.substr(at, next - at) + "\n";
  }
  return "problems:\n  - id: p\n    kind: render\n    given:\n" + indented +
         "      pixels: [[3, 4]]\n";
}

TEST(FrameWork, TheRenderKindRefusesWhatRenderWouldAndBoundsItsTriangles) {
  // Its own bound first: every triangle competes for every queried pixel.
  const ProblemSet many = load_problem_set_from_string(render_problem(64, 100'001), "many.yaml");
  ASSERT_EQ(many.problems.size(), 1u);
  ASSERT_TRUE(many.problems[0].error);
  EXPECT_TRUE(has(many.problems[0].error->format(), "scene.objects: 100001 triangles"))
      << many.problems[0].error->format();
  EXPECT_TRUE(has(many.problems[0].error->format(), "(the limit is 100000 triangles"));
  const ProblemSet fine = load_problem_set_from_string(render_problem(64, 100'000), "fine.yaml");
  EXPECT_FALSE(fine.problems.at(0).error) << fine.problems[0].error->format();
  // The frame's, as `frustum render` refuses it.
  const long n = layers_at_the_bound(1024);
  const ProblemSet frame = load_problem_set_from_string(render_problem(1024, n + 1), "frame.yaml");
  ASSERT_TRUE(frame.problems.at(0).error);
  EXPECT_TRUE(has(frame.problems[0].error->format(), "given.scene.objects: the frame's triangles"))
      << frame.problems[0].error->format();
  EXPECT_TRUE(has(frame.problems[0].error->format(), "(the limit is 1073741824 pixel tests"));
  const ProblemSet at = load_problem_set_from_string(render_problem(1024, n), "at.yaml");
  EXPECT_FALSE(at.problems.at(0).error) << at.problems[0].error->format();
}

// ------------------------------------------------------------------ hidden lines

// `n` unit cubes side by side along x: a closed mesh of 6n faces.
Mesh cubes(int n) {
  const Mesh cube = named_solid("cube");
  Mesh m;
  for (int k = 0; k < n; ++k) {
    const int base = static_cast<int>(m.vertices.size());
    for (const Vec3<Exact>& v : cube.vertices)
      m.vertices.push_back(Vec3<Exact>(v(0) + 3 * k, v(1), v(2)));
    for (std::vector<int> f : cube.faces) {
      for (int& i : f) i += base;
      m.faces.push_back(f);
    }
  }
  return m;
}

std::int64_t tested_pairs(const Mesh& m, const Vec3<Exact>& eye) {
  const std::vector<EdgeClass> classes =
      classify_edges(mesh_edges(m), face_tests(m, face_normals(m), eye));
  const auto edges = std::count_if(classes.begin(), classes.end(),
                                   [](EdgeClass c) { return c != EdgeClass::Hidden; });
  return static_cast<std::int64_t>(edges) * static_cast<std::int64_t>(face_triangles(m).size());
}

TEST(HiddenLineLimits, PairsAreCountedBeforeAnyIsTested) {
  const Vec3<Exact> eye(1, 7, 40);
  const Mesh small = cubes(4);
  const std::int64_t pairs = tested_pairs(small, eye);
  ASSERT_GT(pairs, 100);
  EXPECT_EQ(hidden_lines(small, eye, pairs).edges.size(), mesh_edges(small).size());
  try {
    hidden_lines(small, eye, pairs - 1);
    ADD_FAILURE() << "tested";
  } catch (const DomainError& e) {
    EXPECT_EQ(e.field(), "mesh.faces");
    EXPECT_TRUE(has(e.what(), fmt::format("are {} pairs to test (the limit is {} edge–face pairs "
                                          "a picture)",
                                          pairs, pairs - 1)))
        << e.what();
  }
  // 300 cubes: about 2 700 edges against 3 600 triangles, past the default bound.
  const Mesh large = cubes(300);
  EXPECT_GT(tested_pairs(large, eye), kMaxHiddenLinePairs);
  try {
    hidden_lines(large, eye);
    ADD_FAILURE() << "tested";
  } catch (const DomainError& e) {
    EXPECT_TRUE(has(e.what(), "(the limit is 2000000 edge–face pairs a picture)")) << e.what();
  }
}

TEST(HiddenLineLimits, DrawNamesTheBoundAtTheMesh) {
  const Mesh m = cubes(300);
  std::string vertices, faces;
  for (const Vec3<Exact>& v : m.vertices)
    vertices += fmt::format("{}[{}, {}, {}]", vertices.empty() ? "" : ", ", to_double(v(0)),
                            to_double(v(1)), to_double(v(2)));
  for (const std::vector<int>& f : m.faces)
    faces += fmt::format("{}[{}]", faces.empty() ? "" : ", ", fmt::join(f, ", "));
  const fs::path dir = test::scratch_dir("bounds_draw");
  const std::string set =
      write_file(dir, "mesh.yaml",
                 "problems:\n  - id: many\n    kind: edge_visibility\n"
                 "    given:\n      eye: [1, 7, 40]\n      mesh:\n"
                 "        vertices: [" +
                     vertices + "]\n        faces: [" + faces + "]\n    ask: [edges]\n")
          .string();
  const CliRun r = frustum_cli({"draw", set, "--id", "many", "-o", (dir / "m.svg").string()});
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_TRUE(has(r.output, "mesh.yaml:8:16: problems[0].given.mesh.faces: the hidden lines of"))
      << r.output;
  EXPECT_TRUE(has(r.output, "(the limit is 2000000 edge–face pairs a picture)")) << r.output;
  EXPECT_FALSE(fs::exists(dir / "m.svg"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
