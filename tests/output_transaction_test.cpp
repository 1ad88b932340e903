// Grading again into the same output directory: the run before the published one is written over
// in place (no file deleted, none created), and what is published is exactly what a grading into
// a fresh directory publishes — whatever the kept run held (longer or shorter files, files of
// students no longer in the class, a file linked elsewhere, a planted symlink).
#include "batch/output_transaction.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <unordered_set>
#include <vector>

#include "batch/batch.hpp"
#include "solver/problem/problem_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratch_dir("reuse_" + name); }

ino_t inode_of(const fs::path& p) {
  struct stat st {};
  return ::lstat(p.c_str(), &st) == 0 ? st.st_ino : 0;
}

int run_directories(const fs::path& out) {
  int runs = 0;
  for (const auto& e : fs::directory_iterator(out / ".frustum"))
    runs += e.path().filename().string().rfind("run-", 0) == 0;
  return runs;
}

// One run: `files` declared, each written with its content.
void publish(const fs::path& out, const std::map<std::string, std::string>& files,
             bool declare = true) {
  std::unordered_set<std::string> names;
  for (const auto& [f, _] : files) names.insert(f);
  OutputTransaction t(out.string(), {"gradebook.csv", "feedback"},
                      declare ? std::optional(names) : std::nullopt);
  for (const auto& [f, content] : files) t.write(f, content);
  t.commit();
}

TEST(OutputTransaction, TheRunBeforeIsKeptAndTheNextRunIsWrittenIntoIt) {
  const fs::path dir = scratch("kept");
  const fs::path out = dir / "out";
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "first\n"}});
  const fs::path first = fs::read_symlink(out / ".frustum" / "current");
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "second\n"}});
  // The first run is kept beside the published one, whole.
  EXPECT_EQ(run_directories(out), 2);
  EXPECT_EQ(test::read_file(out / ".frustum" / first / "feedback" / "a.md"), "first\n");
  const ino_t kept = inode_of(out / ".frustum" / first / "feedback" / "a.md");
  // The third run is the first one's directory, its file written where it lay.
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "third\n"}});
  EXPECT_EQ(run_directories(out), 2);
  EXPECT_EQ(test::read_file(out / "feedback" / "a.md"), "third\n");
  EXPECT_EQ(inode_of(out / "feedback" / "a.md"), kept);
  EXPECT_EQ(test::read_file(out / ".frustum" / "run-2" / "feedback" / "a.md"), "second\n");
  // A run that names no files gets a fresh directory; the kept run is removed first.
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "fourth\n"}}, false);
  EXPECT_EQ(test::read_file(out / "feedback" / "a.md"), "fourth\n");
  EXPECT_NE(inode_of(out / "feedback" / "a.md"), kept);
  EXPECT_EQ(run_directories(out), 2);
  fs::remove_all(dir);
}

// Lengths around the block size, written over every other length: the published file is the
// new content exactly (no old bytes after it, no zeros of the padding).
TEST(OutputTransaction, AFileWrittenOverInPlaceHoldsExactlyItsNewContent) {
  const fs::path dir = scratch("lengths");
  const fs::path out = dir / "out";
  const std::vector<std::size_t> lengths = {0, 1, 100, 4095, 4096, 4097, 8192, 12000, 70000};
  for (const std::size_t before : lengths) {
    for (const std::size_t after : lengths) {
      const std::string old_text(before, 'o');
      std::string new_text;
      for (std::size_t i = 0; i < after; ++i) new_text += static_cast<char>('a' + i % 26);
      publish(out, {{"feedback/f.md", old_text}});  // kept by the next run…
      publish(out, {{"feedback/f.md", "between"}});
      publish(out, {{"feedback/f.md", new_text}});  // …which this one writes over
      EXPECT_EQ(test::read_file(out / "feedback" / "f.md"), new_text)
          << before << " bytes written over by " << after;
    }
  }
  fs::remove_all(dir);
}

// A first grading of students a and b (b's page in a subdirectory too), graded again below
// with fewer files.
const std::map<std::string, std::string> kTwoStudents = {{"gradebook.csv", "a,b\n"},
                                                         {"feedback/a.md", "a\n"},
                                                         {"feedback/b.md", "b\n"},
                                                         {"feedback/sub/c.md", "c\n"}};

TEST(OutputTransaction, WhatTheKeptRunHeldBeyondThisRunsFilesIsNotPublished) {
  const fs::path dir = scratch("stale");
  const fs::path out = dir / "out";
  publish(out, kTwoStudents);
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "a\n"}});
  // Something else put into the kept run by hand.
  const fs::path kept = out / ".frustum" / "run-1";
  test::write_file(kept / "notes.txt", "x");
  fs::create_directories(kept / "feedback" / "b.md.d");
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "again\n"}});
  // The students' files of the first grading are gone; what Frustum did not write is set aside.
  EXPECT_EQ(
      test::published_tree(out),
      (std::map<std::string, std::string>{
          {"feedback/a.md", "again\n"}, {"gradebook.csv", "a\n"}, {"set-aside/notes.txt", "x"}}));
  EXPECT_FALSE(fs::exists(out / ".frustum" / "run-3" / "notes.txt"));
  fs::remove_all(dir);
}

// Nothing Frustum did not write is deleted: a gradebook and notes that were in the output
// directory before the first grading, and notes put into the published feedback/ by hand, are
// moved to set-aside/ (each said), whatever gradings follow; Frustum's own files of a student no
// longer in the class are deleted.
TEST(OutputTransaction, FilesFrustumDidNotWriteAreSetAsideNeverDeleted) {
  const fs::path dir = scratch("instructor");
  const fs::path out = dir / "out";
  fs::create_directories(out / "feedback");
  test::write_file(out / "gradebook.csv", "my own marks\n");
  test::write_file(out / "feedback" / "notes.txt", "talk to b\n");
  test::write_file(out / "README.txt", "beside the outputs: never touched\n");
  std::vector<std::pair<std::string, std::string>> said;
  const auto grade = [&](const std::map<std::string, std::string>& files) {
    std::unordered_set<std::string> names;
    for (const auto& [name, text] : files) names.insert(name);
    OutputTransaction t(out.string(), {"gradebook.csv", "feedback"}, names);
    for (const auto& [name, text] : files) t.write(name, text);
    t.commit();
    said.insert(said.end(), t.set_aside().begin(), t.set_aside().end());
  };
  grade(kTwoStudents);
  ASSERT_EQ(said.size(), 2u);
  EXPECT_EQ(said[0], std::pair((out / "gradebook.csv").string(),
                               (out / "set-aside" / "gradebook.csv").string()));
  EXPECT_EQ(said[1],
            std::pair((out / "feedback").string(), (out / "set-aside" / "feedback").string()));
  // Notes written through the published directory, then three more gradings with fewer students.
  test::write_file(out / "feedback" / "later.txt", "written by hand\n");
  for (int i = 0; i < 3; ++i) grade({{"gradebook.csv", "a\n"}, {"feedback/a.md", "a\n"}});
  EXPECT_EQ(said.size(), 3u);
  EXPECT_EQ(test::published_tree(out), (std::map<std::string, std::string>{
                                           {"README.txt", "beside the outputs: never touched\n"},
                                           {"feedback/a.md", "a\n"},
                                           {"gradebook.csv", "a\n"},
                                           {"set-aside/feedback/later.txt", "written by hand\n"},
                                           {"set-aside/feedback/notes.txt", "talk to b\n"},
                                           {"set-aside/gradebook.csv", "my own marks\n"}}));
  // A second file of the same name set aside later keeps the first: gradebook~2.csv.
  fs::remove(out / "gradebook.csv");
  test::write_file(out / "gradebook.csv", "marks again\n");
  grade({{"gradebook.csv", "a\n"}});
  EXPECT_EQ(test::read_file(out / "set-aside" / "gradebook~2.csv"), "marks again\n");
  EXPECT_EQ(test::read_file(out / "set-aside" / "gradebook.csv"), "my own marks\n");
  fs::remove_all(dir);
}

// Another section graded into the same directory: the run it replaces keeps only the files the
// new run has too, so the first section's pages do not stay behind under .frustum/.
TEST(OutputTransaction, TheReplacedRunKeepsOnlyTheFilesTheNewRunHas) {
  const fs::path dir = scratch("sections");
  const fs::path out = dir / "out";
  publish(out, kTwoStudents);
  const fs::path first = out / ".frustum" / fs::read_symlink(out / ".frustum" / "current");
  publish(out, {{"gradebook.csv", "a\n"}, {"feedback/a.md", "a again\n"}});
  EXPECT_EQ(test::read_file(first / "feedback" / "a.md"), "a\n");  // the previous grading of a
  EXPECT_FALSE(fs::exists(first / "feedback" / "b.md"));
  EXPECT_FALSE(fs::exists(first / "feedback" / "sub"));
  // A run that does not name its files leaves the run it replaces whole (and the next run that
  // names its files writes over it after clearing it).
  publish(out, {{"gradebook.csv", "z\n"}, {"feedback/z.md", "z\n"}}, false);
  const fs::path second = out / ".frustum" / "run-2";
  EXPECT_EQ(test::read_file(second / "feedback" / "a.md"), "a again\n");
  fs::remove_all(dir);
}

// A file of the kept run that is also linked elsewhere (a copy made with `cp -al`) keeps its
// content there; a symlink put in the kept run is not followed.
TEST(OutputTransaction, LinksIntoTheKeptRunAreNotWrittenThrough) {
  const fs::path dir = scratch("links");
  const fs::path out = dir / "out";
  publish(out, {{"feedback/a.md", "kept a\n"}, {"feedback/b.md", "kept b\n"}});
  publish(out, {{"feedback/a.md", "2\n"}, {"feedback/b.md", "2\n"}});
  const fs::path kept = out / ".frustum" / "run-1" / "feedback";
  fs::create_hard_link(kept / "a.md", dir / "backup-a.md");
  test::write_file(dir / "elsewhere.md", "not ours\n");
  fs::remove(kept / "b.md");
  fs::create_symlink(dir / "elsewhere.md", kept / "b.md");
  publish(out, {{"feedback/a.md", "new a\n"}, {"feedback/b.md", "new b\n"}});
  EXPECT_EQ(test::read_file(out / "feedback" / "a.md"), "new a\n");
  EXPECT_EQ(test::read_file(out / "feedback" / "b.md"), "new b\n");
  // A pipe and a directory put where files were, after the run began (the transaction made,
  // nothing written yet): replaced by files, the pipe never opened for writing (that would wait
  // for a reader).
  {
    publish(out, {{"feedback/a.md", "4\n"}, {"feedback/b.md", "4\n"}});
    std::unordered_set<std::string> names{"feedback/a.md", "feedback/b.md"};
    OutputTransaction t(out.string(), {"feedback"}, names);
    ASSERT_TRUE(t.reused());
    fs::path run;  // the run being written: the highest number
    for (const auto& e : fs::directory_iterator(out / ".frustum"))
      if (e.path().filename().string().rfind("run-", 0) == 0 &&
          (run.empty() || std::stoi(e.path().filename().string().substr(4)) >
                              std::stoi(run.filename().string().substr(4))))
        run = e.path();
    ASSERT_TRUE(fs::exists(run / "feedback" / "a.md")) << run;
    fs::remove(run / "feedback" / "a.md");
    ASSERT_EQ(::mkfifo((run / "feedback" / "a.md").c_str(), 0644), 0);
    fs::remove(run / "feedback" / "b.md");
    fs::create_directories(run / "feedback" / "b.md" / "inside");
    t.write("feedback/a.md", "5 a\n");
    t.write("feedback/b.md", "5 b\n");
    t.commit();
  }
  EXPECT_EQ(test::read_file(out / "feedback" / "a.md"), "5 a\n");
  EXPECT_EQ(test::read_file(out / "feedback" / "b.md"), "5 b\n");
  EXPECT_EQ(test::read_file(dir / "backup-a.md"), "kept a\n");
  EXPECT_EQ(test::read_file(dir / "elsewhere.md"), "not ours\n");
  EXPECT_FALSE(fs::is_symlink(out / ".frustum" / "run-3" / "feedback" / "b.md"));
  fs::remove_all(dir);
}

const char* kSet = R"(problems:
  - id: zbuf
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    ask: [z, plane]
)";

// A class whose student i answers z = 8 (right) or something else (wrong, so that the page
// carries a derivation) by `pattern`, students first … first + count − 1.
fs::path make_class(const fs::path& dir, int first, int count, int pattern) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (int i = first; i < first + count; ++i)
    test::write_file(dir / ("s" + std::to_string(i) + ".yaml"),
                     "student: s" + std::to_string(i) +
                         "\nanswers:\n  zbuf: {z: " + std::to_string((i + pattern) % 3 ? 8 : 7) +
                         ((i + pattern) % 2 ? ", plane: [1, 1, -1, -6]" : "") + "}\n");
  return dir;
}

std::map<std::string, std::string> graded(const ProblemSet& set, const fs::path& in,
                                          const fs::path& out, std::size_t jobs) {
  BatchOptions o;
  o.out_dir = out.string();
  o.jobs = jobs;
  grade_batch(set, collect_submissions(in.string()), o);
  return test::published_tree(out);
}

// The whole batch, three times into one directory with the class changing between (students
// gone, students new, answers changed so that pages grow and shrink): each time the published
// outputs are byte for byte those of a grading into a fresh directory, and from the third time
// on no file of a student still in the class is made anew.
TEST(OutputTransaction, GradingAgainPublishesWhatAFreshGradingPublishes) {
  const fs::path dir = scratch("regrade");
  const ProblemSet set = load_problem_set_from_string(kSet, "set.yaml");
  const fs::path out = dir / "out";
  const std::vector<std::array<int, 3>> classes = {
      {100, 30, 0}, {100, 30, 1}, {105, 30, 2}, {95, 20, 1}, {95, 40, 0}};
  std::vector<std::map<std::string, ino_t>> inodes;  // per round: published file → inode
  for (std::size_t round = 0; round < classes.size(); ++round) {
    const auto [first, count, pattern] = classes[round];
    const fs::path in = make_class(dir / "in", first, count, pattern);
    const std::size_t jobs = 1 + round % 2;
    const auto again = graded(set, in, out, jobs);
    const auto fresh = graded(set, in, dir / ("fresh" + std::to_string(round)), jobs);
    EXPECT_EQ(again, fresh) << "round " << round;
    int pages = 0;
    for (const auto& [file, _] : again) pages += file.rfind("feedback/", 0) == 0;
    EXPECT_EQ(pages, 2 * count) << "round " << round;
    inodes.emplace_back();
    for (const auto& [file, _] : again) inodes.back()[file] = inode_of(fs::canonical(out / file));
    // Written in place: a file has the inode it had when the kept run (two rounds before) was
    // published, if the round between had that file too (else it was cleared from the kept run
    // when the round between was published).
    if (round < 2) continue;
    int same = 0, compared = 0;
    for (const auto& [file, inode] : inodes[round - 2])
      if (const auto it = inodes[round].find(file);
          it != inodes[round].end() && inodes[round - 1].count(file)) {
        ++compared;
        same += it->second == inode;
      }
    EXPECT_GT(compared, count / 2) << "round " << round;
    EXPECT_EQ(same, compared) << "round " << round;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum
