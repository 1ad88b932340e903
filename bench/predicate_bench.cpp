// The filtered predicates (solver/geometry/predicates.hpp) against the plain double sign on
// ordinary input, in one run: the edge function (inside a triangle) and the back-face
// discriminant D_f. Ordinary input: decimal coordinates in [−10, 10] with three decimals (not
// exactly representable, so the input-rounding part of the bound is exercised), converted to
// double once outside the timing, as the numeric paths do. The filter proves every sign here,
// so the exact fallback never runs; the ratio filtered/plain is the cost of the bound (the
// target is ≤ 1.2). The facing bound is measured both computed per call and prepared once with the
// inputs (as backface's numeric path does). Not part of ctest.
#include <benchmark/benchmark.h>

#include <limits>
#include <random>
#include <vector>

#include "solver/geometry/facing.hpp"
#include "solver/geometry/predicates.hpp"

namespace frustum {
namespace {

constexpr int kCases = 4096;

struct Case {
  std::array<Vec3<double>, 3> t;
  Vec3<double> eye;
  double facing_bound = 0;  // the filter's bound, computed with the inputs and kept beside them,
                            // as backface's prepared solve does
  Polygon3<double> poly;
  Vec2<double> pixel;
  std::array<Vec3<Exact>, 3> exact_t;
  Vec3<Exact> exact_eye;
  Vec2<Exact> exact_pixel;
  Polygon3<Exact> exact_poly;
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = [] {
    std::mt19937 rng(14);
    std::uniform_int_distribution<int> thousandths(-10000, 10000);
    auto number = [&] { return Exact(GiNaC::numeric(thousandths(rng), 1000)); };
    auto point = [&] { return Vec3<Exact>(number(), number(), number()); };
    std::vector<Case> out(kCases);
    for (Case& c : out) {
      for (auto& v : c.exact_t) v = point();
      c.exact_eye = point();
      c.exact_pixel = Vec2<Exact>(number(), number());
      for (int k = 0; k < 3; ++k) c.t[k] = to_double(c.exact_t[k]);
      c.eye = to_double(c.exact_eye);
      c.pixel = to_double(c.exact_pixel);
      c.poly.assign(c.t.begin(), c.t.end());
      c.exact_poly.assign(c.exact_t.begin(), c.exact_t.end());
      c.facing_bound = facing_error_bound_fast(c.poly, c.eye);
    }
    return out;
  }();
  return all;
}

// Inside the closed triangle from the three edge signs.
void BM_InsidePlain(benchmark::State& state) {
  const std::vector<Case>& cs = cases();
  for (auto _ : state) {
    int inside = 0;
    for (const Case& c : cs) {
      int s[3];
      for (int k = 0; k < 3; ++k)
        s[k] = scalar_sign(edge_function<double>(c.t[k], c.t[(k + 1) % 3], c.pixel));
      inside += inside_closed_triangle(s[0], s[1], s[2]);
    }
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * kCases);
}

void BM_InsideFiltered(benchmark::State& state) {
  const std::vector<Case>& cs = cases();
  long fallbacks = 0;
  for (auto _ : state) {
    int inside = 0;
    for (const Case& c : cs) {
      int s[3];
      for (int k = 0; k < 3; ++k) {
        const int j = (k + 1) % 3;
        const SignDecision d =
            edge_sign(c.t[k], c.t[j], c.pixel, c.exact_t[k], c.exact_t[j], c.exact_pixel, true);
        s[k] = d.sign;
        fallbacks += d.exact;
      }
      inside += inside_closed_triangle(s[0], s[1], s[2]);
    }
    benchmark::DoNotOptimize(inside);
  }
  state.SetItemsProcessed(state.iterations() * kCases);
  state.counters["fallbacks"] = static_cast<double>(fallbacks);
}

// Front or back: the sign of D_f = (eye − p₀)·n.
void BM_FacingPlain(benchmark::State& state) {
  const std::vector<Case>& cs = cases();
  for (auto _ : state) {
    int front = 0;
    for (const Case& c : cs) front += scalar_sign(facing_discriminant(c.poly, c.eye));
    benchmark::DoNotOptimize(front);
  }
  state.SetItemsProcessed(state.iterations() * kCases);
}

// How many of the cases the exact fallback decided, counted once outside the timed loop (the
// timed loops do what the plain one does: sum the signs).
double facing_fallbacks(bool prepared) {
  long fallbacks = 0;
  for (const Case& c : cases())
    fallbacks += facing(c.poly, c.eye, c.exact_poly, c.exact_eye, true,
                        prepared ? c.facing_bound : std::numeric_limits<double>::quiet_NaN())
                     .used_exact;
  return static_cast<double>(fallbacks);
}

void BM_FacingFiltered(benchmark::State& state) {
  const std::vector<Case>& cs = cases();
  for (auto _ : state) {
    int front = 0;
    for (const Case& c : cs) front += facing(c.poly, c.eye, c.exact_poly, c.exact_eye, true).sign;
    benchmark::DoNotOptimize(front);
  }
  state.SetItemsProcessed(state.iterations() * kCases);
  state.counters["fallbacks"] = facing_fallbacks(false);
}

// As backface's numeric path runs it: the bound computed once when the inputs are converted.
void BM_FacingFilteredPrepared(benchmark::State& state) {
  const std::vector<Case>& cs = cases();
  for (auto _ : state) {
    int front = 0;
    for (const Case& c : cs)
      front += facing(c.poly, c.eye, c.exact_poly, c.exact_eye, true, c.facing_bound).sign;
    benchmark::DoNotOptimize(front);
  }
  state.SetItemsProcessed(state.iterations() * kCases);
  state.counters["fallbacks"] = facing_fallbacks(true);
}

BENCHMARK(BM_InsidePlain)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_InsideFiltered)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FacingPlain)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FacingFiltered)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_FacingFilteredPrepared)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace frustum
