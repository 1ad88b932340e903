// A square homogeneous transformation matrix, judged per block (linear part, translation column,
// bottom row); a purely linear one may be given as its linear part.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

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
constexpr Phrase kMatrixRowByRow{"a matrix row by row, such as [[1, 0], [0, 1]]",
                                 "[[1, 0], [0, 1]] のように行ごとに書いた行列",
                                 "матрица по строкам, например [[1, 0], [0, 1]]"};

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

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  const ComponentRules entries{nullptr, true, false};
  if (got.shape == Value::Shape::Matrix && expected.rows == got.rows + 1 && got.rows == got.cols) {
    if (!purely_linear(expected))
      return incorrect(say(kTransformMovesOrigin, expected.rows, expected.rows));
    if (!r.linear_matrix)
      return incorrect(say(kAsksForHomogeneousMatrix, expected.rows, expected.rows));
    AnswerRules linear = r;
    linear.trivial = nullptr;
    linear.scale = nullptr;
    Comparison c = compare_components(linear_part(expected), got, linear, entries);
    if (c.verdict == Verdict::Correct) c.feedback = say(kLinearPartWithoutTranslation);
    return c;
  }
  return compare_components(expected, got, r, entries);
}

}  // namespace

AnswerType transform_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Transform;
  t.syntax = {
      {"transform matrix",
       R"md(a list of rows, each a list or a string of numbers; for a purely linear transform (no translation, bottom row 0 0 0 1) its 3×3 (2×2 in 2D) linear part too, unless the set says `grading: {linear_matrix: false}`)md",
       R"md(`[[1, 0, 0, 2], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]`)md"}};
  t.read = read_matrix;
  t.compare = compare_with_key;
  t.quiz = ask_numbers;
  t.typed_hint = &kMatrixRowByRow;
  t.block_magnitudes = true;
  t.transposed_is_convention = true;
  return t;
}

}  // namespace frustum
