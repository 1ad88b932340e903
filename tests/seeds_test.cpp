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

const char* const kSeedSets[] = {"000_projection_and_hidden_surfaces.yaml",
                                 "001_zbuffer_plane_method.yaml",
                                 "002_transforms_and_view_volume.yaml",
                                 "003_polygons_backface.yaml", "004_placing_and_projecting.yaml"};

TEST(Seed000, ProjectionPlaneIsMinus100Root3AndPPrime) {
  const SetResult r = solve_seed("000_projection_and_hidden_surfaces.yaml");
  const ProblemResult& p = problem(r, "seed000-projection-plane");
  EXPECT_EQ(exact_text(p, "plane_z"), "-100*sqrt(3)");
  EXPECT_EQ(exact_text(p, "projected"), "0, 100*sqrt(3)/3, -100*sqrt(3)");
  EXPECT_NEAR(p.answers.find("plane_z")->numbers[0], -173.2, 0.05);
}

TEST(Seed000, NearPlaneMapsToMinusOneDespiteTheProse) {
  const SetResult r = solve_seed("000_projection_and_hidden_surfaces.yaml");
  const ProblemResult& p = problem(r, "seed000-near-far-map");
  EXPECT_EQ(exact_text(p, "ndc"), "0, 0, -1");
  bool noted = false;
  for (const Step& s : p.derivation.steps())
    noted = noted || s.note.en().find("contradicts this matrix") != std::string::npos;
  EXPECT_TRUE(noted) << "the derivation notes, in neutral words, the prose that says otherwise";
}

// (50, 50, 100) lies on the back plane z = z_max = 100, halfway from its centre to its corner
// (100, 100, 100).
TEST(Seed002, NormalizedViewVolumeMapsAPointOfTheBackPlaneToZOne) {
  const SetResult r = solve_seed("002_transforms_and_view_volume.yaml");
  const ProblemResult& p = problem(r, "seed002-view-volume");
  EXPECT_EQ(exact_text(p, "point"), "1/2, 1/2, 1");
  EXPECT_EQ(exact_text(p, "perspective_matrix"),
            "1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 100/99, -1/99, 0, 0, 1, 0");
}

TEST(Seed004, RotationAboutOneOneOneCyclesTheAxes) {
  const SetResult r = solve_seed("004_placing_and_projecting.yaml");
  const ProblemResult& p = problem(r, "seed004-axis-rotation");
  EXPECT_EQ(exact_text(p, "points"), "0, 1, 0");
  bool noted = false;
  for (const ProblemResult& q : r.problems)
    for (const Step& s : q.derivation.steps())
      noted = noted || s.note.en().find("−b = t = n·(w/h)·tan(θ/2)") != std::string::npos;
  EXPECT_TRUE(noted)
      << "the perspective derivation notes, in neutral words, where the aspect ratio belongs";
}

TEST(Seeds, PublishedAnswersScoreFullMarks) {
  for (const std::string name : kSeedSets) {
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
  for (const std::string name : kSeedSets) {
    const ProblemSet set = load_problem_set(source_path("problems/seeds/" + name));
    EXPECT_TRUE(set.all_errors().empty()) << name;
    const SetResult r = solve_set(set, false);
    for (const ProblemResult& p : r.problems) EXPECT_FALSE(p.error) << p.id;
  }
}

}  // namespace
}  // namespace frustum
