#include "solver/accuracy/accuracy.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <string_view>

#include "solver/derivation/svg.hpp"
#include "solver/problem/registry.hpp"
#include "solver/problem/rng.hpp"

namespace frustum::bench {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kMaxDraws = 1000;
// In the plot, errors of 0 (the exact backend) sit on a floor row below every measured error.
constexpr double kFloor = 1e-22;

// One `given` mapping of a well-conditioned problem of the kind: its accuracy_given, drawn
// again until it accepts a draw.
std::string draw_given(const KindInfo* kind, Rng& rng) {
  if (kind && kind->accuracy_given)
    for (int attempt = 0; attempt < kMaxDraws; ++attempt)
      if (std::optional<std::string> given = kind->accuracy_given(rng)) return *given;
  return "{}";
}

// `count` problems of the kind drawn from `seed` (with radicals in their givens: with_radicals),
// read through the normal loader so that they are validated like hand-written ones.
ProblemSet drawn_problems(const std::string& kind, int count, std::uint64_t seed, bool radicals) {
  Rng rng(seed ^ fnv1a64(kind));
  std::string yaml =
      "title: generated " + kind + (radicals ? " with radicals" : "") + "\nproblems:\n";
  for (int i = 0; i < count; ++i) {
    const std::string given = draw_given(builtin_kinds().find(kind), rng);
    yaml += fmt::format("  - id: {}{}\n    kind: {}\n    given: {}\n", radicals ? 'r' : 'g', i,
                        kind, radicals ? with_radicals(given) : given);
  }
  return load_problem_set_from_string(yaml,
                                      (radicals ? "radical-" : "generated-") + kind + ".yaml");
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

}  // namespace

std::vector<std::string> generated_kinds() {
  std::vector<std::string> out;
  for (const KindInfo& k : builtin_kinds().all())
    if (k.solve_numeric && k.accuracy_given) out.push_back(k.name);
  return out;
}

ProblemSet generated_problems(const std::string& kind, int count, std::uint64_t seed) {
  return drawn_problems(kind, count, seed, false);
}

std::string with_radicals(const std::string& given) {
  // A decimal token: an optional sign, digits, a point, digits, not part of a word or a quoted
  // string (the generators write fractions such as "4/3" quoted and angles as integers).
  static const char* const kRadicals[] = {"sqrt(2)", "sqrt(3)", "sqrt(5)"};
  std::string out;
  bool quoted = false;
  int decimals = 0;
  for (std::size_t i = 0; i < given.size();) {
    const char c = given[i];
    if (c == '"') quoted = !quoted;
    const bool starts =
        !quoted && (std::isdigit(static_cast<unsigned char>(c)) || c == '-') &&
        (i == 0 || std::string_view("[{ ,:").find(given[i - 1]) != std::string::npos);
    if (!starts) {
      out += c;
      ++i;
      continue;
    }
    std::size_t j = i + 1;
    while (j < given.size() &&
           (std::isdigit(static_cast<unsigned char>(given[j])) || given[j] == '.'))
      ++j;
    const std::string token = given.substr(i, j - i);
    if (token.find('.') != std::string::npos && decimals++ % 3 == 0)
      out += fmt::format("\"{} + {}/10\"", token, kRadicals[(decimals / 3) % 3]);
    else
      out += token;
    i = j;
  }
  return out;
}

ProblemSet radical_problems(const std::string& kind, int count, std::uint64_t seed) {
  return drawn_problems(kind, count, seed, true);
}

CaseError compare(const NumericResult& got, const NumericResult& exact) {
  CaseError e;
  for (const auto& [name, value] : exact.answers.items()) {
    const Value* g = got.answers.find(name);
    if (!g || g->shape != value.shape) {
      e.wrong = true;
      continue;
    }
    if (value.shape == Value::Shape::Bool && g->flag != value.flag) e.wrong = true;
    if (value.shape == Value::Shape::Word && g->word != value.word) e.wrong = true;
  }
  for (const auto& [name, ref] : exact.raw) {
    const std::vector<long double>* x = got.find_raw(name);
    const Value* want = exact.answers.find(name);
    if (!x || x->size() != ref.size() || !want || want->exact.size() != ref.size()) {
      e.error = kInfinity;
      continue;
    }
    // A backend that keeps exact values (the exact one) is measured on them, not on their
    // long double rounding (which would score it about 1e-20).
    const Value* g = got.answers.find(name);
    e.error = std::max(e.error, g && g->exact.size() == want->exact.size()
                                    ? exact_relative_error(g->exact, want->exact)
                                    : relative_error(*x, want->exact));
  }
  return e;
}

double exact_relative_error(const std::vector<Exact>& got, const std::vector<Exact>& exact) {
  bool equal = got.size() == exact.size();
  for (std::size_t i = 0; equal && i < exact.size(); ++i)
    equal = canonical(got[i] - exact[i]).is_zero();
  if (equal) return 0.0;
  std::vector<long double> near;
  for (const Exact& x : got) near.push_back(from_exact<long double>(x));
  return relative_error(near, exact);
}

double relative_error(const std::vector<long double>& got, const std::vector<Exact>& exact) {
  // max |xᵢ − eᵢ| / max |eᵢ| in exact arithmetic, against the exact values themselves: a
  // result that underflowed to 0 where the exact value is 10⁻⁴⁰⁰ is a total loss (error 1),
  // not a match of two zeros.
  using GiNaC::numeric;
  numeric diff = 0, size = 0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    if (!std::isfinite(got[i])) return kInfinity;
    const numeric want = rational_near(exact[i]);
    const numeric have = GiNaC::ex_to<numeric>(exact_of(got[i]));
    diff = std::max(diff, GiNaC::abs(have - want));
    size = std::max(size, GiNaC::abs(want));
  }
  const numeric err = size.is_zero() ? diff : diff / size;
  // Beyond a double's range the error is total (or, below it, none to speak of).
  if (err > numeric(std::numeric_limits<double>::max())) return kInfinity;
  if (err < numeric(std::numeric_limits<double>::min()))
    return err.is_zero() ? 0.0 : std::numeric_limits<double>::min();
  return err.to_double();
}

std::vector<AccuracyRow> measure(const ProblemSet& set, const std::string& suite, double min_ns) {
  // Kinds in the order they first appear.
  std::vector<std::string> kinds;
  for (const ProblemSpec& p : set.problems)
    if (!p.error && p.info && p.info->solve_numeric &&
        std::find(kinds.begin(), kinds.end(), p.kind) == kinds.end())
      kinds.push_back(p.kind);
  std::vector<AccuracyRow> rows;
  for (const std::string& kind : kinds) {
    std::vector<const ProblemSpec*> specs;
    std::vector<NumericResult> reference;
    for (const ProblemSpec& p : set.problems) {
      if (p.error || p.kind != kind || !p.info || !p.info->solve_numeric) continue;
      try {
        auto exact = p.info->solve_numeric(p.given, Precision::Exact);
        exact->run();
        reference.push_back(exact->result());
        specs.push_back(&p);
      } catch (const std::exception&) {
        // A problem the exact path cannot solve (a domain error) has no reference.
      }
    }
    if (specs.empty()) continue;
    for (Precision precision : kAllPrecisions) {
      std::vector<std::unique_ptr<NumericSolver>> solvers;
      for (const ProblemSpec* p : specs)
        solvers.push_back(p->info->solve_numeric(p->given, precision));
      using Clock = std::chrono::steady_clock;
      const auto start = Clock::now();
      long passes = 0;
      double elapsed = 0;
      do {
        for (auto& s : solvers) s->run();
        ++passes;
        elapsed = static_cast<double>(
            std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - start).count());
      } while (elapsed < min_ns);
      AccuracyRow row{suite,
                      kind,
                      precision,
                      specs.size(),
                      elapsed / (static_cast<double>(passes) * static_cast<double>(specs.size())),
                      0,
                      0,
                      0};
      std::vector<double> errors;
      for (std::size_t i = 0; i < solvers.size(); ++i) {
        const CaseError e = compare(solvers[i]->result(), reference[i]);
        errors.push_back(e.error);
        row.wrong += e.wrong ? 1 : 0;
      }
      row.median_error = median(errors);
      row.max_error = *std::max_element(errors.begin(), errors.end());
      rows.push_back(row);
    }
  }
  return rows;
}

namespace {

std::string sci(double v) {
  if (v == 0) return "0";
  if (!std::isfinite(v)) return "∞";
  return fmt::format("{:.1e}", v);
}

}  // namespace

std::string markdown_table(const std::vector<AccuracyRow>& rows) {
  std::string out =
      "| suite | kind | backend | cases | ns/solve | median rel. error | max rel. error | wrong "
      "decisions |\n"
      "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: |\n";
  for (const AccuracyRow& r : rows)
    out += fmt::format("| {} | {} | {} | {} | {:.0f} | {} | {} | {} |\n", r.suite, r.kind,
                       to_string(r.precision), r.cases, r.ns_per_solve, sci(r.median_error),
                       sci(r.max_error), r.wrong);
  return out;
}

std::string speed_error_svg(const std::vector<AccuracyRow>& all, const std::string& suite) {
  std::vector<AccuracyRow> rows;
  for (const AccuracyRow& r : all)
    if (r.suite == suite) rows.push_back(r);
  auto err = [](const AccuracyRow& r) { return std::max(r.median_error, kFloor); };
  const double width = 760, height = 520, left = 80, right = 200, top = 40, bottom = 60;
  double x_lo = 1e300, x_hi = 0;
  for (const AccuracyRow& r : rows) {
    x_lo = std::min(x_lo, r.ns_per_solve);
    x_hi = std::max(x_hi, r.ns_per_solve);
  }
  const double lx0 = std::floor(std::log10(std::max(x_lo, 1.0))),
               lx1 = std::ceil(std::log10(std::max(x_hi, 10.0)));
  const double ly0 = std::log10(kFloor), ly1 = 0;
  auto px = [&](double ns) {
    return left + (std::log10(std::max(ns, 1.0)) - lx0) / std::max(lx1 - lx0, 1.0) *
                      (width - left - right);
  };
  auto py = [&](double e) {
    return top + (ly1 - std::log10(std::min(std::max(e, kFloor), 1.0))) / (ly1 - ly0) *
                     (height - top - bottom);
  };
  Svg svg(width, height);
  svg.title("Frustum: speed against error (" + suite + " problems)");
  svg.style(
      ".axis{stroke:#333;stroke-width:1}.grid{stroke:#ddd;stroke-width:0.5}"
      "text{font:11px sans-serif;fill:#222}.front{fill:none;stroke-width:1.5}");
  const char* colors[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};
  for (double e = lx0; e <= lx1; ++e) {
    svg.line({px(std::pow(10, e)), top}, {px(std::pow(10, e)), height - bottom}, "grid");
    svg.text({px(std::pow(10, e)) - 10, height - bottom + 16}, fmt::format("1e{:.0f}", e), "");
  }
  for (double e = ly0; e <= ly1; e += 2) {
    svg.line({left, py(std::pow(10, e))}, {width - right, py(std::pow(10, e))}, "grid");
    svg.text({8, py(std::pow(10, e)) + 4}, e == ly0 ? "exact (0)" : fmt::format("1e{:.0f}", e), "");
  }
  svg.line({left, height - bottom}, {width - right, height - bottom}, "axis");
  svg.line({left, top}, {left, height - bottom}, "axis");
  svg.text({left + 120, height - 18}, "nanoseconds per solve (numeric path, log scale)", "");
  svg.text({left, 24},
           "median relative error against exact (log scale); filled = Pareto front of its kind",
           "");
  std::vector<std::string> kinds;
  for (const AccuracyRow& r : rows)
    if (std::find(kinds.begin(), kinds.end(), r.kind) == kinds.end()) kinds.push_back(r.kind);
  const char* shapes[] = {"float", "double", "long-double", "exact"};
  for (std::size_t k = 0; k < kinds.size(); ++k) {
    const std::string color = colors[k % 8];
    std::vector<const AccuracyRow*> mine, front;
    for (const AccuracyRow& r : rows)
      if (r.kind == kinds[k]) mine.push_back(&r);
    for (const AccuracyRow* r : mine) {
      bool dominated = false;
      for (const AccuracyRow* o : mine)
        dominated =
            dominated || (o != r && o->ns_per_solve <= r->ns_per_solve && err(*o) <= err(*r) &&
                          (o->ns_per_solve < r->ns_per_solve || err(*o) < err(*r)));
      if (!dominated) front.push_back(r);
    }
    std::sort(front.begin(), front.end(),
              [](auto* a, auto* b) { return a->ns_per_solve < b->ns_per_solve; });
    std::vector<Eigen::Vector2d> line;
    for (const AccuracyRow* r : front)
      line.push_back(Eigen::Vector2d(px(r->ns_per_solve), py(err(*r))));
    for (std::size_t i = 1; i < line.size(); ++i)
      svg.line(line[i - 1], line[i], "front", "stroke=\"" + color + "\"");
    for (const AccuracyRow* r : mine) {
      const bool on_front = std::find(front.begin(), front.end(), r) != front.end();
      const Eigen::Vector2d c(px(r->ns_per_solve), py(err(*r)));
      const std::string style = fmt::format("fill=\"{}\" stroke=\"{}\" stroke-width=\"1.5\"",
                                            on_front ? color : "white", color);
      const int shape = static_cast<int>(r->precision);
      if (shape == 0)
        svg.circle(c, 4.5, "", style);
      else if (shape == 1)
        svg.rect(c.x() - 4, c.y() - 4, 8, 8, "", style);
      else if (shape == 2)
        svg.polygon({{c.x(), c.y() - 5.5}, {c.x() + 5, c.y() + 4}, {c.x() - 5, c.y() + 4}}, "",
                    style);
      else
        svg.polygon({{c.x(), c.y() - 5.5},
                     {c.x() + 5.5, c.y()},
                     {c.x(), c.y() + 5.5},
                     {c.x() - 5.5, c.y()}},
                    "", style);
    }
    svg.rect(width - right + 14, top + 18.0 * static_cast<double>(k), 10, 10, "",
             "fill=\"" + color + "\"");
    svg.text({width - right + 30, top + 9 + 18.0 * static_cast<double>(k)}, kinds[k], "");
  }
  const double legend = top + 18.0 * static_cast<double>(kinds.size()) + 20;
  for (int s = 0; s < 4; ++s) {
    const Eigen::Vector2d c(width - right + 19, legend + 18.0 * s);
    const std::string style = "fill=\"white\" stroke=\"#333\" stroke-width=\"1.5\"";
    if (s == 0)
      svg.circle(c, 4.5, "", style);
    else if (s == 1)
      svg.rect(c.x() - 4, c.y() - 4, 8, 8, "", style);
    else if (s == 2)
      svg.polygon({{c.x(), c.y() - 5.5}, {c.x() + 5, c.y() + 4}, {c.x() - 5, c.y() + 4}}, "",
                  style);
    else
      svg.polygon(
          {{c.x(), c.y() - 5.5}, {c.x() + 5.5, c.y()}, {c.x(), c.y() + 5.5}, {c.x() - 5.5, c.y()}},
          "", style);
    svg.text({width - right + 30, legend + 4 + 18.0 * s}, shapes[s], "");
  }
  return svg.str();
}

}  // namespace frustum::bench
