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
constexpr Phrase kExpectedOneNumber{"expected one number", "数が一つ必要です",
                                    "ожидалось одно число"};
constexpr Phrase kExactlyEqual{"exactly equal", "完全に一致", "точно равно"};
constexpr Phrase kWithinTolerance{"within tolerance", "許容誤差内", "в пределах допуска"};
constexpr Phrase kEqual{"equal", "一致", "равно"};
constexpr Phrase kExpectedItemsGot{"expected {0} items, got {1}",
                                   "要素は {0} 個のはずですが, {1} 個です",
                                   "ожидалось элементов: {0}, получено: {1}"};
constexpr Phrase kSameItemsAnyOrder{"the same items (order does not matter)",
                                    "同じ要素 (順序は問いません)",
                                    "те же элементы (порядок не важен)"};
constexpr Phrase kExpectedComponentsGot{"expected {0} components, got {1}",
                                        "成分は {0} 個のはずですが, {1} です",
                                        "ожидалось компонент: {0}, получено: {1}"};
constexpr Phrase kZeroVectorHasNoDirection{"The zero vector has no direction: it is no normal.",
                                           "零ベクトルには向きがなく, 法線になりません.",
                                           "У нулевого вектора нет направления: это не нормаль."};
constexpr Phrase kSameDirection{
    "the same direction (a normal is right up to a positive factor)",
    "同じ向き (法線は正の定数倍を除いて正しい)",
    "то же направление (нормаль верна с точностью до положительного множителя)"};
constexpr Phrase kPointsTheOppositeWay{"it points the opposite way", "向きが逆です",
                                       "направлена в противоположную сторону"};
constexpr Phrase kPlaneHasFourCoefficients{"a plane has 4 coefficients", "平面の係数は 4 つです",
                                           "у плоскости 4 коэффициента"};
constexpr Phrase kSamePlane{
    "the same plane (equations agree up to a non-zero factor)",
    "同じ平面 (方程式が 0 でない定数倍を除いて一致)",
    "та же плоскость (уравнения совпадают с точностью до ненулевого множителя)"};
constexpr Phrase kReadWithLeadingZeros{"read as {0} (the leading zeros restored)",
                                       "{0} と読みました (先頭の 0 を補いました)",
                                       "прочитано как {0} (ведущие нули восстановлены)"};
constexpr Phrase kBitsOnePerWindowEdge{"{0} bits, one per window edge",
                                       "ウィンドウの辺ごとに 1 ビット、計 {0} ビットです",
                                       "{0} бит, по одному на каждую сторону окна"};
constexpr Phrase kSameSetAnyOrder{"the same set (order does not matter)",
                                  "同じ集合 (順序は問いません)",
                                  "то же множество (порядок не важен)"};
constexpr Phrase kExpectedItemsAndExtra{
    "{0} of the {1} expected items, and {2} that should not be there",
    "期待される {1} 個のうち {0} 個, および余分なもの {2} 個",
    "{0} из {1} ожидаемых элементов и {2} лишних"};
constexpr Phrase kExpectedItemsExtraAndCopies{
    "{0} of the {1} expected items, and {2} that should not be there, {3} of them a second copy of "
    "an item (an item written twice is right once; the copy counts as one that should not be "
    "there)",
    "期待される {1} 個のうち {0} 個, および余分なもの {2} 個 (うち {3} 個は同じ項目の二度目: "
    "二度書いた項目は一度だけ正解とし, 二度目は余分なものと数える)",
    "{0} из {1} ожидаемых элементов и {2} лишних, из них {3} — повтор элемента (элемент, "
    "записанный дважды, верен один раз; повтор считается лишним)"};
constexpr Phrase kRightItemsWrongOrder{"the right items in the wrong order",
                                       "要素は正しいが順序が違います",
                                       "верные элементы в неверном порядке"};
constexpr Phrase kExpectedVerticesGot{"expected {0} vertices, got {1}",
                                      "頂点は {0} 個のはずですが, {1} 個です",
                                      "ожидалось вершин: {0}, получено: {1}"};
constexpr Phrase kSamePolygonOtherStart{"the same polygon, starting at another vertex",
                                        "同じ多角形 (別の頂点から始まる)",
                                        "тот же многоугольник, начиная с другой вершины"};
constexpr Phrase kRightVerticesOppositeOrder{
    "the right vertices in the opposite order: the orientation decides which side is the front",
    "頂点は正しいが順序が逆です. 向きがどちらの側が表かを決めます",
    "верные вершины в обратном порядке: ориентация решает, какая сторона лицевая"};
constexpr Phrase kCannotBeGradedYet{"answers of this kind cannot be graded yet",
                                    "この種類の解答はまだ採点できません",
                                    "ответы этого вида пока не оцениваются"};
constexpr Phrase kTransformMovesOrigin{
    "this transform moves the origin (a translation or a projection): it needs the {0}×{1} "
    "homogeneous matrix",
    "この変換は原点を動かします (平行移動または投影). {0}×{1} の同次変換行列が必要です",
    "это преобразование сдвигает начало координат (перенос или проекция): нужна однородная матрица "
    "{0}×{1}"};
constexpr Phrase kAsksForHomogeneousMatrix{"this problem asks for the {0}×{1} homogeneous matrix",
                                           "この問題は {0}×{1} の同次変換行列を求めています",
                                           "в этой задаче нужна однородная матрица {0}×{1}"};
constexpr Phrase kLinearPartWithoutTranslation{"the linear part of a transform without translation",
                                               "平行移動を含まない変換の線形部分",
                                               "линейная часть преобразования без переноса"};
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
constexpr Phrase kSameSegmentOtherOrder{"the same segment, its endpoints in the other order",
                                        "同じ線分 (端点の順序が逆)",
                                        "тот же отрезок, концы в другом порядке"};
constexpr Phrase kSameHomogeneousPoint{
    "the same homogeneous point (a positive multiple)", "同じ同次座標の点 (正の定数倍)",
    "та же точка в однородных координатах (положительное кратное)"};
constexpr Phrase kDirectionRightLengthIs{
    "the direction is right but the length is {0} — a unit vector has length 1 (divide by the "
    "length)",
    "向きは正しいが長さが {0} です — 単位ベクトルの長さは 1 (長さで割る)",
    "направление верное, но длина {0} — у единичного вектора длина 1 (разделите на длину)"};
constexpr Phrase kNotNormalised{"not normalised", "正規化していない", "не нормирован"};
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
constexpr Phrase kEntryTwiceSameWord{"an entry written twice with the same word counts once",
                                     "同じ語で二度書いた項目は一度と数える",
                                     "элемент, записанный дважды одним словом, считается один раз"};
constexpr Phrase kEntriesRightBeyondConstant{
    "{0} of {1} entries right; answering \"{2}\" everywhere would get {3}, so the credit counts "
    "the entries beyond that.",
    "{1} 個中 {0} 個が正しい. どこにも「{2}」と答えると {3} 個になるので, "
    "得点はそれを超えた分だけ数える.",
    "верно {0} из {1}; ответ «{2}» везде дал бы {3}, поэтому засчитываются только элементы сверх "
    "этого."};
constexpr Phrase kEntriesRightNoMoreThanConstant{
    "{0} of {1} entries right, no more than one word written everywhere would get.",
    "{1} 個中 {0} 個が正しいが, どこにも同じ一語を書いた場合を超えていない.",
    "верно {0} из {1}, не больше, чем дало бы одно слово, написанное везде."};
constexpr Phrase kEntryTwiceDifferentWords{
    "{0} entry is written twice with different words: neither word counts as right.",
    "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
    "{0} элемент записан дважды разными словами: ни одно из слов не засчитывается."};
constexpr Phrase kEntriesTwiceDifferentWords{
    "{0} entries are written twice with different words: neither word counts as right.",
    "{0} 個の項目が異なる語で二度書かれています. どちらの語も正解とは数えません.",
    "Записано дважды разными словами элементов: {0}; ни одно из этих слов не засчитывается."};
constexpr Phrase kEntryNamesNoSuchFace{
    "{0} entry names a face the problem does not have; it counts as a wrong entry.",
    "{0} 個の項目は問題にない面を指しています. 誤った項目として数えます.",
    "{0} элемент называет грань, которой нет в задаче; он считается неверным."};
constexpr Phrase kEntryNamesNoSuchEdge{
    "{0} entry names an edge the problem does not have; it counts as a wrong entry.",
    "{0} 個の項目は問題にない稜線を指しています. 誤った項目として数えます.",
    "{0} элемент называет ребро, которого нет в задаче; он считается неверным."};
constexpr Phrase kEntriesNameNoSuchFaces{
    "{0} entries name faces the problem does not have; each counts as a wrong entry.",
    "{0} 個の項目は問題にない面を指しています. それぞれ誤った項目として数えます.",
    "Элементов с гранями, которых нет в задаче: {0}; каждый считается неверным."};
constexpr Phrase kEntriesNameNoSuchEdges{
    "{0} entries name edges the problem does not have; each counts as a wrong entry.",
    "{0} 個の項目は問題にない稜線を指しています. それぞれ誤った項目として数えます.",
    "Элементов с рёбрами, которых нет в задаче: {0}; каждый считается неверным."};

Comparison correct(Said why = {}) { return {Verdict::Correct, 1.0, std::move(why), {}, false, {}}; }
Comparison incorrect(Said why = {}) {
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

Comparison compare_components(const Value& expected, const Value& got, const AnswerRules& r) {
  const AnswerKind kind = r.spec->kind;
  if (r.spec->point_rows)
    if (const std::optional<PointReading> p = point_rows_of(expected, got)) {
      AnswerRules plain = r;
      AnswerSpec spec = *r.spec;
      spec.point_rows = false;
      plain.spec = &spec;
      Comparison c = compare_components(expected, p->rows, plain);
      c.feedback = c.verdict == Verdict::Correct || c.feedback.empty()
                       ? p->how
                       : say(kReadAndThen, p->how, c.feedback);
      return c;
    }
  if (kind == AnswerKind::Transform && got.shape == Value::Shape::Matrix &&
      expected.rows == got.rows + 1 && got.rows == got.cols) {
    if (!purely_linear(expected))
      return incorrect(say(kTransformMovesOrigin, expected.rows, expected.rows));
    if (!r.linear_matrix)
      return incorrect(say(kAsksForHomogeneousMatrix, expected.rows, expected.rows));
    AnswerRules linear = r;
    linear.trivial = nullptr;
    linear.scale = nullptr;
    Comparison c = compare_components(linear_part(expected), got, linear);
    if (c.verdict == Verdict::Correct) c.feedback = say(kLinearPartWithoutTranslation);
    return c;
  }
  if (got.numbers.size() != expected.numbers.size() ||
      (expected.shape == Value::Shape::Matrix && got.shape == Value::Shape::Matrix &&
       expected.cols != got.cols))
    return incorrect(shape_mismatch(expected, got));
  if (exactly_equal(expected, got)) return correct(say(kExactlyEqual));
  const ComponentJudge judge = judge_of(expected, r);
  if (judge.all(expected.numbers, got.numbers)) return correct(say(kWithinTolerance));
  if (kind == AnswerKind::Segment) {
    const auto e = rows_of(expected), g = rows_of(got);
    std::vector<double> reversed;
    for (auto it = g.rbegin(); it != g.rend(); ++it)
      reversed.insert(reversed.end(), it->begin(), it->end());
    if (judge.all(expected.numbers, reversed)) return correct(say(kSameSegmentOtherOrder));
  }
  if (kind == AnswerKind::Point && multiple_of(expected, got, r) == Multiple::Positive)
    return correct(say(kSameHomogeneousPoint));
  if (kind == AnswerKind::UnitVector) {
    const Multiple m = multiple_of(expected, got, r);
    if (m == Multiple::Positive) {
      // The student's own length (multiple_of's ratio is taken between rescaled vectors).
      Comparison c = incorrect(say(kDirectionRightLengthIs, format_approx(length_of(got))));
      c.mistake = say(kNotNormalised);
      return c;
    }
    if (m == Multiple::Negative) return incorrect(say(kPointsTheOppositeWay));
  }
  if (auto c = trivial_match(expected, got, judge, r)) return *c;
  if (r.partial &&
      (kind == AnswerKind::Vector || kind == AnswerKind::Matrix || kind == AnswerKind::Transform))
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
    return correct(got.entries.size() > n ? say(kEntryTwiceSameWord) : Said());
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
  Said notes;
  if (undecided > 0)
    notes +=
        say(undecided == 1 ? kEntryTwiceDifferentWords : kEntriesTwiceDifferentWords, undecided);
  if (!extra.empty()) {
    const bool one = extra.size() == 1, edges = r.spec->unordered_pairs;
    notes += say(one ? (edges ? kEntryNamesNoSuchEdge : kEntryNamesNoSuchFace)
                     : (edges ? kEntriesNameNoSuchEdges : kEntriesNameNoSuchFaces),
                 extra.size());
  }
  const std::size_t total = n + extra.size();
  if (right > best_constant && total > best_constant)
    return {Verdict::Partial,
            static_cast<double>(right - best_constant) / static_cast<double>(total - best_constant),
            say(kEntriesRightBeyondConstant, right, total, words::vocabulary_word(best_word),
                best_constant) +
                notes,
            {},
            false,
            {}};
  if (right == 0) return incorrect(notes);
  return incorrect(say(kEntriesRightNoMoreThanConstant, right, total) + notes);
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
    return got.shape == Value::Shape::Null ? correct(say(kNoSuchValue))
                                           : incorrect(say(kNoSuchValueHere));
  }
  // "none" for an empty list (no hidden edges) says the same thing.
  if (got.shape == Value::Shape::Null && expected.shape == Value::Shape::WordList &&
      expected.words.empty())
    return correct(say(kThereAreNone));
  // "none" chooses no statement.
  if (r.spec->kind == AnswerKind::Statements) return compare_statement_choice(expected, got);
  if (got.shape == Value::Shape::Null) return incorrect(say(kThereIsAValueHere));
  switch (r.spec->kind) {
    case AnswerKind::Scalar: {
      if (got.numbers.size() != 1 || expected.numbers.size() != 1)
        return incorrect(say(kExpectedOneNumber));
      if (exactly_equal(expected, got)) return correct(say(kExactlyEqual));
      if (judge_of(expected, r).ok(0, expected.numbers[0], got.numbers[0]))
        return correct(say(kWithinTolerance));
      return incorrect();
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
        return incorrect(say(kExpectedItemsGot, e.size(), g.size()));
      // Sorted, the rows usually pair off at once (pixels are integers); otherwise each expected
      // row takes the first unused row within tolerance.
      auto se = e, sg = g;
      std::sort(se.begin(), se.end());
      std::sort(sg.begin(), sg.end());
      bool paired = true;
      for (std::size_t i = 0; i < se.size() && paired; ++i)
        paired = judge_of(numeric_value(expected, se[i]), r).all(se[i], sg[i]);
      if (paired) return correct(say(kSameItemsAnyOrder));
      std::vector<bool> used(g.size(), false);
      for (const auto& row : e) {
        const ComponentJudge judge = judge_of(numeric_value(expected, row), r);
        std::size_t j = 0;
        while (j < g.size() && (used[j] || !judge.all(row, g[j]))) ++j;
        if (j == g.size()) return incorrect();
        used[j] = true;
      }
      return correct(say(kSameItemsAnyOrder));
    }
    case AnswerKind::Direction: {
      if (got.numbers.size() != expected.numbers.size())
        return incorrect(say(kExpectedComponentsGot, expected.numbers.size(), got.numbers.size()));
      if (exactly_equal(expected, got)) return correct(say(kEqual));
      if (max_abs(got.numbers) == 0 && all_finite_and_faithful(got)) {
        Comparison c = incorrect(say(kZeroVectorHasNoDirection));
        c.trivial = say(kZeroVectorAnswer);
        c.no_work = true;
        return c;
      }
      const Multiple m = multiple_of(expected, got, r);
      if (m == Multiple::Positive) return correct(say(kSameDirection));
      if (m == Multiple::Negative) return incorrect(say(kPointsTheOppositeWay));
      // A vertex or another given copied as the normal.
      if (auto c = trivial_match(expected, got, judge_of(expected, r), r)) return *c;
      return incorrect();
    }
    case AnswerKind::Plane: {
      if (got.numbers.size() != 4) return incorrect(say(kPlaneHasFourCoefficients));
      if (multiple_of(expected, got, r) != Multiple::None) return correct(say(kSamePlane));
      return incorrect();
    }
    case AnswerKind::Bool:
      return got.flag == expected.flag ? correct() : incorrect();
    case AnswerKind::Category:
      return got.word == expected.word ? correct() : incorrect();
    case AnswerKind::BitString: {
      if (got.word == expected.word) return correct();
      // Written as a number, an outcode loses its leading zeros (0 for 0000, 101 for 0101):
      // the same bits, read with the zeros restored.
      if (!got.word.empty() && got.word.size() < expected.word.size() &&
          std::string(expected.word.size() - got.word.size(), '0') + got.word == expected.word)
        return correct(say(kReadWithLeadingZeros, expected.word));
      if (got.word.size() != expected.word.size())
        return incorrect(say(kBitsOnePerWindowEdge, expected.word.size()));
      return incorrect();
    }
    case AnswerKind::WordList: {
      const std::vector<std::string> items = items_read(got, expected, r);
      if (auto c = unreadable_list(items, expected, r)) return *c;
      std::vector<std::string> a = folded(expected.words, expected.words),
                               b = folded(items, expected.words);
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a == b) return correct(say(kSameSetAnyOrder));
      // An item written twice is right once; its second copy counts as one that should not be
      // there (common / max(expected, given)).
      std::vector<std::string> both;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(both));
      const std::size_t common = both.size();
      const std::size_t copies = b.size() - static_cast<std::size_t>(std::distance(
                                                b.begin(), std::unique(b.begin(), b.end())));
      const Said counted =
          copies == 0
              ? say(kExpectedItemsAndExtra, common, a.size(), b.size() - common)
              : say(kExpectedItemsExtraAndCopies, common, a.size(), b.size() - common, copies);
      if (common > 0 && !a.empty())
        return {Verdict::Partial,
                static_cast<double>(common) / static_cast<double>(std::max(a.size(), b.size())),
                counted,
                {},
                false,
                {}};
      return incorrect(copies == 0 ? Said() : counted);
    }
    case AnswerKind::Sequence: {
      const std::vector<std::string> items = items_read(got, expected, r);
      if (auto c = unreadable_list(items, expected, r)) return *c;
      const std::vector<std::string> a = folded(expected.words, expected.words),
                                     b = folded(items, expected.words);
      if (a == b) return correct();
      std::vector<std::string> sa = a, sb = b;
      std::sort(sa.begin(), sa.end());
      std::sort(sb.begin(), sb.end());
      return incorrect(sa == sb ? say(kRightItemsWrongOrder) : Said());
    }
    case AnswerKind::WordMap:
      return compare_word_map(expected, keys_read(got, expected, r), r);
    case AnswerKind::Statements:
      return compare_statement_choice(expected, got);
    case AnswerKind::Polygon: {
      // The same vertex cycle, starting anywhere (orientation must match).
      const auto e = rows_of(expected), g = rows_of(got);
      if (e.size() != g.size() || e.empty())
        return incorrect(say(kExpectedVerticesGot, e.size(), g.size()));
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
        return correct(say(*shift ? kSamePolygonOtherStart : kEqual));
      if (cycle_matches(true)) return incorrect(say(kRightVerticesOppositeOrder));
      return incorrect();
    }
  }
  return incorrect(say(kCannotBeGradedYet));
}

}  // namespace frustum
