// Files that are not YAML text at all, refused before anything is parsed: another encoding,
// a FIFO, a device, a directory, a file over the size limit.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "grader/grade.hpp"
#include "solver/input/yaml_document.hpp"
#include "solver/problem/problem_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

TEST(BadInputFiles, Utf16IsNamedNotMisread) {
  // yaml-cpp read UTF-16 as "unknown escape character: o".
  const Submission s =
      load_submission(test::source_path("tests/bad_inputs/files/utf16_answers.yaml"));
  ASSERT_EQ(s.errors.size(), 1u);
  EXPECT_EQ(s.errors[0].message, "the file is UTF-16 text: save it as UTF-8");
  EXPECT_EQ(s.errors[0].where.line, 1);
  const ProblemSet set =
      load_problem_set(test::source_path("tests/bad_inputs/files/utf16_no_bom_set.yaml"));
  ASSERT_FALSE(set.all_errors().empty());
  EXPECT_NE(set.all_errors()[0].message.find("UTF-16"), std::string::npos);
}

TEST(BadInputFiles, FifoDeviceAndDirectoryAreRefusedWithoutBlocking) {
  const fs::path dir = fs::temp_directory_path() / ("frustum-files-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string fifo = (dir / "answers.yaml").string();
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string text;
  // A FIFO with no writer would block `grade` forever, and /dev/zero would fill the memory.
  for (const std::string& path : {fifo, std::string("/dev/zero"), dir.string()}) {
    const std::optional<Diagnostic> d = read_text_file(path, kMaxYamlFileBytes, text);
    ASSERT_TRUE(d.has_value()) << path;
    EXPECT_EQ(d->where.file, path);
  }
  EXPECT_NE(read_text_file(fifo, 100, text)->message.find("not a regular file"), std::string::npos);
  fs::remove_all(dir);
}

TEST(BadInputFiles, SizeIsCheckedBeforeReading) {
  const fs::path file =
      fs::temp_directory_path() / ("frustum-big-" + std::to_string(getpid()) + ".yaml");
  std::ofstream(file) << std::string(2000, '#');
  std::string text;
  const std::optional<Diagnostic> d = read_text_file(file.string(), 1000, text);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->message.find("larger than"), std::string::npos);
  EXPECT_TRUE(text.empty());
  EXPECT_FALSE(read_text_file(file.string(), 2000, text).has_value());
  EXPECT_EQ(text.size(), 2000u);
  fs::remove(file);
}

}  // namespace
}  // namespace frustum
