// The course a running server serves follows its files: a set changed on disk is served as it
// is now from the next look on, a request keeps the course it began with, a file that no longer
// loads leaves its set as it was (its errors reported once), and an unchanged file is not read
// into a new course.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <mutex>

#include "server/live_course.hpp"
#include "server/tokens.hpp"
#include "test_util.hpp"

namespace frustum::server {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSet = R"(title: "Depth"
problems:
  - id: zbuf
    kind: depth_at_pixel
    text: "Find the z value of pixel {pixel}."
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
    ask: [z]
)";

TEST(LiveCourse, ASetChangedOnDiskIsServedAsItIsNow) {
  const fs::path dir = fs::temp_directory_path() / ("frustum-live-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  test::write_file(dir / "week1.yaml", kSet);
  std::vector<std::vector<Diagnostic>> reported;
  std::mutex exact_math;
  auto live = std::make_unique<LiveCourse>(
      load_course(dir.string(), {"alice"}), exact_math, 1000,
      [&](const std::vector<Diagnostic>& errors) { reported.push_back(errors); });
  const std::shared_ptr<const Course> before = live->at(0);
  ASSERT_EQ(before->sets.size(), 1u);
  EXPECT_EQ(before->sets[0].version, sha256_hex(kSet));
  EXPECT_EQ(live->at(10).get(), before.get());  // nothing changed: the same course

  std::string edited = kSet;
  edited.replace(edited.find("pixel: [1, 1]"), 13, "pixel: [1, 2]");
  test::write_file(dir / "week1.yaml", edited);
  EXPECT_EQ(live->at(500).get(), before.get());  // not looked at again within the second
  const std::shared_ptr<const Course> after = live->at(1000);
  EXPECT_EQ(after->find("week1")->version, sha256_hex(edited));
  EXPECT_EQ(after->find("week1")->set.problems[0].given_node["pixel"][1].Scalar(), "2");
  // The request that began before the change still reads the set it began with.
  EXPECT_EQ(before->find("week1")->version, sha256_hex(kSet));
  EXPECT_EQ(before->find("week1")->set.problems[0].given_node["pixel"][1].Scalar(), "1");

  // Rewritten with the same bytes: looked at, not read into a new course.
  test::write_file(dir / "week1.yaml", edited);
  EXPECT_EQ(live->at(2000).get(), after.get());

  // A file that no longer loads: the set as it was, its errors reported once.
  test::write_file(dir / "week1.yaml", std::string(kSet) + "    points: lots\n");
  const std::shared_ptr<const Course> broken = live->at(3000);
  EXPECT_EQ(broken->find("week1")->version, sha256_hex(edited));
  ASSERT_EQ(reported.size(), 1u);
  ASSERT_FALSE(reported[0].empty());
  EXPECT_NE(reported[0][0].format().find("week1.yaml:8"), std::string::npos)
      << reported[0][0].format();
  live->at(4000);
  EXPECT_EQ(reported.size(), 1u);

  // Fixed again, and seen at once after a save (refresh), within the second.
  test::write_file(dir / "week1.yaml", kSet);
  live->refresh(4001);
  EXPECT_EQ(live->current()->find("week1")->version, sha256_hex(kSet));
  live.reset();  // frees every course it kept, under exact_math
  fs::remove_all(dir);
}

}  // namespace
}  // namespace frustum::server
