// Grading throughput: answers graded per second for numeric answers, single thread,
// and a class of 1,000 students × 20 problems graded in process (the set solved once).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "grader/grade.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum {
namespace {

// Twenty depth_at_pixel problems (3 numeric answers each: normal, plane, z) on different
// triangles.
std::string twenty_problems() {
  std::string s = "problems:\n";
  for (int i = 0; i < 20; ++i)
    s += fmt::format(
        "  - id: p{}\n    kind: depth_at_pixel\n    given:\n      triangle: [[0, 0, {}], [{}, 0, "
        "9], [0, 3, 9]]\n"
        "      pixel: [1, 1]\n    ask: [normal, plane, z]\n",
        i, 6 + i % 3, 3 + i % 4);
  return s;
}

// A student's numeric answers (decimals, as typed), right or slightly off.
std::string student_answers(const ProblemSet& set, const SolvedSet& solved, int student) {
  std::string s = fmt::format("student: s{:04d}\nanswers:\n", student);
  for (std::size_t i = 0; i < set.problems.size(); ++i) {
    const Answers& a = solved.results[i].answers;
    const auto& n = a.find("normal")->numbers;
    const auto& p = a.find("plane")->numbers;
    const double z =
        a.find("z")->numbers[0] + ((student + static_cast<int>(i)) % 5 == 0 ? 0.5 : 0.0);
    s += fmt::format(
        "  {}: {{normal: [{:.6f}, {:.6f}, {:.6f}], plane: [{:.6f}, {:.6f}, {:.6f}, {:.6f}], z: "
        "{:.6f}}}\n",
        set.problems[i].id, n[0], n[1], n[2], p[0], p[1], p[2], p[3], z);
  }
  return s;
}

void BM_GradeNumericAnswers(benchmark::State& state) {
  const ProblemSet set = load_problem_set_from_string(twenty_problems(), "bench.yaml");
  const SolvedSet solved = solve_for_grading(set);
  const Submission sub =
      load_submission_from_string(student_answers(set, solved, 1), "answers.yaml");
  std::size_t answers = 0;
  for (auto _ : state) {
    const GradeReport r = grade(set, sub, &solved);
    benchmark::DoNotOptimize(r.score);
    answers += 60;
  }
  state.counters["answers/s"] =
      benchmark::Counter(static_cast<double>(answers), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GradeNumericAnswers)->Unit(benchmark::kMicrosecond);

// A class of 1,000 × 20 problems: parsing each answer file and grading it.
void BM_GradeClassOf1000(benchmark::State& state) {
  const ProblemSet set = load_problem_set_from_string(twenty_problems(), "bench.yaml");
  const SolvedSet solved = solve_for_grading(set);
  std::vector<std::string> files;
  for (int s = 0; s < 1000; ++s) files.push_back(student_answers(set, solved, s));
  for (auto _ : state) {
    double total = 0;
    for (const std::string& f : files)
      total += grade(set, load_submission_from_string(f, "a.yaml"), &solved).score;
    benchmark::DoNotOptimize(total);
  }
  state.counters["students/s"] = benchmark::Counter(
      1000.0 * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_GradeClassOf1000)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace frustum
