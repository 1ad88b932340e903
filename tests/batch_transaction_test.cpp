// A batch as a transaction: one name per student, a lock per output directory,
// outputs that agree with the gradebook after a kill at any moment, a grading child that dies
// with its parent, and outputs safe to open in a spreadsheet, a Markdown viewer or a terminal.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>
#include <sstream>
#include <thread>

#include "batch/batch.hpp"
#include "batch/csv.hpp"
#include "batch/file_names.hpp"
#include "batch/output_transaction.hpp"
#include "report/feedback.hpp"
#include "report/gradescope.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

const char* const kSet = test::kOneDepthProblemSet;

fs::path scratch(const std::string& name) { return test::scratch_dir("txn_" + name); }

fs::path make_class(const fs::path& dir, int students) {
  const fs::path in = dir / "in";
  fs::create_directories(in);
  for (int i = 0; i < students; ++i)
    test::write_file(in / ("s" + std::to_string(100 + i) + ".yaml"),
                     "student: s" + std::to_string(100 + i) +
                         "\nanswers:\n  zbuf: {z: " + std::to_string(i % 2 ? 8 : 9) + "}\n");
  return in;
}

TEST(FileNames, DifferentIdsNeverShareAName) {
  EXPECT_EQ(file_name_for("a/b"), "a%2Fb");
  EXPECT_EQ(file_name_for("a_b"), "a_b");
  EXPECT_EQ(file_name_for(".."), "%2E.");
  EXPECT_EQ(file_name_for(""), "%");
  EXPECT_EQ(file_name_for("--"), "%2D-");  // no name starts with '-' (an option, a formula)
  EXPECT_EQ(file_name_for("a-b"), "a-b");
  // Property: random ids over a hostile alphabet map to distinct names.
  std::mt19937 rng(15);
  const std::string alphabet = "aA_-./%~ \x1b\xc3\xa9=";
  std::set<std::string> ids, names;
  for (int i = 0; i < 5000; ++i) {
    std::string id;
    for (int k = static_cast<int>(rng() % 6); k >= 0; --k) id += alphabet[rng() % alphabet.size()];
    if (!ids.insert(id).second) continue;
    const std::string name = file_name_for(id);
    EXPECT_TRUE(names.insert(name).second) << "'" << id << "' shares " << name;
    EXPECT_EQ(name.find('/'), std::string::npos);
    EXPECT_NE(name[0], '.');
    EXPECT_NE(name[0], '-');
  }
  // Within a batch, repeats and case-only differences get their own names.
  EXPECT_EQ(unique_file_names({"a-2", "a", "a", "A"}),
            (std::vector<std::string>{"a-2", "a", "a~2", "A~3"}));
  const std::string long_id(400, 'x');
  EXPECT_LE(file_name_for(long_id).size(), 120u);
  EXPECT_NE(file_name_for(long_id), file_name_for(long_id + "y"));
}

TEST(BatchTransaction, IdsThatMapToOneNameEachKeepTheirOwnFeedback) {
  // Ids a-2, a, a once made one student's feedback overwrite another's.
  const fs::path dir = scratch("ids");
  fs::create_directories(dir / "in");
  test::write_file(dir / "in" / "1.yaml", "student: a-2\nanswers:\n  zbuf: {z: 8}\n");
  test::write_file(dir / "in" / "2.yaml", "student: a\nanswers:\n  zbuf: {z: 9}\n");
  test::write_file(dir / "in" / "3.yaml", "student: a\nanswers:\n  zbuf: {z: 7}\n");
  BatchOptions o;
  o.out_dir = (dir / "out").string();
  const BatchResult r = grade_batch(load_problem_set_from_string(kSet, "set.yaml"),
                                    collect_submissions((dir / "in").string()), o);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_EQ(r.rows[0].feedback_stem, "a-2");
  EXPECT_EQ(r.rows[1].feedback_stem, "a");
  EXPECT_EQ(r.rows[2].feedback_stem, "a~2");
  EXPECT_NE(test::read_file(dir / "out" / "feedback" / "a.md").find("9"), std::string::npos);
  EXPECT_NE(test::read_file(dir / "out" / "feedback" / "a~2.md").find("7"), std::string::npos);
  const CsvTable book = parse_csv(test::read_file(dir / "out" / "gradebook.csv"));
  ASSERT_EQ(book.rows.size(), 4u);
  EXPECT_EQ(book.rows[0].fields.back(), "file");
  EXPECT_EQ(book.rows[3].fields.back(), "a~2");
  fs::remove_all(dir);
}

TEST(BatchTransaction, TheGradebookFileColumnNamesAFeedbackPageForEveryId) {
  // Found by fuzz_batch: student "--" had the page --.md, but the gradebook guards a cell that
  // starts with '-' against being read as a formula and wrote '-- in the `file` column, which
  // named no page. No file name starts with '-' now, so the column is the name as it is.
  const fs::path dir = scratch("dash");
  fs::create_directories(dir / "in");
  const std::vector<std::string> ids = {"--", "-x", "=1+1", "@a", "+b", "-5"};
  for (std::size_t i = 0; i < ids.size(); ++i)
    test::write_file(dir / "in" / (std::to_string(i) + ".yaml"),
                     "student: \"" + ids[i] + "\"\nanswers:\n  zbuf: {z: 8}\n");
  BatchOptions o;
  o.out_dir = (dir / "out").string();
  const BatchResult r = grade_batch(load_problem_set_from_string(kSet, "set.yaml"),
                                    collect_submissions((dir / "in").string()), o);
  ASSERT_EQ(r.rows.size(), ids.size());
  const CsvTable book = parse_csv(test::read_file(dir / "out" / "gradebook.csv"));
  ASSERT_FALSE(book.error);
  ASSERT_EQ(book.rows.size(), ids.size() + 1);
  for (std::size_t k = 1; k < book.rows.size(); ++k) {
    const std::string& file = book.rows[k].fields.back();
    EXPECT_TRUE(fs::exists(dir / "out" / "feedback" / (file + ".md"))) << file;
    EXPECT_TRUE(fs::exists(dir / "out" / "feedback" / (file + ".html"))) << file;
  }
  fs::remove_all(dir);
}

TEST(BatchTransaction, ASecondBatchOnTheSameOutputIsRefused) {
  const fs::path dir = scratch("lock");
  const fs::path in = make_class(dir, 2);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  BatchOptions o;
  o.out_dir = (dir / "out").string();
  grade_batch(set, collect_submissions(in.string()), o);
  const std::string before = test::read_file(dir / "out" / "gradebook.csv");
  {
    OutputTransaction held(o.out_dir, {"gradebook.csv"});
    try {
      grade_batch(set, collect_submissions(in.string()), o);
      ADD_FAILURE() << "a locked output directory was written";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("another batch is writing here"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(test::read_file(dir / "out" / "gradebook.csv"), before);
  grade_batch(set, collect_submissions(in.string()), o);  // released with its holder
  fs::remove_all(dir);
}

TEST(BatchTransaction, AnUnwritableOutputIsAnErrorNotAnAbort) {
  const fs::path dir = scratch("unwritable");
  const fs::path in = make_class(dir, 1);
  test::write_file(dir / "file", "a file, not a directory");
  BatchOptions o;
  o.out_dir = (dir / "file" / "out").string();
  EXPECT_THROW(grade_batch(load_problem_set_from_string(kSet, "set.yaml"),
                           collect_submissions(in.string()), o),
               std::runtime_error);
  fs::remove_all(dir);
}

// The published outputs agree with the gradebook: one feedback page and one Gradescope file
// per row, named in its `file` column, and nothing else.
void expect_consistent(const fs::path& out) {
  if (!fs::exists(out / "gradebook.csv")) {
    EXPECT_FALSE(fs::exists(out / "feedback" / "s100.md")) << "outputs without a gradebook";
    return;
  }
  const CsvTable book = parse_csv(test::read_file(out / "gradebook.csv"));
  ASSERT_GE(book.rows.size(), 2u);
  std::set<std::string> listed, on_disk;
  for (std::size_t r = 1; r < book.rows.size(); ++r) listed.insert(book.rows[r].fields.back());
  for (const auto& e : fs::directory_iterator(out / "gradescope"))
    on_disk.insert(e.path().stem().string());
  EXPECT_EQ(listed, on_disk);
  for (const std::string& f : listed) {
    const std::string md = test::read_file(out / "feedback" / (f + ".md"));
    EXPECT_NE(md.find(f), std::string::npos) << f;
  }
}

// A batch of the first `students` files of `in`, each student taking `student_ms` at least (so
// that the kill lands while students are being graded), killed after `kill_ms`.
struct SlowBatch {
  std::size_t jobs = 1;
  std::size_t students = 0;
  int student_ms = 0;
};
void kill_batch(const ProblemSet& set, const fs::path& in, const std::string& out,
                const SlowBatch& slow, int kill_ms) {
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    BatchOptions o;
    o.out_dir = out;
    o.jobs = slow.jobs;
    o.set_for = [&](const ProblemSet& s, const std::string&, std::string&) {
      std::this_thread::sleep_for(std::chrono::milliseconds(slow.student_ms));
      return s;
    };
    std::vector<BatchEntry> entries = collect_submissions(in.string());
    entries.resize(std::min(entries.size(), slow.students));
    grade_batch(set, entries, o);
    _exit(0);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(kill_ms));
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
}

TEST(BatchTransaction, AKillAtAnyMomentLeavesConsistentOutputsAndNoGradingChild) {
  const fs::path dir = scratch("kill");
  const fs::path in = make_class(dir, 12);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const std::string out = (dir / "out").string();
  for (int round = 0; round < 6; ++round) {
    // Every other run grades a different class size, so the outputs differ between runs.
    kill_batch(set, in, out, {.jobs = 1, .students = round % 2 ? 7u : 12u, .student_ms = 20},
               40 + 45 * round);
    expect_consistent(out);
    // The killed batch's grading child held the lock too: a new batch gets it within a moment
    // only because that child died with its parent.
    bool locked = true;
    for (int tries = 0; tries < 50 && locked; ++tries) {
      try {
        OutputTransaction probe(out, {"gradebook.csv"});
        locked = false;
      } catch (const std::runtime_error&) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
    EXPECT_FALSE(locked) << "round " << round << ": the grading child outlived its parent";
  }
  // A last complete run publishes, and leaves its own run directory and the one it replaced
  // (kept for the next run to be written into), none of what the killed runs left.
  std::error_code none;
  const fs::path before = fs::read_symlink(dir / "out" / ".frustum" / "current", none);
  BatchOptions o;
  o.out_dir = out;
  grade_batch(set, collect_submissions(in.string()), o);
  expect_consistent(out);
  std::set<std::string> runs;
  for (const auto& e : fs::directory_iterator(dir / "out" / ".frustum"))
    if (e.path().filename().string().rfind("run-", 0) == 0) runs.insert(e.path().filename());
  std::set<std::string> expected{fs::read_symlink(dir / "out" / ".frustum" / "current")};
  if (!before.empty()) expected.insert(before.string());
  EXPECT_EQ(runs, expected);
  fs::remove_all(dir);
}

// write_back() has the disk write what is there so far; it publishes nothing. Files written
// after it, and a file taken back after it, are published as commit() finds them; a run that is
// written back but never committed leaves the published outputs as they were.
TEST(BatchTransaction, WritingBackEarlyPublishesNothingAndLosesNothing) {
  const fs::path dir = scratch("write_back");
  const std::string out = (dir / "out").string();
  {
    OutputTransaction t(out, {"gradebook.csv", "feedback"});
    t.write("feedback/a.md", "first\n");
    t.write("feedback/gone.md", "taken back\n");
    t.write_back();
    EXPECT_FALSE(fs::exists(dir / "out" / "feedback")) << "write_back() published the run";
    t.remove("feedback/gone.md");
    t.write("feedback/a.md", "second\n");  // rewritten after the write-back
    t.write("feedback/b.md", "after\n");
    t.write("gradebook.csv", "student\na\nb\n");
    t.write_back();
    t.commit();
  }
  EXPECT_EQ(test::read_file(dir / "out" / "feedback" / "a.md"), "second\n");
  EXPECT_EQ(test::read_file(dir / "out" / "feedback" / "b.md"), "after\n");
  EXPECT_FALSE(fs::exists(dir / "out" / "feedback" / "gone.md"));
  {
    OutputTransaction t(out, {"gradebook.csv", "feedback"});
    t.write("feedback/a.md", "never published\n");
    t.write("gradebook.csv", "student\n");
    t.write_back();
  }  // no commit()
  EXPECT_EQ(test::read_file(dir / "out" / "feedback" / "a.md"), "second\n");
  EXPECT_EQ(test::read_file(dir / "out" / "gradebook.csv"), "student\na\nb\n");
  int runs = 0;
  for (const auto& e : fs::directory_iterator(dir / "out" / ".frustum"))
    runs += e.path().filename().string().rfind("run-", 0) == 0;
  EXPECT_EQ(runs, 1) << "the uncommitted run was left behind";
  fs::remove_all(dir);
}

// The points of write-back of a class: each eighth, then the first rows that leave fewer than a
// sixteenth, a thirty-second and a sixty-fourth of the class; none for a small class, none at
// the last row (the sync before publishing is that one).
TEST(BatchTransaction, AClassIsWrittenBackAtEachEighthAndThenCloserToItsEnd) {
  const auto points = [](std::size_t n) {
    std::vector<std::size_t> at;
    for (std::size_t done = 0; done <= n + 1; ++done)
      if (write_back_due(done, n)) at.push_back(done);
    return at;
  };
  EXPECT_EQ(points(1000),
            (std::vector<std::size_t>{125, 250, 375, 500, 625, 750, 875, 938, 969, 985}));
  EXPECT_EQ(points(64), (std::vector<std::size_t>{8, 16, 24, 32, 40, 48, 56, 61, 63}));
  EXPECT_TRUE(points(63).empty());
  EXPECT_TRUE(points(1).empty());
  // Every class: at most eleven points, strictly before the last row, the last one leaving
  // at most a sixty-fourth of the class (rounded up) to the final sync.
  for (std::size_t n = kWriteBackClass; n <= 5000; n += 7) {
    const std::vector<std::size_t> at = points(n);
    ASSERT_FALSE(at.empty()) << n;
    EXPECT_LE(at.size(), 11u) << n;
    EXPECT_LT(at.back(), n) << n;
    EXPECT_LE((n - at.back()) * kLastWriteBack, n + kLastWriteBack) << n;
  }
}

// A class large enough to be written back to disk while it is graded (64 students or more):
// killed at any moment it leaves consistent outputs, and a whole run publishes every student.
TEST(BatchTransaction, AClassWrittenBackWhileGradedStaysConsistentWhenKilled) {
  const fs::path dir = scratch("write_back_kill");
  const fs::path in = make_class(dir, 80);
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const std::string out = (dir / "out").string();
  for (int round = 0; round < 4; ++round) {
    kill_batch(set, in, out, {.jobs = 2, .students = round % 2 ? 70u : 80u, .student_ms = 3},
               30 + 40 * round);
    expect_consistent(out);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));  // the children die with it
  }
  BatchOptions o;
  o.out_dir = out;
  o.jobs = 2;
  const BatchResult r = grade_batch(set, collect_submissions(in.string()), o);
  ASSERT_EQ(r.rows.size(), 80u);
  expect_consistent(out);
  const CsvTable book = parse_csv(test::read_file(dir / "out" / "gradebook.csv"));
  EXPECT_EQ(book.rows.size(), 81u);
  for (int i = 0; i < 80; ++i)
    EXPECT_TRUE(fs::exists(dir / "out" / "gradescope" / ("s" + std::to_string(100 + i) + ".json")))
        << i;
  fs::remove_all(dir);
}

TEST(BatchTransaction, ASymlinkLoopIsARowNotAnAbort) {
  const fs::path dir = scratch("loop");
  const fs::path in = make_class(dir, 2);
  fs::create_symlink("loop.yaml", in / "loop.yaml");
  BatchOptions o;
  o.out_dir = (dir / "out").string();
  const BatchResult r = grade_batch(load_problem_set_from_string(kSet, "set.yaml"),
                                    collect_submissions(in.string()), o);
  ASSERT_EQ(r.rows.size(), 3u);
  EXPECT_EQ(r.rows[0].student, "loop");
  EXPECT_EQ(r.rows[0].status, "error");
  EXPECT_NE(r.rows[0].message.find("symbolic links"), std::string::npos) << r.rows[0].message;
  fs::remove_all(dir);
}

TEST(BatchTransaction, TheRosterSaysWhoseFileItIs) {
  // Ids came from the files themselves, so any file could claim any id.
  const fs::path dir = scratch("roster");
  fs::create_directories(dir / "in");
  test::write_file(dir / "in" / "s1.yaml", "student: s1\nanswers:\n  zbuf: {z: 8}\n");
  test::write_file(dir / "in" / "s2.yaml", "student: s1\nanswers:\n  zbuf: {z: 9}\n");  // claims s1
  test::write_file(dir / "in" / "x.yaml", "student: x\nanswers:\n  zbuf: {z: 8}\n");
  const std::vector<BatchEntry> entries =
      apply_roster(collect_submissions((dir / "in").string()), {"s1", "s2", "s3"}, "roster.csv");
  BatchOptions o;
  o.out_dir = (dir / "out").string();
  const BatchResult r = grade_batch(load_problem_set_from_string(kSet, "set.yaml"), entries, o);
  ASSERT_EQ(r.rows.size(), 4u);
  EXPECT_EQ(r.rows[0].student, "s1");
  EXPECT_EQ(r.rows[0].status, "graded");
  EXPECT_DOUBLE_EQ(r.rows[0].score, 1);
  EXPECT_EQ(r.rows[1].student, "s2");
  EXPECT_EQ(r.rows[1].status, "graded");
  EXPECT_DOUBLE_EQ(r.rows[1].score, 0);
  EXPECT_NE(r.rows[1].message.find("the file says student 's1'"), std::string::npos)
      << r.rows[1].message;
  EXPECT_EQ(r.rows[2].student, "s3");
  EXPECT_EQ(r.rows[2].status, "error");
  EXPECT_NE(r.rows[2].message.find("no answers file s3.yaml"), std::string::npos)
      << r.rows[2].message;
  EXPECT_EQ(r.rows[3].status, "error");
  EXPECT_NE(r.rows[3].message.find("not on the roster"), std::string::npos) << r.rows[3].message;
  EXPECT_NE(test::read_file(dir / "out" / "feedback" / "s2.md").find("s2"), std::string::npos);
  fs::remove_all(dir);
}

TEST(OutputHygiene, CsvCellsCannotBeFormulas) {
  for (const char* hostile : {"=HYPERLINK(\"http://x\",\"y\")", "+cmd|' /C calc'!A0",
                              "@SUM(1+1)*cmd", "-2+3", "\t=1", "\r=1"})
    EXPECT_EQ(csv_neutralise(hostile), std::string("'") + hostile) << hostile;
  for (const char* plain : {"-6", "+1.5e3", "-0.25", "s001", "", "x = -6"})
    EXPECT_EQ(csv_neutralise(plain), plain);
  const CsvTable t = parse_csv(csv_row({"=1+1", "-6"}));
  EXPECT_EQ(t.rows[0].fields, (std::vector<std::string>{"'=1+1", "-6"}));
  // A first cell starting with U+FEFF survives (it was taken for a byte-order mark).
  const CsvTable bom = parse_csv(csv_row({"\xEF\xBB\xBFid", "1"}));
  EXPECT_EQ(bom.rows[0].fields, (std::vector<std::string>{"\xEF\xBB\xBFid", "1"}));
}

TEST(OutputHygiene, MarkdownAndGradescopeShowHostileTextLiterally) {
  GradeReport r =
      grade(load_problem_set_from_string(kSet, "set.yaml"),
            load_submission_from_string("student: \"<img src=x onerror=alert(1)>\"\nanswers:\n"
                                        "  zbuf: {z: \"<script>alert(1)</script>\"}\n",
                                        "a.yaml"));
  const std::string md = render_feedback_markdown(r);
  EXPECT_EQ(md.find("<img"), std::string::npos) << md;
  EXPECT_EQ(md.find("<script"), std::string::npos) << md;
  EXPECT_NE(md.find("&lt;img"), std::string::npos) << md;
  const std::string gs = gradescope_results(r).dump();
  EXPECT_EQ(gs.find("<img"), std::string::npos);
  EXPECT_EQ(gs.find("<script"), std::string::npos);
  EXPECT_EQ(markdown_escape("[x](javascript:alert(1)) *b* `c` |"),
            "\\[x\\](javascript:alert(1)) \\*b\\* \\`c\\` \\|");
  // Control characters are shown, not dropped: an id's ESC is seen.
  EXPECT_EQ(markdown_code("a`b\x1b[2J"), "aʼb\\u001B[2J");
  EXPECT_EQ(markdown_escape("a\x1b[2J\x93"), "a\\\\u001B\\[2J\\\\x93");
}

}  // namespace
}  // namespace frustum
