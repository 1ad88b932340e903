#include "grader/trivial.hpp"

#include <cmath>
#include <optional>

#include "grader/answer_type.hpp"
#include "solver/util/expression.hpp"

namespace frustum {

namespace {

// What each trivial answer is called, and what it is (the zero vector and the copy of the given
// are named in trivial.hpp: the grader says them too).
constexpr Phrase kIdentityMatrix{"identity matrix", "単位行列", "единичная матрица"};
constexpr Phrase kIdentityMatrixLeavesPoints{
    "That is the identity matrix: it leaves every point where it is.",
    "それは単位行列です. どの点も動かしません.",
    "Это единичная матрица: она оставляет каждую точку на месте."};
constexpr Phrase kTransposedConvention{
    "transposed matrix (row- vs column-vector convention)",
    "転置行列 (行ベクトルと列ベクトルの規約の取り違え)",
    "транспонированная матрица (путаница строк- и столбцов-векторов)"};
constexpr Phrase kTransposeColumnVectorForm{
    "That is the transpose: the column-vector form p′ = M·p (as OpenGL writes it).",
    "それは転置です. 列ベクトルの形 p′ = M·p (OpenGL の書き方) になっています.",
    "Это транспонированная матрица: форма для столбцов p′ = M·p (как пишет OpenGL)."};
constexpr Phrase kDirectXTranslationInBottomRow{
    "With DirectX's row vectors p′ = p·M the translation stands in the bottom row.",
    "DirectX の行ベクトル p′ = p·M では平行移動は最下行に来ます.",
    "Для строк-векторов DirectX p′ = p·M перенос стоит в нижней строке."};
constexpr Phrase kTransposeRowVectorForm{
    "That is the transpose: the row-vector form p′ = p·M (as DirectX writes it).",
    "それは転置です. 行ベクトルの形 p′ = p·M (DirectX の書き方) になっています.",
    "Это транспонированная матрица: форма для строк p′ = p·M (как пишет DirectX)."};
constexpr Phrase kColumnVectorsTranslationInLastColumn{
    "With column vectors p′ = M·p the translation stands in the last column.",
    "列ベクトル p′ = M·p では平行移動は最後の列に来ます.",
    "Для столбцов-векторов p′ = M·p перенос стоит в последнем столбце."};
constexpr Phrase kTransposedMatrix{"transposed matrix", "転置行列", "транспонированная матрица"};
constexpr Phrase kTransposeOfExpected{
    "That is the transpose of the expected matrix: rows and columns swapped.",
    "それは正解の行列の転置です. 行と列が入れ替わっています.",
    "Это транспонированная верная матрица: строки и столбцы переставлены."};
constexpr Phrase kZeroMatrix{"zero matrix", "零行列", "нулевая матрица"};
constexpr Phrase kEveryEntryZero{"Every entry is 0: that takes no computation.",
                                 "すべて 0 です. 計算を必要としません.",
                                 "Все элементы равны 0: это не требует вычислений."};
constexpr Phrase kGivenCopiedUnchanged{
    "That is the given, copied unchanged: the answer is what the computation makes of it.",
    "それは問題の値をそのまま写したものです. 解答はそれを計算した結果です.",
    "Это данные из условия без изменений: ответ — то, что из них получается при вычислении."};
constexpr Phrase kFieldCopiedUnchanged{
    "That is `{0}` from the problem, copied unchanged: the answer is what the computation makes of "
    "it.",
    "それは問題の `{0}` をそのまま写したものです. 解答はそれを計算した結果です.",
    "Это `{0}` из условия без изменений: ответ — то, что из него получается при вычислении."};

std::optional<Exact> number_of(const YAML::Node& n) {
  if (!n.IsScalar()) return std::nullopt;
  const ExpressionResult r = parse_expression(n.Scalar());
  if (!r || !is_real_constant(*r.value)) return std::nullopt;
  return canonical(*r.value);
}

std::optional<std::vector<Exact>> numbers_of(const YAML::Node& n) {
  if (!n.IsSequence() || n.size() == 0) return std::nullopt;
  std::vector<Exact> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const auto x = number_of(n[i]);
    if (!x) return std::nullopt;
    out.push_back(*x);
  }
  return out;
}

void collect(const YAML::Node& n, const std::string& field, std::vector<GivenList>& out,
             int depth) {
  if (depth > 8) return;
  if (const auto v = numbers_of(n)) {
    out.push_back({field, Value::vector(*v)});
    return;
  }
  if (n.IsSequence()) {
    std::vector<std::vector<Exact>> rows;
    for (std::size_t i = 0; i < n.size(); ++i) {
      const auto row = numbers_of(n[i]);
      if (row && (rows.empty() || row->size() == rows[0].size()))
        rows.push_back(*row);
      else
        rows.clear();
      if (rows.empty()) break;
    }
    if (!rows.empty()) out.push_back({field, Value::matrix(rows)});
    for (std::size_t i = 0; i < n.size(); ++i)
      collect(n[i], field + "[" + std::to_string(i) + "]", out, depth + 1);
  } else if (n.IsMap()) {
    for (auto it = n.begin(); it != n.end(); ++it) {
      const std::string k = it->first.Scalar();
      collect(it->second, field.empty() ? k : field + "." + k, out, depth + 1);
    }
  }
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::abs(a[i] - b[i]) > 1e-12 * std::max({1.0, std::abs(a[i]), std::abs(b[i])}))
      return false;
  return true;
}

Value filled(const Value& key, const std::vector<double>& numbers) {
  Value v;
  v.shape = key.shape;
  v.rows = key.rows;
  v.cols = key.cols;
  v.numbers = numbers;
  return v;
}

}  // namespace

std::vector<GivenList> given_lists(const YAML::Node& given) {
  std::vector<GivenList> out;
  if (given.IsDefined()) collect(given, "", out, 0);
  return out;
}

std::vector<TrivialAnswer> trivial_answers(const Value& key, AnswerKind kind,
                                           const std::vector<GivenList>& given, Api api) {
  std::vector<TrivialAnswer> out;
  const AnswerType& type = answer_type(kind);
  const std::size_t n = key.numbers.size();
  if (n < 2 || (key.shape != Value::Shape::Vector && key.shape != Value::Shape::Matrix)) return out;
  const auto add = [&](Said name, Said feedback, std::vector<double> numbers, bool no_work = true) {
    if (numbers.size() != n || same(numbers, key.numbers)) return;
    for (const TrivialAnswer& t : out)
      if (same(t.value.numbers, numbers)) return;
    out.push_back({std::move(name), std::move(feedback), filled(key, numbers), no_work});
  };
  const bool square = key.shape == Value::Shape::Matrix && key.rows == key.cols && key.rows >= 2;
  if (square) {
    const std::size_t s = static_cast<std::size_t>(key.rows);
    std::vector<double> identity(n, 0.0), transposed(n);
    for (std::size_t i = 0; i < s; ++i) {
      identity[i * s + i] = 1;
      for (std::size_t j = 0; j < s; ++j) transposed[i * s + j] = key.numbers[j * s + i];
    }
    add(say(kIdentityMatrix), say(kIdentityMatrixLeavesPoints), identity);
    if (type.transposed_is_convention)
      add(say(kTransposedConvention),
          api == Api::DirectX
              ? say(kTransposeColumnVectorForm) + say(kDirectXTranslationInBottomRow)
              : say(kTransposeRowVectorForm) + say(kColumnVectorsTranslationInLastColumn),
          transposed, false);
    else
      add(say(kTransposedMatrix), say(kTransposeOfExpected), transposed, false);
  }
  add(say(square ? kZeroMatrix : kZeroVectorAnswer), say(kEveryEntryZero),
      std::vector<double>(n, 0.0));
  for (const GivenList& g : given) {
    std::vector<double> copy = g.value.numbers;
    if (copy.size() + 1 == n && type.homogeneous_copies) copy.push_back(1);
    add(say(kCopiedFromTheGiven),
        g.field.empty() ? say(kGivenCopiedUnchanged) : say(kFieldCopiedUnchanged, g.field), copy);
  }
  return out;
}

}  // namespace frustum
