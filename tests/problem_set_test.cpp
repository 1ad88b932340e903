// Loading problem sets: every kind of mistake gets one clear message naming the file, line,
// column and field, and one broken problem never stops the rest of the set.
#include "solver/problem/solve_set.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// Loads a set whose first problem is broken and whose second is fine; returns the first
// problem's diagnostic after checking the second still solves.
Diagnostic first_error(const std::string& broken_problem) {
  const std::string yaml =
      "problems:\n" + broken_problem +
      "  - id: fine\n    kind: vectors\n    given: {a: [2, 0, 1], b: [1, 2, 0]}\n";
  const ProblemSet set = load_problem_set_from_string(yaml, "set.yaml");
  EXPECT_TRUE(set.errors.empty());
  EXPECT_EQ(set.problems.size(), 2u);
  const SetResult r = solve_set(set, false);
  EXPECT_FALSE(r.problems.at(1).error) << "the rest of the set still runs";
  EXPECT_EQ(test::exact_text(r.problems.at(1), "cross"), "-2, 1, 4");
  const auto& e = r.problems.at(0).error;
  EXPECT_TRUE(e.has_value()) << "the broken problem reports an error";
  return e.value_or(Diagnostic{});
}

TEST(Loader, InvalidYamlNamesLineAndColumn) {
  const ProblemSet set =
      load_problem_set_from_string("problems:\n  - id: a\n    given: [1, 2\n", "bad.yaml");
  ASSERT_EQ(set.errors.size(), 1u);
  EXPECT_EQ(set.errors[0].where.file, "bad.yaml");
  EXPECT_GE(set.errors[0].where.line, 3);
  EXPECT_NE(set.errors[0].format().find("invalid YAML"), std::string::npos);
}

TEST(Loader, UnknownKindSuggestsTheClosest) {
  const Diagnostic d = first_error("  - id: a\n    kind: depth_at_pixle\n    given: {}\n");
  EXPECT_EQ(d.field, "problems[0].kind");
  EXPECT_EQ(d.where.line, 3);
  EXPECT_EQ(d.where.column, 11);
  EXPECT_NE(d.message.find("unknown kind 'depth_at_pixle'"), std::string::npos);
  EXPECT_NE(d.message.find("did you mean 'depth_at_pixel'"), std::string::npos);
}

TEST(Loader, MissingField) {
  const Diagnostic d = first_error(
      "  - id: a\n    kind: depth_at_pixel\n    given:\n      triangle: "
      "[[0,0,6],[3,0,9],[0,3,9]]\n");
  EXPECT_EQ(d.field, "problems[0].given.pixel");
  EXPECT_NE(d.message.find("missing required field"), std::string::npos);
  EXPECT_EQ(d.format().rfind("set.yaml:5:", 0), 0u) << d.format();
}

TEST(Loader, MisspelledFieldIsNamedWithASuggestion) {
  const Diagnostic d = first_error(
      "  - id: a\n    kind: depth_at_pixel\n    given:\n      triangel: "
      "[[0,0,6],[3,0,9],[0,3,9]]\n      pixel: [1, 1]\n");
  EXPECT_NE(d.message.find("triangel"), std::string::npos) << d.format();
  const Diagnostic unknown = first_error(
      "  - id: a\n    kind: vectors\n    given: {a: [1,0,0], b: [0,1,0], c: [0,0,1]}\n");
  EXPECT_EQ(unknown.field, "problems[0].given.c");
  EXPECT_NE(unknown.message.find("unknown field"), std::string::npos);
  const Diagnostic top =
      first_error("  - id: a\n    kind: vectors\n    giben: {a: [1,0,0], b: [0,1,0]}\n");
  EXPECT_NE(top.message.find("did you mean 'given'"), std::string::npos) << top.format();
}

TEST(Loader, WrongTypeAndLength) {
  const Diagnostic type =
      first_error("  - id: a\n    kind: vectors\n    given: {a: \"hello\", b: [0,1,0]}\n");
  EXPECT_EQ(type.field, "problems[0].given.a");
  EXPECT_NE(type.message.find("expected a list of 3 numbers"), std::string::npos);
  const Diagnostic length =
      first_error("  - id: a\n    kind: vectors\n    given: {a: [1, 2], b: [0,1,0]}\n");
  EXPECT_NE(length.message.find("got a list of 2"), std::string::npos);
  const Diagnostic point = first_error(
      "  - id: a\n    kind: backface\n    given: {points: [[0,0,0],[1,0],[0,1,0]], eye: "
      "[0,0,1]}\n");
  EXPECT_EQ(point.field, "problems[0].given.points[1]");
  const Diagnostic word =
      first_error("  - id: a\n    kind: vectors\n    given: {a: [1, abc, 0], b: [0,1,0]}\n");
  EXPECT_EQ(word.field, "problems[0].given.a[1]");
  EXPECT_NE(word.message.find("unknown name"), std::string::npos) << word.format();
}

TEST(Loader, NonFiniteNumbers) {
  for (const char* bad : {".nan", ".inf", "-.inf", "nan", "inf"}) {
    const Diagnostic d =
        first_error(std::string("  - id: a\n    kind: vectors\n    given: {a: [1, ") + bad +
                    ", 0], b: [0,1,0]}\n");
    EXPECT_EQ(d.field, "problems[0].given.a[1]") << bad;
    EXPECT_NE(d.message.find("not a finite number"), std::string::npos) << bad << ": " << d.message;
  }
}

TEST(Loader, HugeAndTinyNumbersStayExact) {
  const ProblemResult r = test::solve_yaml(
      "problems:\n  - id: a\n    kind: vectors\n    given: {a: [1.0e308, 0, 0], b: [0, 4.9e-324, "
      "0]}\n");
  ASSERT_FALSE(r.error) << test::error_text(r);
  EXPECT_EQ(test::exact_text(r, "angle"), "90");
}

TEST(Loader, DuplicateIdsAndUnknownAsk) {
  const ProblemSet set = load_problem_set_from_string(
      "problems:\n  - id: a\n    kind: vectors\n    given: {a: [1,0,0], b: [0,1,0]}\n"
      "  - id: a\n    kind: vectors\n    given: {a: [1,0,0], b: [0,1,0]}\n"
      "  - id: c\n    kind: vectors\n    ask: [dot, crosss]\n    given: {a: [1,0,0], b: [0,1,0]}\n",
      "dup.yaml");
  ASSERT_EQ(set.problems.size(), 3u);
  EXPECT_FALSE(set.problems[0].error);
  ASSERT_TRUE(set.problems[1].error);
  EXPECT_NE(set.problems[1].error->message.find("duplicate id 'a'"), std::string::npos);
  EXPECT_EQ(set.problems[1].error->where.line, 5);
  ASSERT_TRUE(set.problems[2].error);
  EXPECT_NE(set.problems[2].error->message.find("did you mean 'cross'"), std::string::npos);
}

TEST(Loader, AnAnswerThatNeedsAnUngivenFieldIsNotAsked) {
  // A transform with no points once asked for "points" with the expected answer "none", so a
  // student who rightly left it out lost a third of the marks.
  const ProblemSet set = load_problem_set_from_string(
      "problems:\n"
      "  - id: t\n    kind: transform\n    given: {steps: [{translate: [1, 2, 3]}]}\n"
      "  - id: p\n    kind: transform\n    given: {steps: [{translate: [1, 2, 3]}], points: [[0, "
      "0, 0]]}\n"
      "  - id: l\n    kind: look_at\n    given: {eye: [0, 0, 5], center: [0, 0, 0], up: [0, 1, "
      "0]}\n"
      "  - id: x\n    kind: transform\n    ask: [matrix, points]\n    given: {steps: [{translate: "
      "[1, 2, 3]}]}\n",
      "ask.yaml");
  ASSERT_EQ(set.problems.size(), 4u);
  EXPECT_EQ(set.problems[0].ask, (std::vector<std::string>{"matrix", "inverse"}));
  EXPECT_EQ(set.problems[1].ask, (std::vector<std::string>{"matrix", "points", "inverse"}));
  EXPECT_EQ(set.problems[2].ask, std::vector<std::string>{"matrix"});
  ASSERT_TRUE(set.problems[3].error);
  EXPECT_NE(set.problems[3].error->message.find("needs given.points"), std::string::npos);
  EXPECT_EQ(set.problems[3].error->where.line, 13);
}

TEST(Loader, ConventionsAndToleranceAreInheritedAndOverridden) {
  const ProblemSet set = load_problem_set_from_string(
      "conventions: {api: directx, angles: radians}\ntolerance: {rel: 0.01}\n"
      "problems:\n  - id: a\n    kind: vectors\n    given: {a: [1,0,0], b: [0,1,0]}\n"
      "  - id: b\n    kind: vectors\n    conventions: {angles: degrees}\n    tolerance: {abs: "
      "0.5}\n"
      "    ask: [angle]\n    points: 4\n    given: {a: [1,0,0], b: [0,1,0]}\n",
      "c.yaml");
  ASSERT_TRUE(set.all_errors().empty());
  EXPECT_EQ(set.problems[0].conventions.api, Api::DirectX);
  EXPECT_EQ(set.problems[0].conventions.angles, AngleUnit::Radians);
  EXPECT_DOUBLE_EQ(set.problems[0].tolerance.rel, 0.01);
  EXPECT_DOUBLE_EQ(set.problems[0].tolerance.abs, kAbsTolDefault);
  EXPECT_EQ(set.problems[1].conventions.api, Api::DirectX);
  EXPECT_EQ(set.problems[1].conventions.angles, AngleUnit::Degrees);
  EXPECT_DOUBLE_EQ(set.problems[1].tolerance.abs, 0.5);
  EXPECT_EQ(set.problems[1].ask, std::vector<std::string>{"angle"});
  EXPECT_DOUBLE_EQ(set.problems[1].max_score(), 4);
  EXPECT_EQ(set.problems[0].ask.size(), 7u) << "no ask: every answer of the kind";
}

TEST(Loader, BadConventionsAreNamed) {
  const ProblemSet set = load_problem_set_from_string(
      "conventions: {api: opengles}\nproblems:\n  - id: a\n    kind: vectors\n    given: {a: "
      "[1,0,0], b: [0,1,0]}\n",
      "conv.yaml");
  ASSERT_EQ(set.errors.size(), 1u);
  EXPECT_EQ(set.errors[0].field, "conventions.api");
  EXPECT_NE(set.errors[0].message.find("did you mean 'opengl'"), std::string::npos);
}

TEST(Loader, NotAProblemSetAtAll) {
  EXPECT_FALSE(load_problem_set_from_string("- 1\n- 2\n", "list.yaml").errors.empty());
  EXPECT_FALSE(load_problem_set_from_string("title: x\n", "noproblems.yaml").errors.empty());
  EXPECT_FALSE(load_problem_set_from_string("", "empty.yaml").errors.empty());
  EXPECT_FALSE(load_problem_set("/nonexistent/set.yaml").errors.empty());
  const ProblemSet notmap = load_problem_set_from_string("problems: [1, {id: b}]\n", "items.yaml");
  ASSERT_EQ(notmap.problems.size(), 2u);
  EXPECT_TRUE(notmap.problems[0].error);
  EXPECT_TRUE(notmap.problems[1].error);
}

TEST(Loader, HostileExpressionsInGivenAreRefusedQuickly) {
  const Diagnostic power = first_error(
      "  - id: a\n    kind: vectors\n    given: {a: [\"2^2^2^2^2^2^2^2^2\", 0, 0], b: [0,1,0]}\n");
  EXPECT_NE(power.message.find("exponent"), std::string::npos) << power.message;
  const std::string deep = std::string(100000, '(') + "1" + std::string(100000, ')');
  const Diagnostic nested = first_error("  - id: a\n    kind: vectors\n    given: {a: [\"" + deep +
                                        "\", 0, 0], b: [0,1,0]}\n");
  EXPECT_EQ(nested.field, "problems[0].given.a[0]");
}

}  // namespace
}  // namespace frustum

namespace frustum {
namespace {

// A problem without `given` (or with `given:` empty) is a located error that says what the kind
// reads — it was "internal error: invalid node", also with `vary: default`.
TEST(Loader, AProblemWithoutGivenSaysWhatTheKindReads) {
  for (const char* tail : {"", "    vary: default\n", "    given:\n"}) {
    const ProblemSet set = load_problem_set_from_string(
        std::string("problems:\n  - id: p\n    kind: normal\n") + tail, "g.yaml");
    const std::vector<Diagnostic> errors = set.all_errors();
    ASSERT_EQ(errors.size(), 1u) << tail;
    EXPECT_EQ(errors[0].format(),
              "g.yaml:2:5: problems[0].given: missing: a problem gives its data under `given:` "
              "(normal reads points, A, B, C, cross)")
        << tail;
  }
}

}  // namespace
}  // namespace frustum
