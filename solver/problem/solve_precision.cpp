#include "solver/problem/solve_precision.hpp"

#include "solver/problem/variants.hpp"

namespace frustum {

namespace {

std::string backend_note(Precision p) {
  return "Answers computed in " + describe(p) +
         (p == Precision::Exact
              ? "."
              : "; values only, no derivation steps (--precision exact gives them).");
}

// Long double's answers shown with every digit it holds: the answers are doubles (what the
// grader compares), so their default display would cut long double to a double's 17 digits.
void show_all_digits(Answers& answers, const NumericResult& n) {
  Answers shown;
  for (auto [name, value] : answers.items()) {
    const std::vector<long double>* raw = n.find_raw(name);
    const bool numeric = value.shape == Value::Shape::Scalar ||
                         value.shape == Value::Shape::Vector || value.shape == Value::Shape::Matrix;
    if (raw && numeric && value.display.empty() && value.exact.empty() &&
        raw->size() == value.numbers.size()) {
      std::vector<MathText> digits;
      for (const long double v : *raw) digits.push_back(long_number(v));
      if (value.shape == Value::Shape::Matrix) {
        value.display = matrix_of(digits, static_cast<std::size_t>(value.cols));
      } else if (value.shape == Value::Shape::Scalar) {
        value.display = digits[0];
      } else {
        value.display = tuple_of(digits);
      }
    }
    shown.set(name, std::move(value));
  }
  answers = std::move(shown);
}

}  // namespace

ProblemResult solve_problem(const ProblemSpec& spec, const std::string& file, bool with_steps,
                            Precision precision) {
  const bool numeric =
      precision != Precision::Exact && !spec.error && spec.info && spec.info->solve_numeric;
  if (!numeric) {
    ProblemResult r = solve_problem(spec, file, with_steps);
    if (with_steps && !r.error) {
      if (precision == Precision::Exact)
        r.derivation.note("Backend", backend_note(precision));
      else
        r.derivation.note("Backend", "The kind " + spec.kind +
                                         " has no numeric path; it was solved "
                                         "exactly (" +
                                         describe(Precision::Exact) + ").");
    }
    return r;
  }
  ProblemResult r = unsolved_result(spec);
  solve_located(spec, file, r, [&] {
    const NumericResult n = [&] {
      auto solver = spec.info->solve_numeric(spec.given, precision);
      solver->run();
      return solver->result();
    }();
    r.answers = n.answers;
    if (precision == Precision::LongDouble) show_all_digits(r.answers, n);
    if (with_steps) {
      if (const std::string c = describe(spec.conventions, spec.info->uses); !c.empty())
        r.derivation.note("Conventions", c);
      std::string text = backend_note(precision);
      // One line per note: each is a sentence of its own (and is translated as one).
      for (const std::string& how : n.notes) text += "\n" + how + ".";
      r.derivation.note("Backend", text);
      for (const NumericWarning& w : n.warnings) r.derivation.warn(w.title, w.text);
    }
  });
  return r;
}

SetResult solve_set(const ProblemSet& set, bool with_steps,
                    const std::optional<std::string>& only_id, Precision precision) {
  if (precision == Precision::Exact && !with_steps) return solve_set(set, with_steps, only_id);
  // The selection and the set's errors as solve_set makes them, with no problem solved twice.
  ProblemSet none = set;
  none.problems.clear();
  SetResult out = solve_set(none, false);
  for (const ProblemSpec& p : set.problems)
    if (!only_id || p.id == *only_id)
      out.problems.push_back(solve_problem(p, set.file, with_steps, precision));
  if (only_id && out.problems.empty()) out = solve_set(set, false, only_id);
  return out;
}

}  // namespace frustum
