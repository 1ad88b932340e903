#include "solver/problem/solve_set.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "solver/input/given_reader.hpp"
#include "solver/input/text_reader.hpp"
#include "solver/problem/conventions_note.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

ProblemResult unsolved_result(const ProblemSpec& spec) {
  ProblemResult r;
  r.id = spec.id;
  r.kind = spec.kind;
  r.text = spec.text.map([&](const std::string& t) { return fill_text(t, spec.given_node); });
  r.conventions = spec.conventions;
  r.ask = spec.ask;
  return r;
}

void solve_located(const ProblemSpec& spec, const std::string& file, ProblemResult& r,
                   const std::function<void()>& solve) {
  try {
    solve();
  } catch (const DomainError& e) {
    GivenReader reader(spec.given_node, file, spec.field + ".given", {});
    r.error = reader.locate(e.field(), e.what());
  } catch (const InputError& e) {
    r.error = e.diagnostic();
  } catch (const std::exception& e) {
    r.error = Diagnostic{spec.where, spec.field, std::string("cannot solve: ") + e.what()};
  }
}

ProblemResult solve_problem(const ProblemSpec& spec, const std::string& file, bool with_steps) {
  ProblemResult r = unsolved_result(spec);
  if (spec.error) {
    r.error = spec.error;
    return r;
  }
  // What students read is checked before they read it: every placeholder names a value.
  // In every language the set gives, each checked where it is written.
  for (const auto& [lang, text] : spec.text.all())
    if (const auto bad = placeholder_error(text, spec.given_node)) {
      const bool mapping = spec.text_node.IsMap();
      const YAML::Node at = local_text_node(spec.text_node, lang, spec.text.lang);
      r.error = Diagnostic{
          mapping ? location_of(at, file) : spec.where,
          spec.field + ".text" + (mapping ? "." + std::string(to_string(lang)) : ""), *bad};
      return r;
    }
  solve_located(spec, file, r, [&] {
    // The conventions line only where a convention can change the answers.
    if (with_steps)
      if (const Said c = conventions_note(spec.conventions, spec.info->uses); !c.empty())
        r.derivation.note(say(kConventionsTitle), c);
    Answers answers = !with_steps && spec.drawn_answers
                          ? *spec.drawn_answers
                          : spec.info->solve(spec.given, with_steps ? &r.derivation : nullptr);
    // Exact inputs near 1e308 can give answers beyond double's range (1e308 · 1e308): their
    // decimals would be inf or NaN (null in JSON). An asked one refuses the problem; one not
    // asked is left out, so a question that asks only what stays in range (whether a pixel is
    // inside a triangle at 1e300) is answered.
    Answers kept;
    for (const auto& [name, value] : answers.items()) {
      if (std::all_of(value.numbers.begin(), value.numbers.end(),
                      [](double x) { return std::isfinite(x); })) {
        kept.set(name, value);
        continue;
      }
      if (std::find(spec.ask.begin(), spec.ask.end(), name) == spec.ask.end()) continue;
      r.error = Diagnostic{location_of(spec.given_node, file), spec.field + ".given",
                           "the answer '" + name +
                               "' is beyond the range of a double (about ±1.8e308): scale the "
                               "given numbers down"};
      return;
    }
    r.answers = std::move(kept);
  });
  return r;
}

SetResult solve_set(const ProblemSet& set, bool with_steps,
                    const std::optional<std::string>& only_id) {
  SetResult out;
  out.file = set.file;
  out.title = set.title;
  out.source = set.source;
  out.errors = set.errors;
  for (const ProblemSpec& p : set.problems) {
    if (only_id && p.id != *only_id) continue;
    out.problems.push_back(solve_problem(p, set.file, with_steps));
  }
  if (only_id && out.problems.empty())
    out.errors.push_back(
        Diagnostic{SourceLocation{set.file, 0, 0}, "id", "no problem with id '" + *only_id + "'"});
  return out;
}

}  // namespace frustum
