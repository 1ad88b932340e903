// Sample answers with expected verdicts (`samples:`): the loader locates a bad field, the grader
// grades each sample against the key, and `frustum check` reports each one graded otherwise
// than its author expects, at its line, with a non-zero exit status.
#include <gtest/gtest.h>

#include <sstream>

#include "app/commands.hpp"
#include "batch/set_check.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

namespace fs = std::filesystem;

// Seed 001 as bundled (its last problem asks normal, unit_normal, plane, z, inside; z = 8 on
// the plane x + y − z = −6), with `samples` added to that last problem.
std::string seed001_with(const std::string& samples) {
  std::string yaml =
      test::read_file(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  while (!yaml.empty() && (yaml.back() == '\n' || yaml.back() == ' ')) yaml.pop_back();
  return yaml + "\n    samples:\n" + samples;
}

constexpr const char* kGoodSamples =
    "      - {answers: {plane: \"x + y - z = -6\", z: 8}, expect: right}\n"
    "      - {answers: {z: 7}, expect: wrong, note: an arithmetic slip}\n"
    "      - answers: {plane: \"x + y - z = -6\", z: 7}\n"
    "        expect: partly\n"
    "        credit: 0.5\n"
    "      - {answers: {z: \"8 +\"}, expect: unparseable}\n";

int line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find(needle);
  return at == std::string::npos
             ? -1
             : 1 + static_cast<int>(std::count(
                       text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

TEST(Samples, EverySampleOfTheSeedIsGradedAsExpected) {
  const ProblemSet set = load_problem_set_from_string(seed001_with(kGoodSamples), "s.yaml");
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  ASSERT_EQ(set.problems.back().samples.size(), 4u);
  const SetCheck check = check_set(set);
  EXPECT_TRUE(check.errors.empty());
  ASSERT_EQ(check.samples.size(), 4u);
  EXPECT_EQ(check.samples[0].verdict, SampleVerdict::Right);
  EXPECT_DOUBLE_EQ(check.samples[0].credit, 1.0);
  EXPECT_EQ(check.samples[1].verdict, SampleVerdict::Wrong);
  EXPECT_DOUBLE_EQ(check.samples[1].credit, 0.0);
  EXPECT_EQ(check.samples[2].verdict, SampleVerdict::Partly);
  EXPECT_DOUBLE_EQ(check.samples[2].credit, 0.5);
  EXPECT_EQ(check.samples[3].verdict, SampleVerdict::Unparseable);
  for (const SampleOutcome& s : check.samples) EXPECT_TRUE(s.as_expected) << s.mismatch.format();
  EXPECT_TRUE(check.ok());
}

TEST(Samples, CheckReportsTheSampleGradedOtherwiseAtItsLine) {
  const std::string yaml = seed001_with(
      std::string(kGoodSamples) + "      - {answers: {z: 7}, expect: right, note: \"seven\"}\n");
  const fs::path dir = test::scratch_dir("samples");
  test::write_file(dir / "set.yaml", yaml);
  std::ostringstream out, err;
  EXPECT_EQ(app::run_check((dir / "set.yaml").string(), app::Output{out, err, false}), 1);
  const std::string said = out.str();
  const std::string where = (dir / "set.yaml").string() + ":" +
                            std::to_string(line_of(yaml, "{z: 7}, expect: right")) + ":";
  EXPECT_NE(said.find(where), std::string::npos) << said;
  EXPECT_NE(said.find("problems[2].samples[4]: expected right, graded wrong"), std::string::npos)
      << said;
  EXPECT_NE(said.find("z: incorrect"), std::string::npos) << said;
  EXPECT_NE(said.find("note: seven"), std::string::npos) << said;
  EXPECT_EQ(said.find("samples[1]"), std::string::npos) << "only the mismatch: " << said;
  EXPECT_NE(said.find("1 error"), std::string::npos) << said;
  // Without it, the same set passes and says how many samples it graded.
  test::write_file(dir / "set.yaml", seed001_with(kGoodSamples));
  std::ostringstream out2;
  EXPECT_EQ(app::run_check((dir / "set.yaml").string(), app::Output{out2, err, false}), 0);
  EXPECT_NE(out2.str().find("4 samples graded as expected"), std::string::npos) << out2.str();
  fs::remove_all(dir);
}

TEST(Samples, CreditOtherThanExpectedIsAMismatch) {
  const ProblemSet set = load_problem_set_from_string(
      seed001_with("      - {answers: {plane: \"x + y - z = -6\", z: 7}, credit: 0.75}\n"),
      "s.yaml");
  const SetCheck check = check_set(set);
  ASSERT_EQ(check.sample_mismatches().size(), 1u);
  EXPECT_NE(check.sample_mismatches()[0].message.find(
                "expected credit 0.75, graded partly with credit 0.5"),
            std::string::npos)
      << check.sample_mismatches()[0].message;
  EXPECT_FALSE(check.ok());
}

// The loader's error for a bad sample: the field and where it is written.
Diagnostic bad_sample(const std::string& sample) {
  const std::string yaml = seed001_with(sample);
  const ProblemSet set = load_problem_set_from_string(yaml, "s.yaml");
  const std::vector<Diagnostic> errors = set.all_errors();
  EXPECT_EQ(errors.size(), 1u);
  return errors.empty() ? Diagnostic{} : errors[0];
}

TEST(Samples, TheLoaderLocatesABadField) {
  const std::string base = seed001_with("");
  const int line = line_of(base, "    samples:") + 1;  // the sample's own line
  Diagnostic d = bad_sample("      - {answers: {z: 8}, expect: rigth}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].expect");
  EXPECT_EQ(d.where.file, "s.yaml");
  EXPECT_EQ(d.where.line, line);
  EXPECT_NE(d.message.find("did you mean 'right'"), std::string::npos) << d.message;
  d = bad_sample("      - {answers: {zz: 8}, expect: right}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].answers.zz");
  EXPECT_NE(d.message.find("not an asked answer"), std::string::npos) << d.message;
  d = bad_sample("      - {answers: {z: 8}, expect: right, verdict: right}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].verdict");
  d = bad_sample("      - {answers: {z: 8}}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].expect");
  d = bad_sample("      - {answers: {z: 8}, credit: 2}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].credit");
  EXPECT_EQ(d.where.line, line);
  d = bad_sample("      - {answers: 8, expect: right}\n");
  EXPECT_EQ(d.field, "problems[2].samples[0].answers");
}

}  // namespace
}  // namespace frustum
