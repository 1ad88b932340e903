// Grading a class: CSV reading, atomic writes, isolation of slow and crashing work, the batch's
// gradebook, feedback pages, Gradescope results, reproducible outputs, and Japanese feedback.
#include "batch/batch.hpp"

#include <fmt/format.h>
#include <sys/single_threaded.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <random>
#include <regex>
#include <sstream>
#include <thread>

#include "batch/atomic_file.hpp"
#include "batch/csv.hpp"
#include "batch/gradebook.hpp"
#include "batch/isolate.hpp"
#include "batch/output_transaction.hpp"
#include "report/feedback.hpp"
#include "report/gradescope.hpp"
#include "report/report.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/problem/problem_figure.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

const char* kSet = R"Y(title: Batch test
problems:
  - id: zbuf
    kind: depth_at_pixel
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
    ask: [normal, plane, z]
  - id: bf
    kind: backface
    given: {points: [[1,0,0],[1,1,1],[0,1,2]], eye: [0,1,0]}
    ask: [df, facing]
)Y";

TEST(Csv, ReadsQuotesDoubledQuotesLineBreaksAndCrlf) {
  const CsvTable t = parse_csv(
      "\xEF\xBB\xBFstudent,zbuf.plane\r\ns1,\"x + y - z = -6\"\r\n"
      "\"s,2\",\"say \"\"hi\"\"\nthere\"\n\n");
  ASSERT_FALSE(t.error);
  ASSERT_EQ(t.rows.size(), 3u);
  EXPECT_EQ(t.rows[0].fields, (std::vector<std::string>{"student", "zbuf.plane"}));
  EXPECT_EQ(t.rows[1].fields, (std::vector<std::string>{"s1", "x + y - z = -6"}));
  EXPECT_EQ(t.rows[2].fields, (std::vector<std::string>{"s,2", "say \"hi\"\nthere"}));
  EXPECT_EQ(t.rows[2].line, 3);
  EXPECT_EQ(parse_csv("a,\"b\nc").error.value_or(""), "line 1: unterminated quoted field");
}

TEST(Csv, WritingAndReadingRoundTrips) {
  const std::vector<std::string> fields = {"plain", "with,comma", "with \"quote\"", "two\nlines",
                                           ""};
  const CsvTable t = parse_csv(csv_row(fields) + csv_row({"x"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0].fields, fields);
}

TEST(AtomicFile, WritesTheWholeFileAndLeavesNoTemporaryBehind) {
  const fs::path dir = test::scratch_dir("batch-atomic");
  const fs::path target = dir / "sub" / "out.txt";
  write_file_atomically(target.string(), "first");
  write_file_atomically(target.string(), std::string(1 << 20, 'x'));
  EXPECT_EQ(test::read_file(target), std::string(1 << 20, 'x'));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir / "sub"), fs::directory_iterator()), 1);
  EXPECT_THROW(write_file_atomically((dir / "sub" / "out.txt" / "below").string(), "x"),
               std::exception);
  fs::remove_all(dir);
}

// Hidden files (the temporary files of staged outputs) left in a directory.
std::vector<std::string> hidden_files(const fs::path& dir) {
  std::vector<std::string> out;
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().rfind('.', 0) == 0) out.push_back(e.path().string());
  return out;
}

// A group committed in the background (generate's groups of files): in place once waited for,
// while the next group is staged meanwhile and stays out of sight until its own commit.
TEST(FileBatch, AGroupCommittedInTheBackgroundIsInPlaceOnceWaitedFor) {
  const fs::path dir = test::scratch_dir("batch-background");
  FileBatch files;
  for (int i = 0; i < 50; ++i)
    files.stage((dir / "a" / fmt::format("f{}.txt", i)).string(), fmt::format("first {}", i));
  files.commit_in_background();
  EXPECT_EQ(files.staged(), 0u);
  for (int i = 0; i < 50; ++i)
    files.stage((dir / "b" / fmt::format("f{}.txt", i)).string(), fmt::format("second {}", i));
  files.wait_commit();
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(test::read_file(dir / "a" / fmt::format("f{}.txt", i)), fmt::format("first {}", i));
    EXPECT_FALSE(fs::exists(dir / "b" / fmt::format("f{}.txt", i)));
  }
  EXPECT_TRUE(hidden_files(dir / "a").empty());
  files.commit_in_background();
  files.commit();  // waits for the group in flight first
  for (int i = 0; i < 50; ++i)
    EXPECT_EQ(test::read_file(dir / "b" / fmt::format("f{}.txt", i)), fmt::format("second {}", i));
  EXPECT_TRUE(hidden_files(dir).empty());
  fs::remove_all(dir);
}

// Groups larger than the committer's read block (names of every length up to 200 bytes, so
// that messages split anywhere) arrive whole, one group after another.
TEST(FileBatch, LargeGroupsThroughTheCommitterArriveWhole) {
  const fs::path dir = test::scratch_dir("batch-large-groups");
  FileBatch files;
  files.start_committer();
  std::vector<fs::path> written;
  for (int group = 0; group < 3; ++group) {
    for (int i = 0; i < 1500; ++i) {
      const fs::path path = dir / fmt::format("g{}-{}-{}.txt", group, i,
                                              std::string(static_cast<std::size_t>(i % 190), 'x'));
      files.stage(path.string(), fmt::format("{} {}", group, i));
      written.push_back(path);
    }
    files.commit_in_background();
    files.wait_commit();
  }
  for (std::size_t k = 0; k < written.size(); ++k)
    EXPECT_EQ(test::read_file(written[k]), fmt::format("{} {}", k / 1500, k % 1500)) << written[k];
  EXPECT_TRUE(hidden_files(dir).empty());
  fs::remove_all(dir);
}

// Written files are readable by everyone unless the umask says otherwise, as any file a program
// creates: 0644 less the umask.
TEST(FileBatch, FilesTakeTheUsualModeLessTheUmask) {
  const fs::path dir = test::scratch_dir("batch-modes");
  for (const mode_t mask : {mode_t{022}, mode_t{027}, mode_t{077}}) {
    const mode_t saved = ::umask(mask);
    const fs::path path = dir / fmt::format("m{:o}.txt", mask);
    FileBatch files;
    files.stage(path.string(), "x");
    files.commit();
    write_file_atomically((dir / fmt::format("w{:o}.txt", mask)).string(), "y");
    ::umask(saved);
    for (const fs::path& p : {path, dir / fmt::format("w{:o}.txt", mask)}) {
      struct stat st {};
      ASSERT_EQ(::stat(p.c_str(), &st), 0) << p;
      EXPECT_EQ(st.st_mode & 0777, 0644 & ~mask) << p;
    }
  }
  fs::remove_all(dir);
}

// A background commit that cannot put a file in place: its error (naming the file) comes back
// from wait_commit(), as commit() would have thrown it, and no temporary file is left.
TEST(FileBatch, ABackgroundCommitThatFailsReportsItsErrorAndLeavesNoTemporaryFile) {
  const fs::path dir = test::scratch_dir("batch-background-fails");
  FileBatch files;
  for (int i = 0; i < 5; ++i)
    files.stage((dir / fmt::format("f{}.txt", i)).string(), fmt::format("file {}", i));
  // A directory where one file is to go: the rename over it fails.
  fs::create_directories(dir / "f2.txt");
  test::write_file(dir / "f2.txt" / "inside", "in the way");
  files.commit_in_background();
  try {
    files.wait_commit();
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("f2.txt: cannot rename into place"), std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(hidden_files(dir).empty()) << hidden_files(dir)[0];
  files.commit();  // nothing is left to commit, nothing is thrown again
  fs::remove_all(dir);
}

// Many groups in turn through the one committing child: a group that fails reports its own
// error and leaves no temporary file, and the groups after it are still put in place; a group
// still in flight when the batch ends is waited for, not lost.
TEST(FileBatch, GroupsAfterAFailedGroupAreStillPutInPlace) {
  const fs::path dir = test::scratch_dir("batch-many-groups");
  {
    FileBatch files;
    for (int g = 0; g < 6; ++g) {
      for (int i = 0; i < 20; ++i)
        files.stage((dir / fmt::format("g{}", g) / fmt::format("f{}.txt", i)).string(),
                    fmt::format("group {} file {}", g, i));
      if (g == 2) {  // a directory where one file of this group is to go
        fs::create_directories(dir / "g2" / "f7.txt");
        test::write_file(dir / "g2" / "f7.txt" / "inside", "in the way");
      }
      files.commit_in_background();
      if (g == 5) break;  // left in flight for the destructor
      if (g == 2) {
        try {
          files.wait_commit();
          ADD_FAILURE() << "no error for group 2";
        } catch (const std::runtime_error& e) {
          EXPECT_NE(std::string(e.what()).find("f7.txt: cannot rename into place"),
                    std::string::npos)
              << e.what();
        }
      } else {
        files.wait_commit();
        for (int i = 0; i < 20; ++i)
          EXPECT_EQ(test::read_file(dir / fmt::format("g{}", g) / fmt::format("f{}.txt", i)),
                    fmt::format("group {} file {}", g, i));
      }
      EXPECT_TRUE(hidden_files(dir / fmt::format("g{}", g)).empty()) << g;
    }
  }
  for (int i = 0; i < 20; ++i)
    EXPECT_EQ(test::read_file(dir / "g5" / fmt::format("f{}.txt", i)),
              fmt::format("group 5 file {}", i));
  EXPECT_TRUE(hidden_files(dir / "g5").empty());
  fs::remove_all(dir);
}

TEST(Isolate, SlowAndCrashingItemsCostOnlyTheirOwnResult) {
  std::vector<std::size_t> seen;
  const auto results = run_isolated_each(
      5,
      [](std::size_t i) -> std::string {
        if (i == 1) std::this_thread::sleep_for(std::chrono::seconds(30));
        if (i == 2) std::raise(SIGSEGV);
        if (i == 3) throw std::runtime_error("bad answers");
        return "item " + std::to_string(i);
      },
      0.5, [&](std::size_t i, const IsolatedResult&) { seen.push_back(i); });
  ASSERT_EQ(results.size(), 5u);
  EXPECT_EQ(results[0].status, IsolatedResult::Status::Ok);
  EXPECT_EQ(results[0].output, "item 0");
  EXPECT_EQ(results[1].status, IsolatedResult::Status::Timeout);
  EXPECT_NE(results[1].error.find("time limit"), std::string::npos);
  EXPECT_EQ(results[2].status, IsolatedResult::Status::Crashed);
  // SIGSEGV, or SIGABRT when a sanitizer catches it first.
  EXPECT_NE(results[2].error.find("signal"), std::string::npos) << results[2].error;
  EXPECT_EQ(results[3].status, IsolatedResult::Status::Failed);
  EXPECT_EQ(results[3].error, "bad answers");
  EXPECT_EQ(results[4].output, "item 4");
  EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

// Stopped by the caller: every item started is handed over, none is started after.
TEST(Isolate, AStoppedRunStartsNoFurtherItem) {
  for (const Shares shares : {Shares::Contiguous, Shares::Dynamic}) {
    std::vector<std::size_t> seen;
    const auto results = run_isolated_each(
        200,
        [](std::size_t i) -> std::string {
          std::this_thread::sleep_for(std::chrono::milliseconds(20));
          return "item " + std::to_string(i);
        },
        10, [&](std::size_t i, const IsolatedResult&) { seen.push_back(i); }, 64u << 20, 2,
        [&] { return seen.size() >= 3; }, shares);
    ASSERT_EQ(results.size(), 200u);
    EXPECT_LT(seen.size(), 100u);  // each child finishes the item it is on (4 s of items a share)
    for (std::size_t i = 0; i < results.size(); ++i) {
      const bool handed = std::find(seen.begin(), seen.end(), i) != seen.end();
      EXPECT_EQ(results[i].status == IsolatedResult::Status::Ok, handed) << i;
      if (!handed) {
        EXPECT_EQ(results[i].error, "not run") << i;
      }
    }
  }
}

// Three children, in either kind of share: a slow item, a crash and a throw each cost only
// their own result.
TEST(Isolate, SharesInParallelKeepEachItemsOwnResult) {
  for (const Shares shares : {Shares::Contiguous, Shares::Dynamic}) {
    std::vector<std::size_t> seen;
    const auto results = run_isolated_each(
        9,
        [](std::size_t i) -> std::string {
          if (i == 1) std::this_thread::sleep_for(std::chrono::seconds(30));
          if (i == 5) std::raise(SIGSEGV);
          if (i == 7) throw std::runtime_error("bad answers");
          return "item " + std::to_string(i);
        },
        0.5, [&](std::size_t i, const IsolatedResult&) { seen.push_back(i); }, 64u << 20, 3, {},
        shares);
    ASSERT_EQ(results.size(), 9u);
    for (std::size_t i : {0, 2, 3, 4, 6, 8}) {
      EXPECT_EQ(results[i].status, IsolatedResult::Status::Ok) << i;
      EXPECT_EQ(results[i].output, "item " + std::to_string(i));
    }
    EXPECT_EQ(results[1].status, IsolatedResult::Status::Timeout);
    EXPECT_EQ(results[5].status, IsolatedResult::Status::Crashed);
    EXPECT_EQ(results[7].status, IsolatedResult::Status::Failed);
    EXPECT_EQ(results[7].error, "bad answers");
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(seen, (std::vector<std::size_t>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
  }
}

// With a reaper, the children that end owing nothing are left to it (still there when
// run_isolated_each returns, gone once the reaper is); a child that crashes on an item is still
// waited for at once, so that its item says how it ended.
TEST(Isolate, AReaperWaitsForTheChildrenThatOweNothing) {
  for (const Shares shares : {Shares::Contiguous, Shares::Dynamic}) {
    std::vector<IsolatedResult> results;
    {
      Reaper reaper;
      results = run_isolated_each(
          12,
          [](std::size_t i) -> std::string {
            if (i == 4) std::raise(SIGSEGV);
            return "item " + std::to_string(i);
          },
          10, {}, 64u << 20, 3, {}, shares, &reaper);
      EXPECT_NE(waitpid(-1, nullptr, WNOHANG), -1) << "every child was waited for already";
    }
    errno = 0;
    EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);
    EXPECT_EQ(errno, ECHILD) << "a child was left behind";
    ASSERT_EQ(results.size(), 12u);
    for (std::size_t i = 0; i < 12; ++i) {
      if (i == 4) {
        EXPECT_EQ(results[i].status, IsolatedResult::Status::Crashed);
        continue;
      }
      EXPECT_EQ(results[i].status, IsolatedResult::Status::Ok) << i;
      EXPECT_EQ(results[i].output, "item " + std::to_string(i));
    }
  }
  // Without one, no child is left when run_isolated_each returns.
  run_isolated_each(
      6, [](std::size_t i) { return std::to_string(i); }, 10, {}, 64u << 20, 2);
  errno = 0;
  EXPECT_EQ(waitpid(-1, nullptr, WNOHANG), -1);
  EXPECT_EQ(errno, ECHILD);
}

// Dynamic shares: while one child is held on a long item, the other takes every other item
// (contiguous shares would leave items 1–9 queued behind item 0 in its child). Item 0 is held
// until item 19 is done, so the test does not depend on timing.
TEST(Isolate, DynamicSharesGiveTheRestToTheFreeChild) {
  const fs::path marker = test::scratch_dir("batch-dynamic") / "item19-done";
  fs::remove(marker);
  const auto results = run_isolated_each(
      20,
      [&](std::size_t i) -> std::string {
        if (i == 0)
          for (int k = 0; k < 1000 && !fs::exists(marker); ++k)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        if (i == 19) test::write_file(marker, "done");
        return std::to_string(getpid());
      },
      60, {}, 64u << 20, 2, {}, Shares::Dynamic);
  ASSERT_EQ(results.size(), 20u);
  for (std::size_t i = 0; i < 20; ++i) ASSERT_EQ(results[i].status, IsolatedResult::Status::Ok);
  for (std::size_t i = 1; i < 20; ++i)
    EXPECT_NE(results[i].output, results[0].output) << "item " << i << " waited behind item 0";
  fs::remove_all(marker.parent_path());
}

// A child runs ahead while this process is busy: its results wait in a pipe of 1 MiB (the
// default 64 KiB stalled generate's children while it synced and renamed a group of files). The
// first result's handler waits until the last item is done, which the child reaches only if
// 200 kB of results fit in the pipe.
TEST(Isolate, AChildRunsAheadWhileTheParentIsBusy) {
  std::ifstream limit("/proc/sys/fs/pipe-max-size");
  long max_pipe = 0;
  limit >> max_pipe;
  if (max_pipe < (1 << 20)) GTEST_SKIP() << "pipes are limited to " << max_pipe << " bytes here";
  const fs::path marker = test::scratch_dir("batch-ahead") / "last-done";
  bool waited_for_nothing = false;
  const auto results = run_isolated_each(
      500,
      [&](std::size_t i) -> std::string {
        if (i == 499) test::write_file(marker, "done");
        return std::string(400, 'a' + static_cast<char>(i % 26));
      },
      60,
      [&](std::size_t i, const IsolatedResult&) {
        if (i != 0) return;
        for (int k = 0; k < 500 && !fs::exists(marker); ++k)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
        waited_for_nothing = !fs::exists(marker);
      });
  EXPECT_FALSE(waited_for_nothing) << "the child stopped before its last item";
  for (std::size_t i = 0; i < 500; ++i)
    ASSERT_EQ(results[i].output, std::string(400, 'a' + static_cast<char>(i % 26))) << i;
  fs::remove_all(marker.parent_path());
}

// A class of five: right, wrong, broken YAML, empty, and too big.
fs::path make_class(const fs::path& dir) {
  const fs::path in = dir / "in";
  fs::create_directories(in);
  test::write_file(
      in / "a_right.yaml",
      "student: s001\nanswers:\n  zbuf: {normal: [1, 1, -1], plane: \"x + y - z = -6\", z: 8}\n"
      "  bf: {df: -2, facing: back}\n");
  test::write_file(
      in / "b_wrong.yaml",
      "student: s002\nanswers:\n  zbuf: {normal: [-1, -1, 1], plane: [1, 1, -1, -6], z: 9}\n");
  test::write_file(in / "c_broken.yaml", "answers: [1, 2\n");
  test::write_file(in / "d_empty.yaml", "");
  test::write_file(in / "e_huge.yaml",
                   "student: s005\n#" + std::string(kMaxSubmissionBytes + 10, 'x') + "\n");
  test::write_file(in / "notes.txt", "not an answers file");
  return in;
}

TEST(Batch, GradebookListsEveryStudentAndFeedbackIsWritten) {
  const fs::path dir = test::scratch_dir("batch-class");
  const fs::path in = make_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.out_dir = (dir / "out").string();
  std::vector<std::size_t> progress;
  options.on_progress = [&](std::size_t done, std::size_t total, const std::string&) {
    progress.push_back(done);
    EXPECT_EQ(total, 5u);
  };
  const BatchResult r = grade_batch(set, collect_submissions(in.string()), options);
  ASSERT_EQ(r.rows.size(), 5u);
  EXPECT_EQ(progress, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
  EXPECT_EQ(r.rows[0].student, "s001");
  EXPECT_EQ(r.rows[0].status, "graded");
  EXPECT_DOUBLE_EQ(r.rows[0].score, 5);
  EXPECT_DOUBLE_EQ(r.rows[0].max_score, 5);
  EXPECT_EQ(r.rows[1].student, "s002");
  EXPECT_EQ(r.rows[1].status, "graded");
  EXPECT_LT(r.rows[1].score, 2);
  EXPECT_EQ(r.rows[2].student, "c_broken");
  EXPECT_EQ(r.rows[2].status, "error");
  EXPECT_NE(r.rows[2].message.find("c_broken.yaml:2:"), std::string::npos) << r.rows[2].message;
  EXPECT_EQ(r.rows[3].status, "error");
  EXPECT_EQ(r.rows[4].student, "e_huge");
  EXPECT_EQ(r.rows[4].status, "error");
  EXPECT_NE(r.rows[4].message.find("larger than the limit"), std::string::npos);

  const std::string book = test::read_file(dir / "out" / "gradebook.csv");
  const CsvTable t = parse_csv(book);
  ASSERT_EQ(t.rows.size(), 6u) << book;
  EXPECT_EQ(t.rows[0].fields[0], "student");
  EXPECT_EQ(t.rows[0].fields[5], "zbuf");
  EXPECT_EQ(t.rows[1].fields[1], "5");
  EXPECT_EQ(t.rows[1].fields[3], "100.0");
  for (const char* stem : {"s001", "s002", "c_broken", "d_empty", "e_huge"}) {
    EXPECT_TRUE(fs::exists(dir / "out" / "feedback" / (std::string(stem) + ".md"))) << stem;
    EXPECT_TRUE(fs::exists(dir / "out" / "gradescope" / (std::string(stem) + ".json"))) << stem;
  }
  const auto gs = nlohmann::json::parse(test::read_file(dir / "out" / "gradescope" / "s002.json"));
  ASSERT_EQ(gs["tests"].size(), 2u);
  EXPECT_EQ(gs["tests"][0]["name"], "zbuf");
  EXPECT_EQ(gs["tests"][0]["status"], "failed");
  EXPECT_EQ(gs["tests"][0]["max_score"], 3);
  EXPECT_EQ(gs["tests"][0]["output_format"], "md");
  EXPECT_EQ(gs["tests"][0]["visibility"], "visible");
  EXPECT_NE(gs["tests"][0]["output"].get<std::string>().find("x + y − z = −6"), std::string::npos);
  const std::string html = test::read_file(dir / "out" / "feedback" / "s002.html");
  EXPECT_NE(html.find("data-verdict=\"incorrect\""), std::string::npos);
  // The page loads nothing from outside the output directory: only the class's one copy of
  // KaTeX beside feedback/, and every file that copy names is there (the directory works
  // offline as a whole).
  for (const char* load : {"src=\"http", "src='http", "src=\"//", "href=\"http", "href=\"//",
                           "url(http", "url(//", "@import"})
    EXPECT_EQ(html.find(load), std::string::npos) << "the page must not load anything: " << load;
  const std::regex link(R"re((?:src|href)="([^"]*)")re");
  std::vector<std::string> loaded;
  for (auto m = std::sregex_iterator(html.begin(), html.end(), link); m != std::sregex_iterator();
       ++m)
    if ((*m)[1].str().rfind("data:", 0) != 0) loaded.push_back((*m)[1]);  // pictures are inline
  EXPECT_EQ(loaded, (std::vector<std::string>{"../katex/katex.min.css", "../katex/katex.min.js"}));
  EXPECT_NE(
      html.find("<figure class=\"figure\"><img alt=\"Figure\" src=\"data:image/svg+xml;base64,"),
      std::string::npos);
  for (const std::string& l : loaded)
    EXPECT_TRUE(fs::is_regular_file(dir / "out" / "feedback" / l)) << l;
  const std::string css = test::read_file(dir / "out" / "katex" / "katex.min.css");
  const std::regex font(R"re(url\(([^)]*)\))re");
  int fonts = 0;
  for (auto m = std::sregex_iterator(css.begin(), css.end(), font); m != std::sregex_iterator();
       ++m, ++fonts) {
    EXPECT_EQ((*m)[1].str().rfind("fonts/", 0), 0u) << (*m)[1];
    EXPECT_GT(fs::file_size(dir / "out" / "katex" / (*m)[1].str()), 1000u) << (*m)[1];
  }
  EXPECT_GE(fonts, 10);
  // The page is small: KaTeX is not inlined in it.
  EXPECT_LT(html.size(), 100'000u);
  fs::remove_all(dir);
}

TEST(Batch, ASecondRunGivesByteIdenticalOutputs) {
  const fs::path dir = test::scratch_dir("batch-twice");
  const fs::path in = make_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.out_dir = (dir / "one").string();
  grade_batch(set, collect_submissions(in.string()), options);
  options.out_dir = (dir / "two").string();
  grade_batch(set, collect_submissions(in.string()), options);
  const auto one = test::published_tree(dir / "one"), two = test::published_tree(dir / "two");
  // gradebook, 5 Gradescope files, 5 Markdown pages, 4 HTML pages (not for the file never read),
  // and the class's copy of KaTeX
  const std::size_t katex = katex_files().size();
  EXPECT_GT(katex, 10u);
  EXPECT_EQ(one.size(), 15u + katex);
  EXPECT_TRUE(one == two);
  fs::remove_all(dir);
}

TEST(Batch, OneChildOrSeveralGiveTheSameBytes) {
  const fs::path dir = test::scratch_dir("batch-jobs");
  const fs::path in = make_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.jobs = 1;
  options.out_dir = (dir / "one").string();
  const BatchResult one_child = grade_batch(set, collect_submissions(in.string()), options);
  options.jobs = 3;
  options.out_dir = (dir / "three").string();
  const BatchResult three = grade_batch(set, collect_submissions(in.string()), options);
  EXPECT_TRUE(test::published_tree(dir / "one") == test::published_tree(dir / "three"));
  ASSERT_EQ(three.rows.size(), 5u);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(three.rows[i].student, one_child.rows[i].student);
  // The page the batch writes is the page made alone, linking the class's copy of KaTeX
  // instead of carrying it, with the problems' pictures.
  const Submission sub = load_submission_from_string(test::read_file(in / "b_wrong.yaml"),
                                                     (in / "b_wrong.yaml").string());
  const GradeReport alone = grade(set, sub);
  const Figures figures = problem_figures(set);
  EXPECT_EQ(test::read_file(dir / "three" / "feedback" / "s002.html"),
            render_feedback_html(alone, Lang::En, html_math_head_linked("../katex/"), &figures));
  // So are the Markdown page and the Gradescope results (the batch formats the keys once for
  // the class and each problem's Markdown once for both).
  EXPECT_EQ(test::read_file(dir / "three" / "feedback" / "s002.md"),
            render_feedback_markdown(alone));
  EXPECT_EQ(test::read_file(dir / "three" / "gradescope" / "s002.json"),
            json_text(gradescope_results(alone)) + "\n");
  fs::remove_all(dir);
}

TEST(Batch, CsvRosterGradesLikeAnswerFiles) {
  const fs::path dir = test::scratch_dir("batch-csv");
  test::write_file(dir / "roster.csv",
                   "student,zbuf.normal,zbuf.plane,zbuf.z,bf.df,bf.facing\n"
                   "s001,\"[1, 1, -1]\",x + y - z = -6,8,-2,back\n"
                   "s002,\"[2, 2, -2]\",\"[1, 1, -1, -6]\",9,,\n"
                   ",,,,,\n");
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const std::vector<BatchEntry> entries = collect_submissions((dir / "roster.csv").string());
  ASSERT_EQ(entries.size(), 3u);
  // A row without an id is refused, not given one (it was "row-4").
  EXPECT_EQ(entries[2].student, "");
  EXPECT_EQ(entries[2].error,
            (dir / "roster.csv").string() + ":4:1: student: the student id is empty");
  BatchOptions options;
  options.out_dir = (dir / "out").string();
  const BatchResult r = grade_batch(set, entries, options);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_DOUBLE_EQ(r.rows[0].score, 5);
  EXPECT_DOUBLE_EQ(r.rows[1].score, 2);  // normal and plane right, z wrong, bf missing
  EXPECT_DOUBLE_EQ(r.rows[2].score, 0);
  EXPECT_EQ(r.rows[2].status, "error");
  EXPECT_EQ(r.rows[0].source, (dir / "roster.csv").string() + " row 2");
  test::write_file(dir / "bad.csv", "name,zbuf.z\nx,1\n");
  EXPECT_THROW(collect_submissions((dir / "bad.csv").string()), InputError);
  fs::remove_all(dir);
}

// Nothing handed in is passed over in silence: two files claiming one student both say so, and
// other files and folders beside the answers are listed as not graded (hidden ones are not).
TEST(Batch, SharedClaimsAndOtherFilesAreReportedNotSilent) {
  const fs::path dir = test::scratch_dir("batch-claims");
  test::write_file(dir / "a.yaml", "student: ann\nanswers: {zbuf: {z: 8}}\n");
  test::write_file(dir / "b.yml", "student: ann\nanswers: {zbuf: {z: 9}}\n");
  test::write_file(dir / "c.yaml", "student: cy\nanswers: {zbuf: {z: 8}}\n");
  test::write_file(dir / "answers.json", "{\"student\": \"dee\"}\n");
  test::write_file(dir / ".DS_Store", "x");
  fs::create_directories(dir / "section2");
  std::vector<Diagnostic> not_graded;
  const std::vector<BatchEntry> entries =
      collect_submissions(dir.string(), kMaxSubmissionBytes, &not_graded);
  ASSERT_EQ(entries.size(), 3u);
  EXPECT_EQ(entries[0].note,
            (dir / "b.yml").string() +
                " also claims student 'ann': each file is graded; keep the one that counts");
  EXPECT_EQ(entries[1].note,
            (dir / "a.yaml").string() +
                " also claims student 'ann': each file is graded; keep the one that counts");
  EXPECT_EQ(entries[2].note, "");
  ASSERT_EQ(not_graded.size(), 2u);
  EXPECT_EQ(not_graded[0].format(),
            (dir / "answers.json").string() + ": not an answers file (.yaml or .yml): not graded");
  EXPECT_EQ(not_graded[1].format(),
            (dir / "section2").string() + ": a directory: not graded (grade it on its own)");
  // A roster decides whose each file is: the files' shared claim no longer matters.
  const std::vector<BatchEntry> rostered = apply_roster(entries, {"a", "b"}, "roster.csv");
  ASSERT_GE(rostered.size(), 2u);
  EXPECT_EQ(rostered[0].student, "a");
  EXPECT_EQ(rostered[0].note.find("also claims"), std::string::npos) << rostered[0].note;
  // The batch's rows carry the note, so the gradebook shows both submissions for what they are.
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.out_dir = (dir / "out").string();
  options.jobs = 1;
  const BatchResult r = grade_batch(set, entries, options);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_NE(r.rows[0].message.find("also claims student 'ann'"), std::string::npos)
      << r.rows[0].message;
  EXPECT_NE(test::read_file(dir / "out" / "gradebook.csv").find("also claims student 'ann'"),
            std::string::npos);
  fs::remove_all(dir);
}

TEST(Feedback, JapaneseFeedbackTranslatesVerdictsAndStepTitles) {
  const GradeReport r =
      grade(load_problem_set_from_string(kSet, "set.yaml"),
            load_submission_from_string("student: s1\nanswers:\n  zbuf: {z: 9}\n", "a.yaml"));
  const std::string ja = render_grade_text(r, TextStyle{false, Lang::Ja});
  EXPECT_NE(ja.find("不正解"), std::string::npos) << ja;
  EXPECT_NE(ja.find("求め方"), std::string::npos);
  EXPECT_NE(ja.find("法線"), std::string::npos);
  EXPECT_NE(ja.find("未解答"), std::string::npos);
  const std::string en = render_grade_text(r, TextStyle{false, Lang::En});
  EXPECT_NE(en.find("incorrect"), std::string::npos);
  EXPECT_EQ(en.find("不正解"), std::string::npos);
  const std::string md = render_feedback_markdown(r, Lang::Ja);
  EXPECT_NE(md.find("| 解答 | 判定 |"), std::string::npos) << md;
}

TEST(Feedback, JapaneseFeedbackNamesTheMistakeAndCarriesCreditForward) {
  // The reversed normal (seed 001's left-handed projection space), and a z that follows from
  // the student's own wrong plane: the mistake, its explanation and the carried credit in Japanese.
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const SolvedSet solved = solve_for_grading(set);
  const Answers& key = solved.results[0].answers;
  const auto& n = key.find("normal")->numbers;
  const auto& p = key.find("plane")->numbers;
  const std::string answers = fmt::format(
      "student: s1\nanswers:\n  zbuf: {{normal: [{}, {}, {}], plane: [{}, {}, {}, {}], z: {}}}\n",
      -n[0], -n[1], -n[2], p[0], p[1], p[2], p[3] + 3, (p[3] + 3 - p[0] - p[1]) / p[2]);
  const GradeReport r = grade(set, load_submission_from_string(answers, "a.yaml"), &solved);
  const std::string ja = render_grade_text(r, TextStyle{false, Lang::Ja});
  EXPECT_NE(ja.find("よくある誤り: 外積の順序が逆"), std::string::npos) << ja;
  EXPECT_NE(ja.find("投影座標系は左手系なので"), std::string::npos) << ja;
  EXPECT_NE(ja.find("あなた自身の前の解答から正しく導かれています"), std::string::npos) << ja;
  EXPECT_NE(ja.find("誤りの持ち越し"), std::string::npos) << ja;
  const std::string html = render_feedback_html(r, Lang::Ja);
  EXPECT_NE(html.find("外積の順序が逆"), std::string::npos);
  // English stays English.
  const std::string en = render_grade_text(r, TextStyle{false, Lang::En});
  EXPECT_NE(en.find("reversed cross product"), std::string::npos) << en;
  EXPECT_NE(en.find("error carried forward"), std::string::npos) << en;
  EXPECT_EQ(en.find("外積"), std::string::npos);
}

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// tools/gradescope/run_autograder in a stand-in for Gradescope's /autograder tree.
TEST(Gradescope, AutograderScriptWritesResultsJson) {
  const fs::path ag = test::scratch_dir("batch-autograder");
  fs::create_directories(ag / "source" / "build");
  fs::create_directories(ag / "submission");
  fs::create_symlink(FRUSTUM_BINARY, ag / "source" / "build" / "frustum");
  fs::create_symlink(test::source_path("problems"), ag / "source" / "problems");
  test::write_file(ag / "source" / "autograder.conf",
                   "SET=problems/seeds/001_zbuffer_plane_method.yaml\nLANG_FEEDBACK=ja\n");
  RunOptions in_root;
  in_root.environment = {"AUTOGRADER_ROOT=" + ag.string()};
  const auto run = [&] {
    return run_program({"bash", test::source_path("tools/gradescope/run_autograder")}, in_root)
        .status;
  };
  // No answers file: a zero score that says why.
  ASSERT_EQ(run(), 0);
  auto results = nlohmann::json::parse(test::read_file(ag / "results" / "results.json"));
  EXPECT_EQ(results["score"], 0);
  EXPECT_NE(results["output"].get<std::string>().find("No answers file"), std::string::npos);
  // The published answers: full marks, one test per problem, feedback in Japanese.
  fs::copy_file(test::source_path("problems/seeds/answers/001_zbuffer_plane_method.yaml"),
                ag / "submission" / "answers.yaml");
  ASSERT_EQ(run(), 0);
  results = nlohmann::json::parse(test::read_file(ag / "results" / "results.json"));
  EXPECT_EQ(results["score"], 8);
  ASSERT_EQ(results["tests"].size(), 3u);
  for (const auto& t : results["tests"]) {
    EXPECT_EQ(t["status"], "passed");
    EXPECT_EQ(t["score"], t["max_score"]);
  }
  EXPECT_NE(results["tests"][0]["output"].get<std::string>().find("判定"), std::string::npos);
  fs::remove_all(ag);
}

// The ids of a directory's files: read up to the value, taken from the file's name when
// there is none, unreadable files and shared claims noted.
TEST(Batch, IdsAreReadUpToTheirValue) {
  const fs::path dir = test::scratch_dir("batch-ids");
  for (int i = 0; i < 23; ++i)
    test::write_file(dir / fmt::format("f{:02d}.yaml", i),
                     i % 7 == 3 ? std::string("student: [not, an, id]\nanswers: {}\n")
                     : i % 5 == 1
                         ? std::string("student: s1\nstudent: s2\n")  // the first id
                         : fmt::format("student: s{}\nanswers: {{zbuf: {{z: 8}}}}\n", i % 11));
  fs::create_directories(dir / "f99.yaml");  // a directory named like a file: not read
  std::string one;
  for (const BatchEntry& e : collect_submissions(dir.string()))
    one += fmt::format("{}|{}|{}|{}|{}\n", e.source, e.student, e.claimed, e.error.value_or("-"),
                       e.note);
  // The id is read up to its value: the second `student:` is the grading's error to report.
  EXPECT_NE(one.find("f01.yaml|s1|s1|-|"), std::string::npos) << one;
  EXPECT_NE(one.find("f03.yaml|f03||-|"), std::string::npos) << one;   // not an id: the file's name
  EXPECT_NE(one.find("f02.yaml|s2|s2|-|"), std::string::npos) << one;  // read from the file
  EXPECT_NE(one.find("also claims student 's2'"), std::string::npos) << one;  // f02 and f13
  EXPECT_EQ(one.find("f99"), std::string::npos) << one;
  fs::remove_all(dir);
}

// A file saved as some Windows editors save UTF-8 (a byte-order mark, CR LF line ends) is the
// same answers: the same id, score and feedback as the plain file. With the mark, every line
// after `student:` was once lost, and the student was marked as having no answers.
TEST(Batch, AnswersSavedWithAByteOrderMarkGradeLikeThePlainFile) {
  const fs::path dir = test::scratch_dir("batch-bom");
  const std::string answers = "student: s1\nanswers:\n  zbuf: {z: 8}\n";
  std::string windows = "\xEF\xBB\xBF";
  for (const char c : answers) windows += c == '\n' ? std::string("\r\n") : std::string(1, c);
  fs::create_directories(dir / "plain");
  fs::create_directories(dir / "windows");
  test::write_file(dir / "plain" / "a.yaml", answers);
  test::write_file(dir / "windows" / "a.yaml", windows);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  std::vector<BatchRow> rows;
  std::vector<std::string> feedback;
  for (const char* side : {"plain", "windows"}) {
    BatchOptions o;
    o.out_dir = (dir / (std::string(side) + "-out")).string();
    const BatchResult r = grade_batch(set, collect_submissions((dir / side).string()), o);
    ASSERT_EQ(r.rows.size(), 1u) << side;
    rows.push_back(r.rows[0]);
    feedback.push_back(test::read_file(dir / (std::string(side) + "-out") / "feedback" / "s1.md"));
  }
  EXPECT_EQ(rows[1].student, "s1");
  EXPECT_EQ(rows[1].status, "graded") << rows[1].message;
  EXPECT_GT(rows[0].score, 0);
  EXPECT_EQ(rows[1].score, rows[0].score);
  EXPECT_EQ(feedback[1], feedback[0]);
  fs::remove_all(dir);
}

// Reading a class leaves the process single-threaded, so the children grade_batch forks count
// shared references without atomic instructions (with threads here, every child would pay for
// atomic ones, and -j 2 would cost more CPU per student than -j 1). ctest runs each test in a
// process of its own.
TEST(Batch, ReadingAClassLeavesTheProcessSingleThreaded) {
  ASSERT_TRUE(__libc_single_threaded) << "run this test in a process of its own";
  const fs::path dir = test::scratch_dir("batch-single");
  for (int i = 0; i < 40; ++i)
    test::write_file(dir / fmt::format("f{:02d}.yaml", i),
                     fmt::format("student: s{}\nanswers: {{zbuf: {{z: 8}}}}\n", i));
  EXPECT_EQ(collect_submissions(dir.string()).size(), 40u);
  EXPECT_TRUE(__libc_single_threaded);
  fs::remove_all(dir);
}

// A class's files are not held in memory while it is graded: each is read again when graded. A
// file changed after its id was read (another student's answers pasted in, a new id) is an error
// row that says so, never graded under the id read before; a file removed is an error row; the
// others are graded as ever.
TEST(Batch, AFileChangedWhileTheClassIsGradedIsAnErrorRowNotAnotherStudentsGrade) {
  const fs::path dir = test::scratch_dir("batch-changed");
  const fs::path in = make_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const std::vector<BatchEntry> entries = collect_submissions(in.string());
  ASSERT_EQ(entries.size(), 5u);
  for (const BatchEntry& e : entries) {
    EXPECT_TRUE(e.yaml.empty()) << e.source;  // not kept
    EXPECT_EQ(e.read_when_graded, !e.error) << e.source;
  }
  BatchOptions options;
  options.out_dir = (dir / "before").string();
  const BatchResult before = grade_batch(set, entries, options);
  // b_wrong.yaml now holds a's right answers under a's id; the same length or not, it is refused.
  test::write_file(in / "b_wrong.yaml", test::read_file(in / "a_right.yaml"));
  fs::remove(in / "c_broken.yaml");
  options.out_dir = (dir / "after").string();
  const BatchResult after = grade_batch(set, entries, options);
  ASSERT_EQ(after.rows.size(), 5u);
  EXPECT_EQ(after.rows[0].status, "graded");
  EXPECT_DOUBLE_EQ(after.rows[0].score, before.rows[0].score);
  EXPECT_EQ(after.rows[1].student, "s002");
  EXPECT_EQ(after.rows[1].status, "error");
  EXPECT_DOUBLE_EQ(after.rows[1].score, 0);
  EXPECT_NE(after.rows[1].message.find("changed while the class was being graded"),
            std::string::npos)
      << after.rows[1].message;
  EXPECT_EQ(after.rows[2].status, "error");
  EXPECT_EQ(before.rows[1].status, "graded");
  EXPECT_GT(before.rows[1].score, 0);
  // The same text again (even rewritten) grades as before.
  test::write_file(in / "b_wrong.yaml",
                   "student: s002\nanswers:\n  zbuf: {normal: [-1, -1, 1], plane: [1, 1, -1, -6], "
                   "z: 9}\n");
  options.out_dir = (dir / "again").string();
  const BatchResult again = grade_batch(set, entries, options);
  EXPECT_EQ(again.rows[1].status, "graded");
  EXPECT_DOUBLE_EQ(again.rows[1].score, before.rows[1].score);
  fs::remove_all(dir);
}

// The gradebook is written as rows come, in the class's order whatever order they come in:
// the same bytes as the whole text made at once, every row passed on once, in order.
TEST(Batch, GradebookRowsComingInAnyOrderAreWrittenInTheClassOrder) {
  const fs::path dir = test::scratch_dir("batch-stream");
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  std::mt19937 rng(7);
  for (const std::size_t n : {0u, 1u, 7u, 3000u}) {
    std::vector<BatchRow> rows(n);
    for (std::size_t i = 0; i < n; ++i) {
      rows[i].student = fmt::format("s{:05}", i);
      rows[i].status = i % 7 == 3 ? "error" : "graded";
      rows[i].score = static_cast<double>(i % 6);
      rows[i].max_score = 5;
      rows[i].problem_scores = {static_cast<double>(i % 3), 1.5};
      rows[i].message = i % 11 == 0 ? "a note, with \"quotes\"\nand a line break" : "";
      rows[i].source = fmt::format("in/{}.yaml", i);
      rows[i].feedback_stem = rows[i].student;
    }
    std::vector<std::size_t> order(n);
    for (std::size_t i = 0; i < n; ++i) order[i] = i;
    // Nearly in order, as children taking students in turn finish them, and some far out.
    for (std::size_t i = 0; i + 1 < n; i += 2)
      if (rng() % 2) std::swap(order[i], order[i + 1]);
    if (n > 100) std::swap(order[5], order[n - 5]);
    const fs::path out_dir = dir / fmt::format("out{}", n);
    std::vector<std::string> passed;
    {
      OutputTransaction out(out_dir.string(), {"gradebook.csv"});
      GradebookStream book(set, out, "gradebook.csv",
                           [&](BatchRow&& row) { passed.push_back(row.student); });
      for (const std::size_t i : order) book.add(i, rows[i]);
      book.finish();
      out.commit();
    }
    EXPECT_EQ(test::read_file(out_dir / "gradebook.csv"), gradebook_csv(set, rows)) << n;
    ASSERT_EQ(passed.size(), n);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(passed[i], rows[i].student);
  }
  fs::remove_all(dir);
}

// A caller that takes the rows as they come keeps none: the same rows, in order, and the same
// outputs as a batch that keeps them.
TEST(Batch, RowsComeInOrderAndNeedNotBeKept) {
  const fs::path dir = test::scratch_dir("batch-onrow");
  const fs::path in = make_class(dir);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions options;
  options.jobs = 3;
  options.out_dir = (dir / "kept").string();
  const BatchResult kept = grade_batch(set, collect_submissions(in.string()), options);
  std::vector<BatchRow> passed;
  options.keep_rows = false;
  options.on_row = [&](const BatchRow& row) { passed.push_back(row); };
  options.out_dir = (dir / "passed").string();
  const BatchResult none = grade_batch(set, collect_submissions(in.string()), options);
  EXPECT_TRUE(none.rows.empty());
  ASSERT_EQ(passed.size(), kept.rows.size());
  for (std::size_t i = 0; i < passed.size(); ++i) {
    EXPECT_EQ(passed[i].student, kept.rows[i].student);
    EXPECT_EQ(passed[i].status, kept.rows[i].status);
    EXPECT_EQ(passed[i].score, kept.rows[i].score);
    EXPECT_EQ(passed[i].message, kept.rows[i].message);
  }
  EXPECT_TRUE(test::published_tree(dir / "kept") == test::published_tree(dir / "passed"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
