// Batch grading under faults: a malformed, empty, huge, hostile or slow submission
// gets its own row with a reason (and a time limit), the gradebook lists every student, no
// temporary file is left behind, and a second run over the same inputs writes byte-identical
// outputs.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "batch/batch.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

// A time limit short enough for a fast test, long enough for seed 001 under sanitizers.
constexpr double kTestTimeout = 3.0;

class BatchFaults : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("frustum_batch_fault_" +
             std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
             std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
    fs::create_directories(root_ / "in");
    const fs::path in = root_ / "in";
    test::write_file(
        in / "a_good.yaml",
        test::read_file(test::source_path("problems/seeds/answers/001_zbuffer_plane_method.yaml")));
    test::write_file(in / "b_malformed.yaml",
                     "student: malformed\nanswers:\n  seed001-pixel-z:\n    z: [8\n");
    test::write_file(in / "c_empty.yaml", "");
    test::write_file(in / "d_huge.yaml",
                     "student: huge\nanswers: {}\n" + std::string(kMaxSubmissionBytes, '#'));
    test::write_file(in / "e_slow.yaml", "student: slow\nanswers:\n  seed001-pixel-z: {z: 8}\n");
    test::write_file(in / "f_hostile.yaml",
                     "student: hostile\nanswers:\n  seed001-pixel-z:\n    z: \"" +
                         std::string(100000, '(') + "8" + std::string(100000, ')') +
                         "\"\n    plane: \"x + y - z = -6\"\n    inside: \"\xff\xfe\"\n");
    test::write_file(in / "g_yaml_bomb.yaml", "student: bomb\nanswers: " + std::string(20000, '[') +
                                                  std::string(20000, ']') + "\n");
    set_ = load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
    ASSERT_TRUE(set_.all_errors().empty());
  }
  void TearDown() override { fs::remove_all(root_); }

  BatchResult run(const std::string& out) {
    BatchOptions o;
    o.out_dir = (root_ / out).string();
    o.timeout_seconds = kTestTimeout;
    // Stands in for a submission that takes too long: the grader must not wait for it.
    o.set_for = [](const ProblemSet& s, const std::string& student, std::string&) {
      if (student == "slow") std::this_thread::sleep_for(std::chrono::seconds(60));
      return s;
    };
    return grade_batch(set_, collect_submissions((root_ / "in").string()), o);
  }

  fs::path root_;
  ProblemSet set_;
};

// One test, two runs: the time limit costs kTestTimeout per run.
TEST_F(BatchFaults, EveryStudentHasARowWithAReasonAndASecondRunIsByteIdentical) {
  const BatchResult r = run("out");
  ASSERT_EQ(r.rows.size(), 7u);
  std::map<std::string, BatchRow> by;
  for (const BatchRow& row : r.rows) by[row.student] = row;

  EXPECT_EQ(by.at("seed001-published").status, "graded");
  EXPECT_DOUBLE_EQ(by.at("seed001-published").score, by.at("seed001-published").max_score);

  // Malformed and empty files get an error row naming the file's mistake; a file broken below
  // its `student:` line is that student's row.
  EXPECT_EQ(by.at("malformed").status, "error");
  EXPECT_NE(by.at("malformed").message.find("invalid YAML"), std::string::npos)
      << by.at("malformed").message;
  EXPECT_EQ(by.at("c_empty").status, "error");
  EXPECT_NE(by.at("c_empty").message.find("empty"), std::string::npos) << by.at("c_empty").message;

  EXPECT_EQ(by.at("d_huge").status, "error");
  EXPECT_NE(by.at("d_huge").message.find("larger than the limit"), std::string::npos);

  EXPECT_EQ(by.at("slow").status, "timeout");
  EXPECT_NE(by.at("slow").message.find("time limit"), std::string::npos) << by.at("slow").message;

  // Hostile answers are unparseable, not fatal: the rest of the file still earns its points.
  EXPECT_EQ(by.at("hostile").status, "graded") << by.at("hostile").message;
  EXPECT_GT(by.at("hostile").score, 0);

  EXPECT_EQ(by.at("bomb").status, "error");
  EXPECT_NE(by.at("bomb").message.find("nested too deeply"), std::string::npos)
      << by.at("bomb").message;
  for (const BatchRow& row : r.rows) {
    if (row.status != "graded") {
      EXPECT_DOUBLE_EQ(row.score, 0) << row.student;
    }
  }

  // The gradebook lists every student; every output was renamed into place.
  const std::string book = test::read_file(root_ / "out" / "gradebook.csv");
  for (const char* s :
       {"seed001-published", "b_malformed", "c_empty", "d_huge", "slow", "hostile", "g_yaml_bomb"})
    EXPECT_NE(book.find(s), std::string::npos) << s << " missing from\n" << book;
  for (const auto& [path, text] : test::published_tree(root_ / "out")) {
    EXPECT_NE(fs::path(path).filename().string()[0], '.') << "a temporary file was left: " << path;
    EXPECT_FALSE(text.empty()) << path;
  }

  run("second");
  const auto first = test::published_tree(root_ / "out");
  const auto second = test::published_tree(root_ / "second");
  ASSERT_FALSE(first.empty());
  ASSERT_EQ(first.size(), second.size());
  for (const auto& [path, text] : first) {
    ASSERT_TRUE(second.count(path)) << path;
    EXPECT_EQ(text, second.at(path)) << path << " differs between runs";
  }
}

}  // namespace
}  // namespace frustum
