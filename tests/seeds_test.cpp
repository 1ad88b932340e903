// The seeds' worked answers, exactly as published.
#include "grader/grade.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using test::exact_text;
using test::source_path;

SetResult solve_seed(const std::string& file) {
  const ProblemSet set = load_problem_set(source_path("problems/seeds/" + file));
  EXPECT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  return solve_set(set, true);
}

const ProblemResult& problem(const SetResult& r, const std::string& id) {
  for (const ProblemResult& p : r.problems)
    if (p.id == id) return p;
  throw std::runtime_error("no problem " + id);
}

TEST(Seed001, UnitNormalIsOneOverRootThree) {
  const SetResult r = solve_seed("001_zbuffer_plane_method.yaml");
  const ProblemResult& p = problem(r, "seed001-unit-normal");
  EXPECT_EQ(exact_text(p, "normal"), "9, 9, -9");
  EXPECT_EQ(exact_text(p, "unit_normal"), "sqrt(3)/3, sqrt(3)/3, -sqrt(3)/3");
}

TEST(Seed001, PlaneIsXPlusYMinusZEqualsMinusSix) {
  const SetResult r = solve_seed("001_zbuffer_plane_method.yaml");
  const ProblemResult& p = problem(r, "seed001-plane");
  EXPECT_EQ(exact_text(p, "plane"), "1, 1, -1, -6");
  EXPECT_EQ(p.answers.find("plane")->shown().unicode, "x + y − z = −6");
}

TEST(Seed001, PixelDepthIsEight) {
  const SetResult r = solve_seed("001_zbuffer_plane_method.yaml");
  const ProblemResult& p = problem(r, "seed001-pixel-z");
  EXPECT_EQ(exact_text(p, "z"), "8");
  EXPECT_EQ(p.answers.find("z")->numbers[0], 8.0);
  EXPECT_TRUE(p.answers.find("inside")->flag);
}

TEST(Seed001, NormLengthIsNineRootThreeInTheDerivation) {
  const SetResult r = solve_seed("001_zbuffer_plane_method.yaml");
  const ProblemResult& p = problem(r, "seed001-pixel-z");
  bool found = false;
  for (const Step& s : p.derivation.steps())
    found = found || s.formula.unicode.find("9√3") != std::string::npos ||
            s.substitution.unicode.find("9√3") != std::string::npos;
  EXPECT_TRUE(found) << "the derivation shows |AC × AB| = 9√3";
}

TEST(Seed003, CrossProductAreaSineAndUnitNormal) {
  const SetResult r = solve_seed("003_polygons_backface.yaml");
  const ProblemResult& p = problem(r, "seed003-cross-product");
  EXPECT_EQ(exact_text(p, "cross"), "-2, 1, 4");
  EXPECT_EQ(exact_text(p, "area"), "sqrt(21)");
  EXPECT_EQ(exact_text(p, "sin"), "sqrt(21)/5");
  EXPECT_EQ(exact_text(p, "unit_normal"), "-2*sqrt(21)/21, sqrt(21)/21, 4*sqrt(21)/21");
}

TEST(Seed003, BackfaceDiscriminantIsMinusTwoSoBack) {
  const SetResult r = solve_seed("003_polygons_backface.yaml");
  const ProblemResult& p = problem(r, "seed003-backface");
  EXPECT_EQ(exact_text(p, "normal"), "1, -1, 1");
  EXPECT_EQ(exact_text(p, "view"), "-1, 1, 0");
  EXPECT_EQ(exact_text(p, "df"), "-2");
  EXPECT_EQ(p.answers.find("facing")->word, "back");
}

TEST(Seeds, PublishedAnswersScoreFullMarks) {
  for (const std::string name : {"001_zbuffer_plane_method.yaml", "003_polygons_backface.yaml"}) {
    const ProblemSet set = load_problem_set(source_path("problems/seeds/" + name));
    const Submission s = load_submission(source_path("problems/seeds/answers/" + name));
    const GradeReport g = grade(set, s);
    EXPECT_TRUE(g.errors.empty()) << name << ": " << g.errors[0].format();
    EXPECT_GT(g.max_score, 0);
    EXPECT_DOUBLE_EQ(g.score, g.max_score) << name;
    for (const ProblemGrade& pg : g.problems)
      for (const AnswerGrade& a : pg.answers)
        EXPECT_EQ(a.verdict, Verdict::Correct) << pg.id << "." << a.name << ": " << a.feedback;
  }
}

TEST(Seeds, EverySeedSetChecksClean) {
  for (const std::string name : {"001_zbuffer_plane_method.yaml", "003_polygons_backface.yaml"}) {
    const ProblemSet set = load_problem_set(source_path("problems/seeds/" + name));
    EXPECT_TRUE(set.all_errors().empty()) << name;
    const SetResult r = solve_set(set, false);
    for (const ProblemResult& p : r.problems) EXPECT_FALSE(p.error) << p.id;
  }
}

}  // namespace
}  // namespace frustum
