// run_program: another program run from an argument vector, never through a shell.
#include "batch/run_program.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

TEST(RunProgram, ArgumentsReachTheProgramAsTheyAreWithNoShellReadingThem) {
  const fs::path dir = test::scratch_dir("run_program");
  RunOptions in_dir;
  in_dir.cwd = dir.string();
  // What a shell would run (a quote closed, a command, a substitution, a redirection) is text.
  const ProgramRun r = run_program({"printf", "%s|", "w';touch HACKED;'.yaml", "O'Brien",
                                    "$(touch X)", "a b", "> out", "`touch Y`"},
                                   in_dir);
  ASSERT_TRUE(r.started) << r.start_error;
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, "w';touch HACKED;'.yaml|O'Brien|$(touch X)|a b|> out|`touch Y`|");
  EXPECT_TRUE(fs::is_empty(dir)) << "a shell ran something";
  fs::remove_all(dir);
}

TEST(RunProgram, StatusDirectoryEnvironmentAndFiles) {
  const fs::path dir = test::scratch_dir("run_program_env");
  RunOptions o;
  o.cwd = dir.string();
  o.environment = {"FRUSTUM_RUN_TEST=set here"};
  o.out = OutputTo::File;
  o.err = OutputTo::File;
  o.log_file = (dir / "log.txt").string();
  const ProgramRun r =
      run_program({"sh", "-c", "pwd; echo \"$FRUSTUM_RUN_TEST\"; echo to-stderr >&2; exit 3"}, o);
  EXPECT_EQ(r.status, 3);
  EXPECT_EQ(r.output, "");
  EXPECT_EQ(test::read_file(dir / "log.txt"),
            fs::canonical(dir).string() + "\nset here\nto-stderr\n");
  fs::remove_all(dir);
}

TEST(RunProgram, AProgramThatCannotStartOrDoesNotEndIsSaidSo) {
  const ProgramRun missing = run_program({"frustum-no-such-program-anywhere"});
  EXPECT_FALSE(missing.started);
  EXPECT_NE(missing.start_error.find("frustum-no-such-program-anywhere"), std::string::npos);
  RunOptions brief;
  brief.seconds = 0.2;
  // The shell's own child (sleep) is killed with it: the whole process group ends.
  const ProgramRun slow = run_program({"sh", "-c", "sleep 30; echo late"}, brief);
  EXPECT_TRUE(slow.started);
  EXPECT_TRUE(slow.timed_out);
  EXPECT_EQ(slow.status, -1);
  EXPECT_EQ(slow.output, "");
}

TEST(RunProgram, CapturedOutputIsBoundedButTheProgramRunsToItsEnd) {
  RunOptions small;
  small.max_output = 1000;
  const ProgramRun r = run_program({"head", "-c", "1000000", "/dev/zero"}, small);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output.size(), 1000u);
}

}  // namespace
}  // namespace frustum
