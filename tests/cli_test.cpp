// The `frustum` command line, run as a user would.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "test_util.hpp"

namespace frustum {
namespace {

struct CliRun {
  int status;
  std::string out;
};

// Standard output and, unless `with_stderr` is false, standard error (-1: no normal exit).
CliRun run(const std::string& args, bool with_stderr = true) {
  const ProgramRun r = test::frustum_run(args, with_stderr);
  return {r.status, r.output};
}

CliRun stdout_of(const std::string& args) { return run(args, false); }

std::string seed(const std::string& name) { return test::source_path("problems/seeds/" + name); }

TEST(Cli, SolveJsonGivesTheSeedAnswersExactly) {
  const CliRun r =
      run("solve " + seed("001_zbuffer_plane_method.yaml") + " --id seed001-pixel-z --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["problems"].size(), 1u);
  const auto& a = j["problems"][0]["answers"];
  EXPECT_EQ(a["z"]["value"], 8);
  EXPECT_EQ(a["z"]["exact"], "8");
  EXPECT_EQ(a["unit_normal"]["exact"], nlohmann::json({"sqrt(3)/3", "sqrt(3)/3", "-sqrt(3)/3"}));
  EXPECT_EQ(a["plane"]["value"], nlohmann::json({1, 1, -1, -6}));
}

TEST(Cli, SolveDirectorySolvesEverySeedSet) {
  const CliRun r = run("solve " + test::source_path("problems/seeds"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("seed001-pixel-z"), std::string::npos);
  EXPECT_NE(r.out.find("seed003-backface"), std::string::npos);
  EXPECT_NE(r.out.find("D_f = −2"), std::string::npos);
}

TEST(Cli, CheckReportsLocatedErrorsAndExitsNonZero) {
  const std::string path = ::testing::TempDir() + "/broken_set.yaml";
  std::ofstream(path)
      << "problems:\n  - id: a\n    kind: vectors\n    given: {a: [1, .nan, 0], b: [0,1,0]}\n"
         "  - id: b\n    kind: nope\n    given: {}\n";
  const CliRun r = run("check " + path);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find(path + ":4:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("problems[0].given.a[1]: '.nan' is not a finite number"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("problems[1].kind: unknown kind 'nope'"), std::string::npos) << r.out;
  const CliRun clean = run("check " + seed("003_polygons_backface.yaml"));
  EXPECT_EQ(clean.status, 0) << clean.out;
  EXPECT_EQ(clean.out.find("seed003"), std::string::npos) << "check prints no solutions";
}

TEST(Cli, GradeJsonScoresThePublishedAnswersFully) {
  const CliRun r = run("grade " + seed("003_polygons_backface.yaml") + " " +
                       seed("answers/003_polygons_backface.yaml") + " --format json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["student"], "seed003-published");
  EXPECT_EQ(j["score"], j["max_score"]);
}

TEST(Cli, GradeTextShowsTheDerivationUnderAWrongAnswer) {
  const std::string path = ::testing::TempDir() + "/wrong_answers.yaml";
  std::ofstream(path) << "student: s1\nanswers:\n  seed001-pixel-z: {z: 9}\n";
  const CliRun r = run("grade " + seed("001_zbuffer_plane_method.yaml") + " " + path);
  EXPECT_NE(r.out.find("z: incorrect"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("How to get it"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Depth at the pixel"), std::string::npos) << r.out;
}

// A gradebook the instructor keeps in the output directory is moved aside, said, never deleted.
TEST(Cli, GradingIntoADirectoryWithTheInstructorsFilesSetsThemAside) {
  const std::filesystem::path dir = test::scratch_dir("cli_set_aside");
  std::filesystem::create_directories(dir / "class");
  std::filesystem::copy_file(
      test::source_path("problems/seeds/answers/001_zbuffer_plane_method.yaml"),
      dir / "class" / "s.yaml");
  std::filesystem::create_directories(dir / "out");
  test::write_file(dir / "out" / "gradebook.csv", "my own marks\n");
  const CliRun r = run("grade " + seed("001_zbuffer_plane_method.yaml") + " " +
                       (dir / "class").string() + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("note: " + (dir / "out" / "gradebook.csv").string() +
                       " was not written by Frustum: moved to " +
                       (dir / "out" / "set-aside" / "gradebook.csv").string()),
            std::string::npos)
      << r.out;
  EXPECT_EQ(test::read_file(dir / "out" / "set-aside" / "gradebook.csv"), "my own marks\n");
  EXPECT_NE(test::read_file(dir / "out" / "gradebook.csv").find("seed001-published,8,8"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

TEST(Cli, AnUnreadableAnswersFileIsOneErrorNotEveryProblemMissing) {
  // A file that is not YAML text (here: invalid YAML; a FIFO or an oversized file alike) once
  // printed every problem as "missing" with its whole derivation.
  const std::string path = ::testing::TempDir() + "/broken_answers.yaml";
  std::ofstream(path) << "student: s1\nanswers: [broken\n";
  const CliRun r = run("grade " + seed("001_zbuffer_plane_method.yaml") + " " + path);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.out.find("error: " + path), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing was graded"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("missing"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("How to get it"), std::string::npos) << r.out;
  EXPECT_TRUE(stdout_of("grade " + seed("001_zbuffer_plane_method.yaml") + " " + path).out.empty());
  // The platform outputs still say why, with or without --variants (a Gradescope upload that
  // does not parse scores 0 with the reason instead of stopping the autograder).
  const std::string results = ::testing::TempDir() + "/broken_results.json";
  std::filesystem::remove(results);
  EXPECT_EQ(run("grade " + seed("001_zbuffer_plane_method.yaml") + " " + path + " --variants " +
                ::testing::TempDir() + " --gradescope " + results)
                .status,
            1);
  std::ifstream in(results);
  const std::string json((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(json.find("broken_answers.yaml:3:1: invalid YAML"), std::string::npos) << json;
  EXPECT_NE(json.find("\"score\": 0"), std::string::npos) << json;
}

TEST(Cli, GenerateRefusesWhatCheckRefusesBeforeWritingAnything) {
  // {window.zmin} names no field: `check` refused the set, but `generate` wrote every variant
  // and an answer key without the problem, exit 0.
  const std::string dir = ::testing::TempDir() + "/gen-refused";
  const std::string path = ::testing::TempDir() + "/placeholder_set.yaml";
  std::ofstream(path)
      << "title: t\nvariants: per_student\nproblems:\n"
         "  - id: c\n    kind: clip_line\n    text: \"Clip against z = {window.zmin}.\"\n"
         "    given: {p: [-2, 5], q: [3, 1], window: {xmin: 0, xmax: 4, ymin: 0, ymax: 4}}\n";
  const CliRun r = run("generate " + path + " --student s1 -o " + dir);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("placeholder_set.yaml:4:5: problems[0].text: the placeholder {window.zmin}"),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/placeholder_set-s1.yaml"));
}

// A variant's text states its drawn values, not the triangle written in the set (its given and
// key are drawn anew), and a literal that cannot be tied to one field is refused by check and
// generate, naming the problem, language and literal.
TEST(Cli, AVariantsTextStatesItsDrawnValuesOrTheSetIsRefused) {
  const std::string dir = ::testing::TempDir() + "/gen-literals";
  const CliRun g =
      run("generate " + seed("001_zbuffer_plane_method.yaml") + " --seed 1 --count 1 -o " + dir);
  ASSERT_EQ(g.status, 0) << g.out;
  const YAML::Node v = YAML::LoadFile(dir + "/001_zbuffer_plane_method-seed1-0.yaml");
  const YAML::Node a = v["problems"][0]["given"]["A"];
  const std::string point = "A(" + a[0].Scalar() + "," + a[1].Scalar() + "," + a[2].Scalar() + ")";
  for (const char* lang : {"en", "ja", "ru"})
    EXPECT_NE(v["problems"][0]["text"][lang].Scalar().find(point), std::string::npos)
        << lang << ": " << v["problems"][0]["text"][lang].Scalar();

  const std::string path = ::testing::TempDir() + "/twins_set.yaml";
  std::ofstream(path) << "variants: per_student\nproblems:\n"
                         "  - id: twins\n    kind: vectors\n"
                         "    text: {en: \"a = (1, 2, 3)\", ja: \"(1, 2, 3)\"}\n"
                         "    given: {a: [1, 2, 3], b: [1, 2, 3]}\n";
  const CliRun c = run("check " + path);
  EXPECT_EQ(c.status, 1) << c.out;
  EXPECT_NE(c.out.find("twins_set.yaml:5:16: problems[0].text.en: problem twins (en): the literal "
                       "\"(1, 2, 3)\" could state any of several values"),
            std::string::npos)
      << c.out;
  const CliRun r = run("generate " + path + " --student s1 -o " + dir);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(r.out.find("problem twins (en)"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/twins_set-s1.yaml"));
}

TEST(Cli, GenerateStopsWhenAProblemRunsOutOfVariants) {
  // Two pixels to choose from: the third variant cannot be new. Each later variant once spent
  // every draw and failed alike (a 100,000-variant run of a narrow set took half an hour).
  const std::string dir = ::testing::TempDir() + "/gen-exhausted";
  const std::string path = ::testing::TempDir() + "/narrow_set.yaml";
  std::ofstream(path) << "title: t\nproblems:\n"
                         "  - id: z\n    kind: depth_at_pixel\n"
                         "    given: {triangle: [[0, 0, 6], [6, 0, 9], [0, 6, 9]], pixel: [1, 1]}\n"
                         "    vary: {pixel: {choices: [[1, 1], [2, 1]]}}\n";
  const CliRun r = run("generate " + path + " --seed 1 --count 1000 -o " + dir);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_NE(
      r.out.find("stopped at variant 3 of 1000 (2 distinct variants of this problem were drawn)"),
      std::string::npos)
      << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir + "/narrow_set-seed1-1.yaml"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/narrow_set-seed1-3.yaml"));
}

// Every file under dir (path relative to dir → content).
std::map<std::string, std::string> files_under(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) {
      std::ifstream in(e.path(), std::ios::binary);
      out[std::filesystem::relative(e.path(), dir).string()] =
          std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
  return out;
}

// `generate ARGS -j J` into a fresh directory: its status, output and files, the directory's
// name written DIR (a redrawn student's file names it).
struct Generated {
  int status;
  std::string out;
  std::map<std::string, std::string> files;
};
Generated generate_with_jobs(const std::string& args, int jobs, const std::string& name) {
  // A directory of this run's own (two checkouts' suites may run this test at once).
  const std::string dir = test::scratch_dir(name + "-j" + std::to_string(jobs)).string();
  std::filesystem::remove_all(dir);
  const CliRun r = run("generate " + args + " -j " + std::to_string(jobs) + " -o " + dir);
  const auto named = [&](std::string text) {
    for (std::size_t at; (at = text.find(dir)) != std::string::npos;)
      text.replace(at, dir.size(), "DIR");
    return text;
  };
  Generated out{r.status, named(r.out), {}};
  if (std::filesystem::exists(dir))
    for (const auto& [path, text] : files_under(dir)) out.files[path] = named(text);
  return out;
}

void expect_same_whatever_jobs(const std::string& args, const std::string& name) {
  const Generated one = generate_with_jobs(args, 1, name);
  EXPECT_FALSE(one.files.empty()) << one.out;
  for (const int jobs : {2, 3}) {
    const Generated more = generate_with_jobs(args, jobs, name);
    EXPECT_EQ(more.status, one.status) << jobs;
    EXPECT_EQ(more.out, one.out) << jobs;
    EXPECT_EQ(more.files.size(), one.files.size()) << jobs;
    EXPECT_TRUE(more.files == one.files) << "the files of -j " << jobs << " differ from -j 1";
  }
}

TEST(Cli, GenerateWritesTheSameFilesWhateverJobs) {
  expect_same_whatever_jobs(seed("001_zbuffer_plane_method.yaml") + " --seed 1 --count 200",
                            "gen-jobs-seed001");
}

// More files than one sync takes (8,192): the groups are put in place by one committing
// process while the workers go on, and every path printed is in place, whatever -j is.
TEST(Cli, GenerateOfManyGroupsWritesTheSameFilesWhateverJobs) {
  const std::string path = ::testing::TempDir() + "/many_groups_set.yaml";
  const std::string coord = "{range: [-20, 20]}", depth = "{range: [1, 40]}";
  const std::string point = "[" + coord + ", " + coord + ", " + depth + "]";
  std::ofstream(path) << "title: many groups\nproblems:\n"
                         "  - id: n\n    kind: normal\n"
                         "    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9], cross: [AC, AB]}\n"
                         "    vary: {A: "
                      << point << ", B: " << point << ", C: " << point
                      << "}\n    ask: [normal, unit_normal]\n";
  const Generated one = generate_with_jobs(path + " --seed 2 --count 4200", 1, "gen-groups");
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_EQ(one.files.size(), 8400u);  // every variant and its key, no temporary file left
  EXPECT_EQ(std::count(one.out.begin(), one.out.end(), '\n'), 4200) << one.out.substr(0, 400);
  const Generated two = generate_with_jobs(path + " --seed 2 --count 4200", 2, "gen-groups");
  EXPECT_EQ(two.status, 0);
  EXPECT_EQ(two.out, one.out);
  EXPECT_TRUE(two.files == one.files) << "the files of -j 2 differ from -j 1";
}

// 120 pixels for 100 variants: the later shares' own draws mostly repeat an earlier share's, so
// nearly every variant there is drawn again by the parent, as one process would have drawn it.
TEST(Cli, GenerateKeepsVariantsDistinctAcrossShares) {
  const std::string path = ::testing::TempDir() + "/crowded_set.yaml";
  std::ofstream(path)
      << "title: crowded\nproblems:\n"
         "  - id: z\n    kind: depth_at_pixel\n"
         "    given: {triangle: [[0, 0, 6], [40, 0, 9], [0, 40, 9]], pixel: [1, 1]}\n"
         "    vary: {pixel: [{range: [1, 12]}, {range: [1, 10]}]}\n";
  expect_same_whatever_jobs(path + " --seed 4 --count 100", "gen-jobs-crowded");
  // Used up: the same stop at the same variant, the same files before it.
  expect_same_whatever_jobs(path + " --seed 4 --count 200", "gen-jobs-used-up");
  // A class: redrawn students (#2, #3…) exactly as one process redraws them.
  const std::string roster = ::testing::TempDir() + "/crowded_roster.txt";
  {
    std::ofstream out(roster);
    for (int i = 0; i < 110; ++i) out << "s" << i << "\n";
  }
  expect_same_whatever_jobs(path + " --roster " + roster, "gen-jobs-class");
}

TEST(Cli, BadUsageIsAnErrorNotACrash) {
  EXPECT_NE(run("solve /nonexistent.yaml").status, 0);
  EXPECT_NE(run("frobnicate").status, 0);
  EXPECT_NE(run("solve " + seed("001_zbuffer_plane_method.yaml") + " --format pdf").status, 0);
}

// Output that cannot be written (standard output on a full disk) is an error, not status 0 with
// the output cut short; what the command prints on standard error says so.
TEST(Cli, OutputThatCannotBeWrittenIsAnError) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  for (const std::string& args :
       {"solve " + seed("001_zbuffer_plane_method.yaml"), std::string("--version"),
        "solve " + seed("001_zbuffer_plane_method.yaml") + " --format html"}) {
    // Standard error to the pipe, standard output to the full device.
    RunOptions full;
    full.out = OutputTo::File;
    full.log_file = "/dev/full";
    const ProgramRun p = test::frustum_run(test::words(args), true, full);
    const CliRun r{p.status, p.output};
    EXPECT_EQ(r.status, 1) << args;
    EXPECT_NE(r.out.find("standard output could not be written in full"), std::string::npos)
        << args << ": " << r.out;
  }
  // Written in full, the same commands end with status 0 and nothing on standard error.
  RunOptions quiet;
  quiet.out = OutputTo::Null;
  const ProgramRun q =
      test::frustum_run({"solve", seed("001_zbuffer_plane_method.yaml")}, true, quiet);
  const CliRun ok{q.status, q.output};
  EXPECT_EQ(ok.status, 0);
  EXPECT_EQ(ok.out, "");
}

// --version, help and `check` print on standard output only.

TEST(Cli, VersionPrintsTheProjectVersion) {
  const CliRun r = stdout_of("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("frustum ") + FRUSTUM_VERSION + "\n");
}

TEST(Cli, EverySubcommandHasAnExampleAndPlainChoices) {
  for (const char* sub : {"solve", "check", "grade", "kinds", "generate", "draw", "render", "bench",
                          "bench accuracy", "export"}) {
    const CliRun r = stdout_of(std::string(sub) + " --help");
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find("Example"), std::string::npos) << sub << ":\n" << r.out;
    EXPECT_NE(r.out.find("frustum " + std::string(sub).substr(0, std::string(sub).find(' '))),
              std::string::npos)
        << sub;
    EXPECT_EQ(r.out.find("->"), std::string::npos) << sub << " shows CLI11's internal mapping:\n"
                                                   << r.out;
  }
  EXPECT_NE(stdout_of("solve --help").out.find("{text,markdown,json,html,latex}"),
            std::string::npos);
  EXPECT_NE(stdout_of("solve --help").out.find("{exact,double,float,long-double}"),
            std::string::npos);
  EXPECT_NE(stdout_of("grade --help").out.find("{text,json}"), std::string::npos);
  // The words still select what they name.
  EXPECT_EQ(stdout_of("solve " + test::source_path("problems/seeds/001_zbuffer_plane_method.yaml") +
                      " --format JSON")
                .out.substr(0, 1),
            "{");
  EXPECT_NE(stdout_of("solve " + test::source_path("problems/seeds/001_zbuffer_plane_method.yaml") +
                      " --format 2")
                .status,
            0);
}

TEST(Cli, CheckPrintsItsSummaryOnStandardOutput) {
  const CliRun r =
      stdout_of("check " + test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("001_zbuffer_plane_method.yaml: 3 problems, no errors"), std::string::npos)
      << r.out;
}

// Problems in the students' languages: check names a bad language key with its
// location; solve, export and generate show the chosen language's text.
TEST(Cli, ProblemTextsInTheChosenLanguage) {
  const std::string dir = ::testing::TempDir() + "frustum_cli_texts";
  std::filesystem::create_directories(dir);
  const std::string bad = dir + "/bad.yaml";
  std::ofstream(bad) << "problems:\n  - id: p\n    kind: vectors\n    text: {en: a, de: b}\n"
                        "    given: {a: [1, 0, 0], b: [0, 1, 0]}\n";
  const CliRun checked = run("check " + bad);
  EXPECT_EQ(checked.status, 1);
  EXPECT_NE(checked.out.find("bad.yaml:4:19: problems[0].text.de: 'de' is not a language"),
            std::string::npos)
      << checked.out;
  const std::string seed003 = seed("003_polygons_backface.yaml");
  const CliRun ru = stdout_of("solve " + seed003 + " --lang ru --format json");
  EXPECT_NE(ru.out.find("\"text\": \"Какие из следующих утверждений верны?\""), std::string::npos);
  EXPECT_NE(ru.out.find("\"ja\": \"次の記述のうち正しいものを選べ.\""), std::string::npos);
  const std::string xml = dir + "/q.xml";
  ASSERT_EQ(run("export moodle " + seed003 + " --lang ru -o " + xml).status, 0);
  const std::string moodle = test::read_file(xml);
  EXPECT_NE(moodle.find("Нужны нормали граней, а не вершин."), std::string::npos);
  EXPECT_EQ(moodle.find("Back-face culling"), std::string::npos);
  ASSERT_EQ(run("generate " + seed003 + " --seed 3 --format latex --lang ja -o " + dir).status, 0);
  const std::string exam = test::read_file(dir + "/003_polygons_backface-exams.tex");
  EXPECT_NE(exam.find("凹多面体を描画する場合はバックフェースカリングを使うべきではない."),
            std::string::npos);
  EXPECT_EQ(exam.find("Back-face culling"), std::string::npos);
}

// A set that declares `lang: ja` is read in Japanese without --lang: the derivation, the
// feedback and the exam sheets; --lang en still chooses English.
TEST(Cli, ASetIsReadInItsOwnLanguageWithoutLang) {
  const std::string seed003 = seed("003_polygons_backface.yaml");
  const CliRun solved = stdout_of("solve " + seed003 + " --format json");
  EXPECT_NE(solved.out.find("\"text\": \"次の記述のうち正しいものを選べ.\""), std::string::npos)
      << solved.out.substr(0, 2000);
  const CliRun english = stdout_of("solve " + seed003 + " --lang en --format json");
  EXPECT_EQ(english.out.find("\"text\": \"次の記述のうち正しいものを選べ.\""), std::string::npos);
  const CliRun graded =
      stdout_of("grade " + seed003 + " " +
                test::source_path("problems/seeds/answers/003_polygons_backface.yaml"));
  EXPECT_EQ(graded.status, 0) << graded.out;
  EXPECT_EQ(graded.out.find("Student "), std::string::npos) << graded.out;
  const std::string dir = ::testing::TempDir() + "frustum_cli_own_lang";
  std::filesystem::create_directories(dir);
  ASSERT_EQ(run("generate " + seed003 + " --seed 3 --format latex -o " + dir).status, 0);
  const std::string exam = test::read_file(dir + "/003_polygons_backface-exams.tex");
  EXPECT_NE(exam.find("凹多面体を描画する場合はバックフェースカリングを使うべきではない."),
            std::string::npos);
}

// `check` warns (exit status 0: the set solves) when a problem's text never states a given the
// answers are computed from, naming the field at its line; a text that states it — literally
// or by placeholder — gets no warning.
TEST(Cli, CheckWarnsWhenATextNeverStatesAGiven) {
  const std::string dir = ::testing::TempDir() + "frustum_cli_unstated";
  std::filesystem::create_directories(dir);
  const std::string silent = dir + "/silent.yaml";
  std::ofstream(silent) << "problems:\n  - id: t\n    kind: transform\n"
                           "    text: \"Apply the 2-D translation to the point (1, 2).\"\n"
                           "    given: {dim: 2, steps: [{translate: [3, 4]}], points: [[1, 2]]}\n";
  const CliRun warned = stdout_of("check " + silent);
  EXPECT_EQ(warned.status, 0) << warned.out;
  EXPECT_NE(warned.out.find("silent.yaml:5:21: problems[0].given.steps: warning: problem t: its "
                            "text never states steps"),
            std::string::npos)
      << warned.out;
  EXPECT_EQ(warned.out.find("given.points"), std::string::npos) << warned.out;
  EXPECT_EQ(warned.out.find("given.dim"), std::string::npos) << warned.out;
  const std::string stated = dir + "/stated.yaml";
  std::ofstream(stated) << "problems:\n  - id: t\n    kind: transform\n"
                           "    text: \"Translate the point (1, 2) by (3, 4).\"\n"
                           "    given: {dim: 2, steps: [{translate: [3, 4]}], points: [[1, 2]]}\n";
  EXPECT_EQ(stdout_of("check " + stated).out.find("warning"), std::string::npos);
  // The bundled sets state what they ask.
  for (const char* bundled : {"problems/seeds", "problems/examples"}) {
    const CliRun r = stdout_of("check " + test::source_path(bundled));
    EXPECT_EQ(r.out.find("never states"), std::string::npos) << r.out;
  }
}

}  // namespace
}  // namespace frustum
