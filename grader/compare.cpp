#include "grader/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <set>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/compare_parts.hpp"
#include "grader/list_items.hpp"
#include "solver/derivation/vocabulary.hpp"
#include "solver/util/exact_format.hpp"
#include "solver/util/expression.hpp"
#include "solver/util/words.hpp"

namespace frustum {

std::string_view to_string(Verdict v) {
  switch (v) {
    case Verdict::Correct:
      return "correct";
    case Verdict::Incorrect:
      return "incorrect";
    case Verdict::Partial:
      return "partial";
    case Verdict::Unparseable:
      return "unparseable";
    case Verdict::Missing:
      return "missing";
  }
  return "incorrect";
}

namespace {

// What a comparison tells the student: why the answer is right, or how it is wrong.
constexpr Phrase kNoSuchValue{"there is no such value", "その値は存在しません",
                              "такого значения нет"};
constexpr Phrase kNoSuchValueHere{"there is no such value here", "ここには値がありません",
                                  "здесь такого значения нет"};
constexpr Phrase kThereAreNone{"there are none", "ありません", "их нет"};
constexpr Phrase kThereIsAValueHere{"there is a value here", "ここには値があります",
                                    "здесь значение есть"};
constexpr Phrase kCannotBeGradedYet{"answers of this kind cannot be graded yet",
                                    "この種類の解答はまだ採点できません",
                                    "ответы этого вида пока не оцениваются"};
constexpr Phrase kExpectedMatrixGotMatrix{"expected a {0} matrix, got a {1} matrix",
                                          "{0} 行列のはずですが, {1} 行列です",
                                          "ожидалась матрица {0}, получена матрица {1}"};
constexpr Phrase kExpectedMatrixGotComponents{"expected a {0} matrix, got {1} components",
                                              "{0} 行列のはずですが, 成分 {1} 個です",
                                              "ожидалась матрица {0}, получено компонент: {1}"};
constexpr Phrase kExpectedComponentsGotMatrix{"expected {0} components, got a {1} matrix",
                                              "成分は {0} 個のはずですが, {1} 行列です",
                                              "ожидалось компонент: {0}, получена матрица {1}"};
constexpr Phrase kExpectedComponentsGotComponents{"expected {0} components, got {1} components",
                                                  "成分は {0} 個のはずですが, {1} 個です",
                                                  "ожидалось компонент: {0}, получено: {1}"};
constexpr Phrase kEntriesWithWorkRight{"{0} of the {1} entries that take work are right",
                                       "計算を要する {1} 個の要素のうち {0} 個が正しい",
                                       "верно {0} из {1} элементов, требующих вычисления"};
constexpr Phrase kComponentsWithWorkRight{"{0} of the {1} components that take work are right",
                                          "計算を要する {1} 個の成分のうち {0} 個が正しい",
                                          "верно {0} из {1} компонент, требующих вычисления"};
constexpr Phrase kEntriesWithWorkRightTrivialUncounted{
    "{0} of the {1} entries that take work are right (entries a trivial answer also has do not "
    "count)",
    "計算を要する {1} 個の要素のうち {0} 個が正しい (自明な解答でも得られる要素は数えない)",
    "верно {0} из {1} элементов, требующих вычисления (элементы, которые есть и у тривиального "
    "ответа, не считаются)"};
constexpr Phrase kComponentsWithWorkRightTrivialUncounted{
    "{0} of the {1} components that take work are right (entries a trivial answer also has do not "
    "count)",
    "計算を要する {1} 個の成分のうち {0} 個が正しい (自明な解答でも得られる成分は数えない)",
    "верно {0} из {1} компонент, требующих вычисления (элементы, которые есть и у тривиального "
    "ответа, не считаются)"};
constexpr Phrase kEntriesWithWorkRightFreeWrong{
    "{0} of the {1} entries that take work are right, and {2} of those that take no work are "
    "wrong: {3} of {4} counted",
    "計算を要する {1} 個の要素のうち {0} 個が正しく, 計算を要しない要素のうち {2} 個が誤り. 数えた "
    "{4} 個のうち {3} 個",
    "верно {0} из {1} элементов, требующих вычисления, и {2} из не требующих вычисления неверны: "
    "засчитано {3} из {4}"};
constexpr Phrase kComponentsWithWorkRightFreeWrong{
    "{0} of the {1} components that take work are right, and {2} of those that take no work are "
    "wrong: {3} of {4} counted",
    "計算を要する {1} 個の成分のうち {0} 個が正しく, 計算を要しない成分のうち {2} 個が誤り. 数えた "
    "{4} 個のうち {3} 個",
    "верно {0} из {1} компонент, требующих вычисления, и {2} из не требующих вычисления неверны: "
    "засчитано {3} из {4}"};
// Points read as the rows they mean (point_rows_of), then what the comparison of those says.
constexpr Phrase kReadAsOnePoint{"read as one point", "1 つの点として読みました",
                                 "прочитано как одна точка"};
constexpr Phrase kReadAsOneHomogeneousPoint{
    "read as one point in homogeneous coordinates (w = 1)",
    "同次座標 (w = 1) の 1 つの点として読みました",
    "прочитано как одна точка в однородных координатах (w = 1)"};
constexpr Phrase kReadAsHomogeneousPoints{"read as points in homogeneous coordinates (w = 1)",
                                          "同次座標 (w = 1) の点として読みました",
                                          "прочитано как точки в однородных координатах (w = 1)"};
constexpr Phrase kReadAsHomogeneousCoordinates{
    "read as homogeneous coordinates: (x, y, z, w) is the point (x/w, y/w, z/w)",
    "同次座標として読みました: (x, y, z, w) は点 (x/w, y/w, z/w) です",
    "прочитано как однородные координаты: (x, y, z, w) — это точка (x/w, y/w, z/w)"};
constexpr Phrase kReadAndThen{"{0}; {1}", "{0}; {1}", "{0}; {1}"};
// Lists and word maps.
constexpr Phrase kCannotReadAsPair{
    "cannot read {0} as a pair such as 0-1: write the items separated by commas, spaces or arrows",
    "`{0}` を 0-1 のような組として読めません. 項目はコンマ, 空白または矢印で区切って書いてください",
    "не удаётся прочитать `{0}` как пару вида 0-1: разделяйте элементы запятыми, пробелами или "
    "стрелками"};
constexpr Phrase kCannotReadAsItem{
    "cannot read {0} as an item of this list: write the items separated by commas, spaces or "
    "arrows",
    "`{0}` をこのリストの項目として読めません. 項目はコンマ, "
    "空白または矢印で区切って書いてください",
    "не удаётся прочитать `{0}` как элемент этого списка: разделяйте элементы запятыми, пробелами "
    "или стрелками"};

}  // namespace

namespace comparing {

Comparison correct(Said why) { return {Verdict::Correct, 1.0, std::move(why), {}, false, {}}; }
Comparison incorrect(Said why) { return {Verdict::Incorrect, 0.0, std::move(why), {}, false, {}}; }

bool exactly_equal(const Value& a, const Value& b) {
  if (a.exact.empty() || b.exact.empty() || a.exact.size() != b.exact.size()) return false;
  // Values whose doubles already differ cannot be equal: skip the exact simplification
  // (most wrong and most decimal answers end here, cheaply).
  if (a.numbers.size() == a.exact.size() && b.numbers.size() == b.exact.size())
    for (std::size_t i = 0; i < a.numbers.size(); ++i) {
      const double x = a.numbers[i], y = b.numbers[i];
      if (std::isfinite(x) && std::isfinite(y) &&
          std::abs(x - y) > 1e-9 * std::max({1.0, std::abs(x), std::abs(y)}))
        return false;
    }
  for (std::size_t i = 0; i < a.exact.size(); ++i)
    if (!canonical(a.exact[i] - b.exact[i]).is_zero()) return false;
  return true;
}

ComponentJudge judge_of(const Value& expected, const AnswerRules& r) {
  return ComponentJudge(expected, r.spec->kind, r.tol, r.scale, r.unit_exponent);
}

namespace {

// A component whose double does not hold it: 0 or subnormal for a non-zero exact number (below
// 2.2·10⁻³⁰⁸), or infinite.
bool beyond_double(const Value& v) {
  for (std::size_t i = 0; i < v.numbers.size(); ++i) {
    const double x = v.numbers[i];
    if (!std::isfinite(x)) return i < v.exact.size();
    if (std::abs(x) < std::numeric_limits<double>::min() && i < v.exact.size() &&
        !v.exact[i].is_zero())
      return true;
  }
  return false;
}

// ⌊log₂ |e|⌋ to within one, for any size; nothing for 0 or a value that is no real number.
std::optional<long> binary_exponent(const Exact& e) {
  try {
    const GiNaC::numeric q = rational_near(canonical(e));
    if (q.is_zero()) return std::nullopt;
    return GiNaC::abs(q.numer()).int_length() - q.denom().int_length();
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The largest binary exponent of v's exact components.
std::optional<long> largest_exponent(const Value& v) {
  std::optional<long> out;
  for (const Exact& e : v.exact)
    if (const auto k = binary_exponent(e); k && (!out || *k > *out)) out = k;
  return out;
}

// v times 2⁻ᵏ, exactly, its doubles taken again from the scaled exact numbers.
Value scaled(const Value& v, long k) {
  Value out = v;
  const Exact factor = GiNaC::numeric(2).power(GiNaC::numeric(-k));
  for (std::size_t i = 0; i < out.numbers.size(); ++i) {
    if (i < out.exact.size()) {
      out.exact[i] = canonical(out.exact[i] * factor);
      out.numbers[i] = to_double(out.exact[i]);
    } else {
      out.numbers[i] = std::ldexp(out.numbers[i], static_cast<int>(-k));
    }
  }
  return out;
}

}  // namespace

std::vector<std::vector<double>> rows_of(const Value& v) {
  std::vector<std::vector<double>> out;
  const std::size_t cols = v.cols > 0 ? static_cast<std::size_t>(v.cols) : 1;
  for (std::size_t i = 0; i + cols <= v.numbers.size(); i += cols)
    out.emplace_back(v.numbers.begin() + static_cast<long>(i),
                     v.numbers.begin() + static_cast<long>(i + cols));
  return out;
}

Value numeric_value(const Value& shape, std::vector<double> numbers) {
  Value v;
  v.shape = shape.shape;
  v.rows = shape.rows;
  v.cols = shape.cols;
  v.numbers = std::move(numbers);
  return v;
}

namespace {

// v scaled by a power of two so that its largest |component| is in [0.5, 1): exact in binary,
// so directions of 10⁻¹⁷⁰ or 10¹⁵⁶ compare like any other (no squared length under- or
// overflows).
std::vector<double> normalized_exponent(const std::vector<double>& v) {
  const double m = max_abs(v);
  if (m == 0 || !std::isfinite(m)) return v;
  int e = 0;
  std::frexp(m, &e);
  std::vector<double> out(v);
  for (double& x : out) x = std::ldexp(x, -e);
  return out;
}

}  // namespace

bool all_finite_and_faithful(const Value& v) {
  for (std::size_t i = 0; i < v.numbers.size(); ++i) {
    if (!std::isfinite(v.numbers[i])) return false;
    // A non-zero exact number that became 0 in double (below 10⁻³⁰⁸).
    if (v.numbers[i] == 0 && i < v.exact.size() && !v.exact[i].is_zero()) return false;
  }
  return true;
}

Multiple multiple_of(const Value& expected, const Value& got, const AnswerRules& r, double* k_out) {
  if (!all_finite_and_faithful(expected) || !all_finite_and_faithful(got)) {
    if (expected.exact.empty() || got.exact.size() != expected.exact.size()) return Multiple::None;
    const std::vector<Exact>& e = expected.exact;
    const std::vector<Exact>& g = got.exact;
    Exact dot = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
      dot += e[i] * g[i];
      for (std::size_t j = i + 1; j < e.size(); ++j)
        if (!canonical(g[i] * e[j] - g[j] * e[i]).is_zero()) return Multiple::None;
    }
    const int s = exact_sign(canonical(dot));
    return s > 0 ? Multiple::Positive : s < 0 ? Multiple::Negative : Multiple::None;
  }
  const std::vector<double> e = normalized_exponent(expected.numbers);
  const std::vector<double> g = normalized_exponent(got.numbers);
  double ee = 0, ge = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    ee += e[i] * e[i];
    ge += g[i] * e[i];
  }
  if (ee == 0 || ge == 0) return Multiple::None;
  const double k = ge / ee;
  std::vector<double> ke(e);
  for (double& x : ke) x *= k;
  AnswerRules plain = r;
  plain.scale = nullptr;  // the kind's magnitudes belong to the unscaled key
  if (!judge_of(numeric_value(expected, ke), plain).all(ke, g)) return Multiple::None;
  if (k_out) *k_out = k;
  return k > 0 ? Multiple::Positive : Multiple::Negative;
}

double length_of(const Value& v) {
  double sum = 0;
  for (const double x : v.numbers) sum += x * x;
  if (std::isfinite(sum) || v.exact.empty()) return std::sqrt(sum);
  Exact exact_sum = 0;
  for (const Exact& x : v.exact) exact_sum += x * x;
  return std::sqrt(to_double(canonical(exact_sum)));
}

namespace {

// "expected a 4×4 matrix, got 3 components": a matrix by its size, anything else by its count.
Said shape_mismatch(const Value& expected, const Value& got) {
  const auto size = [](const Value& v) {
    return v.shape == Value::Shape::Matrix ? fmt::format("{}×{}", v.rows, v.cols)
                                           : std::to_string(v.numbers.size());
  };
  const bool em = expected.shape == Value::Shape::Matrix, gm = got.shape == Value::Shape::Matrix;
  const Phrase& p = em ? (gm ? kExpectedMatrixGotMatrix : kExpectedMatrixGotComponents)
                       : (gm ? kExpectedComponentsGotMatrix : kExpectedComponentsGotComponents);
  return say(p, size(expected), size(got));
}

}  // namespace

std::optional<Comparison> trivial_match(const Value& expected, const Value& got,
                                        const ComponentJudge& judge, const AnswerRules& r,
                                        bool up_to_scale) {
  if (!r.trivial) return std::nullopt;
  for (const TrivialAnswer& t : *r.trivial) {
    if (t.value.numbers.size() != got.numbers.size() ||
        judge.all(expected.numbers, t.value.numbers))
      continue;
    // A homogeneous point is the copy at any positive multiple ((2, 4, −10, 2) for (1, 2, −5)).
    const bool is_copy =
        ComponentJudge(t.value, r.spec->kind, r.tol, nullptr).all(t.value.numbers, got.numbers) ||
        (up_to_scale && multiple_of(t.value, got, r) == Multiple::Positive);
    if (!is_copy) continue;
    Comparison c = incorrect(t.feedback);
    c.trivial = t.name;
    c.no_work = t.no_work;
    return c;
  }
  return std::nullopt;
}

namespace {

// Credit per component that shows work (docs/grading.md §4). An entry counts when it takes
// work — no answer written without work (zero, identity, a copy of the given) has it right —
// or when the student got it wrong anyway. The transposed key does not make an entry free: a
// diagonal takes the same work in either convention. So a wrong answer never earns full
// points, and tan for cot in both scale entries of a perspective matrix loses both.
std::optional<Comparison> component_credit(const Value& expected, const Value& got,
                                           const ComponentJudge& judge, const AnswerRules& r) {
  std::size_t counted = 0, right = 0, free_wrong = 0;
  for (std::size_t i = 0; i < expected.numbers.size(); ++i) {
    bool free = false;
    if (r.trivial)
      for (const TrivialAnswer& t : *r.trivial)
        free = free || (t.no_work && judge.ok(i, expected.numbers[i], t.value.numbers[i]));
    const bool ok = judge.ok(i, expected.numbers[i], got.numbers[i]);
    if (free && ok) continue;
    ++counted;
    right += ok;
    free_wrong += free && !ok;
  }
  if (right == 0 || counted == 0 || right == counted) return std::nullopt;
  const bool matrix = expected.shape == Value::Shape::Matrix;
  const std::size_t work = counted - free_wrong;
  Said feedback;
  if (free_wrong > 0)
    feedback = say(matrix ? kEntriesWithWorkRightFreeWrong : kComponentsWithWorkRightFreeWrong,
                   right, work, free_wrong, right, counted);
  else if (counted < expected.numbers.size())
    feedback = say(
        matrix ? kEntriesWithWorkRightTrivialUncounted : kComponentsWithWorkRightTrivialUncounted,
        right, work);
  else
    feedback = say(matrix ? kEntriesWithWorkRight : kComponentsWithWorkRight, right, work);
  return Comparison{Verdict::Partial,
                    static_cast<double>(right) / static_cast<double>(counted),
                    std::move(feedback),
                    {},
                    false,
                    {}};
}

// Points written another way than one row each, read as the rows they mean: one point as a
// flat list or a column ([−2, 2, 3] reads as a 3×1 matrix), and points in homogeneous
// coordinates (x, y, z, w), w ≠ 0, as (x/w, y/w, z/w). Nothing when `got` is none of these.
struct PointReading {
  Value rows;
  Said how;
};

std::optional<PointReading> point_rows_of(const Value& expected, const Value& got) {
  if (expected.shape != Value::Shape::Matrix || got.shape != Value::Shape::Matrix)
    return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(expected.cols);
  Value as_rows = got;
  Said how;
  if (expected.rows == 1 && got.cols == 1 && got.rows > 1) {  // one point, as a list or a column
    as_rows.rows = 1;
    as_rows.cols = got.rows;
    how = say(kReadAsOnePoint);
  }
  if (static_cast<std::size_t>(as_rows.cols) == n + 1 && as_rows.rows == expected.rows) {
    // Homogeneous coordinates: (x, y, z, w) is the point (x/w, y/w, z/w); w = 0 is a direction.
    const bool exact = as_rows.exact.size() == as_rows.numbers.size();
    Value affine = as_rows;
    affine.cols = static_cast<int>(n);
    affine.numbers.clear();
    affine.exact.clear();
    bool all_one = true;
    for (std::size_t row = 0; row < static_cast<std::size_t>(as_rows.rows); ++row) {
      const std::size_t at = row * (n + 1);
      const Exact w = exact ? canonical(as_rows.exact[at + n]) : Exact(0);
      const double wd = as_rows.numbers[at + n];
      if (exact ? w.is_zero() : wd == 0) return std::nullopt;
      all_one = all_one && (exact ? canonical(w - 1).is_zero() : wd == 1.0);
      for (std::size_t i = 0; i < n; ++i) {
        affine.numbers.push_back(as_rows.numbers[at + i] / wd);
        if (exact) affine.exact.push_back(canonical(as_rows.exact[at + i] / w));
      }
    }
    if (exact)
      for (std::size_t i = 0; i < affine.exact.size(); ++i)
        affine.numbers[i] = to_double(affine.exact[i]);
    as_rows = affine;
    how = say(all_one ? (expected.rows == 1 ? kReadAsOneHomogeneousPoint : kReadAsHomogeneousPoints)
                      : kReadAsHomogeneousCoordinates);
  }
  if (how.empty() || as_rows.cols != expected.cols) return std::nullopt;
  return PointReading{as_rows, how};
}

}  // namespace

Comparison compare_components(const Value& expected, const Value& got, const AnswerRules& r,
                              const ComponentRules& rules) {
  if (r.spec->point_rows)
    if (const std::optional<PointReading> p = point_rows_of(expected, got)) {
      AnswerRules plain = r;
      AnswerSpec spec = *r.spec;
      spec.point_rows = false;
      plain.spec = &spec;
      Comparison c = compare_components(expected, p->rows, plain, rules);
      c.feedback = c.verdict == Verdict::Correct || c.feedback.empty()
                       ? p->how
                       : say(kReadAndThen, p->how, c.feedback);
      return c;
    }
  if (got.numbers.size() != expected.numbers.size() ||
      (expected.shape == Value::Shape::Matrix && got.shape == Value::Shape::Matrix &&
       expected.cols != got.cols))
    return incorrect(shape_mismatch(expected, got));
  if (exactly_equal(expected, got)) return correct(say(kExactlyEqual));
  const ComponentJudge judge = judge_of(expected, r);
  if (judge.all(expected.numbers, got.numbers)) return correct(say(kWithinTolerance));
  if (rules.also)
    if (auto c = rules.also(expected, got, judge, r)) return *c;
  if (auto c = trivial_match(expected, got, judge, r, rules.up_to_scale)) return *c;
  if (r.partial && rules.credit)
    if (auto c = component_credit(expected, got, judge, r)) return *c;
  return incorrect();
}

// Words compared without case ("Background" is background), unless the expected words differ
// only by case (labels "a" and "A" of two polygons).
std::vector<std::string> folded(const std::vector<std::string>& words,
                                const std::vector<std::string>& expected) {
  std::set<std::string> exact(expected.begin(), expected.end()), lowered;
  for (const std::string& w : exact) lowered.insert(ascii_lower(w));
  if (lowered.size() < exact.size()) return words;
  std::vector<std::string> out;
  for (const std::string& w : words) out.push_back(ascii_lower(w));
  return out;
}

// The student's list items as meant (list_items.hpp): split where one text separates them, and
// unordered pairs in the key's spelling.
std::vector<std::string> items_read(const Value& got, const Value& expected, const AnswerRules& r) {
  std::vector<std::string> items = items_as_written(got.words, expected.words);
  if (r.spec->unordered_pairs)
    for (std::string& item : items) item = pair_as_in_key(item, expected.words);
  return items;
}

// A list answer with an item that cannot be one of its items (list_items.hpp) cannot be read:
// `unparseable` with the reason, never a wrong order or set.
std::optional<Comparison> unreadable_list(const std::vector<std::string>& items,
                                          const Value& expected, const AnswerRules& r) {
  const std::string bad = unreadable_item(items, expected.words, r.spec->unordered_pairs);
  if (bad.empty()) return std::nullopt;
  const std::string item = quote_excerpt(bad);
  return Comparison{Verdict::Unparseable,
                    0.0,
                    say(r.spec->unordered_pairs ? kCannotReadAsPair : kCannotReadAsItem, item),
                    {},
                    false,
                    {}};
}

Comparison compare_number(const Value& expected, const Value& got, const AnswerRules& r) {
  if (got.numbers.size() != 1 || expected.numbers.size() != 1)
    return incorrect(say(reading::kExpectedOneNumber));
  if (exactly_equal(expected, got)) return correct(say(kExactlyEqual));
  if (judge_of(expected, r).ok(0, expected.numbers[0], got.numbers[0]))
    return correct(say(kWithinTolerance));
  return incorrect();
}

}  // namespace comparing

using namespace comparing;

Comparison compare(const Value& expected, const Value& got, const AnswerRules& r) {
  // Numbers beyond double's range (a dot product of −10⁻³⁸⁰ is 0 as a double) are compared
  // scaled by one power of two, exactly, that brings the key's largest component near 1: every
  // window, magnitude and threshold scales with them, so signs and relative errors are judged as
  // at any other size. A magnitude the kind computed in doubles that under- or overflowed is
  // replaced by the key's own largest component.
  if (r.unit_exponent == 0 && answer_type(r.spec->kind).numeric &&
      (beyond_double(expected) || beyond_double(got))) {
    std::optional<long> k = largest_exponent(expected);
    if (!k) k = largest_exponent(got);
    if (k && *k != 0 && std::abs(*k) < (1L << 30)) {
      const Value e = scaled(expected, *k), g = scaled(got, *k);
      AnswerRules rules = r;
      rules.unit_exponent = static_cast<int>(*k);
      rules.trivial = nullptr;  // doubles of the given, not beyond its range
      AnswerScale scale;
      if (r.scale) {
        const double own = max_abs(e.numbers);
        for (const double m : r.scale->magnitude) {
          const double sm = std::ldexp(m, -rules.unit_exponent);
          scale.magnitude.push_back(std::isnormal(m) && std::isnormal(sm) ? sm : own);
        }
        for (const std::vector<double>& ts : r.scale->thresholds) {
          scale.thresholds.emplace_back();
          for (const double t : ts) scale.thresholds.back().push_back(std::ldexp(t, -*k));
        }
        rules.scale = &scale;
      }
      return compare(e, g, rules);
    }
  }
  if (expected.shape == Value::Shape::Null) {
    return got.shape == Value::Shape::Null ? correct(say(kNoSuchValue))
                                           : incorrect(say(kNoSuchValueHere));
  }
  // "none" for an empty list (no hidden edges) says the same thing.
  if (got.shape == Value::Shape::Null && expected.shape == Value::Shape::WordList &&
      expected.words.empty())
    return correct(say(kThereAreNone));
  const AnswerType& type = answer_type(r.spec->kind);
  // "none" is one of the answers of some types (no statement is true).
  if (type.compares_none) return type.compare(expected, got, r);
  if (got.shape == Value::Shape::Null) return incorrect(say(kThereIsAValueHere));
  if (!type.compare) return incorrect(say(kCannotBeGradedYet));
  return type.compare(expected, got, r);
}

}  // namespace frustum
