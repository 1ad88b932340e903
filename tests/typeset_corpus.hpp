// Every derivation the tests typeset: each bundled set (problems/seeds, examples, hard) and,
// for every kind, generated variants (plain, nice, hard) in every API convention.
#pragma once

#include <filesystem>
#include <vector>

#include "solver/problem/registry.hpp"
#include "solver/problem/variants.hpp"
#include "test_util.hpp"

namespace frustum::test {

inline std::vector<std::string> bundled_sets() {
  std::vector<std::string> files;
  for (const char* dir : {"problems/seeds", "problems/examples", "problems/hard"})
    for (const auto& e : std::filesystem::directory_iterator(source_path(dir)))
      if (e.path().extension() == ".yaml") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

// Solved problems with their derivations; `per_kind` variants of each kind per convention.
inline std::vector<ProblemResult> typeset_corpus(int per_kind = 3) {
  std::vector<ProblemResult> out;
  for (const std::string& file : bundled_sets()) {
    const SetResult r = solve_set(load_problem_set(file), true);
    for (const ProblemResult& p : r.problems)
      if (!p.error) out.push_back(p);
  }
  for (const KindInfo& kind : builtin_kinds().all()) {
    if (!kind.generate) continue;
    for (const Api api : {Api::OpenGL, Api::Processing, Api::DirectX})
      for (int i = 0; i < per_kind; ++i) {
        ProblemSpec base = default_problem(kind, i % 3 == 1, i % 3 == 2);
        base.conventions.api = api;
        base.id = kind.name + "-" + std::string(to_string(api)) + "-" + std::to_string(i);
        const ProblemSpec drawn =
            draw_problem(base, "generated.yaml", 1000 + static_cast<std::uint64_t>(i));
        if (drawn.error) continue;
        ProblemResult p = solve_problem(drawn, "generated.yaml", true);
        if (!p.error) out.push_back(std::move(p));
      }
  }
  return out;
}

// Every LaTeX string of a problem: the steps' formulas, substitutions and results, and the
// answers as shown.
inline std::vector<std::string> latex_strings(const ProblemResult& p) {
  std::vector<std::string> out;
  for (const Step& s : p.derivation.steps())
    for (const MathText* m : {&s.formula, &s.substitution, &s.result})
      if (!m->empty()) out.push_back(m->latex);
  for (const auto& [name, v] : p.answers.items()) out.push_back(v.shown().latex);
  return out;
}

}  // namespace frustum::test
