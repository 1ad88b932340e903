// Handedness as a course convention: `conventions: {handedness: left}` declared once
// changes every kind it concerns, each answer relates to the right-handed one as the derivation
// says (a mirror in z), the headers say the same handedness as the steps, and the grader takes
// the course's own form.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>

#include "grader/grade.hpp"
#include "solver/derivation/formats.hpp"
#include "solver/derivation/i18n.hpp"
#include "solver/problem/problem_set.hpp"
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// One problem of `kind` with `given` (YAML flow text), solved under `conventions`.
ProblemResult solve_one(const std::string& conventions, const std::string& kind,
                        const std::string& given) {
  const std::string yaml = "conventions: " + conventions +
                           "\nproblems:\n  - id: p\n    kind: " + kind + "\n    given: " + given +
                           "\n";
  const ProblemSet set = load_problem_set_from_string(yaml, "h.yaml");
  if (set.problems.empty()) throw std::runtime_error("no problem read: " + yaml);
  return solve_problem(set.problems.at(0), set.file, true);
}

const std::string kRight = "{api: opengl}";
const std::string kLeft = "{api: opengl, handedness: left}";

std::string point_text(const std::array<int, 3>& p) {
  return "[" + std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " + std::to_string(p[2]) +
         "]";
}
std::array<int, 3> mirrored(const std::array<int, 3>& p) { return {p[0], p[1], -p[2]}; }

const std::vector<double>& numbers(const ProblemResult& r, const std::string& answer) {
  const Value* v = r.answers.find(answer);
  if (!v) throw std::runtime_error("no answer " + answer);
  return v->numbers;
}

// Seed 003's example read left-handed: n = e₁ × e₀ = (−1, 1, −1), D_f = +2, front (right-handed:
// (1, −1, 1), −2, back).
TEST(Handedness, Seed003BackFaceExampleFlipsInALeftHandedCourse) {
  const std::string given = "{points: [[1, 0, 0], [1, 1, 1], [0, 1, 2]], eye: [0, 1, 0]}";
  const ProblemResult right = solve_one(kRight, "backface", given);
  const ProblemResult left = solve_one(kLeft, "backface", given);
  ASSERT_FALSE(right.error || left.error);
  EXPECT_EQ(test::exact_text(right, "normal"), "1, -1, 1");
  EXPECT_EQ(test::exact_text(right, "df"), "-2");
  EXPECT_EQ(right.answers.find("facing")->word, "back");
  EXPECT_EQ(test::exact_text(left, "normal"), "-1, 1, -1");
  EXPECT_EQ(test::exact_text(left, "df"), "2");
  EXPECT_EQ(left.answers.find("facing")->word, "front");
}

// Property over many triangles and eyes: the left-handed reading of the numbers is the
// right-handed reading of their mirror image in z — normal mirrored, D_f and facing the same —
// and, on the same numbers, the normal and D_f change sign.
TEST(Handedness, NormalAndFacingAreTheMirrorImagesOfTheRightHandedOnes) {
  std::mt19937 rng(16);
  std::uniform_int_distribution<int> coord(-6, 6);
  int checked = 0;
  for (int i = 0; i < 60; ++i) {
    std::array<std::array<int, 3>, 4> p;  // three vertices and the eye
    for (auto& q : p)
      for (int& c : q) c = coord(rng);
    const auto given = [&](bool mirror) {
      const auto at = [&](int k) { return point_text(mirror ? mirrored(p[k]) : p[k]); };
      return "{points: [" + at(0) + ", " + at(1) + ", " + at(2) + "], eye: " + at(3) + "}";
    };
    const ProblemResult left = solve_one(kLeft, "backface", given(false));
    if (left.error) continue;  // a degenerate triangle
    const ProblemResult right_mirror = solve_one(kRight, "backface", given(true));
    const ProblemResult right_same = solve_one(kRight, "backface", given(false));
    ASSERT_FALSE(right_mirror.error || right_same.error);
    const std::vector<double>& nl = numbers(left, "normal");
    const std::vector<double>& nm = numbers(right_mirror, "normal");
    const std::vector<double>& ns = numbers(right_same, "normal");
    EXPECT_EQ((std::vector<double>{nl[0], nl[1], -nl[2]}), nm);
    EXPECT_EQ((std::vector<double>{-ns[0], -ns[1], -ns[2]}), nl);
    EXPECT_EQ(numbers(left, "df"), numbers(right_mirror, "df"));
    EXPECT_EQ(numbers(left, "df")[0], -numbers(right_same, "df")[0]);
    EXPECT_EQ(left.answers.find("facing")->word, right_mirror.answers.find("facing")->word);
    // The normal kind agrees with the back-face test's normal, in both forms of its given.
    const ProblemResult normal = solve_one(
        kLeft, "normal",
        "{points: [" + point_text(p[0]) + ", " + point_text(p[1]) + ", " + point_text(p[2]) + "]}");
    const ProblemResult abc = solve_one(
        kLeft, "normal",
        "{A: " + point_text(p[0]) + ", B: " + point_text(p[1]) + ", C: " + point_text(p[2]) + "}");
    EXPECT_EQ(numbers(normal, "normal"), nl);
    EXPECT_EQ(numbers(abc, "normal"), nl);  // AC × AB = e₁ × e₀ for a triangle
    // The plane through them: the same plane, its normal the left-handed front normal.
    const std::string polygon =
        "{points: [" + point_text(p[0]) + ", " + point_text(p[1]) + ", " + point_text(p[2]) + "]}";
    const ProblemResult plane_left = solve_one(kLeft, "plane", polygon);
    const ProblemResult plane_right = solve_one(kRight, "plane", polygon);
    EXPECT_EQ(numbers(plane_left, "normal"), nl);
    EXPECT_EQ(numbers(plane_left, "distance"), numbers(plane_right, "distance"));
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

// Seed 001's plane method is in projection coordinates, left-handed in either course: the same
// answers, and the note says how the course's eye space relates to them.
TEST(Handedness, DepthAtPixelIsTheSameInBothCoursesAndSaysWhy) {
  const std::string given = "{triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}";
  const ProblemResult right = solve_one(kRight, "depth_at_pixel", given);
  const ProblemResult left = solve_one(kLeft, "depth_at_pixel", given);
  ASSERT_FALSE(right.error || left.error);
  EXPECT_EQ(test::exact_text(left, "normal"), "9, 9, -9");
  EXPECT_EQ(test::exact_text(left, "z"), "8");
  EXPECT_EQ(numbers(left, "plane"), numbers(right, "plane"));
  std::string notes;
  for (const Step& st : left.derivation.steps()) notes += st.note.en() + "\n";
  EXPECT_NE(notes.find("as this course's eye space is"), std::string::npos) << notes;
}

// look_at: the camera looks down +z (center at z = +5 in view coordinates), V_right =
// diag(−1, 1, −1, 1)·V_left, and every header of the derivation says left-handed.
TEST(Handedness, LookAtTakesTheLeftHandedBasisAndItsHeadersSaySo) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-5, 5);
  for (int i = 0; i < 30; ++i) {
    const std::array<int, 3> eye{coord(rng), coord(rng), coord(rng)},
        center{coord(rng), coord(rng), coord(rng)};
    const std::string given = "{eye: " + point_text(eye) + ", center: " + point_text(center) +
                              ", up: [0, 1, 0], points: [" + point_text(center) + "]}";
    const ProblemResult left = solve_one(kLeft, "look_at", given);
    const ProblemResult right = solve_one(kRight, "look_at", given);
    if (right.error) continue;  // up along the view direction, or center = eye
    ASSERT_FALSE(left.error);
    const std::vector<double>& l = numbers(left, "matrix");
    const std::vector<double>& r = numbers(right, "matrix");
    for (int row = 0; row < 4; ++row)
      for (int col = 0; col < 4; ++col)
        EXPECT_NEAR(r[row * 4 + col], (row == 0 || row == 2 ? -1 : 1) * l[row * 4 + col], 1e-12);
    const double distance = std::sqrt(double((center[0] - eye[0]) * (center[0] - eye[0]) +
                                             (center[1] - eye[1]) * (center[1] - eye[1]) +
                                             (center[2] - eye[2]) * (center[2] - eye[2])));
    EXPECT_NEAR(numbers(left, "points")[2], distance, 1e-12);
    EXPECT_NEAR(numbers(right, "points")[2], -distance, 1e-12);
    for (const Step& s : left.derivation.steps()) {
      EXPECT_EQ(s.title.en().find("right-handed"), std::string::npos) << s.title.en();
      if (s.title.en() == "Conventions") {
        EXPECT_NE(s.note.en().find("left-handed"), std::string::npos) << s.note.en();
        EXPECT_EQ(s.note.en().find("right-handed"), std::string::npos) << s.note.en();
      }
    }
  }
}

// The projection: P_left = P_right·diag(1, 1, −1, 1) for every type, z = n ↦ −1 and z = f ↦ +1
// looking down +z, and project_point's picture is the right-handed one mirrored left-right.
TEST(Handedness, ProjectionIsTheRightHandedOneMirroredInZ) {
  for (const std::string projection :
       {"perspective: {fovy: 90, aspect: 2, near: 1, far: 3}",
        "frustum: {left: -1, right: 2, bottom: -1, top: 1, near: 2, far: 5}",
        "ortho: {left: -100, right: 100, bottom: -50, top: 50, near: 10, far: 1000}"})
    for (const std::string api : {"opengl", "processing"}) {
      const ProblemResult left = solve_one("{api: " + api + ", handedness: left}",
                                           "projection_matrix", "{" + projection + "}");
      const ProblemResult right =
          solve_one("{api: " + api + "}", "projection_matrix", "{" + projection + "}");
      ASSERT_FALSE(left.error || right.error) << projection;
      const std::vector<double>& l = numbers(left, "matrix");
      const std::vector<double>& r = numbers(right, "matrix");
      for (int k = 0; k < 16; ++k)
        EXPECT_NEAR(l[k], (k % 4 == 2 ? -1 : 1) * r[k], 1e-12) << projection;
      // Looking down +z: the near plane's z = n maps to −1 and the far plane's to +1.
      const Value* m = left.answers.find("matrix");
      const auto ndc_z = [&](const Exact& z) {
        const Exact zc = m->exact[10] * z + m->exact[11], wc = m->exact[14] * z + m->exact[15];
        return to_double(Exact(zc / wc));
      };
      const bool ortho = projection.rfind("ortho", 0) == 0;
      const Exact n = ortho                  ? 10
                      : projection[0] == 'p' ? 1
                                             : 2,
                  f = ortho                  ? 1000
                      : projection[0] == 'p' ? 3
                                             : 5;
      EXPECT_NEAR(ndc_z(n), -1, 1e-12) << projection;
      EXPECT_NEAR(ndc_z(f), 1, 1e-12) << projection;
    }
  const std::string given =
      "{point: [1, 2, 0], camera: {eye: [3, 1, 6], center: [0, 0, 0], up: [0, 1, 0]}, perspective: "
      "{fovy: 60, aspect: 1, near: 1, far: 20}, viewport: {width: 200, height: 100}}";
  const ProblemResult left = solve_one(kLeft, "project_point", given);
  const ProblemResult right = solve_one(kRight, "project_point", given);
  ASSERT_FALSE(left.error || right.error);
  const std::vector<double>& l = numbers(left, "ndc");
  const std::vector<double>& r = numbers(right, "ndc");
  EXPECT_NEAR(l[0], -r[0], 1e-12);
  EXPECT_NEAR(l[1], r[1], 1e-12);
  EXPECT_NEAR(l[2], r[2], 1e-12);
  EXPECT_EQ(left.answers.find("inside")->flag, right.answers.find("inside")->flag);
  std::string notes;
  for (const Step& st : left.derivation.steps()) notes += st.note.en() + "\n";
  EXPECT_NE(notes.find("mirrored left to right"), std::string::npos) << notes;
}

// The bundled example: every answer in the course's left-handed form is marked correct; the
// right-handed answers to the same numbers are not, and the grader names the right-handed
// projection matrix.
TEST(Handedness, GraderAcceptsTheCoursesOwnFormAndNamesTheRightHandedOne) {
  const ProblemSet set =
      load_problem_set(test::source_path("problems/examples/course_handedness.yaml"));
  const SolvedSet key = solve_for_grading(set);
  const std::string own =
      "student: s\nanswers:\n"
      "  lh-backface: {normal: [-1, 1, -1], view: [-1, 1, 0], df: 2, facing: front}\n"
      "  lh-perspective:\n    matrix: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 2, -3], [0, 0, 1, 0]]\n"
      "  lh-look-at:\n    matrix: [[-1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -1, 5], [0, 0, 0, 1]]\n";
  const GradeReport mine = grade(set, load_submission_from_string(own, "own.yaml"), &key);
  int graded = 0;
  for (const ProblemGrade& p : mine.problems)
    for (const AnswerGrade& a : p.answers)
      if (a.verdict != Verdict::Missing) {
        EXPECT_EQ(a.verdict, Verdict::Correct) << p.id << "." << a.name << ": " << a.feedback;
        ++graded;
      }
  EXPECT_EQ(graded, 6);
  const std::string right_handed =
      "student: s\nanswers:\n"
      "  lh-backface: {normal: [1, -1, 1], facing: back}\n"
      "  lh-perspective:\n    matrix: [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, -2, -3], [0, 0, -1, "
      "0]]\n";
  const GradeReport theirs = grade(set, load_submission_from_string(right_handed, "rh.yaml"), &key);
  for (const ProblemGrade& p : theirs.problems)
    for (const AnswerGrade& a : p.answers) {
      if (a.verdict == Verdict::Missing) continue;
      EXPECT_NE(a.verdict, Verdict::Correct) << p.id << "." << a.name;
      if (p.id == "lh-perspective") {
        EXPECT_EQ(a.misconception.en(), "right-handed matrix");
      }
    }
}

// Declaring it: a misspelt value is refused with a suggestion, DirectX cannot be right-handed
// here, and the kinds that are not yet left-handed refuse rather than answer right-handed.
TEST(Handedness, DeclarationErrorsNameTheField) {
  const auto error_of = [](const std::string& conventions, const std::string& kind,
                           const std::string& given) {
    const std::string yaml = "conventions: " + conventions +
                             "\nproblems:\n  - id: p\n    kind: " + kind + "\n    given: " + given +
                             "\n";
    const std::vector<Diagnostic> errors =
        load_problem_set_from_string(yaml, "h.yaml").all_errors();
    return errors.empty() ? std::string() : errors.front().format();
  };
  const std::string tri = "{points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}";
  EXPECT_NE(error_of("{handedness: lefty}", "normal", tri).find("did you mean 'left'"),
            std::string::npos)
      << error_of("{handedness: lefty}", "normal", tri);
  EXPECT_NE(
      error_of("{api: directx, handedness: right}", "normal", tri).find("conventions.handedness"),
      std::string::npos);
  EXPECT_EQ(error_of("{api: directx, handedness: left}", "normal", tri), "");
  EXPECT_EQ(
      error_of(kLeft, "projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, 300]}"),
      "");
  EXPECT_EQ(error_of(kLeft, "edge_visibility", "{solid: cube, eye: [3, 4, 5]}"), "");
}

// edge_visibility in a left-handed OpenGL course: counter-clockwise from outside is still front,
// so the front normal is e₁ × e₀. A named solid is listed counter-clockwise from outside in that
// frame, so its faces, edges and convexity are those of the same solid read right-handed; a
// mesh of the instructor's is read the course's way: the right-handed listing of the cube,
// given to a left-handed course, is the cube turned inside out (every face flipped), and its
// listing reversed is the cube again.
TEST(Handedness, EdgeVisibilityFollowsALeftHandedCourse) {
  const auto words = [](const ProblemResult& r, const std::string& name) {
    std::map<std::string, std::string> m;
    for (const auto& [k, w] : r.answers.find(name)->entries) m[k] = w;
    return m;
  };
  std::mt19937 rng(18);
  std::uniform_int_distribution<int> coord(-9, 9);
  int checked = 0;
  for (const char* solid : {"tetrahedron", "cube", "octahedron", "dodecahedron", "icosahedron"})
    for (int i = 0; i < 6; ++i) {
      std::array<int, 3> eye{coord(rng), coord(rng), coord(rng)};
      if (eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2] < 25) continue;
      const std::string given = std::string("{solid: ") + solid + ", eye: " + point_text(eye) + "}";
      const ProblemResult right = solve_one(kRight, "edge_visibility", given);
      const ProblemResult left = solve_one(kLeft, "edge_visibility", given);
      ASSERT_FALSE(right.error || left.error) << given;
      EXPECT_EQ(words(left, "faces"), words(right, "faces")) << given;
      EXPECT_EQ(words(left, "edges"), words(right, "edges")) << given;
      EXPECT_TRUE(left.answers.find("convex")->flag) << given;
      ++checked;
    }
  EXPECT_GT(checked, 20);

  const std::string vertices =
      "[[-1,1,1],[1,1,1],[1,1,-1],[-1,1,-1],[-1,-1,1],[1,-1,1],[1,-1,-1],[-1,-1,-1]]";
  const std::string ccw_right = "[[0,1,2,3],[7,6,5,4],[4,5,1,0],[5,6,2,1],[6,7,3,2],[7,4,0,3]]";
  const std::string ccw_left = "[[0,3,2,1],[7,4,5,6],[4,0,1,5],[5,1,2,6],[6,2,3,7],[7,3,0,4]]";
  const auto mesh = [&](const std::string& faces) {
    return "{mesh: {vertices: " + vertices + ", faces: " + faces + "}, eye: [3, 4, 5]}";
  };
  const ProblemResult right = solve_one(kRight, "edge_visibility", mesh(ccw_right));
  const ProblemResult left = solve_one(kLeft, "edge_visibility", mesh(ccw_left));
  const ProblemResult inside_out = solve_one(kLeft, "edge_visibility", mesh(ccw_right));
  ASSERT_FALSE(right.error || left.error || inside_out.error) << test::error_text(inside_out);
  EXPECT_EQ(words(left, "faces"), words(right, "faces"));
  EXPECT_EQ(words(left, "edges"), words(right, "edges"));
  int front = 0;
  for (const auto& [face, w] : words(right, "faces")) {
    front += w == "front";
    EXPECT_EQ(words(inside_out, "faces")[face], w == "front" ? "back" : "front") << face;
  }
  EXPECT_EQ(front, 3);  // seen from (3, 4, 5): the faces x = 1, y = 1, z = 1
  // The derivation says which normal a left-handed course takes, and the faces as given.
  const std::string text = render_problem_markdown(left, Lang::En);
  EXPECT_NE(text.find("n = e₁ × e₀"), std::string::npos) << text;
  EXPECT_NE(text.find("face 0 [0 3 2 1]"), std::string::npos) << text;
  EXPECT_NE(render_problem_markdown(left, Lang::Ja).find("e₁ × e₀ である"), std::string::npos);
}

// projection_plane in a left-handed course: the eye looks down +z, so the plane is at +s and a
// point in front of the eye has z > 0; the answers are the right-handed ones mirrored in z (the
// seed's window 200 × 200, fov 60°: s = 100√3, P(0, 100, 300) ↦ (0, 100√3/3, 100√3)).
TEST(Handedness, ProjectionPlaneLooksDownPlusZInALeftHandedCourse) {
  const ProblemResult right =
      solve_one(kRight, "projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, -300]}");
  const ProblemResult left =
      solve_one(kLeft, "projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, 300]}");
  ASSERT_FALSE(right.error || left.error) << test::error_text(left);
  EXPECT_EQ(test::exact_text(right, "plane_z"), "-100*sqrt(3)");
  EXPECT_EQ(test::exact_text(left, "plane_z"), "100*sqrt(3)");
  EXPECT_EQ(test::exact_text(left, "projected"), "0, 100*sqrt(3)/3, 100*sqrt(3)");
  // Property: any point and window, mirrored in z, gives the mirrored answer.
  std::mt19937 rng(19);
  std::uniform_int_distribution<int> c(-40, 40), depth(1, 40);
  for (int i = 0; i < 30; ++i) {
    const std::array<int, 3> p{10 * c(rng), 10 * c(rng), 10 * depth(rng)};
    const std::string window = i % 2 ? "[640, 480]" : "[400, 300]";
    const std::string fov = std::to_string(30 + 15 * (i % 4));
    const ProblemResult r = solve_one(
        kRight, "projection_plane",
        "{window: " + window + ", fov: " + fov + ", point: " + point_text(mirrored(p)) + "}");
    const ProblemResult l =
        solve_one(kLeft, "projection_plane",
                  "{window: " + window + ", fov: " + fov + ", point: " + point_text(p) + "}");
    ASSERT_FALSE(r.error || l.error);
    const std::vector<double>& a = numbers(r, "projected");
    const std::vector<double>& b = numbers(l, "projected");
    EXPECT_DOUBLE_EQ(b[0], a[0]);
    EXPECT_DOUBLE_EQ(b[1], a[1]);
    EXPECT_DOUBLE_EQ(b[2], -a[2]);
  }
  // A point behind a left-handed eye (z < 0) has no projection.
  EXPECT_TRUE(
      solve_one(kLeft, "projection_plane", "{window: [200, 200], fov: 60, point: [0, 100, -300]}")
          .error);
  EXPECT_NE(render_problem_markdown(left, Lang::Ru).find("левой системе координат курса"),
            std::string::npos);
}

// JSON states the handedness each problem was solved in: the declared one, else the API's own.
TEST(Handedness, JsonStatesTheHandednessUsed) {
  for (const auto& [conventions, expected] : {std::pair<std::string, std::string>{kLeft, "left"},
                                              {kRight, "right"},
                                              {"{api: directx}", "left"},
                                              {"{api: processing, handedness: right}", "right"}}) {
    const std::string yaml =
        "conventions: " + conventions +
        "\nproblems:\n  - id: p\n    kind: normal\n    given: {points: [[0, 0, 0], "
        "[1, 0, 0], [0, 1, 0]]}\n";
    const SetResult solved = solve_set(load_problem_set_from_string(yaml, "h.yaml"), false, {});
    EXPECT_EQ(render_json(solved)["problems"][0]["conventions"]["handedness"], expected)
        << conventions;
  }
}

// A scene in a left-handed OpenGL or Processing course renders through LookAtLH's basis and the
// projection with its third column negated: the picture is the right-handed picture of the scene
// mirrored in z (every vertex, the camera and the light), pixel for pixel — culling
// (counter-clockwise = front in the window) included. DirectX's own left-handedness renders too.
TEST(Handedness, RenderOfALeftHandedSceneIsTheRightHandedRenderOfItsMirror) {
  const std::string dir = ::testing::TempDir();
  const auto scene = [&](const std::string& name, const std::string& conventions, int s) {
    const auto p = [&](int x, int y, int z) {
      return "[" + std::to_string(x) + ", " + std::to_string(y) + ", " + std::to_string(s * z) +
             "]";
    };
    std::ofstream(dir + name) << "conventions: " << conventions
                              << "\nscene:\n  viewport: {width: 48, height: 40}\n"
                              << "  camera: {eye: " << p(2, 3, 9) << ", center: " << p(0, 0, 0)
                              << ", up: " << p(0, 1, 1)
                              << "}\n  perspective: {fovy: 60, aspect: 1.2, near: 1, far: 30}\n"
                              << "  light: {direction: " << p(1, -2, -3) << "}\n"
                              << "  objects:\n"
                              << "    - {triangle: [" << p(-3, -2, 0) << ", " << p(3, -2, 1) << ", "
                              << p(0, 3, -1) << "], fill: [200, 40, 40]}\n"
                              << "    - {triangle: [" << p(-2, 2, 2) << ", " << p(0, -3, 2) << ", "
                              << p(2, 2, 3) << "], fill: [40, 200, 40], cull: back}\n"
                              << "    - {triangle: [" << p(-2, -1, 3) << ", " << p(2, 0, 4) << ", "
                              << p(-1, 2, 4) << "], fill: [40, 40, 200], cull: back}\n";
    return dir + name;
  };
  const auto run = [](const std::string& args) { return test::frustum_run(args).output; };
  for (const std::string api : {"opengl", "processing"}) {
    const std::string left =
        run("render " + scene("lh.yaml", "{api: " + api + ", handedness: left}", 1) + " -o " + dir +
            "lh.png");
    const std::string right =
        run("render " + scene("rh.yaml", "{api: " + api + "}", -1) + " -o " + dir + "rh.png");
    EXPECT_NE(left.find("drawn"), std::string::npos) << left;
    EXPECT_NE(right.find("drawn"), std::string::npos) << right;
    const std::string a = test::read_file(dir + "lh.png"), b = test::read_file(dir + "rh.png");
    ASSERT_FALSE(a.empty());
    EXPECT_EQ(a, b) << api
                    << ": the left-handed picture differs from the mirrored right-handed one";
    // And it is not the right-handed picture of the same numbers (the test would be vacuous).
    run("render " + scene("rs.yaml", "{api: " + api + "}", 1) + " -o " + dir + "rs.png");
    EXPECT_NE(a, test::read_file(dir + "rs.png")) << api;
  }
  const std::string dx =
      run("render " + scene("dx.yaml", "{api: directx}", 1) + " -o " + dir + "dx.png");
  EXPECT_NE(dx.find("drawn"), std::string::npos) << dx;
  // The render kind in a set (exact decisions included) answers the same pixels.
  const auto given = [](int s) {
    const auto z = [&](int v) { return std::to_string(s * v); };
    return "{scene: {viewport: {width: 48, height: 40}, camera: {eye: [2, 3, " + z(9) +
           "], center: [0, 0, 0], up: [0, 1, " + z(1) +
           "]}, perspective: {fovy: 60, aspect: 1.2, near: 1, far: 30}, light: {direction: [1, "
           "-2, " +
           z(-3) + "]}, objects: [{triangle: [[-3, -2, 0], [3, -2, " + z(1) + "], [0, 3, " + z(-1) +
           "]], fill: [200, 40, 40]}, {triangle: [[-2, 2, " + z(2) + "], [0, -3, " + z(2) +
           "], [2, 2, " + z(3) +
           "]], fill: [40, 200, 40], cull: back}]}, pixels: [[24, 20], [20, 18], [30, 25]]}";
  };
  const ProblemResult left = solve_one(kLeft, "render", given(1));
  const ProblemResult right = solve_one(kRight, "render", given(-1));
  ASSERT_FALSE(left.error || right.error) << test::error_text(left);
  EXPECT_EQ(numbers(left, "pixels"), numbers(right, "pixels"));
  EXPECT_EQ(numbers(left, "pixels")[0], 196);  // lit, drawn: the first triangle's front
}

}  // namespace
}  // namespace frustum
