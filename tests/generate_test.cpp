// Generated variants: the random numbers, `vary`, reproducibility pinned byte for
// byte, per-student grading, and the self-test of every kind — generated variants graded against
// their own key (full marks), a key perturbed by ten times the tolerance (not correct) and
// malformed answers (unparseable, never a crash). FRUSTUM_SELFTEST_COUNT=N runs N per kind.
#include "solver/problem/generate.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "grader/compare.hpp"
#include "grader/grade.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// ---------------------------------------------------------------- random numbers

TEST(Rng, Fnv1a64KnownValues) {
  EXPECT_EQ(fnv1a64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a64("foobar"), 0x85944171f73967e8ULL);
  // Streaming: hashing in two parts is hashing the whole.
  EXPECT_EQ(fnv1a64("bar", fnv1a64("foo")), fnv1a64("foobar"));
}

TEST(Rng, SplitMix64ReferenceSequence) {
  // Vigna's splitmix64.c from state 1234567.
  Rng rng(1234567);
  EXPECT_EQ(rng.next(), 6457827717110365317ULL);
  EXPECT_EQ(rng.next(), 3203168211198807973ULL);
  EXPECT_EQ(rng.next(), 9817491932198370423ULL);
  EXPECT_EQ(rng.next(), 4593380528125082431ULL);
  EXPECT_EQ(rng.next(), 16408922859458223821ULL);
}

TEST(Rng, IntegersCoverTheirRangeEvenly) {
  Rng rng(42);
  std::map<std::int64_t, int> counts;
  constexpr int kDraws = 70000;
  for (int i = 0; i < kDraws; ++i) {
    const std::int64_t v = rng.integer(-3, 3);
    ASSERT_GE(v, -3);
    ASSERT_LE(v, 3);
    ++counts[v];
  }
  ASSERT_EQ(counts.size(), 7u);
  for (const auto& [v, c] : counts) EXPECT_NEAR(c, kDraws / 7, 500) << v;  // ~5 standard deviations
  // A range that is not a power of two: rejection keeps 0..2 uniform.
  int zeros = 0;
  for (int i = 0; i < 30000; ++i) zeros += rng.below(3) == 0;
  EXPECT_NEAR(zeros, 10000, 400);
  for (int i = 0; i < 1000; ++i) EXPECT_NE(rng.nonzero(-1, 1), 0);
}

// ---------------------------------------------------------------- vary

// Variants per kind in the self-test (FRUSTUM_SELFTEST_COUNT overrides).
constexpr int kSelfTestCount = 20;

// Pinned output: these must never change across machines, compilers or library versions.
const char* kGoldenSetS1234567 = R"(# student s1234567
title: "Z-buffer drill"
problems:
  - id: zbuf
    kind: depth_at_pixel
    text: "Find z at pixel (1, 1)."
    given:
      triangle: [[0, 0, 2], [2, 3, 2], [0, 3, 9]]
      pixel: [1, 1]
    ask: [z]
  - id: df
    kind: backface
    given:
      points: [[1, 0, 0], [1, 1, 1], [0, 1, 2]]
      eye: [0, 1, 0]
  - id: fixed
    kind: vectors
    given:
      a: [2, 0, 1]
      b: [1, 2, 0]
    ask: [dot]
)";
const char* kGoldenKeyS1234567 = R"(student: s1234567
answers:
  zbuf:
    z: 5/6
  df:
    normal: [1, -1, 1]
    view: [-1, 1, 0]
    df: -2
    facing: back
  fixed:
    dot: 2
)";
const char* kGoldenSetS7654321 = R"(title: "Z-buffer drill"
problems:
  - id: zbuf
    kind: depth_at_pixel
    text: "Find z at pixel (1, 1)."
    given:
      triangle: [[0, 0, 8], [1, 2, 3], [0, 3, 9]]
      pixel: [1, 1]
    ask: [z]
  - id: df
    kind: backface
    given:
      points: [[1, 0, 0], [1, 1, 1], [0, 1, 2]]
      eye: [0, 1, 0]
  - id: fixed
    kind: vectors
    given:
      a: [2, 0, 1]
      b: [1, 2, 0]
    ask: [dot]
)";

const char* kVariedSet = R"(title: "Z-buffer drill"
problems:
  - id: zbuf
    kind: depth_at_pixel
    text: "Find z at pixel {pixel}."
    given:
      triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]]
      pixel: [1, 1]
    vary:
      triangle: [[0, 0, {range: [2, 8], step: 2}], {each: {range: [1, 3]}}, [0, 3, 9]]
    ask: [z]
  - id: df
    kind: backface
    given:
      points: [[1, 0, 0], [1, 1, 1], [0, 1, 2]]
      eye: [0, 1, 0]
    vary:
      eye: {choices: [[0, 1, 0], [5, 5, 5], [-4, 2, 7]]}
  - id: fixed
    kind: vectors
    given: {a: [2, 0, 1], b: [1, 2, 0]}
    ask: [dot]
)";

TEST(Vary, GeneratedVariantsArePinnedByteForByte) {
  const ProblemSet set = load_problem_set_from_string(kVariedSet, "drill.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  ASSERT_TRUE(set_varies(set));
  const ProblemSet a = variant_for(set, "s1234567");
  ASSERT_TRUE(a.all_errors().empty()) << a.all_errors()[0].format();
  ASSERT_TRUE(a.variant);
  const YAML::Node root = YAML::Load(kVariedSet);
  EXPECT_EQ(emit_variant_set(root, a, "student s1234567"), kGoldenSetS1234567);
  EXPECT_EQ(emit_answer_key(a, "s1234567", ""), kGoldenKeyS1234567);
  const ProblemSet b = variant_for(set, "s7654321");
  EXPECT_EQ(emit_variant_set(root, b, ""), kGoldenSetS7654321);
}

const char* kDefaultsSet = R"(title: "Defaults"
variants: per_student
problems:
  - {id: v, kind: vectors, nice: true, given: {a: [2, 0, 1], b: [1, 2, 0]}}
  - {id: z, kind: depth_at_pixel, nice: true, given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}}
  - {id: m, kind: transform, given: {dim: 2, steps: [{rotate: 90}], points: [[1, 0]]}}
  - {id: p, kind: project_point, given: {point: [0, 0, -5], perspective: {fovy: 90, aspect: 1, near: 1, far: 10}, viewport: {width: 200, height: 200}}}
)";
const char* kGoldenDefaults0 = R"(title: "Defaults"
problems:
  - id: v
    kind: vectors
    given:
      a: [1, -1, -2]
      b: [1, -3, 2]
  - id: z
    kind: depth_at_pixel
    given:
      triangle: [[4, 0, 4], [6, 6, 4], [1, 1, 8]]
      pixel: [3, 2]
  - id: m
    kind: transform
    given:
      dim: 2
      steps: [{rotate: 120}]
      points: [[2, 0]]
  - id: p
    kind: project_point
    given:
      point: [9/2, 9/2, -9]
      perspective: {fovy: 60, aspect: 4/3, near: 2, far: 57}
      viewport: {width: 640, height: 480}
)";
const char* kGoldenDefaults1 = R"(title: "Defaults"
problems:
  - id: v
    kind: vectors
    given:
      a: [2, 0, -2]
      b: [-3, -1, -3]
  - id: z
    kind: depth_at_pixel
    given:
      triangle: [[3, 8, 10], [2, 1, 8], [1, 2, 6]]
      pixel: [2, 4]
  - id: m
    kind: transform
    given:
      dim: 2
      steps: [{rotate: 30}]
      points: [[1, 0]]
  - id: p
    kind: project_point
    given:
      point: [-49/4, 0, -49]
      perspective: {fovy: 60, aspect: 4/3, near: 2, far: 91}
      viewport: {width: 640, height: 480}
)";

TEST(Vary, DefaultGeneratorsArePinnedByteForByte) {
  const ProblemSet set = load_problem_set_from_string(kDefaultsSet, "defaults.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  const std::vector<ProblemSet> v = variants_from_seed(set, 2024, 2);
  const YAML::Node root = YAML::Load(kDefaultsSet);
  EXPECT_EQ(emit_variant_set(root, v[0], ""), kGoldenDefaults0);
  EXPECT_EQ(emit_variant_set(root, v[1], ""), kGoldenDefaults1);
}

TEST(Vary, SeedsAreTheDocumentedHash) {
  const ProblemSet set = load_problem_set_from_string(kVariedSet, "drill.yaml");
  const ProblemSet v = variant_for(set, "s1");
  ASSERT_TRUE(v.variant);
  EXPECT_EQ(v.variant->student, "s1");
  const std::string text =
      std::string("frustum-variant/1") + '\x1f' + "Z-buffer drill" + '\x1f' + "student:s1";
  EXPECT_EQ(v.variant->seed, fnv1a64(text));
  EXPECT_EQ(problem_seed(v.variant->seed, "zbuf"), fnv1a64(text + '\x1f' + "zbuf"));
  // Without a title the key is the file name's stem.
  ProblemSet untitled = set;
  untitled.title = {};
  EXPECT_EQ(set_key(untitled), "drill");
}

TEST(Vary, OnlyTheVariedFieldsChangeAndFixedProblemsStay) {
  const ProblemSet set = load_problem_set_from_string(kVariedSet, "drill.yaml");
  for (const std::string student : {"a", "b", "c", "d"}) {
    const ProblemSet v = variant_for(set, student);
    ASSERT_TRUE(v.all_errors().empty());
    const YAML::Node t = v.problems[0].given_node["triangle"];
    EXPECT_EQ(emit_flow(t[0][0]), "0");
    EXPECT_EQ(emit_flow(t[2]), "[0, 3, 9]");
    const int z0 = t[0][2].as<int>();
    EXPECT_TRUE(z0 == 2 || z0 == 4 || z0 == 6 || z0 == 8) << z0;
    for (std::size_t i = 0; i < 3; ++i) {
      const int c = t[1][i].as<int>();
      EXPECT_TRUE(c >= 1 && c <= 3) << c;
    }
    EXPECT_EQ(emit_flow(v.problems[2].given_node), "{a: [2, 0, 1], b: [1, 2, 0]}");
  }
}

TEST(Vary, SeededVariantsArePairwiseDistinct) {
  const std::string yaml = R"(problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary: {a: [{range: [1, 3]}, 0, 0]}
)";
  const ProblemSet set = load_problem_set_from_string(yaml, "few.yaml");
  const std::vector<ProblemSet> three = variants_from_seed(set, 7, 3);
  std::set<std::string> seen;
  for (const ProblemSet& v : three) {
    ASSERT_TRUE(v.all_errors().empty());
    seen.insert(emit_flow(v.problems[0].given_node));
  }
  EXPECT_EQ(seen.size(), 3u);
  // Only three values exist: a fourth distinct variant is a clear error, not a hang.
  const std::vector<ProblemSet> four = variants_from_seed(set, 7, 4);
  ASSERT_TRUE(four[3].problems[0].error);
  EXPECT_NE(four[3].problems[0].error->message.find("the same as another variant"),
            std::string::npos);
}

TEST(Vary, ClassVariantsArePairwiseDistinct) {
  // Six possible givens: six students get six different ones; a seventh cannot, and is told so.
  const std::string yaml = R"(problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary: {a: [{range: [1, 6]}, 0, 0]}
  - id: fixed
    kind: vectors
    given: {a: [1, 2, 3], b: [0, 1, 0]}
)";
  const ProblemSet set = load_problem_set_from_string(yaml, "six.yaml");
  std::vector<std::string> students;
  for (int i = 0; i < 7; ++i) students.push_back("s" + std::to_string(i));
  const std::vector<ProblemSet> cls = variants_for_class(set, students, false);
  ASSERT_EQ(cls.size(), 7u);
  std::set<std::string> seen;
  int redrawn = 0;
  for (int i = 0; i < 6; ++i) {
    ASSERT_TRUE(cls[i].all_errors().empty()) << i;
    EXPECT_TRUE(seen.insert(emit_flow(cls[i].problems[0].given_node)).second)
        << "student " << i << " repeats";
    EXPECT_EQ(emit_flow(cls[i].problems[1].given_node),
              emit_flow(set.problems[1].given_node));  // not varied
    const int draw = cls[i].variant->draw;
    redrawn += draw > 1;
    // A first draw is the student's own variant, the one grading regenerates from the id.
    if (draw == 1) {
      EXPECT_EQ(emit_flow(cls[i].problems[0].given_node),
                emit_flow(variant_for_student(set, students[i], false).problems[0].given_node));
    }
  }
  EXPECT_GT(redrawn, 0) << "six students over six values: collisions are all but certain";
  EXPECT_EQ(cls[0].variant->draw, 1);
  ASSERT_FALSE(cls[6].all_errors().empty());
  EXPECT_NE(cls[6].all_errors()[0].message.find("fewer variants than the class"),
            std::string::npos);
  // The same roster gives the same class.
  const std::vector<ProblemSet> again = variants_for_class(set, students, false);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(emit_flow(again[i].problems[0].given_node), emit_flow(cls[i].problems[0].given_node));
}

// A problem with fewer variants than the class is named in the error of every student left
// over (told at once, not after a hundred draws each); with allow_repeats that problem repeats
// among the class while the others stay pairwise distinct, and every student has a variant.
TEST(Vary, AProblemThatRunsOutIsNamedOrAllowedToRepeat) {
  const std::string yaml = R"(problems:
  - id: few
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary: {a: [{range: [1, 3]}, 0, 0]}
  - id: many
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary: {a: [{range: [1, 60]}, {range: [1, 60]}, 0]}
)";
  const ProblemSet set = load_problem_set_from_string(yaml, "few.yaml");
  std::vector<std::string> students;
  for (int i = 0; i < 8; ++i) students.push_back("s" + std::to_string(i));
  const std::vector<ProblemSet> strict = variants_for_class(set, students, false);
  int refused = 0;
  for (const ProblemSet& v : strict) {
    if (v.all_errors().empty()) continue;
    ++refused;
    EXPECT_NE(v.all_errors()[0].message.find("problem 'few' has fewer variants than the class"),
              std::string::npos)
        << v.all_errors()[0].message;
    EXPECT_NE(v.all_errors()[0].message.find("--allow-repeats"), std::string::npos);
  }
  EXPECT_EQ(refused, 5);  // three values for eight students
  ClassVariants drawn(set, false, true);
  std::set<std::string> few, many;
  for (const std::string& s : students) {
    const ProblemSet v = drawn.draw(s);
    ASSERT_TRUE(v.all_errors().empty()) << s << ": " << v.all_errors()[0].message;
    few.insert(emit_flow(v.problems[0].given_node));
    EXPECT_TRUE(many.insert(emit_flow(v.problems[1].given_node)).second)
        << s << " repeats a problem with room for the class";
  }
  EXPECT_EQ(few.size(), 3u);  // every value used, then repeated
  EXPECT_EQ(drawn.exhausted(), std::vector<std::string>{"few"});
}

TEST(Vary, MistakesAreLocatedErrors) {
  const std::string yaml = R"(variants: per_student
problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary:
      c: {range: [1, 3]}
  - id: w
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary:
      a: {range: [3, 1]}
  - id: x
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary:
      a: {choices: [[0, 0, 0]]}
)";
  const ProblemSet v = variant_for(load_problem_set_from_string(yaml, "bad.yaml"), "s");
  ASSERT_TRUE(v.problems[0].error);
  EXPECT_EQ(v.problems[0].error->format(),
            "bad.yaml:7:7: problems[0].vary.c: not a given field of vectors (did you mean 'a'?)");
  ASSERT_TRUE(v.problems[1].error);
  EXPECT_EQ(v.problems[1].error->format(),
            "bad.yaml:12:18: problems[1].vary.a.range: lo must not exceed hi");
  // Every draw fails (a zero vector): a bounded number of attempts, then the reason.
  ASSERT_TRUE(v.problems[2].error);
  EXPECT_NE(v.problems[2].error->message.find("no acceptable variant in 100 draws"),
            std::string::npos);
  EXPECT_NE(v.problems[2].error->message.find("zero vector"), std::string::npos);
  // A student id is needed to pick the variant.
  const ProblemSet none = variant_for(load_problem_set_from_string(kVariedSet, "drill.yaml"), "");
  ASSERT_FALSE(none.errors.empty());
  EXPECT_EQ(none.errors[0].field, "student");
}

TEST(Vary, NiceAndHardShapeTheDefaultGenerators) {
  const std::string yaml = R"(variants: per_student
problems:
  - {id: z, kind: depth_at_pixel, nice: true, given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}}
  - {id: edge, kind: backface, difficulty: hard, given: {points: [[1, 0, 0], [1, 1, 1], [0, 1, 2]], eye: [0, 1, 0]}}
  - {id: fov, kind: projection_plane, nice: true, given: {window: [200, 200], fov: 60, point: [0, 100, -300]}}
  - {id: flat, kind: normal, difficulty: hard, given: {points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}}
)";
  const ProblemSet set = load_problem_set_from_string(yaml, "opts.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  for (int s = 0; s < 20; ++s) {
    const ProblemSet v = variant_for(set, "student" + std::to_string(s));
    ASSERT_TRUE(v.all_errors().empty()) << v.all_errors()[0].format();
    const SetResult r = solve_set(v, false);
    const GiNaC::ex z = r.problems[0].answers.find("z")->exact[0];
    EXPECT_TRUE(GiNaC::is_a<GiNaC::numeric>(z) && GiNaC::ex_to<GiNaC::numeric>(z).is_integer())
        << z;
    EXPECT_EQ(r.problems[1].answers.find("facing")->word, "edge_on");
    const int fov = v.problems[2].given_node["fov"].as<int>();
    EXPECT_TRUE(fov == 60 || fov == 90) << fov;
    EXPECT_TRUE(not_nice(r.problems[2].answers, v.problems[2].ask).empty());
    EXPECT_LT(triangle_shape(doubles(std::vector<Vec3<Exact>>{
                  Vec3<Exact>(v.problems[3].given_node["points"][0][0].as<int>(),
                              v.problems[3].given_node["points"][0][1].as<int>(),
                              v.problems[3].given_node["points"][0][2].as<int>()),
                  Vec3<Exact>(v.problems[3].given_node["points"][1][0].as<int>(),
                              v.problems[3].given_node["points"][1][1].as<int>(),
                              v.problems[3].given_node["points"][1][2].as<int>()),
                  Vec3<Exact>(v.problems[3].given_node["points"][2][0].as<int>(),
                              v.problems[3].given_node["points"][2][1].as<int>(),
                              v.problems[3].given_node["points"][2][2].as<int>())})),
              kMinTriangleShape);
  }
}

TEST(Vary, GradingRegeneratesTheStudentsVariant) {
  const ProblemSet set = load_problem_set_from_string(kVariedSet, "drill.yaml");
  const ProblemSet mine = variant_for(set, "s42");
  const Submission key = load_submission_from_string(emit_answer_key(mine, "s42", ""), "key.yaml");
  ASSERT_EQ(key.student, "s42");
  const GradeReport r = grade(variant_for(set, key.student), key);
  EXPECT_TRUE(r.errors.empty());
  EXPECT_GT(r.max_score, 0);
  EXPECT_DOUBLE_EQ(r.score, r.max_score);
  // Someone else's key against this student's variant loses marks (the z answers differ).
  Submission other = key;
  other.student = "s43";
  const GradeReport wrong = grade(variant_for(set, other.student), other);
  EXPECT_LT(wrong.score, wrong.max_score);
}

// ---------------------------------------------------------------- the command line

// Its output (stdout and stderr); `status` is the exit status (-1: no normal exit).
std::string run_cli(const std::string& args, int& status) {
  const ProgramRun r = test::frustum_run(args);
  status = r.status;
  return r.output;
}

TEST(GenerateCli, WritesReproducibleSetsWhoseKeysGradeFullMarks) {
  const std::string dir = ::testing::TempDir() + "frustum_generate_cli";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string set = dir + "/drill.yaml";
  std::ofstream(set) << kVariedSet;
  int status = 0;
  run_cli("generate " + set + " --student s1 --student s2 -o " + dir + "/a", status);
  ASSERT_EQ(status, 0);
  run_cli("generate " + set + " --student s1 -o " + dir + "/b", status);
  ASSERT_EQ(status, 0);
  const std::string first = test::read_file(dir + "/a/drill-s1.yaml");
  EXPECT_NE(first.find("seed "), std::string::npos);
  EXPECT_EQ(first, test::read_file(dir + "/b/drill-s1.yaml"));
  EXPECT_EQ(test::read_file(dir + "/a/answers/drill-s1.yaml"),
            test::read_file(dir + "/b/answers/drill-s1.yaml"));
  // The key grades full marks against the master set, which regenerates s1's variant.
  const std::string out =
      run_cli("grade " + set + " " + dir + "/a/answers/drill-s1.yaml --format json", status);
  EXPECT_EQ(status, 0) << out;
  EXPECT_NE(out.find("variant of student s1"), std::string::npos) << out;
  const nlohmann::json j = nlohmann::json::parse(out.substr(out.find('{')));
  EXPECT_EQ(j["score"], j["max_score"]);
  // Each student is graded against their own variant.
  const std::string cross =
      run_cli("grade " + set + " " + dir + "/a/answers/drill-s2.yaml", status);
  EXPECT_NE(cross.find("Student s2"), std::string::npos) << cross;
  // Seeded variants grade against their own generated files.
  run_cli("generate " + set + " --seed 5 --count 2 -o " + dir + "/c", status);
  ASSERT_EQ(status, 0);
  const std::string own = run_cli(
      "grade " + dir + "/c/drill-seed5-1.yaml " + dir + "/c/answers/drill-seed5-1.yaml", status);
  EXPECT_EQ(status, 0) << own;
  EXPECT_NE(own.find(": 6 / 6"), std::string::npos) << own;
  // Usage errors.
  run_cli("generate " + set, status);
  EXPECT_NE(status, 0);
}

// `grade --variants DIR` never grades against a stale file: a generated set records the
// fingerprint of the set it was drawn from; after the set changed, the student's variant is drawn
// again from the set as it is now when that gives the same givens (so a key or tolerance fixed
// since reaches the grade), and is refused otherwise.
TEST(GenerateCli, GradingAgainstGeneratedFilesNeverUsesAStaleSet) {
  const std::filesystem::path dir = test::scratch_dir("generate_stale");
  const std::string set = (dir / "drill.yaml").string();
  const std::string vdir = (dir / "v").string();
  std::ofstream(set) << kVariedSet;
  int status = 0;
  run_cli("generate " + set + " --student s1 -o " + vdir, status);
  ASSERT_EQ(status, 0);
  const std::string file = vdir + "/drill-s1.yaml";
  EXPECT_NE(test::read_file(file).find("drawn_from: {set: drill.yaml, fingerprint: "),
            std::string::npos);
  // s1's key, with dot = 2.3 where a·b = 2: wrong at the set's tolerance.
  std::string answers = test::read_file(vdir + "/answers/drill-s1.yaml");
  const std::size_t dot = answers.find("dot: 2");
  ASSERT_NE(dot, std::string::npos) << answers;
  answers.replace(dot, 6, "dot: 2.3");
  const std::string mine = (dir / "s1.yaml").string();
  std::ofstream(mine) << answers;
  const auto grade_s1 = [&]() {
    return run_cli("grade " + set + " " + mine + " --variants " + vdir, status);
  };

  std::string out = grade_s1();
  EXPECT_EQ(status, 0) << out;  // the wrong dot is a verdict, not an error
  EXPECT_NE(out.find("graded against " + file), std::string::npos) << out;
  EXPECT_NE(out.find("fixed (vectors): 0 / 1"), std::string::npos) << out;
  // A comment or a layout change is no change.
  std::ofstream(set, std::ios::app) << "# reviewed\n";
  out = grade_s1();
  EXPECT_NE(out.find("graded against " + file), std::string::npos) << out;
  // The key fixed (a tolerance): the variant is drawn again from the set as it is now, and the
  // fix reaches the grade.
  std::string text = kVariedSet;
  text.replace(text.find("    ask: [dot]"), 14, "    ask: [dot]\n    tolerance: {rel: 0.2}");
  std::ofstream(set) << text;
  out = grade_s1();
  EXPECT_NE(out.find("drawn again from " + set + " as it is now"), std::string::npos) << out;
  EXPECT_NE(out.find("fixed (vectors): 1 / 1"), std::string::npos) << out;
  // A varying given changed: s1's problem is not the one in the file any more, so refused.
  text.replace(text.find("[[0, 1, 0], [5, 5, 5], [-4, 2, 7]]"), 34, "[[9, 9, 9], [8, 8, -8]]");
  std::ofstream(set) << text;
  out = grade_s1();
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("changed since " + file + " was generated, and the student's problem df"),
            std::string::npos)
      << out;
  // A file that does not say what it was drawn from (an earlier frustum's) is refused too.
  std::string written = test::read_file(file);
  written.erase(written.find("drawn_from:"),
                written.find('\n', written.find("drawn_from:")) - written.find("drawn_from:") + 1);
  std::ofstream(file) << written;
  out = grade_s1();
  EXPECT_EQ(status, 1) << out;
  EXPECT_NE(out.find("does not say which version of " + set), std::string::npos) << out;
}

TEST(GenerateCli, RosterGivesDistinctVariantsGradedAgainstTheirFiles) {
  const std::string dir = ::testing::TempDir() + "frustum_generate_roster";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/answers");
  const std::string set = dir + "/few.yaml";
  std::ofstream(set) << R"(problems:
  - id: v
    kind: vectors
    given: {a: [1, 0, 0], b: [0, 1, 0]}
    vary: {a: [{range: [1, 4]}, 0, 0]}
    ask: [dot]
)";
  std::ofstream(dir + "/roster.csv") << "student,name\nana,Ana\nben,Ben\ncy,Cy\ndee,Dee\n";
  int status = 0;
  const std::string gen =
      run_cli("generate " + set + " --roster " + dir + "/roster.csv -o " + dir + "/gen", status);
  ASSERT_EQ(status, 0) << gen;
  std::set<std::string> givens;
  bool redrawn = false;
  for (const std::string s : {"ana", "ben", "cy", "dee"}) {
    const std::string text = test::read_file(dir + "/gen/few-" + s + ".yaml");
    givens.insert(text.substr(text.find("given:")));
    redrawn = redrawn || text.find("Draw ") != std::string::npos;
    std::filesystem::copy_file(dir + "/gen/answers/few-" + s + ".yaml",
                               dir + "/answers/" + s + ".yaml");
  }
  EXPECT_EQ(givens.size(), 4u) << "four students, four values: all different";
  EXPECT_TRUE(redrawn) << gen;
  EXPECT_NE(gen.find("--variants"), std::string::npos) << gen;
  // Against their generated files every key grades full marks, redrawn students included.
  const std::string out = run_cli(
      "grade " + set + " " + dir + "/answers --variants " + dir + "/gen -o " + dir + "/grades",
      status);
  EXPECT_EQ(status, 0) << out;
  const std::string book = test::read_file(dir + "/grades/gradebook.csv");
  for (const std::string s : {"ana", "ben", "cy", "dee"})
    EXPECT_NE(book.find(s + ",1,1,100"), std::string::npos) << book;
  // In a batch, a student with no generated file is an error row that says why.
  std::ofstream(dir + "/answers/zed.yaml") << "student: zed\nanswers:\n  v: {dot: 0}\n";
  run_cli("grade " + set + " " + dir + "/answers --variants " + dir + "/gen -o " + dir + "/grades2",
          status);
  EXPECT_NE(status, 0);
  const std::string book2 = test::read_file(dir + "/grades2/gradebook.csv");
  EXPECT_NE(book2.find("zed,0,"), std::string::npos) << book2;
  EXPECT_NE(book2.find(",error,"), std::string::npos) << book2;
  EXPECT_NE(book2.find("no generated set for student zed"), std::string::npos) << book2;
  std::filesystem::remove(dir + "/answers/zed.yaml");
  // One student alone, and a student with no generated file.
  const std::string one =
      run_cli("grade " + set + " " + dir + "/answers/cy.yaml --variants " + dir + "/gen", status);
  EXPECT_EQ(status, 0) << one;
  EXPECT_NE(one.find("graded against"), std::string::npos) << one;
  std::ofstream(dir + "/zed.yaml") << "student: zed\nanswers:\n  v: {dot: 0}\n";
  const std::string none =
      run_cli("grade " + set + " " + dir + "/zed.yaml --variants " + dir + "/gen", status);
  EXPECT_NE(status, 0);
  EXPECT_NE(none.find("no generated set for student zed"), std::string::npos) << none;
  // The same roster regenerates the class, redraws included.
  const std::string by_roster = run_cli("grade " + set + " " + dir + "/answers --roster " + dir +
                                            "/roster.csv -o " + dir + "/grades3",
                                        status);
  EXPECT_EQ(status, 0) << by_roster;
  const std::string book3 = test::read_file(dir + "/grades3/gradebook.csv");
  for (const std::string s : {"ana", "ben", "cy", "dee"})
    EXPECT_NE(book3.find(s + ",1,1,100"), std::string::npos) << book3;
  for (const std::string s : {"ana", "ben", "cy", "dee"}) {
    const std::string alone = run_cli(
        "grade " + set + " " + dir + "/answers/" + s + ".yaml --roster " + dir + "/roster.csv",
        status);
    EXPECT_NE(alone.find(": 1 / 1"), std::string::npos) << alone;
  }
  // Without either, each student is graded against the variant drawn from their own id, whoever
  // else is in the class: every row is the row of that student's file graded alone. The pairs whose
  // id variants share a problem are named to the instructor, with how to grade a roster class.
  const std::string guessed =
      run_cli("grade " + set + " " + dir + "/answers -o " + dir + "/grades4", status);
  EXPECT_EQ(status, 0) << guessed;
  EXPECT_NE(guessed.find("share problem v"), std::string::npos) << guessed;
  EXPECT_NE(guessed.find("--roster"), std::string::npos) << guessed;
  const std::string book4 = test::read_file(dir + "/grades4/gradebook.csv");
  // A student's row up to the file's path (the one column that differs when graded alone).
  const auto row_of = [](const std::string& book, const std::string& student) {
    const std::size_t at = book.find("\n" + student + ",");
    if (at == std::string::npos) return std::string("<no row>");
    const std::string row = book.substr(at + 1, book.find('\n', at + 1) - at - 1);
    return row.substr(0, row.find(",/"));
  };
  for (const std::string s : {"ana", "ben", "cy", "dee"}) {
    const std::string alone_dir = dir + "/alone-" + s;
    std::filesystem::create_directories(alone_dir);
    std::filesystem::copy_file(dir + "/answers/" + s + ".yaml", alone_dir + "/" + s + ".yaml");
    run_cli("grade " + set + " " + alone_dir + " -o " + alone_dir + "/out", status);
    EXPECT_EQ(row_of(book4, s), row_of(test::read_file(alone_dir + "/out/gradebook.csv"), s));
    EXPECT_NE(row_of(book4, s).find(",graded,"), std::string::npos) << book4;
  }
  // A student alone without either is graded against the id's draw, and the report says how to
  // grade a roster-generated class.
  const std::string single = run_cli("grade " + set + " " + dir + "/answers/ana.yaml", status);
  EXPECT_NE(single.find("--roster"), std::string::npos) << single;
  // A roster naming a student twice is a located error.
  std::ofstream(dir + "/twice.txt") << "ana\n# comment\n\nana\n";
  const std::string twice =
      run_cli("generate " + set + " --roster " + dir + "/twice.txt -o " + dir + "/t", status);
  EXPECT_NE(status, 0);
  EXPECT_NE(twice.find("twice.txt:4:1"), std::string::npos) << twice;
}

// A set that does not vary is every student's set: with --roster (which then says only whose each
// file is) the published answers grade full marks for everyone, never against a drawn variant.
TEST(GenerateCli, ARosterOnASetThatDoesNotVaryGradesEveryoneAgainstTheSet) {
  const std::string dir = ::testing::TempDir() + "frustum_roster_fixed";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/answers");
  const std::string set = test::source_path("problems/seeds/001_zbuffer_plane_method.yaml");
  std::string published =
      test::read_file(test::source_path("problems/seeds/answers/001_zbuffer_plane_method.yaml"));
  const std::string claim = "student: seed001-published";
  ASSERT_NE(published.find(claim), std::string::npos);
  for (const std::string s : {"ana", "ben"})
    test::write_file(
        dir + "/answers/" + s + ".yaml",
        std::string(published).replace(published.find(claim), claim.size(), "student: " + s));
  std::ofstream(dir + "/roster.csv") << "student\nana\nben\n";
  int status = 0;
  const std::string out = run_cli(
      "grade " + set + " " + dir + "/answers --roster " + dir + "/roster.csv -o " + dir + "/grades",
      status);
  EXPECT_EQ(status, 0) << out;
  const std::string book = test::read_file(dir + "/grades/gradebook.csv");
  for (const std::string s : {"ana", "ben"})
    EXPECT_NE(book.find(s + ",8,8,100"), std::string::npos) << book;
  const std::string one = run_cli(
      "grade " + set + " " + dir + "/answers/ana.yaml --roster " + dir + "/roster.csv", status);
  EXPECT_EQ(status, 0) << one;
  EXPECT_NE(one.find(": 8 / 8"), std::string::npos) << one;
}

// ---------------------------------------------------------------- self-test of every kind

int selftest_count() {
  if (const char* env = std::getenv("FRUSTUM_SELFTEST_COUNT")) return std::max(1, std::atoi(env));
  return kSelfTestCount;
}

// Every number moved by ten times its tolerance window (alternating signs); for answers
// compared up to scale, one component.
YAML::Node perturbed(const Value& v, const AnswerSpec& spec, const ComponentJudge& judge) {
  switch (v.shape) {
    case Value::Shape::Null:
      return YAML::Node("1");
    case Value::Shape::Bool:
      return YAML::Node(v.flag ? "false" : "true");
    case Value::Shape::Word: {
      if (spec.kind == AnswerKind::BitString)
        return YAML::Node((v.word[0] == '0' ? "1" : "0") + v.word.substr(1));
      for (const std::string& w : spec.words)
        if (w != v.word) return YAML::Node(w);
      return YAML::Node("front");
    }
    case Value::Shape::WordMap: {
      YAML::Node n = answer_node(v);
      const std::string first = v.entries[0].second;
      n[v.entries[0].first] = first == "front" ? "back" : first == "visible" ? "hidden" : "visible";
      return n;
    }
    case Value::Shape::WordList: {
      YAML::Node n = answer_node(v);
      if (spec.kind == AnswerKind::Sequence && v.words.size() >= 2 &&
          v.words.front() != v.words.back()) {
        YAML::Node r(YAML::NodeType::Sequence);
        for (std::size_t i = v.words.size(); i-- > 0;) r.push_back(v.words[i]);
        return r;
      }
      n.push_back("nonsense");
      return n;
    }
    default:
      break;
  }
  // The grader's own window of each component (at least 1 where the window is 0: an exact 0).
  const auto off = [&](std::size_t i) {
    const double w = judge.window(i, v.numbers[i]);
    return w > 0 ? 10 * w : 1.0;
  };
  Value p = v;
  p.exact.clear();
  if (spec.kind == AnswerKind::Direction || spec.kind == AnswerKind::Plane ||
      spec.kind == AnswerKind::Point) {
    // Compared up to scale: move only the smallest component, which no rescaling undoes (the
    // residual is at least 10·window·√(1 − 1/n)).
    std::size_t k = 0;
    for (std::size_t i = 1; i < p.numbers.size(); ++i)
      if (std::abs(v.numbers[i]) < std::abs(v.numbers[k])) k = i;
    p.numbers[k] += off(k);
    return answer_node(p);
  }
  for (std::size_t i = 0; i < p.numbers.size(); ++i) p.numbers[i] += (i % 2 ? -1 : 1) * off(i);
  return answer_node(p);
}

// Not an answer of its kind in any reading.
YAML::Node malformed(const AnswerSpec& spec) {
  switch (spec.kind) {
    case AnswerKind::Bool:
      return YAML::Node("maybe");
    case AnswerKind::Category:
      return YAML::Node("sideways");
    case AnswerKind::BitString:
      return YAML::Node("01x");
    case AnswerKind::WordList:
    case AnswerKind::Sequence:
      return YAML::Load("{a: 1}");
    case AnswerKind::WordMap:
      return YAML::Node("x");
    default:
      return YAML::Node("1 +* ");
  }
}

std::string submission_text(const ProblemSpec& spec,
                            const std::function<YAML::Node(const AnswerSpec&)>& make) {
  std::string s = "student: s\nanswers:\n  p:\n";
  for (const std::string& name : spec.ask)
    s += "    " + name + ": " + emit_flow(make(*spec.info->answer(name))) + "\n";
  return s;
}

class SelfTest : public ::testing::TestWithParam<std::string> {};

TEST_P(SelfTest, KeysGradeFullPerturbedKeysDoNotMalformedAnswersAreUnparseable) {
  const KindInfo& kind = *builtin_kinds().find(GetParam());
  ASSERT_TRUE(kind.generate) << kind.name << " has no default generator";
  const int count = selftest_count();
  for (int i = 0; i < count; ++i) {
    // Every fourth variant nice, every fifth hard: all three kinds of draws are checked.
    const ProblemSpec base = default_problem(kind, i % 4 == 1, i % 5 == 2);
    ProblemSet set;
    set.file = "selftest.yaml";
    set.problems.push_back(
        draw_problem(base, set.file, fnv1a64(kind.name + "/" + std::to_string(i))));
    const ProblemSpec& spec = set.problems[0];
    ASSERT_FALSE(spec.error) << kind.name << " #" << i << ": " << spec.error->format();
    const std::string given = emit_flow(spec.given_node);
    const ProblemResult solved = solve_problem(spec, set.file, false);
    ASSERT_FALSE(solved.error) << given;

    // (a) its own key: full marks.
    const GradeReport full =
        grade(set, load_submission_from_string(emit_answer_key(set, "s", ""), "key.yaml"));
    ASSERT_TRUE(full.errors.empty()) << given << "\n" << full.errors[0].format();
    ASSERT_FALSE(full.problems[0].error) << given;
    for (const AnswerGrade& a : full.problems[0].answers)
      EXPECT_EQ(a.verdict, Verdict::Correct) << kind.name << " " << a.name << " of " << given
                                             << ": got " << a.got_text << ", " << a.feedback;
    EXPECT_DOUBLE_EQ(full.score, full.max_score) << given;

    // (b) perturbed by ten times the tolerance: no answer is correct.
    const ProblemJudging judging = prepare_judging(spec, solved.answers);
    const std::string off = submission_text(spec, [&](const AnswerSpec& a) {
      const Value& key = *solved.answers.find(a.name);
      const AnswerRules rules = judging.rules(spec, a.name);
      return perturbed(key, a, ComponentJudge(key, a.kind, rules.tol, rules.scale));
    });
    const GradeReport wrong = grade(set, load_submission_from_string(off, "off.yaml"));
    for (const AnswerGrade& a : wrong.problems[0].answers)
      EXPECT_NE(a.verdict, Verdict::Correct)
          << kind.name << " " << a.name << " of " << given << ": " << a.got_text;
    EXPECT_LT(wrong.score, wrong.max_score);

    // (c) malformed: unparseable, and graded without a crash.
    const GradeReport bad =
        grade(set, load_submission_from_string(submission_text(spec, malformed), "bad.yaml"));
    for (const AnswerGrade& a : bad.problems[0].answers)
      EXPECT_EQ(a.verdict, Verdict::Unparseable)
          << kind.name << " " << a.name << ": " << a.got_text;
    EXPECT_EQ(bad.score, 0);
  }
}

// Kinds with something to draw (a fixed kind, the instructor's statements, tests itself in
// statements_test.cpp).
std::vector<std::string> kind_names() {
  std::vector<std::string> out;
  for (const KindInfo& k : builtin_kinds().all())
    if (!k.fixed) out.push_back(k.name);
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryKind, SelfTest, ::testing::ValuesIn(kind_names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// A drawn variant carries the answers its draw was checked with, and the answer key reuses
// them: for every seed set (every problem varied) and many students they are the answers
// solving the variant again gives.
TEST(Generate, AnswerKeysFromTheDrawEqualKeysSolvedAgain) {
  int reused = 0;  // problems whose key came from the draw
  for (const char* file : {"problems/seeds/000_projection_and_hidden_surfaces.yaml",
                           "problems/seeds/001_zbuffer_plane_method.yaml",
                           "problems/seeds/002_transforms_and_view_volume.yaml",
                           "problems/seeds/003_polygons_backface.yaml",
                           "problems/seeds/004_placing_and_projecting.yaml"}) {
    const ProblemSet set = load_problem_set(test::source_path(file));
    for (int s = 0; s < 8; ++s) {
      const std::string student = "s" + std::to_string(s);
      const ProblemSet drawn = variant_for_student(set, student, true);
      ProblemSet solved_again = drawn;
      for (ProblemSpec& p : solved_again.problems) {
        reused += p.drawn_answers != nullptr;
        p.drawn_answers.reset();
      }
      EXPECT_EQ(emit_answer_key(drawn, student, ""), emit_answer_key(solved_again, student, ""))
          << file << " " << student;
    }
  }
  EXPECT_GT(reused, 100);
}

}  // namespace
}  // namespace frustum
