// The numeric paths against the exact backend (generated well-conditioned problems), and the
// hard-case suite problems/hard: exact answers, robust numeric answers, the studies' findings.
#include "solver/accuracy/accuracy.hpp"

#include <cmath>
#include <filesystem>
#include <limits>
#include <set>

#include "grader/grade.hpp"
#include "solver/accuracy/hard_cases.hpp"
#include "solver/numeric/condition.hpp"
#include "solver/problem/numeric_result.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/solve_precision.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::exact_text;
using test::source_path;

constexpr std::uint64_t kSeed = 7;

NumericResult numeric(const ProblemSpec& spec, Precision p) {
  auto s = spec.info->solve_numeric(spec.given, p);
  s->run();
  return s->result();
}

const ProblemSpec& problem(const ProblemSet& set, const std::string& id) {
  const ProblemSpec* p = set.find(id);
  EXPECT_NE(p, nullptr) << id;
  return *p;
}

// Every set in problems/hard (tests/accuracy_test.cpp checks the list against the folder).
constexpr const char* kHardSets[] = {"normals",    "planes",        "backface",    "eye_plane",
                                     "magnitudes", "exact_signs",   "coverage",    "decisions",
                                     "render",     "render_frames", "conditioning"};

ProblemSet hard(const std::string& name) {
  return load_problem_set(source_path("problems/hard/" + name));
}

bool has_warning(const NumericResult& r, const std::string& title_part) {
  for (const NumericWarning& w : r.warnings)
    if (w.title.en().find(title_part) != std::string::npos) return true;
  return false;
}

std::vector<long double> raw(const NumericResult& r, const std::string& name) {
  const std::vector<long double>* v = r.find_raw(name);
  EXPECT_NE(v, nullptr) << name;
  return v ? *v : std::vector<long double>{};
}

TEST(Precision, NamesRoundTripAndUnitRoundoff) {
  for (Precision p : kAllPrecisions) EXPECT_EQ(parse_precision(to_string(p)), p);
  EXPECT_EQ(parse_precision("quad"), std::nullopt);
  EXPECT_EQ(unit_roundoff(Precision::Double), std::ldexp(1.0, -53));
  EXPECT_EQ(unit_roundoff(Precision::Float), std::ldexp(1.0, -24));
  EXPECT_EQ(unit_roundoff(Precision::Exact), 0.0);
  EXPECT_NEAR(decimal_digits(Precision::Double), 15.95, 0.01);
}

TEST(Precision, ExactConversionsAreExactAndNearest) {
  const long double third = from_exact<long double>(Exact(1) / 3);
  EXPECT_NEAR(static_cast<double>(std::abs(third * 3 - 1)), 0.0, 2e-19);
  EXPECT_EQ(from_exact<float>(Exact(1) / 3), 1.0f / 3.0f);
  for (long double v : {0.1L, -3.0e-300L, 1.0e300L, 12345.678901234567L, 1.0e4000L})
    if (std::abs(v) < 1e308L) {
      EXPECT_EQ(from_exact<long double>(exact_of(v)), v);
    }
  EXPECT_TRUE(test::same(exact_of(1.0e4000L) / exact_of(0.5e4000L), 2));
  EXPECT_TRUE(test::same(exact_of(0.5f), Exact(1) / 2));
}

// Float and long double round the exact value once, over their whole range: 10⁻⁴⁰⁰ is a long
// double (not flushed through double), √2·10⁻³¹⁰ a subnormal double, 10⁻⁴⁵ a subnormal float.
TEST(Precision, ConversionsKeepTheBackendsWholeRange) {
  const Exact tiny = GiNaC::pow(Exact(10), -400);
  const long double t = from_exact<long double>(tiny);
  EXPECT_GT(t, 0.0L);
  EXPECT_NEAR(static_cast<double>(t / 1e-400L), 1.0, 1e-15);
  EXPECT_EQ(from_exact<long double>(-tiny), -t);
  EXPECT_EQ(from_exact<long double>(GiNaC::pow(Exact(10), 5000)),
            std::numeric_limits<long double>::infinity());
  const double sub = from_exact<double>(GiNaC::sqrt(Exact(2)) * GiNaC::pow(Exact(10), -310));
  EXPECT_GT(sub, 0.0);
  EXPECT_NEAR(sub / 1.4142135623730951e-310, 1.0, 1e-9);  // a subnormal keeps fewer bits
  EXPECT_EQ(from_exact<float>(GiNaC::pow(Exact(10), -45)),
            std::numeric_limits<float>::denorm_min());
  // Ties to even at the float grid: 1 + 2⁻²⁴ rounds to 1, 1 + 3·2⁻²⁴ to 1 + 2⁻²².
  EXPECT_EQ(from_exact<float>(1 + GiNaC::pow(Exact(2), -24)), 1.0f);
  EXPECT_EQ(from_exact<float>(1 + 3 * GiNaC::pow(Exact(2), -24)), 1.0f + std::ldexp(1.0f, -22));
}

// bench accuracy measures against the exact values themselves: a result flushed to 0 where
// the exact value is 10⁻⁴⁰⁰ is a total loss, and the error of a long double is seen beyond
// double's precision.
TEST(BenchAccuracy, ErrorIsMeasuredAgainstTheExactValue) {
  const Exact tiny = GiNaC::pow(Exact(10), -400);
  EXPECT_EQ(bench::relative_error({0.0L}, {tiny}), 1.0);
  EXPECT_EQ(bench::relative_error({0.0L, 1.0L}, {0, 1}), 0.0);
  EXPECT_NEAR(bench::relative_error({from_exact<long double>(tiny)}, {tiny}), 0.0, 1e-19);
  const double third = bench::relative_error({1.0L / 3}, {Exact(1) / 3});
  EXPECT_GT(third, 0.0);
  EXPECT_LT(third, 1.1e-19);
  EXPECT_EQ(bench::relative_error({std::numeric_limits<long double>::infinity()}, {1}),
            std::numeric_limits<double>::infinity());
}

// The exact backend is measured on its exact values: its error is 0, not the ~1e-20 of their
// long double rounding; the other backends' errors are measured and non-zero somewhere.
TEST(BenchAccuracy, TheExactBackendScoresZero) {
  const Exact third = Exact(1) / 3, root = GiNaC::sqrt(Exact(3)) / 3;
  EXPECT_EQ(bench::exact_relative_error({third, root}, {third, root}), 0.0);
  EXPECT_GT(bench::exact_relative_error({third}, {root}), 0.0);
  const ProblemSet set =
      load_problem_set(test::source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  bool exact_seen = false, float_error = false;
  for (const bench::AccuracyRow& row : bench::measure(set, "seed", 0)) {
    if (row.precision == Precision::Exact) {
      exact_seen = true;
      EXPECT_EQ(row.max_error, 0.0) << row.kind;
    }
    if (row.precision == Precision::Float && row.max_error > 0) float_error = true;
    EXPECT_EQ(row.wrong, 0u) << row.kind;
  }
  EXPECT_TRUE(exact_seen);
  EXPECT_TRUE(float_error);
}

TEST(Condition, EstimatesGrowAsProblemsDegenerate) {
  const std::vector<Eigen::Vector3d> good = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_LT(normal_condition(good), 10);
  const std::vector<Eigen::Vector3d> thin = {{0, 0, 0}, {1, 0, 0}, {2, 1e-9, 0}};
  EXPECT_GT(normal_condition(thin), 1e8);
  EXPECT_LT(facing_condition(good, {0, 0, 1}), 10);
  EXPECT_GT(facing_condition(good, {0.3, 0.3, 1e-12}), 1e11);
  EXPECT_EQ(trusted_digits(1e10, Precision::Float), 0.0);
  EXPECT_NEAR(trusted_digits(1e10, Precision::Double), 5.95, 0.01);
}

// κ is a ratio of terms of one degree in the coordinates, so it does not change when every
// coordinate is scaled by a power of two — also where the products would under- or overflow in
// double (10⁻²⁰⁰, 10²⁰⁰): the estimates are computed on the rescaled points.
TEST(Condition, EstimatesDoNotChangeWithTheScale) {
  const std::vector<Eigen::Vector3d> good = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Eigen::Vector3d> thin = {
      {0.5, 0.25, 0.1}, {1, 0.25, 0.3}, {2, 0.25 + 1e-9, 0.7}};
  const Eigen::Vector3d eye(0.3, 0.3, 1e-6);
  const Eigen::Vector2d pixel(0.75, 0.3);
  for (const int k : {-700, -400, 400, 700}) {
    auto scaled = [k](std::vector<Eigen::Vector3d> p) {
      for (Eigen::Vector3d& q : p) q = q * std::ldexp(1.0, k);
      return p;
    };
    const double s = std::ldexp(1.0, k);
    EXPECT_DOUBLE_EQ(normal_condition(scaled(good)), normal_condition(good)) << k;
    EXPECT_DOUBLE_EQ(normal_condition(scaled(thin)), normal_condition(thin)) << k;
    EXPECT_DOUBLE_EQ(facing_condition(scaled(good), eye * s), facing_condition(good, eye)) << k;
    const DepthCondition d = depth_condition(thin[0], thin[1], thin[2], pixel);
    const DepthCondition ds = depth_condition(thin[0] * s, thin[1] * s, thin[2] * s, pixel * s);
    EXPECT_DOUBLE_EQ(ds.kappa_c, d.kappa_c) << k;
    EXPECT_DOUBLE_EQ(ds.kappa_z, d.kappa_z) << k;
  }
  EXPECT_GT(normal_condition(thin), 1e8);
  EXPECT_GT(depth_condition(thin[0], thin[1], thin[2], pixel).kappa_c, 1e8);
}

// Every kind with a numeric path, on generated well-conditioned problems: each backend within
// a few units of its roundoff times the condition bound (50) of the exact backend, and the
// same decisions (inside, facing, nulls).
TEST(NumericPaths, AgreeWithExactOnGeneratedProblems) {
  for (const std::string& kind : bench::generated_kinds()) {
    const ProblemSet set = bench::generated_problems(kind, 12, kSeed);
    ASSERT_TRUE(set.all_errors().empty()) << kind << ": " << set.all_errors()[0].format();
    ASSERT_EQ(set.problems.size(), 12u);
    for (const ProblemSpec& spec : set.problems) {
      ASSERT_TRUE(spec.info->solve_numeric) << kind;
      const NumericResult exact = numeric(spec, Precision::Exact);
      for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
        const bench::CaseError e = bench::compare(numeric(spec, p), exact);
        EXPECT_FALSE(e.wrong) << kind << " " << spec.id << " " << to_string(p);
        EXPECT_LT(e.error, 1e4 * unit_roundoff(p)) << kind << " " << spec.id << " " << to_string(p);
      }
    }
  }
}

// The exact backend of the numeric path and the kind's own exact solve give the same values
// (the plane is compared up to scale: the solve writes it with integer coefficients).
TEST(NumericPaths, ExactBackendMatchesTheDerivation) {
  for (const std::string& kind : bench::generated_kinds()) {
    const ProblemSet set = bench::generated_problems(kind, 4, kSeed + 1);
    for (const ProblemSpec& spec : set.problems) {
      const ProblemResult solved = solve_problem(spec, set.file, false);
      ASSERT_FALSE(solved.error) << kind << ": " << solved.error->format();
      const NumericResult exact = numeric(spec, Precision::Exact);
      for (const auto& [name, v] : solved.answers.items()) {
        const Value* n = exact.answers.find(name);
        ASSERT_NE(n, nullptr) << kind << " " << name;
        ASSERT_EQ(n->numbers.size(), v.numbers.size()) << kind << " " << name;
        if (name == "plane") {
          const double scale = n->numbers[0] / v.numbers[0];
          for (std::size_t i = 0; i < v.numbers.size(); ++i)
            EXPECT_NEAR(n->numbers[i], scale * v.numbers[i],
                        1e-9 * std::abs(scale * v.numbers[i]) + 1e-12);
          continue;
        }
        for (std::size_t i = 0; i < v.numbers.size(); ++i)
          EXPECT_NEAR(n->numbers[i], v.numbers[i], 1e-12 * std::abs(v.numbers[i]) + 1e-12)
              << kind << " " << spec.id << " " << name << "[" << i << "]";
        EXPECT_EQ(n->flag, v.flag) << kind << " " << name;
        EXPECT_EQ(n->word, v.word) << kind << " " << name;
      }
    }
  }
}

// The radical suite of `frustum bench accuracy`: every third decimal of a generated given
// becomes an irrational number near it; every kind's problems load, the exact backend solves
// them, and the kind's exact solve (the derivation) agrees with it and with double.
TEST(NumericPaths, RadicalInputsAreSolvedExactly) {
  EXPECT_EQ(bench::with_radicals("{a: [1.25, -3.5, 2], b: [-0.5, 7.75, 1.5, 2.25], fovy: 45, "
                                 "aspect: \"4/3\"}"),
            "{a: [\"1.25 + sqrt(2)/10\", -3.5, 2], b: [-0.5, \"7.75 + sqrt(3)/10\", 1.5, 2.25], "
            "fovy: 45, aspect: \"4/3\"}");
  for (const std::string& kind : bench::generated_kinds()) {
    const ProblemSet set = bench::radical_problems(kind, 3, kSeed);
    ASSERT_TRUE(set.all_errors().empty()) << kind << ": " << set.all_errors()[0].format();
    int irrational = 0;
    for (const ProblemSpec& spec : set.problems) {
      const ProblemResult solved = solve_problem(spec, set.file, false);
      ASSERT_FALSE(solved.error) << kind << " " << spec.id << ": " << solved.error->format();
      const NumericResult exact = numeric(spec, Precision::Exact);
      const bench::CaseError e = bench::compare(numeric(spec, Precision::Double), exact);
      EXPECT_FALSE(e.wrong) << kind << " " << spec.id;
      EXPECT_LT(e.error, 1e-10) << kind << " " << spec.id;
      for (const auto& [name, v] : exact.answers.items())
        for (const Exact& x : v.exact) irrational += !GiNaC::is_a<GiNaC::numeric>(canonical(x));
    }
    EXPECT_GT(irrational, 0) << kind << ": no answer carries the radicals";
  }
}

// One formula per concept: depth_at_pixel's exact solve and numeric path compute the plane
// depth (plane_depth.hpp) and the edge decisions (edge_sign) by the same templates, and
// backface's D_f and its facing (facing.hpp, facing_side) likewise, and normal and plane take
// the polygon's normal from polygon_normal_formula, vectors its area, sin and cos from
// vector_measures, and project_point its w > 0 and inside from the same seven sign tests
// (volume_tests). For many drawn problems (every third hard: pixels on an edge, eyes in the
// polygon's plane, nearly collinear vertices, nearly parallel vectors) the double path's
// values are within 10⁻⁸ (relative) of the exact solve's, its discrete answers (inside, facing,
// whether the unit normal exists) are equal, and it refuses exactly what the exact solve refuses.
TEST(NumericPaths, DoublePathAgreesWithTheExactSolveOfEachUnifiedKind) {
  for (const std::string kind :
       {"depth_at_pixel", "backface", "normal", "plane", "vectors", "project_point"}) {
    const KindInfo& info = *builtin_kinds().find(kind);
    int solved = 0;  // problems both paths solved (not refused)
    for (int i = 0; i < 90; ++i) {
      const ProblemSpec base = default_problem(info, i % 4 == 1, i % 3 == 2);
      ProblemSet set;
      set.file = "formula.yaml";
      set.problems.push_back(
          draw_problem(base, set.file, fnv1a64(kind + "/formula/" + std::to_string(i))));
      const ProblemSpec& spec = set.problems[0];
      ASSERT_FALSE(spec.error) << kind << " #" << i << ": " << spec.error->format();
      const ProblemResult exact = solve_problem(spec, set.file, false);
      const ProblemResult dbl = solve_problem(spec, set.file, false, Precision::Double);
      ASSERT_EQ(bool(exact.error), bool(dbl.error)) << kind << " #" << i;
      if (exact.error) {
        EXPECT_EQ(dbl.error->message, exact.error->message) << kind << " #" << i;
        continue;
      }
      ++solved;
      for (const auto& [name, v] : exact.answers.items()) {
        const Value* n = dbl.answers.find(name);
        ASSERT_NE(n, nullptr) << kind << " " << name;
        EXPECT_EQ(n->flag, v.flag) << kind << " #" << i << " " << name;
        EXPECT_EQ(n->word, v.word) << kind << " #" << i << " " << name;
        ASSERT_EQ(n->numbers.size(), v.numbers.size()) << kind << " " << name;
        double big = 0;
        std::size_t lead = 0;
        for (std::size_t k = 0; k < v.numbers.size(); ++k)
          if (std::abs(v.numbers[k]) > big) big = std::abs(v.numbers[lead = k]);
        // The plane is compared up to scale: the solve writes it with integer coefficients.
        const double scale = name == "plane" && big > 0 ? n->numbers[lead] / v.numbers[lead] : 1;
        for (std::size_t k = 0; k < v.numbers.size(); ++k)
          EXPECT_NEAR(n->numbers[k], scale * v.numbers[k], 1e-8 * std::abs(scale) * (big + 1))
              << kind << " #" << i << " " << name << "[" << k << "]";
      }
    }
    EXPECT_GT(solved, 60) << kind;
  }
}

// M·M⁻¹ = I for the numeric composite and its inverse, in every floating backend.
TEST(NumericPaths, TransformTimesInverseIsIdentity) {
  const ProblemSet set = bench::generated_problems("transform", 20, kSeed);
  for (const ProblemSpec& spec : set.problems)
    for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
      const NumericResult r = numeric(spec, p);
      const std::vector<long double> m = raw(r, "matrix"), inv = raw(r, "inverse");
      ASSERT_EQ(m.size(), 16u);
      ASSERT_EQ(inv.size(), 16u);
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
          long double s = 0;
          for (int k = 0; k < 4; ++k)
            s += m[static_cast<std::size_t>(4 * i + k)] * inv[static_cast<std::size_t>(4 * k + j)];
          EXPECT_NEAR(static_cast<double>(s), i == j ? 1.0 : 0.0, 1e3 * unit_roundoff(p))
              << to_string(p);
        }
    }
}

TEST(SolvePrecision, DerivationNamesTheBackendAndKeepsOtherKindsExact) {
  const ProblemSet set =
      load_problem_set(source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const SetResult r = solve_set(set, true, std::nullopt, Precision::Float);
  ASSERT_FALSE(r.problems.empty());
  for (const ProblemResult& p : r.problems) {
    ASSERT_FALSE(p.error) << p.error->format();
    bool backend = false;
    for (const Step& s : p.derivation.steps())
      backend = backend || (s.title.en() == "Backend" &&
                            s.note.en().find(p.kind == "depth_at_pixel" ? "float (IEEE 754 binary32"
                                                                        : "") != std::string::npos);
    EXPECT_TRUE(backend) << p.id;
  }
  // seed 001's pixel: z = 8 in float too.
  const ProblemResult z =
      solve_problem(problem(set, "seed001-pixel-z"), set.file, true, Precision::Float);
  ASSERT_FALSE(z.error);
  EXPECT_FLOAT_EQ(static_cast<float>(z.answers.find("z")->numbers[0]), 8.0f);
  EXPECT_TRUE(z.answers.find("z")->exact.empty());
}

// A long double answer shows the digits long double holds, not a double's 17 (1/√3 to 19 or more
// significant digits, each right); a numeric matrix is written in decimals, never as the binary
// fractions its doubles are.
TEST(SolvePrecision, LongDoubleShowsItsDigitsAndMatricesAreDecimals) {
  const ProblemSet set =
      load_problem_set(source_path("problems/seeds/001_zbuffer_plane_method.yaml"));
  const ProblemResult p =
      solve_problem(problem(set, "seed001-pixel-z"), set.file, false, Precision::LongDouble);
  ASSERT_FALSE(p.error);
  const Value* n = p.answers.find("unit_normal");
  ASSERT_NE(n, nullptr);
  const std::string shown = n->shown().unicode;
  // 1/√3 = 0.57735026918962576450914878…; long double keeps 19–20 of its digits.
  EXPECT_NE(shown.find("0.577350269189625764"), std::string::npos) << shown;
  EXPECT_DOUBLE_EQ(n->numbers[0], 1 / std::sqrt(3.0));  // what is graded stays a double
  for (const Precision precision : {Precision::Double, Precision::LongDouble}) {
    const SetResult r = solve_set(
        load_problem_set(source_path("problems/seeds/002_transforms_and_view_volume.yaml")), false,
        std::nullopt, precision);
    int matrices = 0;
    for (const ProblemResult& q : r.problems)
      for (const auto& [name, value] : q.answers.items()) {
        if (value.shape != Value::Shape::Matrix || !value.exact.empty()) continue;
        ++matrices;
        EXPECT_EQ(value.shown().unicode.find('/'), std::string::npos)
            << q.id << "." << name << ": " << value.shown().unicode;
      }
    EXPECT_GT(matrices, 2);
  }
}

// Range warnings say what happened: an infinity is an overflow, a NaN (0/0 after a
// cancellation) is "not a number" and no overflow, and neither claims the exact backend is
// unlimited (its answers stop at double's range).
TEST(NumericWarnings, InfinityIsOverflowAndNanIsNotANumber) {
  const auto titles = [](const NumericResult& r) {
    std::set<std::string> t;
    for (const NumericWarning& w : r.warnings) {
      t.insert(w.title.en());
      EXPECT_EQ(w.text.en().find("no limit"), std::string::npos) << w.text.en();
    }
    return t;
  };
  const float zero = 0.0f;
  NumericOut<float> nan_out(Precision::Float);
  nan_out.scalar("x", zero / zero);
  EXPECT_EQ(titles(nan_out.take()), std::set<std::string>{"Not a number"});
  NumericOut<float> inf_out(Precision::Float);
  inf_out.scalar("x", std::numeric_limits<float>::max() * 2.0f);
  const NumericResult inf = inf_out.take();
  EXPECT_EQ(titles(inf), std::set<std::string>{"Overflow"});
  EXPECT_NE(inf.warnings[0].text.en().find("1.8·10³⁰⁸"), std::string::npos);
  NumericOut<double> fine(Precision::Double);
  fine.scalar("x", 1.5);
  EXPECT_TRUE(fine.take().warnings.empty());
}

// ---- The hard-case suite ----

// `frustum solve problems/hard` succeeds (warnings only), and every exact answer in
// problems/hard/answers grades full marks.
TEST(HardCases, SolveCleanlyAndMatchTheirExactAnswers) {
  for (const char* name : kHardSets) {
    const ProblemSet set = hard(std::string(name) + ".yaml");
    ASSERT_TRUE(set.all_errors().empty()) << name << ": " << set.all_errors()[0].format();
    const SetResult solved = solve_set(set, true);
    for (const ProblemResult& p : solved.problems) EXPECT_FALSE(p.error) << name << " " << p.id;
    const GradeReport g = grade(
        set, load_submission(source_path(std::string("problems/hard/answers/") + name + ".yaml")));
    EXPECT_TRUE(g.errors.empty()) << name;
    EXPECT_GT(g.max_score, 0) << name;
    EXPECT_DOUBLE_EQ(g.score, g.max_score) << name;
    for (const ProblemGrade& p : g.problems)
      for (const AnswerGrade& a : p.answers)
        EXPECT_EQ(a.verdict, Verdict::Correct)
            << name << " " << p.id << " " << a.name << ": " << a.feedback;
  }
}

TEST(HardCases, EverySetInTheFolderIsChecked) {
  std::set<std::string> listed(std::begin(kHardSets), std::end(kHardSets)), found;
  for (const auto& f : std::filesystem::directory_iterator(source_path("problems/hard")))
    if (f.path().extension() == ".yaml") found.insert(f.path().stem().string());
  EXPECT_EQ(listed, found);
}

// The discrete part of an answer: a word, a flag, word lists and maps, whether it exists
// (null: no NDC behind the eye, no unit normal of a zero vector), and how many rows a list of
// points has (the vertices left by clipping).
std::string discrete_part(const Value& v) {
  std::string s = std::to_string(static_cast<int>(v.shape));
  if (v.shape == Value::Shape::Matrix) s += " rows=" + std::to_string(v.rows);
  if (v.shape == Value::Shape::Bool) s += v.flag ? " true" : " false";
  s += " " + v.word;
  for (const auto& [k, w] : v.entries) s += " " + k + "=" + w;
  for (const std::string& w : v.words) s += " " + w;
  return s;
}

// Every hard case in every backend: each discrete answer equals the exact one, and the
// derivation says when the exact fallback decided.
TEST(HardCases, DiscreteAnswersAreExactInEveryBackend) {
  int compared = 0, fallbacks = 0;
  for (const char* name : kHardSets) {
    const ProblemSet set = hard(std::string(name) + ".yaml");
    for (const ProblemSpec& spec : set.problems) {
      const ProblemResult exact = solve_problem(spec, set.file, false);
      ASSERT_FALSE(exact.error) << name << " " << spec.id;
      for (Precision p :
           {Precision::Float, Precision::Double, Precision::LongDouble, Precision::Exact}) {
        const ProblemResult r = solve_problem(spec, set.file, true, p);
        ASSERT_FALSE(r.error) << name << " " << spec.id << " " << to_string(p);
        for (const AnswerSpec& a : spec.info->answers) {
          const bool discrete = a.kind == AnswerKind::Bool || a.kind == AnswerKind::Category ||
                                a.kind == AnswerKind::WordMap || a.kind == AnswerKind::WordList ||
                                a.kind == AnswerKind::Sequence || a.kind == AnswerKind::BitString ||
                                a.kind == AnswerKind::Polygon || a.kind == AnswerKind::Segment;
          const Value* want = exact.answers.find(a.name);
          const Value* got = r.answers.find(a.name);
          if (!want) continue;
          ASSERT_NE(got, nullptr) << spec.id << " " << a.name << " " << to_string(p);
          // A value exactly where the exact answer has one: "none" (no NDC behind the eye, no
          // unit normal of parallel vectors) is itself a discrete answer.
          EXPECT_EQ(got->shape == Value::Shape::Null, want->shape == Value::Shape::Null)
              << name << " " << spec.id << " " << a.name << " " << to_string(p);
          if (!discrete) continue;
          EXPECT_EQ(discrete_part(*got), discrete_part(*want))
              << name << " " << spec.id << " " << a.name << " " << to_string(p);
          ++compared;
        }
        for (const Step& s : r.derivation.steps())
          if (s.title.en() == "Backend" &&
              s.note.en().find("decided by exact arithmetic") != std::string::npos)
            ++fallbacks;
      }
    }
  }
  EXPECT_GT(compared, 60);
  EXPECT_GT(fallbacks, 10);  // the boundary cases need the fallback, and say so
}

// Every digit estimate on the hard-case suite checked against the
// digits actually lost (the error against the exact values, measured exactly). A backend that
// says "keeps about X digits" keeps at least X − 1 of them; a result with no warning at all
// lost at most the 4 digits a warning starts at (kIllConditioned), plus one for the estimate's
// slack.
TEST(HardCases, DigitEstimatesMatchTheDigitsActuallyLost) {
  int checked = 0, estimates = 0;
  for (const char* name : kHardSets) {
    const ProblemSet set = hard(std::string(name) + ".yaml");
    for (const ProblemSpec& spec : set.problems) {
      if (!spec.info->solve_numeric) continue;
      NumericResult exact;
      try {
        exact = numeric(spec, Precision::Exact);
      } catch (const std::exception&) {
        continue;  // no exact reference (a domain error)
      }
      for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
        const NumericResult r = numeric(spec, p);
        const double error = bench::compare(r, exact).error;
        const double kept = error == 0 ? decimal_digits(p) : std::max(0.0, -std::log10(error));
        const std::string where =
            std::string(name) + " " + spec.id + " " + std::string(to_string(p));
        if (r.warnings.empty()) {
          EXPECT_GE(kept, decimal_digits(p) - 5)
              << where << ": error " << error << " with no warning";
        }
        const std::string claim = std::string(to_string(p)) + " keeps about ";
        for (const NumericWarning& w : r.warnings) {
          const std::size_t at = w.text.en().find(claim);
          if (at == std::string::npos) continue;
          const double said = std::stod(w.text.en().substr(at + claim.size()));
          EXPECT_GE(kept, said - 1) << where << ": says " << said << " digits, keeps " << kept
                                    << " (" << w.text.en() << ")";
          ++estimates;
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 60);
  EXPECT_GT(estimates, 3);
}

// An exact answer beyond double's range refuses its problem only when it is asked: whether a
// pixel is inside a triangle at 10³⁰⁰ is answered (the edge values, 10⁶⁰⁰, are not asked).
TEST(HardCases, AnswersBeyondDoublesRangeRefuseOnlyWhenAsked) {
  const std::string given =
      "given: {triangle: [[0, 0, 1e300], [4e300, 0, 2e300], [0, 4e300, 3e300]], pixel: [1e300, "
      "1e300]}";
  const ProblemSet set = load_problem_set_from_string(
      "title: t\nproblems:\n  - {id: inside, kind: barycentric, ask: [inside], " + given +
          "}\n  - {id: edges, kind: barycentric, ask: [edges], " + given + "}\n",
      "range.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  const ProblemResult inside = solve_problem(problem(set, "inside"), set.file, true);
  ASSERT_FALSE(inside.error) << inside.error->format();
  ASSERT_NE(inside.answers.find("inside"), nullptr);
  EXPECT_TRUE(inside.answers.find("inside")->flag);
  EXPECT_EQ(inside.answers.find("edges"), nullptr);  // 10⁶⁰⁰: left out, not printed as inf
  const ProblemResult edges = solve_problem(problem(set, "edges"), set.file, true);
  ASSERT_TRUE(edges.error);
  EXPECT_NE(edges.error->message.find("the answer 'edges' is beyond the range of a double"),
            std::string::npos)
      << edges.error->message;
}

TEST(HardCases, ExactNormalsOfDegeneratePolygonsAreExact) {
  const ProblemSet set = hard("normals.yaml");
  for (const ProblemSpec& spec : set.problems) {
    const ProblemResult r = solve_problem(spec, set.file, true);
    ASSERT_FALSE(r.error) << spec.id;
    // Radicands beyond 10^15 are not factored, so some print as sqrt(3·k²)/(3k): compare values.
    for (const Exact& x : r.answers.find("unit_normal")->exact)
      EXPECT_NEAR(to_double(x), 1 / std::sqrt(3.0), 2e-16) << spec.id;
  }
  // The derivation warns about the ill-conditioned ones, with digits.
  for (const char* id :
       {"offset-1e8-features-1e-8", "offset-1e8-unit-square", "subnormal-triangle"})
    EXPECT_EQ(exact_text(solve_problem(problem(set, id), set.file, false), "unit_normal"),
              "sqrt(3)/3, sqrt(3)/3, sqrt(3)/3")
        << id;
  const ProblemResult thin = solve_problem(problem(set, "near-parallel-edges"), set.file, true);
  EXPECT_TRUE(thin.derivation.has_warnings());
}

TEST(HardCases, NewellAndBestPairBeatTheNaiveCrossProduct) {
  const std::vector<bench::NormalMethods> m = bench::normal_methods(hard("normals.yaml"));
  auto find = [&](const std::string& id, Precision p) {
    for (const bench::NormalMethods& x : m)
      if (x.id == id && x.precision == p) return x;
    ADD_FAILURE() << id;
    return bench::NormalMethods{};
  };
  const double zero = 1.5707;  // π/2 stands for a zero vector
  const auto parallel = find("near-parallel-edges", Precision::Double);
  EXPECT_GT(parallel.naive, 1e-9);
  EXPECT_LT(parallel.newell, 1e-14);
  EXPECT_LT(parallel.best_pair, 1e-14);
  const auto short_edge = find("near-zero-edge", Precision::Double);
  EXPECT_GT(short_edge.naive, 1e-6);
  EXPECT_LT(short_edge.newell, 1e-14);
  EXPECT_LT(short_edge.best_pair, 1e-14);
  // 1e8 with features of 1e-8: the vertices coincide in float, double rounds the edges to
  // whole units of 1.49e-8 (a wrong direction); long double keeps about three digits.
  EXPECT_GE(find("offset-1e8-features-1e-8", Precision::Float).newell, zero);
  EXPECT_GT(find("offset-1e8-features-1e-8", Precision::Double).newell, 0.1);
  EXPECT_LT(find("offset-1e8-features-1e-8", Precision::LongDouble).newell, 1e-2);
  // The unit square at 1e8: exact in double, lost in float.
  EXPECT_LT(find("offset-1e8-unit-square", Precision::Double).newell, 1e-15);
  EXPECT_GE(find("offset-1e8-unit-square", Precision::Float).naive, zero);
  // Subnormal coordinates: every product underflows.
  EXPECT_GE(find("subnormal-triangle", Precision::Double).naive, zero);
}

// The numeric path scales by powers of two, so subnormal and huge polygons keep their normal.
TEST(HardCases, NumericNormalSurvivesSubnormalAndHugeCoordinates) {
  const ProblemSet set = hard("normals.yaml");
  const double third = 1 / std::sqrt(3.0);
  for (const char* id :
       {"subnormal-triangle", "huge-triangle", "near-parallel-edges", "near-zero-edge"}) {
    const NumericResult r = numeric(problem(set, id), Precision::Double);
    const std::vector<long double> u = raw(r, "unit_normal");
    ASSERT_EQ(u.size(), 3u) << id;
    for (long double x : u) EXPECT_NEAR(static_cast<double>(x), third, 1e-12) << id;
  }
}

TEST(HardCases, BackfaceNearThePlaneExactAndAdaptive) {
  const ProblemSet set = hard("backface.yaml");
  const ProblemResult front = solve_problem(problem(set, "eye-1e-18-in-front"), set.file, true);
  EXPECT_EQ(front.answers.find("facing")->word, "front");
  EXPECT_EQ(exact_text(front, "df"), "63/50000000000000000000");
  EXPECT_TRUE(front.derivation.has_warnings());
  const ProblemResult on = solve_problem(problem(set, "eye-in-plane"), set.file, true);
  EXPECT_EQ(on.answers.find("facing")->word, "edge_on");
  EXPECT_EQ(solve_problem(problem(set, "far-face-eye-in-plane"), set.file, false)
                .answers.find("facing")
                ->word,
            "edge_on");
  // In double the inputs are rounded; the numeric path warns that D_f is ill-conditioned.
  EXPECT_TRUE(
      has_warning(numeric(problem(set, "eye-1e-18-in-front"), Precision::Double), "nearly in"));
}

TEST(HardCases, NaiveSignsFailNearThePlaneAdaptiveNever) {
  for (Precision p : {Precision::Float, Precision::Double}) {
    const bench::FacingStudy s = bench::facing_study(p, 400, kSeed);
    EXPECT_EQ(s.cases, 400);
    EXPECT_GT(s.naive_wrong, 10) << to_string(p);
    EXPECT_EQ(s.adaptive_wrong, 0) << to_string(p);
    EXPECT_GE(s.exact_fallbacks, s.naive_wrong) << to_string(p);
  }
}

TEST(HardCases, EdgeOnPlaneMethodWarnsAndFallsBack) {
  const ProblemSet set = hard("planes.yaml");
  const ProblemSpec& spec = problem(set, "edge-on-depth");
  const ProblemResult r = solve_problem(spec, set.file, true);
  ASSERT_FALSE(r.error);
  EXPECT_EQ(exact_text(r, "z"), "5");
  EXPECT_EQ(exact_text(r, "plane"), "1, 5000, -1, 500100");
  bool warned = false;
  for (const Step& s : r.derivation.steps())
    warned =
        warned || (s.level == Step::Level::Warning && s.title.en() == "Nearly edge-on triangle" &&
                   s.note.en().find("κ") != std::string::npos);
  EXPECT_TRUE(warned);
  // float: the plane method would keep no digit, so z comes from barycentric interpolation and
  // stays within the vertices' depths [0, 10]; double and long double land near 5.
  const NumericResult f = numeric(spec, Precision::Float);
  EXPECT_TRUE(has_warning(f, "barycentric"));
  const long double zf = raw(f, "z")[0];
  EXPECT_GE(zf, 0);
  EXPECT_LE(zf, 10);
  EXPECT_NEAR(static_cast<double>(raw(numeric(spec, Precision::Double), "z")[0]), 5.0, 1e-4);
  EXPECT_NEAR(static_cast<double>(raw(numeric(spec, Precision::LongDouble), "z")[0]), 5.0, 1e-7);
}

TEST(HardCases, PointsAtNearAndBehindTheEyePlane) {
  const ProblemSet set = hard("eye_plane.yaml");
  for (const char* id : {"w-zero", "w-negative"}) {
    const ProblemResult r = solve_problem(problem(set, id), set.file, true);
    EXPECT_EQ(r.answers.find("ndc")->shape, Value::Shape::Null) << id;
    EXPECT_FALSE(r.answers.find("inside")->flag) << id;
    EXPECT_TRUE(r.derivation.has_warnings()) << id;
    for (Precision p : {Precision::Float, Precision::Double}) {
      const NumericResult n = numeric(problem(set, id), p);
      EXPECT_EQ(n.answers.find("ndc")->shape, Value::Shape::Null) << id;
      EXPECT_FALSE(n.answers.find("inside")->flag) << id;
    }
  }
  const ProblemResult tiny = solve_problem(problem(set, "w-tiny"), set.file, true);
  EXPECT_EQ(exact_text(tiny, "clip").substr(0, 6), "1, 1, ");
  EXPECT_TRUE(test::same(tiny.answers.find("ndc")->exact[0], GiNaC::pow(10, 12)));
  EXPECT_FALSE(tiny.answers.find("inside")->flag);
  const NumericResult d = numeric(problem(set, "w-tiny"), Precision::Double);
  EXPECT_NEAR(static_cast<double>(raw(d, "ndc")[0]) / 1e12, 1.0, 1e-9);
  const ProblemResult dx = solve_problem(problem(set, "directx-w-tiny"), set.file, false);
  EXPECT_TRUE(test::same(dx.answers.find("ndc")->exact[0], GiNaC::pow(10, 12)));
}

TEST(HardCases, FarNearOneMillionFloatCannotSeparateWhatExactDoes) {
  const ProblemSet set = hard("eye_plane.yaml");
  const ProblemSpec& a = problem(set, "deep-far-near-1e6");
  const ProblemSpec& b = problem(set, "deep-far-near-1e6-behind-by-1e-3");
  const ProblemResult ea = solve_problem(a, set.file, true), eb = solve_problem(b, set.file, false);
  EXPECT_EQ(exact_sign(eb.answers.find("window")->exact[2] - ea.answers.find("window")->exact[2]),
            1);
  bool noted = false;
  for (const Step& s : ea.derivation.steps()) noted = noted || s.title.en() == "Depth precision";
  EXPECT_TRUE(noted);
  EXPECT_EQ(raw(numeric(a, Precision::Float), "window")[2],
            raw(numeric(b, Precision::Float), "window")[2]);
  EXPECT_LT(raw(numeric(a, Precision::Double), "window")[2],
            raw(numeric(b, Precision::Double), "window")[2]);
}

TEST(HardCases, DepthBufferReversedZSeparatesWhatStandardCannot) {
  using bench::DepthMapping;
  for (double ratio : {1e3, 1e4, 1e5, 1e6}) {
    EXPECT_EQ(bench::depth_flips(DepthMapping::ReversedZ, ratio, 1e-4), 0) << ratio;
    if (ratio >= 1e4) {
      EXPECT_GT(bench::depth_flips(DepthMapping::OpenGL, ratio, 1e-4), 0) << ratio;
      EXPECT_GT(bench::depth_flips(DepthMapping::DirectX, ratio, 1e-4), 0) << ratio;
    }
    EXPECT_LT(bench::smallest_separable_gap(DepthMapping::ReversedZ, ratio) * 100,
              bench::smallest_separable_gap(DepthMapping::OpenGL, ratio))
        << ratio;
  }
  // Standard mappings get worse as far/near grows.
  EXPECT_GT(bench::smallest_separable_gap(DepthMapping::OpenGL, 1e6),
            bench::smallest_separable_gap(DepthMapping::OpenGL, 1e3));
}

TEST(HardCases, HugeTinyAndSubnormalVectors) {
  const ProblemSet set = hard("magnitudes.yaml");
  const ProblemResult huge = solve_problem(problem(set, "huge-vectors"), set.file, true);
  EXPECT_EQ(exact_text(huge, "dot"), "1");
  EXPECT_EQ(exact_text(huge, "cross"), "1, -1, -1");
  EXPECT_EQ(exact_text(huge, "angle"), "60");
  const ProblemResult sub = solve_problem(problem(set, "subnormal-vectors"), set.file, true);
  EXPECT_NEAR(to_double(sub.answers.find("cos")->exact[0]), 1 / std::sqrt(5.0), 1e-16);
  for (const char* id : {"huge-vectors", "tiny-vectors", "subnormal-vectors", "mixed-vectors"}) {
    const ProblemSpec& spec = problem(set, id);
    const NumericResult exact = numeric(spec, Precision::Exact);
    const NumericResult d = numeric(spec, Precision::Double);
    // Scale-free answers survive in double thanks to the power-of-two scaling.
    for (const char* name : {"sin", "cos", "angle", "unit_normal"}) {
      const std::vector<long double> x = raw(d, name), r = raw(exact, name);
      ASSERT_EQ(x.size(), r.size()) << id << " " << name;
      for (std::size_t i = 0; i < x.size(); ++i)
        EXPECT_NEAR(static_cast<double>(x[i]), static_cast<double>(r[i]), 1e-12)
            << id << " " << name;
    }
  }
  EXPECT_TRUE(has_warning(numeric(problem(set, "tiny-vectors"), Precision::Double), "Underflow") ||
              raw(numeric(problem(set, "tiny-vectors"), Precision::Double), "cross")[2] == 0);
  EXPECT_TRUE(has_warning(numeric(problem(set, "ill-conditioned-transform"), Precision::Double),
                          "Ill-conditioned"));
}

// Degenerate input in decimals (collinear points, a triangle edge-on to the view): the exact
// solve refuses it, and so must every backend, with the same words — rounded, these points give
// a tiny nonzero normal, D_f or c, and a floating backend used to answer from that noise.
TEST(HardCases, DegenerateInputIsRefusedInEveryBackendAsTheExactSolveRefusesIt) {
  const ProblemSet set = load_problem_set_from_string(R"(
problems:
  - {id: normal, kind: normal, given: {points: [[0.1, 0.2, 0.3], [0.2, 0.4, 0.6], [0.3, 0.6, 0.9]]}}
  - {id: plane, kind: plane, given: {points: [[0.1, 0.2, 0.3], [0.2, 0.4, 0.6], [0.3, 0.6, 0.9]]}}
  - {id: backface, kind: backface, given: {points: [[0.1, 0.2, 0.3], [0.2, 0.4, 0.6], [0.3, 0.6, 0.9]], eye: [1, 0, 0]}}
  - {id: collinear-depth, kind: depth_at_pixel, given: {triangle: [[0.1, 0.2, 1], [0.2, 0.4, 2], [0.3, 0.6, 3]], pixel: [0.2, 0.4]}}
  - {id: edge-on-depth, kind: depth_at_pixel, given: {triangle: [[0.1, 0.2, 1], [0.2, 0.4, 2], [0.3, 0.6, 4]], pixel: [0.2, 0.4]}}
)",
                                                      "degenerate.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  for (const ProblemSpec& spec : set.problems) {
    const ProblemResult exact = solve_problem(spec, set.file, false);
    ASSERT_TRUE(exact.error) << spec.id;
    for (Precision p :
         {Precision::Float, Precision::Double, Precision::LongDouble, Precision::Exact}) {
      const ProblemResult r = solve_problem(spec, set.file, true, p);
      ASSERT_TRUE(r.error) << spec.id << " " << to_string(p);
      EXPECT_EQ(r.error->message, exact.error->message) << spec.id << " " << to_string(p);
    }
  }
  // The refusals name what is wrong.
  EXPECT_NE(solve_problem(set.problems[4], set.file, false).error->message.find("edge-on"),
            std::string::npos);
}

// Parallel decimal vectors have no unit normal in any backend.
TEST(HardCases, ParallelDecimalVectorsHaveNoUnitNormalInAnyBackend) {
  const ProblemSet set = load_problem_set_from_string(R"(
problems:
  - {id: v, kind: vectors, given: {a: [0.1, 0.2, 0.3], b: [0.3, 0.6, 0.9]}}
  - {id: w, kind: vectors, given: {a: [0.7, -0.1, 0.3], b: [-2.1, 0.3, -0.9]}}
)",
                                                      "parallel.yaml");
  for (const ProblemSpec& spec : set.problems)
    for (Precision p : {Precision::Float, Precision::Double, Precision::LongDouble}) {
      const ProblemResult r = solve_problem(spec, set.file, true, p);
      ASSERT_FALSE(r.error) << spec.id;
      const Value* unit = r.answers.find("unit_normal");
      ASSERT_NE(unit, nullptr);
      EXPECT_EQ(unit->shape, Value::Shape::Null) << spec.id << " " << to_string(p);
    }
}

}  // namespace
}  // namespace frustum
