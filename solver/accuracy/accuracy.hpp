// Speed against error of the numeric paths (`frustum bench accuracy`): every kind with a
// numeric path, in every backend, timed on its prepared inputs and compared with the exact
// backend of the same formulas, on generated well-conditioned problems and on the hard-case
// suite (problems/hard). Returns data; app/bench_command.cpp writes the files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "solver/problem/numeric_result.hpp"
#include "solver/problem/problem_set.hpp"

namespace frustum::bench {

struct AccuracyRow {
  std::string suite;  // "generated" or "hard"
  std::string kind;
  Precision precision = Precision::Exact;
  std::size_t cases = 0;
  double ns_per_solve = 0;
  // Per case: the largest relative error over its numeric answers, ‖x − x_exact‖∞ / ‖x_exact‖∞
  // (absolute when x_exact = 0; infinite when the answer is not finite or missing).
  double median_error = 0;
  double max_error = 0;
  std::size_t wrong = 0;  // cases with a wrong decision: a bool, word or null that differs
};

// The kinds the generator knows: every kind with a numeric path and an accuracy generator
// (KindInfo::accuracy_given, in its kind file), in the registry's order.
std::vector<std::string> generated_kinds();

// `count` well-conditioned problems of `kind`, drawn with splitmix64 from `seed`, as a
// problem set read through the normal loader (so they are validated like hand-written ones).
ProblemSet generated_problems(const std::string& kind, int count, std::uint64_t seed);

// The same problems with every third decimal of the given turned into an irrational number
// near it ("-3.25" becomes "-3.25 + sqrt(2)/10", √3 and √5 in turn): the cost of the exact
// backend on radical inputs (the numeric backends round them once, as they round decimals).
ProblemSet radical_problems(const std::string& kind, int count, std::uint64_t seed);
std::string with_radicals(const std::string& given);

// Times and measures every problem of `set` whose kind has a numeric path, per kind and
// backend. Each backend's batch is repeated until it has run for about `min_ns` nanoseconds.
std::vector<AccuracyRow> measure(const ProblemSet& set, const std::string& suite,
                                 double min_ns = 2e7);

// One result against the exact backend's.
struct CaseError {
  double error = 0;
  bool wrong = false;
};
CaseError compare(const NumericResult& got, const NumericResult& exact);

// Relative error max |xᵢ − eᵢ| / max |eᵢ| (absolute when every eᵢ is 0) of computed values
// against exact ones, computed exactly; ∞ when a value is not finite.
double relative_error(const std::vector<long double>& got, const std::vector<Exact>& exact);
// The same for a result kept in exact values: 0 when they are the exact values.
double exact_relative_error(const std::vector<Exact>& got, const std::vector<Exact>& exact);

// The table as Markdown (one row per suite × kind × backend).
std::string markdown_table(const std::vector<AccuracyRow>& rows);
// Speed against error on log axes: one point per kind × backend of `suite`; in each kind, the
// backends on its Pareto front (no other backend both faster and more accurate) are filled and
// joined.
std::string speed_error_svg(const std::vector<AccuracyRow>& rows, const std::string& suite);

}  // namespace frustum::bench
