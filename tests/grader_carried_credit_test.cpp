// Carried credit as an instructor gives it (docs/grading.md §4), as a property over generated
// problems of every kind: the key's answers with one earlier answer replaced — by a copy of a
// given, by zero, or by a common mistake of the kind — and every later answer that depends on it
// recomputed from the replacement (what a student who went on from it writes), never earn more
// than an instructor gives: nothing forward from a copy or zero, carried credit from a worked
// wrong answer exactly once (ecf of the points, never more), and no answer both "copied from the
// given" and "follows correctly".
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "grader/grade.hpp"
#include "grader/trivial.hpp"
#include "solver/input/yaml_emit.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/rng.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

constexpr int kDrawsPerKind = 16;

// Is `later` computed from `earlier`, directly or through other answers?
bool computed_from(const KindInfo& kind, const std::string& later, const std::string& earlier) {
  std::vector<std::string> todo = kind.answer(later)->depends_on;
  std::set<std::string> seen;
  while (!todo.empty()) {
    const std::string d = todo.back();
    todo.pop_back();
    if (d == earlier) return true;
    if (!seen.insert(d).second) continue;
    if (const AnswerSpec* a = kind.answer(d))
      todo.insert(todo.end(), a->depends_on.begin(), a->depends_on.end());
  }
  return false;
}

enum class Made { Copy, Zero, Mistake };

struct Replacement {
  Made made;
  std::string what;  // for messages
  Value value;
};

Value zeros_like(const Value& key) {
  std::vector<Exact> zero(key.numbers.size(), Exact(0));
  if (key.shape != Value::Shape::Matrix) return Value::vector(zero);
  std::vector<std::vector<Exact>> rows(static_cast<std::size_t>(key.rows),
                                       std::vector<Exact>(static_cast<std::size_t>(key.cols), 0));
  return Value::matrix(rows);
}

// What a student may write instead of `key` without the work (a copy of a given list, with
// w = 1 appended where the answer is homogeneous; zero), and what the kind's common mistakes
// give for it.
std::vector<Replacement> replacements(const ProblemSpec& spec, const std::string& name,
                                      const Value& key,
                                      const std::vector<Misconception>& mistakes) {
  std::vector<Replacement> out;
  const bool listed = key.numbers.size() >= 2 &&
                      (key.shape == Value::Shape::Vector || key.shape == Value::Shape::Matrix);
  if (listed) {
    for (const GivenList& g : given_lists(spec.given_node)) {
      if (g.value.exact.size() != g.value.numbers.size()) continue;
      if (key.shape == Value::Shape::Vector && g.value.shape == Value::Shape::Vector) {
        std::vector<Exact> copy = g.value.exact;
        // w = 1 appended only where the answer is homogeneous (as trivial.hpp reads a copy).
        const AnswerKind k = spec.info->answer(name)->kind;
        if (copy.size() + 1 == key.numbers.size() &&
            (k == AnswerKind::Point || k == AnswerKind::Vector))
          copy.push_back(1);
        if (copy.size() == key.numbers.size())
          out.push_back({Made::Copy, "a copy of " + g.field, Value::vector(copy)});
      } else if (key.shape == Value::Shape::Matrix && g.value.shape == Value::Shape::Matrix &&
                 g.value.rows == key.rows && g.value.cols == key.cols) {
        out.push_back({Made::Copy, "a copy of " + g.field, g.value});
      }
    }
    out.push_back({Made::Zero, "zero", zeros_like(key)});
  }
  for (const Misconception& m : mistakes)
    if (const Value* v = m.answers.find(name); v && v->shape != Value::Shape::Null)
      out.push_back({Made::Mistake, "the mistake " + m.name.en(), *v});
  return out;
}

// The student's answers: the key, `name` replaced, and each later answer computed from it
// recomputed by the kind from the student's own earlier ones (left out where the kind cannot).
// `recomputed` gets the later answers that were.
Answers answers_from(const ProblemSpec& spec, const Answers& key, const std::string& name,
                     const Value& replacement, std::set<std::string>& recomputed) {
  const KindInfo& kind = *spec.info;
  Answers out;
  for (const std::string& a : spec.ask)
    if (a == name)
      out.set(a, replacement);
    else if (!computed_from(kind, a, name))
      out.set(a, *key.find(a));
  for (const std::string& a : spec.ask) {
    if (a == name || !computed_from(kind, a, name) || !kind.carry_forward) continue;
    try {
      const Answers carried = kind.carry_forward(spec.given, out);
      if (const Value* v = carried.find(a)) {
        out.set(a, *v);
        recomputed.insert(a);
      }
    } catch (const std::exception&) {
      // Nothing to recompute from this replacement (a zero normal has no unit normal).
    }
  }
  return out;
}

std::string submission(const ProblemSpec& spec, const Answers& answers) {
  std::string s = "student: s\nanswers:\n  p:\n";
  for (const std::string& a : spec.ask)
    if (const Value* v = answers.find(a))
      s += "    " + a + ": " + emit_flow(answer_node(*v)) + "\n";
  return s;
}

bool says(const std::string& feedback, const std::string& words) {
  return feedback.find(words) != std::string::npos;
}

std::size_t times_said(const std::string& feedback, const std::string& words) {
  std::size_t n = 0;
  for (std::size_t at = feedback.find(words); at != std::string::npos;
       at = feedback.find(words, at + 1))
    ++n;
  return n;
}

class CarriedCredit : public ::testing::TestWithParam<std::string> {};

TEST_P(CarriedCredit, NeverMoreThanAnInstructorGives) {
  const KindInfo& kind = *builtin_kinds().find(GetParam());
  ASSERT_TRUE(kind.generate);
  std::size_t cases = 0, carried = 0, refused = 0, candidates = 0;
  for (int i = 0; i < kDrawsPerKind; ++i) {
    const ProblemSpec base = default_problem(kind, i % 3 == 1, false);
    ProblemSet set;
    set.file = "property.yaml";
    set.problems.push_back(
        draw_problem(base, set.file, fnv1a64("carried/" + kind.name + "/" + std::to_string(i))));
    const ProblemSpec& spec = set.problems[0];
    ASSERT_FALSE(spec.error) << kind.name << " #" << i << ": " << spec.error->format();
    const SolvedSet solved = solve_for_grading(set);
    if (solved.results[0].error) continue;  // an ill-posed draw is refused elsewhere
    const Answers& key = solved.results[0].answers;
    const std::string given = emit_flow(spec.given_node);
    for (const std::string& name : spec.ask) {
      const bool has_later = std::any_of(spec.ask.begin(), spec.ask.end(), [&](const auto& a) {
        return computed_from(kind, a, name);
      });
      if (!has_later) continue;
      const std::vector<Replacement> made =
          replacements(spec, name, *key.find(name), solved.mistakes[0]);
      candidates += made.size();
      for (const Replacement& r : made) {
        std::set<std::string> recomputed;
        const Answers student = answers_from(spec, key, name, r.value, recomputed);
        const GradeReport report =
            grade(set, load_submission_from_string(submission(spec, student), "p.yaml"), &solved);
        ASSERT_TRUE(report.errors.empty()) << report.errors[0].format();
        const auto graded = [&](const std::string& n) -> const AnswerGrade* {
          for (const AnswerGrade& a : report.problems[0].answers)
            if (a.name == n) return &a;
          return nullptr;
        };
        const AnswerGrade* replaced = graded(name);
        ASSERT_NE(replaced, nullptr);
        if (replaced->verdict == Verdict::Correct) continue;  // the copy is right here
        ++cases;
        const std::string at = kind.name + " #" + std::to_string(i) + " " + given + ": " + name +
                               " replaced by " + r.what;
        // A mistake that happens to give a copy or zero is judged as one.
        const bool trivial = r.made != Made::Mistake ||
                             replaced->misconception.en() == "copied from the given" ||
                             replaced->misconception.en() == "zero vector" ||
                             replaced->misconception.en() == "zero matrix" ||
                             replaced->misconception.en() == "identity matrix";
        for (const AnswerGrade& a : report.problems[0].answers) {
          const std::string here = at + "; " + a.name + " = " + a.got_text + " (" +
                                   std::string(to_string(a.verdict)) + "): " + a.feedback.en();
          // Never partial with full points, never more than the points.
          EXPECT_LE(a.score, a.max_score + 1e-12) << here;
          if (a.verdict == Verdict::Partial) {
            EXPECT_LT(a.score, a.max_score - 1e-12) << here;
          }
          // Never both copied and following, and carried credit said at most once.
          EXPECT_FALSE(a.misconception.en() == "copied from the given" && a.carried_forward)
              << here;
          EXPECT_LE(times_said(a.feedback.en(), "follows correctly"), 1u) << here;
          EXPECT_EQ(a.carried_forward, says(a.feedback.en(), "follows correctly")) << here;
          if (a.verdict == Verdict::Correct) continue;
          if (a.name == name) {
            // The replaced answer itself follows from nothing; a copy or zero earns nothing (a
            // mistake in a word map may keep credit per entry, below full points).
            if (trivial) {
              EXPECT_EQ(a.score, 0) << here;
            }
            EXPECT_FALSE(a.carried_forward) << here;
            continue;
          }
          if (!computed_from(kind, a.name, name)) continue;
          if (trivial) {
            // Nothing forward from a copy or zero, however far down the chain.
            EXPECT_EQ(a.score, 0) << here;
            EXPECT_FALSE(a.carried_forward) << here;
            refused += a.score == 0;
          } else if (recomputed.count(a.name)) {
            // A worked wrong answer carries: ecf of the points, exactly once (unless the answer's
            // own credit per entry is more).
            const double ecf = spec.grading.ecf * a.max_score;
            if (a.carried_forward) {
              EXPECT_DOUBLE_EQ(a.score, ecf) << here;
            } else {
              EXPECT_GT(a.score, ecf) << here;
            }
            carried += a.carried_forward;
          }
        }
      }
    }
  }
  // Every kind with something to replace before a later answer is exercised (outcodes, words
  // and plane z have no copy, zero or listed mistake to put there).
  if (candidates > 0) {
    EXPECT_GT(cases, 0u) << kind.name;
  }
  RecordProperty("cases", static_cast<int>(cases));
  RecordProperty("carried", static_cast<int>(carried));
  RecordProperty("refused", static_cast<int>(refused));
}

std::vector<std::string> drawn_kinds() {
  std::vector<std::string> out;
  for (const KindInfo& k : builtin_kinds().all())
    if (!k.fixed && k.generate) out.push_back(k.name);
  return out;
}

INSTANTIATE_TEST_SUITE_P(EveryKind, CarriedCredit, ::testing::ValuesIn(drawn_kinds()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
}  // namespace frustum
