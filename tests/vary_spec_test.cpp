// The fast paths of drawing a variant against the plain reading they replace: a `vary` block
// read once (VaryPlan) draws what apply_vary draws, and draw_problem, which refuses a draw
// whose given alone is ill-conditioned before solving it, takes the same draw (or reports the
// same reason) as the plain loop that solves every draw first. Properties over many seeds.
#include "solver/problem/vary_spec.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "solver/input/given_reader.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/variants.hpp"
#include "solver/util/diagnostic.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

// Every form of a `vary` entry: integer ranges (and one beyond the integer fast path),
// rational and irrational steps, choices, each with and without a count, lists, a nested
// mapping over its given, plain values, and a list to vary that the given does not hold.
constexpr const char* kForms = R"(
problems:
  - id: ranges
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    vary:
      triangle: [[{range: [-20, 20]}, {range: [-3, 3], step: 1/2}, {range: [1, 40]}],
                 [{range: [-2, 2], step: sqrt(2)}, {range: [-3000000000, -2999999990]}, 9],
                 {each: {range: [0, 9], step: 3}}]
      pixel: {choices: [[1, 1], [2, 1], 7]}
  - id: counted
    kind: normal
    given: {points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]}
    vary: {points: {each: [{range: [-5, 5]}, {range: [1/3, 3]}, 0], count: 4}}
  - id: window
    kind: clip_line
    given: {p: [0, 0], q: [9, 9], window: {xmin: 1, xmax: 5, ymin: 1, ymax: 5}}
    vary: {window: {xmin: {range: [-5, 0]}, ymax: {choices: [5, 6]}}, q: [{range: [6, 12]}, 9]}
  - id: no-such-given
    kind: normal
    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9]}
    vary: {points: {each: {range: [0, 4]}}}
)";

// The benchmark's plane-method exercise (bench/workloads.py gen-set), and a triangle that is
// nearly always edge-on, so that every draw is refused and the reason reported.
constexpr const char* kPlaneMethod = R"(
problems:
  - id: unit-normal
    kind: normal
    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, 3, 9], cross: [AC, AB]}
    vary: {A: [{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}], B: [{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}], C: [{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}]}
  - id: pixel-z
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1], cross: [AC, AB]}
    vary: {triangle: [[{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}], [{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}], [{range: [-20, 20]}, {range: [-20, 20]}, {range: [1, 40]}]], pixel: [{range: [-5, 5]}, {range: [-5, 5]}]}
  - id: nice-z
    kind: depth_at_pixel
    nice: true
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
    vary: {triangle: [[{range: [-4, 4]}, {range: [-4, 4]}, {range: [1, 9]}], [{range: [-4, 4]}, {range: [-4, 4]}, {range: [1, 9]}], [{range: [-4, 4]}, {range: [-4, 4]}, {range: [1, 9]}]], pixel: [{range: [-2, 2]}, {range: [-2, 2]}]}
  - id: edge-on
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
    vary: {triangle: [[0, 0, {range: [1, 9]}], {choices: [[1, 1, 9], [2, 2, 8]]}, {choices: [[3, 3, 9], [4, 4, 7]]}]}
  - id: near-edge-on-or-fine
    kind: depth_at_pixel
    given: {triangle: [[0, 0, 6], [3, 0, 9], [0, 3, 9]], pixel: [1, 1]}
    vary: {triangle: [[0, 0, {range: [1, 9]}], [{range: [1, 20]}, {range: [1, 2]}, 9], [{range: [3, 4]}, {range: [3, 40]}, 9]]}
)";

std::string error_text(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.diagnostic().format();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(VaryPlan, DrawsWhatApplyVaryDrawsFromTheSameNumbers) {
  const ProblemSet set = load_problem_set_from_string(kForms, "forms.yaml");
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  int compared = 0;
  for (const ProblemSpec& p : set.problems) {
    const std::string field = p.field + ".vary";
    const VaryPlan plan(p.vary, *p.info, set.file, field);
    for (std::uint64_t seed = 0; seed < 2000; ++seed) {
      Rng fast(seed), plain(seed);
      YAML::Node a, b;
      const std::string fast_error = error_text([&] { a = plan.draw(p.given_node, fast); });
      const std::string plain_error =
          error_text([&] { b = apply_vary(p.vary, p.given_node, plain, set.file, field); });
      ASSERT_EQ(fast_error, plain_error) << p.id << " seed " << seed;
      if (plain_error.empty()) {
        ASSERT_EQ(emit_flow(a), emit_flow(b)) << p.id << " seed " << seed;
      }
      ASSERT_EQ(fast.next(), plain.next()) << p.id << " seed " << seed;  // the same numbers used
      ++compared;
    }
  }
  EXPECT_EQ(compared, 8000);
  // The last fails at every draw, as apply_vary does.
  const ProblemSpec& bad = set.problems.back();
  Rng rng(1);
  EXPECT_FALSE(
      error_text([&] {
        VaryPlan(bad.vary, *bad.info, set.file, bad.field + ".vary").draw(bad.given_node, rng);
      }).empty());
}

TEST(VaryPlan, RefusesWhatCheckVaryRefuses) {
  const ProblemSet set = load_problem_set_from_string(
      "problems:\n  - id: p\n    kind: normal\n    given: {A: [0, 0, 6], B: [3, 0, 9], C: [0, "
      "3, 9]}\n    vary: {A: {range: [2, 1]}, D: 1}\n",
      "bad.yaml");
  const ProblemSpec& p = set.problems[0];
  const std::string plain =
      error_text([&] { check_vary(p.vary, *p.info, set.file, p.field + ".vary"); });
  EXPECT_FALSE(plain.empty());
  EXPECT_EQ(error_text([&] { VaryPlan(p.vary, *p.info, set.file, p.field + ".vary"); }), plain);
}

// draw_problem's loop as it reads without its fast paths (vary blocks only): every draw from
// apply_vary, parsed and solved, then judged. The drawn given's text, or "error: " and the
// reason of the last refused draw.
std::string plain_draw(const ProblemSpec& base, const std::string& file, std::uint64_t seed) {
  const KindInfo& kind = *base.info;
  Rng rng(seed);
  std::string last;
  for (int attempt = 0; attempt < kMaxDrawAttempts; ++attempt) {
    try {
      const YAML::Node given =
          apply_vary(base.vary, base.given_node, rng, file, base.field + ".vary");
      GivenReader reader(given, file, base.field + ".given", kind.given_fields);
      const std::any parsed = kind.parse(reader, base.conventions);
      reader.finish();
      const Answers answers = kind.solve(parsed, nullptr);
      last.clear();
      for (const std::string& name : base.ask)
        if (const Value* v = answers.find(name);
            v && v->shape == Value::Shape::Matrix && v->rows == 0)
          last = name + " is empty";
      if (!last.empty()) continue;
      if (!base.hard && kind.ill_conditioned) {
        last = kind.ill_conditioned(parsed, answers);
        if (!last.empty()) continue;
      }
      if (base.nice && !base.hard) {
        last = not_nice(answers, base.ask);
        if (!last.empty()) continue;
      }
      return emit_flow(given);
    } catch (const InputError& e) {
      last = e.diagnostic().field + ": " + e.diagnostic().message;
    } catch (const DomainError& e) {
      last = e.field() + ": " + e.what();
    } catch (const std::exception& e) {
      last = e.what();
    }
  }
  return "error: " + last;
}

TEST(VaryPlan, DrawProblemTakesThePlainLoopsDraw) {
  const std::string file = "plane.yaml";
  const ProblemSet set = load_problem_set_from_string(kPlaneMethod, file);
  ASSERT_TRUE(set.all_errors().empty()) << set.all_errors()[0].format();
  // Through a student's variant of the set (the plan read once) and alone (read at each draw).
  int refused = 0;
  for (int i = 0; i < 150; ++i) {
    const ProblemSet variant = variant_for_student(set, "s" + std::to_string(i), false);
    for (std::size_t k = 0; k < set.problems.size(); ++k) {
      const ProblemSpec& base = set.problems[k];
      const std::uint64_t seed = problem_seed(variant.variant->seed, base.id);
      const std::string plain = plain_draw(base, file, seed);
      std::string text;
      const ProblemSpec alone = draw_problem(base, file, seed, {}, &text);
      const ProblemSpec& drawn = variant.problems[k];
      if (plain.rfind("error: ", 0) == 0) {
        ++refused;
        const std::string reason = "(the last: " + plain.substr(7) + ")";
        ASSERT_TRUE(alone.error && drawn.error) << base.id << " variant " << i;
        EXPECT_NE(alone.error->message.find(reason), std::string::npos) << alone.error->message;
        EXPECT_NE(drawn.error->message.find(reason), std::string::npos) << drawn.error->message;
        continue;
      }
      ASSERT_FALSE(alone.error) << alone.error->format();
      EXPECT_EQ(text, plain) << base.id << " variant " << i;
      EXPECT_EQ(emit_flow(drawn.given_node), plain) << base.id << " variant " << i;
    }
  }
  EXPECT_GE(refused, 150);  // the edge-on problem, at least
}

}  // namespace
}  // namespace frustum
