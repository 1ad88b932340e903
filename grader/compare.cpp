#include "grader/compare.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <set>

#include "grader/list_items.hpp"
#include "grader/statement_choice.hpp"
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

Comparison correct(std::string why) {
  return {Verdict::Correct, 1.0, std::move(why), {}, false, {}};
}
Comparison incorrect(std::string why) {
  return {Verdict::Incorrect, 0.0, std::move(why), {}, false, {}};
}

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

// Rows of `cols` numbers (a polygon's or a segment's vertices).
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

bool all_finite_and_faithful(const Value& v) {
  for (std::size_t i = 0; i < v.numbers.size(); ++i) {
    if (!std::isfinite(v.numbers[i])) return false;
    // A non-zero exact number that became 0 in double (below 10⁻³⁰⁸).
    if (v.numbers[i] == 0 && i < v.exact.size() && !v.exact[i].is_zero()) return false;
  }
  return true;
}

enum class Multiple { None, Positive, Negative };

// Is g a multiple k·e (k ≠ 0), each component of g judged against k·e? Both vectors are first
// scaled by powers of two; numbers beyond double range are compared exactly (g × e = 0).
Multiple multiple_of(const Value& expected, const Value& got, const AnswerRules& r,
                     double* k_out = nullptr) {
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

// ‖v‖ of a vector answer: from its doubles, or from its exact components when a double
// overflowed (1e200 squared).
double length_of(const Value& v) {
  double sum = 0;
  for (const double x : v.numbers) sum += x * x;
  if (std::isfinite(sum) || v.exact.empty()) return std::sqrt(sum);
  Exact exact_sum = 0;
  for (const Exact& x : v.exact) exact_sum += x * x;
  return std::sqrt(to_double(canonical(exact_sum)));
}

bool purely_linear(const Value& m) {
  if (m.shape != Value::Shape::Matrix || m.rows != m.cols || m.rows < 3) return false;
  const std::size_t n = static_cast<std::size_t>(m.rows);
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 1 < n && m.numbers[i * n + n - 1] != 0) return false;              // translation column
    if (m.numbers[(n - 1) * n + i] != (i + 1 == n ? 1.0 : 0.0)) return false;  // bottom row
  }
  return true;
}

// The (n−1)×(n−1) linear part of a homogeneous matrix.
Value linear_part(const Value& m) {
  const int n = m.rows - 1;
  std::vector<std::vector<Exact>> rows(static_cast<std::size_t>(n));
  Value v;
  v.shape = Value::Shape::Matrix;
  v.rows = v.cols = n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const std::size_t k = static_cast<std::size_t>(i * m.cols + j);
      v.numbers.push_back(m.numbers[k]);
      if (!m.exact.empty()) v.exact.push_back(m.exact[k]);
    }
  return v;
}

std::string shape_text(const Value& v) {
  return v.shape == Value::Shape::Matrix ? fmt::format("a {}×{} matrix", v.rows, v.cols)
                                         : fmt::format("{} components", v.numbers.size());
}

// The trivial answer (trivial.hpp) that `got` is as a whole, if any: a wrong answer equal to the
// zero vector, the identity, a list copied from the given or the transposed key.
std::optional<Comparison> trivial_match(const Value& expected, const Value& got,
                                        const ComponentJudge& judge, const AnswerRules& r) {
  if (!r.trivial) return std::nullopt;
  for (const TrivialAnswer& t : *r.trivial) {
    if (t.value.numbers.size() != got.numbers.size() ||
        judge.all(expected.numbers, t.value.numbers))
      continue;
    // A homogeneous point is the copy at any positive multiple ((2, 4, −10, 2) for (1, 2, −5)).
    const bool is_copy =
        ComponentJudge(t.value, r.spec->kind, r.tol, nullptr).all(t.value.numbers, got.numbers) ||
        (r.spec->kind == AnswerKind::Point && multiple_of(t.value, got, r) == Multiple::Positive);
    if (!is_copy) continue;
    Comparison c = incorrect(t.feedback);
    c.trivial = t.name;
    c.no_work = t.no_work;
    return c;
  }
  return std::nullopt;
}

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
  const char* what = matrix ? "entries" : "components";
  const std::size_t work = counted - free_wrong;
  std::string feedback =
      free_wrong == 0 ? fmt::format("{} of the {} {} that take work are right{}", right, work, what,
                                    counted < expected.numbers.size()
                                        ? " (entries a trivial answer also has do not count)"
                                        : "")
                      : fmt::format(
                            "{} of the {} {} that take work are right, and {} of those that take "
                            "no work are wrong: {} of {} counted",
                            right, work, what, free_wrong, right, counted);
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
  std::string how;
};

std::optional<PointReading> point_rows_of(const Value& expected, const Value& got) {
  if (expected.shape != Value::Shape::Matrix || got.shape != Value::Shape::Matrix)
    return std::nullopt;
  const std::size_t n = static_cast<std::size_t>(expected.cols);
  Value as_rows = got;
  std::string how;
  if (expected.rows == 1 && got.cols == 1 && got.rows > 1) {  // one point, as a list or a column
    as_rows.rows = 1;
    as_rows.cols = got.rows;
    how = "read as one point";
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
    how = all_one ? (expected.rows == 1 ? "read as one point in homogeneous coordinates (w = 1)"
                                        : "read as points in homogeneous coordinates (w = 1)")
                  : "read as homogeneous coordinates: (x, y, z, w) is the point (x/w, y/w, z/w)";
  }
  if (how.empty() || as_rows.cols != expected.cols) return std::nullopt;
  return PointReading{as_rows, how};
}

Comparison compare_components(const Value& expected, const Value& got, const AnswerRules& r) {
  const AnswerKind kind = r.spec->kind;
  if (r.spec->point_rows)
    if (const std::optional<PointReading> p = point_rows_of(expected, got)) {
      AnswerRules plain = r;
      AnswerSpec spec = *r.spec;
      spec.point_rows = false;
      plain.spec = &spec;
      Comparison c = compare_components(expected, p->rows, plain);
      c.feedback =
          c.verdict == Verdict::Correct || c.feedback.empty() ? p->how : p->how + "; " + c.feedback;
      return c;
    }
  if (kind == AnswerKind::Transform && got.shape == Value::Shape::Matrix &&
      expected.rows == got.rows + 1 && got.rows == got.cols) {
    if (!purely_linear(expected))
      return incorrect(fmt::format(
          "this transform moves the origin (a translation or a projection): it needs the "
          "{0}×{0} homogeneous matrix",
          expected.rows));
    if (!r.linear_matrix)
      return incorrect(
          fmt::format("this problem asks for the {0}×{0} homogeneous matrix", expected.rows));
    AnswerRules linear = r;
    linear.trivial = nullptr;
    linear.scale = nullptr;
    Comparison c = compare_components(linear_part(expected), got, linear);
    if (c.verdict == Verdict::Correct)
      c.feedback = "the linear part of a transform without translation";
    return c;
  }
  if (got.numbers.size() != expected.numbers.size() ||
      (expected.shape == Value::Shape::Matrix && got.shape == Value::Shape::Matrix &&
       expected.cols != got.cols))
    return incorrect(fmt::format("expected {}, got {}", shape_text(expected), shape_text(got)));
  if (exactly_equal(expected, got)) return correct("exactly equal");
  const ComponentJudge judge = judge_of(expected, r);
  if (judge.all(expected.numbers, got.numbers)) return correct("within tolerance");
  if (kind == AnswerKind::Segment) {
    const auto e = rows_of(expected), g = rows_of(got);
    std::vector<double> reversed;
    for (auto it = g.rbegin(); it != g.rend(); ++it)
      reversed.insert(reversed.end(), it->begin(), it->end());
    if (judge.all(expected.numbers, reversed))
      return correct("the same segment, its endpoints in the other order");
  }
  if (kind == AnswerKind::Point && multiple_of(expected, got, r) == Multiple::Positive)
    return correct("the same homogeneous point (a positive multiple)");
  if (kind == AnswerKind::UnitVector) {
    const Multiple m = multiple_of(expected, got, r);
    if (m == Multiple::Positive) {
      // The student's own length (multiple_of's ratio is taken between rescaled vectors).
      Comparison c = incorrect(
          fmt::format("the direction is right but the length is {} — a unit vector has length 1 "
                      "(divide by the length)",
                      format_approx(length_of(got))));
      c.mistake = "not normalised";
      return c;
    }
    if (m == Multiple::Negative) return incorrect("it points the opposite way");
  }
  if (auto c = trivial_match(expected, got, judge, r)) return *c;
  if (r.partial &&
      (kind == AnswerKind::Vector || kind == AnswerKind::Matrix || kind == AnswerKind::Transform))
    if (auto c = component_credit(expected, got, judge, r)) return *c;
  return incorrect("");
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
                    r.spec->unordered_pairs
                        ? fmt::format("cannot read {} as a pair such as 0-1: write the items "
                                      "separated by commas, spaces or arrows",
                                      item)
                        : fmt::format("cannot read {} as an item of this list: write the items "
                                      "separated by commas, spaces or arrows",
                                      item),
                    {},
                    false,
                    {}};
}

// A word map's keys ("1-0": an edge) in the key's spelling when they are unordered pairs.
Value keys_read(const Value& got, const Value& expected, const AnswerRules& r) {
  if (!r.spec->unordered_pairs) return got;
  std::vector<std::string> keys;
  for (const auto& [k, w] : expected.entries) keys.push_back(k);
  Value out = got;
  for (auto& [k, w] : out.entries) k = pair_as_in_key(k, keys);
  return out;
}

// Word maps (faces, edges): credit per entry, corrected for the best constant answer ("every
// face front"), which shows no work. An entry of the key is right when the student wrote it and
// every copy of it says its word: written twice with the same word it counts once, with two
// words neither is chosen. An entry the key does not have (a face or an edge the problem does
// not have) counts as a wrong one, so a wrong answer never earns full points.
Comparison compare_word_map(const Value& expected, const Value& got, const AnswerRules& r) {
  const std::size_t n = expected.entries.size();
  std::size_t right = 0, undecided = 0;
  for (const auto& entry : expected.entries) {  // (clang 14 cannot capture a structured binding)
    bool said = false, other = false;
    for (const auto& e : got.entries)
      if (e.first == entry.first) (e.second == entry.second ? said : other) = true;
    right += said && !other;
    undecided += said && other;
  }
  std::set<std::string> extra;
  for (const auto& entry : got.entries)
    if (std::none_of(expected.entries.begin(), expected.entries.end(),
                     [&](const auto& e) { return e.first == entry.first; }))
      extra.insert(entry.first);
  if (right == n && extra.empty())
    return correct(got.entries.size() > n ? "an entry written twice with the same word counts once"
                                          : "");
  std::size_t best_constant = 0;
  std::string best_word;
  for (const auto& [k, w] : expected.entries) {
    std::size_t same = 0;
    for (const auto& [k2, w2] : expected.entries) same += w2 == w;
    if (same > best_constant) {
      best_constant = same;
      best_word = w;
    }
  }
  // What else was counted, each a sentence of its own.
  std::string notes;
  if (undecided > 0)
    notes += fmt::format(" {} {} written twice with different words: neither word counts as right.",
                         undecided, undecided == 1 ? "entry is" : "entries are");
  if (!extra.empty()) {
    const bool one = extra.size() == 1, edges = r.spec->unordered_pairs;
    notes += fmt::format(" {} {} the problem does not have; {} as a wrong entry.", extra.size(),
                         one ? (edges ? "entry names an edge" : "entry names a face")
                             : (edges ? "entries name edges" : "entries name faces"),
                         one ? "it counts" : "each counts");
  }
  const std::size_t total = n + extra.size();
  if (right > best_constant && total > best_constant)
    return {Verdict::Partial,
            static_cast<double>(right - best_constant) / static_cast<double>(total - best_constant),
            fmt::format("{} of {} entries right; answering \"{}\" everywhere would get {}, so the "
                        "credit counts the entries beyond that.",
                        right, total, best_word, best_constant) +
                notes,
            {},
            false,
            {}};
  if (right == 0) return incorrect(notes.empty() ? "" : notes.substr(1));
  return incorrect(
      fmt::format("{} of {} entries right, no more than one word written everywhere would get.",
                  right, total) +
      notes);
}

bool numeric_kind(AnswerKind kind) {
  switch (kind) {
    case AnswerKind::Scalar:
    case AnswerKind::Vector:
    case AnswerKind::Direction:
    case AnswerKind::UnitVector:
    case AnswerKind::Plane:
    case AnswerKind::Matrix:
    case AnswerKind::Transform:
    case AnswerKind::Segment:
    case AnswerKind::PointSet:
    case AnswerKind::Point:
    case AnswerKind::Polygon:
      return true;
    default:
      return false;
  }
}

}  // namespace

Comparison compare(const Value& expected, const Value& got, const AnswerRules& r) {
  // Numbers beyond double's range (a dot product of −10⁻³⁸⁰ is 0 as a double) are compared
  // scaled by one power of two, exactly, that brings the key's largest component near 1: every
  // window, magnitude and threshold scales with them, so signs and relative errors are judged as
  // at any other size. A magnitude the kind computed in doubles that under- or overflowed is
  // replaced by the key's own largest component.
  if (r.unit_exponent == 0 && numeric_kind(r.spec->kind) &&
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
    return got.shape == Value::Shape::Null ? correct("there is no such value")
                                           : incorrect("there is no such value here");
  }
  // "none" for an empty list (no hidden edges) says the same thing.
  if (got.shape == Value::Shape::Null && expected.shape == Value::Shape::WordList &&
      expected.words.empty())
    return correct("there are none");
  // "none" chooses no statement.
  if (r.spec->kind == AnswerKind::Statements) return compare_statement_choice(expected, got);
  if (got.shape == Value::Shape::Null) return incorrect("there is a value here");
  switch (r.spec->kind) {
    case AnswerKind::Scalar: {
      if (got.numbers.size() != 1 || expected.numbers.size() != 1)
        return incorrect("expected one number");
      if (exactly_equal(expected, got)) return correct("exactly equal");
      if (judge_of(expected, r).ok(0, expected.numbers[0], got.numbers[0]))
        return correct("within tolerance");
      return incorrect("");
    }
    case AnswerKind::Vector:
    case AnswerKind::Point:
    case AnswerKind::Matrix:
    case AnswerKind::Transform:
    case AnswerKind::Segment:
    case AnswerKind::UnitVector:
      return compare_components(expected, got, r);
    case AnswerKind::PointSet: {
      // The same rows in any order: each expected row matched by a distinct given row.
      const auto e = rows_of(expected), g = rows_of(got);
      if (e.size() != g.size() || (!e.empty() && expected.cols != got.cols))
        return incorrect(fmt::format("expected {} items, got {}", e.size(), g.size()));
      // Sorted, the rows usually pair off at once (pixels are integers); otherwise each expected
      // row takes the first unused row within tolerance.
      auto se = e, sg = g;
      std::sort(se.begin(), se.end());
      std::sort(sg.begin(), sg.end());
      bool paired = true;
      for (std::size_t i = 0; i < se.size() && paired; ++i)
        paired = judge_of(numeric_value(expected, se[i]), r).all(se[i], sg[i]);
      if (paired) return correct("the same items (order does not matter)");
      std::vector<bool> used(g.size(), false);
      for (const auto& row : e) {
        const ComponentJudge judge = judge_of(numeric_value(expected, row), r);
        std::size_t j = 0;
        while (j < g.size() && (used[j] || !judge.all(row, g[j]))) ++j;
        if (j == g.size()) return incorrect("");
        used[j] = true;
      }
      return correct("the same items (order does not matter)");
    }
    case AnswerKind::Direction: {
      if (got.numbers.size() != expected.numbers.size())
        return incorrect(fmt::format("expected {} components, got {}", expected.numbers.size(),
                                     got.numbers.size()));
      if (exactly_equal(expected, got)) return correct("equal");
      if (max_abs(got.numbers) == 0 && all_finite_and_faithful(got)) {
        Comparison c = incorrect("The zero vector has no direction: it is no normal.");
        c.trivial = "zero vector";
        c.no_work = true;
        return c;
      }
      const Multiple m = multiple_of(expected, got, r);
      if (m == Multiple::Positive)
        return correct("the same direction (a normal is right up to a positive factor)");
      if (m == Multiple::Negative) return incorrect("it points the opposite way");
      // A vertex or another given copied as the normal.
      if (auto c = trivial_match(expected, got, judge_of(expected, r), r)) return *c;
      return incorrect("");
    }
    case AnswerKind::Plane: {
      if (got.numbers.size() != 4) return incorrect("a plane has 4 coefficients");
      if (multiple_of(expected, got, r) != Multiple::None)
        return correct("the same plane (equations agree up to a non-zero factor)");
      return incorrect("");
    }
    case AnswerKind::Bool:
      return got.flag == expected.flag ? correct("") : incorrect("");
    case AnswerKind::Category:
      return got.word == expected.word ? correct("") : incorrect("");
    case AnswerKind::BitString: {
      if (got.word == expected.word) return correct("");
      // Written as a number, an outcode loses its leading zeros (0 for 0000, 101 for 0101):
      // the same bits, read with the zeros restored.
      if (!got.word.empty() && got.word.size() < expected.word.size() &&
          std::string(expected.word.size() - got.word.size(), '0') + got.word == expected.word)
        return correct(fmt::format("read as {} (the leading zeros restored)", expected.word));
      if (got.word.size() != expected.word.size())
        return incorrect(fmt::format("{} bits, one per window edge", expected.word.size()));
      return incorrect("");
    }
    case AnswerKind::WordList: {
      const std::vector<std::string> items = items_read(got, expected, r);
      if (auto c = unreadable_list(items, expected, r)) return *c;
      std::vector<std::string> a = folded(expected.words, expected.words),
                               b = folded(items, expected.words);
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a == b) return correct("the same set (order does not matter)");
      // An item written twice is right once; its second copy counts as one that should not be
      // there (common / max(expected, given)).
      std::vector<std::string> both;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
      const std::size_t common = both.size();
      const std::size_t copies = b.size() - static_cast<std::size_t>(std::distance(
                                                b.begin(), std::unique(b.begin(), b.end())));
      const std::string counted =
          copies == 0 ? fmt::format("{} of the {} expected items, and {} that should not be there",
                                    common, a.size(), b.size() - common)
                      : fmt::format(
                            "{} of the {} expected items, and {} that should not be there, {} of "
                            "them a second copy of an item (an item written twice is right "
                            "once; the copy counts as one that should not be there)",
                            common, a.size(), b.size() - common, copies);
      if (common > 0 && !a.empty())
        return {Verdict::Partial,
                static_cast<double>(common) / static_cast<double>(std::max(a.size(), b.size())),
                counted,
                {},
                false,
                {}};
      return incorrect(copies == 0 ? "" : counted);
    }
    case AnswerKind::Sequence: {
      const std::vector<std::string> items = items_read(got, expected, r);
      if (auto c = unreadable_list(items, expected, r)) return *c;
      const std::vector<std::string> a = folded(expected.words, expected.words),
                                     b = folded(items, expected.words);
      if (a == b) return correct("");
      std::vector<std::string> sa = a, sb = b;
      std::sort(sa.begin(), sa.end());
      std::sort(sb.begin(), sb.end());
      return incorrect(sa == sb ? "the right items in the wrong order" : "");
    }
    case AnswerKind::WordMap:
      return compare_word_map(expected, keys_read(got, expected, r), r);
    case AnswerKind::Statements:
      return compare_statement_choice(expected, got);
    case AnswerKind::Polygon: {
      // The same vertex cycle, starting anywhere (orientation must match).
      const auto e = rows_of(expected), g = rows_of(got);
      if (e.size() != g.size() || e.empty())
        return incorrect(fmt::format("expected {} vertices, got {}", e.size(), g.size()));
      const auto cycle_matches = [&](bool reversed) -> std::optional<std::size_t> {
        for (std::size_t shift = 0; shift < e.size(); ++shift) {
          bool all = true;
          for (std::size_t i = 0; i < e.size() && all; ++i) {
            const std::size_t j =
                reversed ? (shift + e.size() - i) % e.size() : (i + shift) % e.size();
            all = judge_of(numeric_value(expected, e[i]), r).all(e[i], g[j]);
          }
          if (all) return shift;
        }
        return std::nullopt;
      };
      if (const auto shift = cycle_matches(false))
        return correct(*shift ? "the same polygon, starting at another vertex" : "equal");
      if (cycle_matches(true))
        return incorrect(
            "the right vertices in the opposite order: the orientation decides which side is the "
            "front");
      return incorrect("");
    }
  }
  return incorrect("answers of this kind cannot be graded yet");
}

}  // namespace frustum
