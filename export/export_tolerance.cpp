#include "export/export_tolerance.hpp"

#include <cmath>

#include "grader/grade.hpp"
#include "grader/tolerance.hpp"

namespace frustum {

namespace {

// Halvings of a window that reaches across a threshold, before giving up on the component.
constexpr int kNarrowingSteps = 60;

}  // namespace

std::vector<double> accepted_windows(const ProblemSpec& problem, const Answers& key,
                                     const std::string& answer, const Value& expected) {
  const ProblemJudging judging = prepare_judging(problem, key);
  const AnswerRules rules = judging.rules(problem, answer);
  const Value* own = key.find(answer);
  // The kind's declared scales describe the key's own numbers; a rescaled value (a unit
  // direction) is judged by the defaults for a vector.
  const bool same = own && own->numbers == expected.numbers;
  const AnswerKind kind = same && rules.spec ? rules.spec->kind : AnswerKind::Vector;
  const ComponentJudge judge(expected, kind, rules.tol, same ? rules.scale : nullptr);
  std::vector<double> out;
  for (std::size_t i = 0; i < expected.numbers.size(); ++i) {
    const double e = expected.numbers[i];
    double w = judge.window(i, e);
    for (int step = 0; step < kNarrowingSteps && !(judge.ok(i, e, e + w) && judge.ok(i, e, e - w));
         ++step)
      w /= 2;
    out.push_back(w);
  }
  return out;
}

}  // namespace frustum
