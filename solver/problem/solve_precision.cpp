#include "solver/problem/solve_precision.hpp"

#include <fmt/format.h>

#include <cmath>

#include "solver/problem/conventions_note.hpp"
#include "solver/problem/variants.hpp"

namespace frustum {

namespace {

constexpr Phrase kBackend{"Backend", "計算方式", "Способ вычисления"};
constexpr Phrase kAnswersComputedExactly{
    "Answers computed in exact (GiNaC: rationals and radicals, no rounding anywhere).",
    "厳密計算 (`GiNaC`: 有理数と根号, 丸めは一切ない) で計算した解答.",
    "Ответы вычислены точно (`GiNaC`: рациональные числа и радикалы, без округлений)."};
constexpr Phrase kAnswersComputedIn{
    "Answers computed in {0} ({1}, {2}-bit significand, unit roundoff {3}, about {4} decimal "
    "digits); values only, no derivation steps (--precision exact gives them).",
    "{0} で計算した解答 (`{1}`, 仮数 {2} ビット, 単位丸め誤差 {3}, 10 進で約 {4} 桁). 値だけで, "
    "導出の手順はない (`--precision exact` で手順が出る).",
    "Ответы вычислены в {0} (`{1}`, мантисса {2} бит, единица округления {3}, около {4} десятичных "
    "знаков); только значения, без шагов вывода (их даёт `--precision exact`)."};
constexpr Phrase kNoNumericPath{"The kind {0} has no numeric path; it was solved exactly ({1}).",
                                "種類 `{0}` には数値計算の経路がないので, 厳密に解いた ({1}).",
                                "У вида `{0}` нет численного пути; он решён точно ({1})."};
constexpr Phrase kExactBackend{"exact (GiNaC: rationals and radicals, no rounding anywhere)",
                               "厳密計算 (`GiNaC`: 有理数と根号, 丸めは一切ない)",
                               "точно (`GiNaC`: рациональные числа и радикалы, без округлений)"};

// The backend the answers were computed in (describe(p) in precision.hpp, said in each language).
Said backend_note(Precision p) {
  if (p == Precision::Exact) return say(kAnswersComputedExactly);
  const int significand_bits = -std::ilogb(unit_roundoff(p));  // u = 2^−p
  const char* format = p == Precision::Float    ? "IEEE 754 binary32"
                       : p == Precision::Double ? "IEEE 754 binary64"
                                                : "x87 80-bit extended";
  return say(kAnswersComputedIn, to_string(p), format, significand_bits,
             fmt::format("{:.1e}", unit_roundoff(p)), fmt::format("{:.1f}", decimal_digits(p)));
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
        r.derivation.note(say(kBackend), backend_note(precision));
      else
        r.derivation.note(say(kBackend), say(kNoNumericPath, spec.kind, say(kExactBackend)));
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
      if (const Said c = conventions_note(spec.conventions, spec.info->uses); !c.empty())
        r.derivation.note(say(kConventionsTitle), c);
      Said text = backend_note(precision);
      // One line per note: each is a sentence of its own.
      for (const Said& how : n.notes) text.append(Said::verbatim("\n")).append(how);
      r.derivation.note(say(kBackend), text);
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
