// Variants generated and solved per second, per kind, without derivation text:
//   Generate/KIND        the kind's default generator alone (random numbers → `given` YAML)
//   GenerateSolve/KIND   draw_problem: generate, parse (exact inputs), solve exactly, check
//                        conditioning — what `frustum generate` does per problem
//   GenerateDouble/KIND  generate, parse, then the numeric double path (solve --precision double)
// Registered at start-up, one benchmark per kind of the registry.
#include <benchmark/benchmark.h>

#include "solver/input/given_reader.hpp"
#include "solver/problem/generate.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/solve_precision.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {
namespace {

void generate_only(benchmark::State& state, const KindInfo* kind) {
  Rng rng(1);
  const GenerateOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(kind->generate(rng, options));
  state.counters["variants/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void generate_solve(benchmark::State& state, const KindInfo* kind) {
  const ProblemSpec base = default_problem(*kind);
  std::uint64_t seed = 1;
  for (auto _ : state) {
    const ProblemSpec spec = draw_problem(base, "bench.yaml", seed++);
    if (spec.error) state.SkipWithError(spec.error->message.c_str());
    benchmark::DoNotOptimize(spec.given);
  }
  state.counters["variants/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void generate_double(benchmark::State& state, const KindInfo* kind) {
  ProblemSpec spec = default_problem(*kind);
  Rng rng(1);
  const GenerateOptions options;
  for (auto _ : state) {
    const YAML::Node given = kind->generate(rng, options);
    try {
      GivenReader reader(given, "bench.yaml", "problems[0].given", kind->given_fields);
      spec.given = kind->parse(reader, spec.conventions);
    } catch (const std::exception&) {
      continue;  // a draw that the exact path would redraw
    }
    benchmark::DoNotOptimize(solve_problem(spec, "bench.yaml", false, Precision::Double));
  }
  state.counters["variants/s"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

const bool kRegistered = [] {
  for (const KindInfo& k : builtin_kinds().all()) {
    if (!k.generate) continue;
    benchmark::RegisterBenchmark(("Generate/" + k.name).c_str(), generate_only, &k);
    benchmark::RegisterBenchmark(("GenerateSolve/" + k.name).c_str(), generate_solve, &k);
    benchmark::RegisterBenchmark(("GenerateDouble/" + k.name).c_str(), generate_double, &k);
  }
  return true;
}();

}  // namespace
}  // namespace frustum
