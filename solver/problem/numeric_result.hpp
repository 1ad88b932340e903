// What the numeric path of a kind produces: answers (values only, no derivation steps), every
// number at the backend's own precision for measuring its error, and the warnings about
// ill-conditioning it found. Kinds build these from their templated cores with NumericOut.
#pragma once

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "solver/derivation/value.hpp"
#include "solver/numeric/precision.hpp"
#include "solver/util/said.hpp"
#include "solver/viewing/transforms.hpp"

namespace frustum {

// What NumericOut says: the inputs' and the values' range warnings, and a decision left to exact
// arithmetic.
inline constexpr Phrase kNumericInputsOverflow{"Inputs overflow", "入力のオーバーフロー",
                                               "Переполнение входных данных"};
inline constexpr Phrase kNumericInputsUnderflow{"Inputs underflow", "入力のアンダーフロー",
                                                "Исчезновение порядка входных данных"};
inline constexpr Phrase kNumericInputsOverflowDecided{
    "some inputs exceed the range of {0} and became infinite; the values computed from them are "
    "meaningless, and every discrete answer was decided on the exact inputs.",
    "一部の入力は {0} の範囲を超えて無限大になった. それから計算した値は意味をもたないが, "
    "離散的な答えはすべて厳密な入力で決めた.",
    "некоторые входные данные выходят за диапазон {0} и стали бесконечными; вычисленные из них "
    "значения бессмысленны, а каждый дискретный ответ решён по точным входным данным."};
inline constexpr Phrase kNumericInputsOverflowMeaningless{
    "some inputs exceed the range of {0} and became infinite; the values computed from them are "
    "meaningless.",
    "一部の入力は {0} の範囲を超えて無限大になった. それから計算した値は意味をもたない.",
    "некоторые входные данные выходят за диапазон {0} и стали бесконечными; вычисленные из них "
    "значения бессмысленны."};
inline constexpr Phrase kNumericInputsUnderflowDecided{
    "some inputs are below the normal range of {0} and were rounded to subnormal numbers or to 0: "
    "the values computed from them keep few or none of their digits, and every discrete answer was "
    "decided on the exact inputs.",
    "一部の入力は {0} の正規化数の範囲より小さく, 非正規化数か 0 に丸められた. "
    "それから計算した値には正しい桁がほとんど残らないが, 離散的な答えはすべて厳密な入力で決めた.",
    "некоторые входные данные меньше нормального диапазона {0} и округлены до субнормальных чисел "
    "или до 0: вычисленные из них значения сохраняют мало верных цифр или ни одной, а каждый "
    "дискретный ответ решён по точным входным данным."};
inline constexpr Phrase kNumericInputsUnderflowFewDigits{
    "some inputs are below the normal range of {0} and were rounded to subnormal numbers or to 0: "
    "the values computed from them keep few or none of their digits.",
    "一部の入力は {0} の正規化数の範囲より小さく, 非正規化数か 0 に丸められた. "
    "それから計算した値には正しい桁がほとんど残らない.",
    "некоторые входные данные меньше нормального диапазона {0} и округлены до субнормальных чисел "
    "или до 0: вычисленные из них значения сохраняют мало верных цифр или ни одной."};
inline constexpr Phrase kNumericDecidedByExactArithmetic{
    "{0}: decided by exact arithmetic on the given numbers (the {1} computation could not settle "
    "it).",
    "{0}: 与えられた数の厳密計算で決めた ({1} の計算では決められなかった).",
    "{0}: решено точной арифметикой на данных числах (вычисление в {1} не смогло это решить)."};
inline constexpr Phrase kNumericOverflow{"Overflow", "オーバーフロー", "Переполнение"};
inline constexpr Phrase kNumericValuesOverflow{
    "some values exceed the range of {0} and are infinite; exact answers are computed up to about "
    "1.8·10³⁰⁸ (the range of a double).",
    "一部の値は {0} の範囲を超えて無限大になった. 厳密計算の答えは約 1.8·10³⁰⁸ (double の範囲) "
    "まで求められる.",
    "некоторые значения выходят за диапазон {0} и равны бесконечности; точные ответы вычисляются "
    "до примерно 1,8·10³⁰⁸ (диапазон double)."};
inline constexpr Phrase kNumericNotANumber{"Not a number", "非数", "Не число"};
inline constexpr Phrase kNumericValuesNotANumber{
    "some values are not a number: an operation without a value in {0} (0/0 or ∞ − ∞, after a "
    "cancellation or an overflow); solve with --precision exact for the exact values.",
    "一部の値は非数になった: {0} で値をもたない演算 (桁落ちやオーバーフローの後の 0/0 や ∞ − ∞) "
    "による. 厳密な値は `--precision exact` で求められる.",
    "некоторые значения не являются числом: операция без значения в {0} (0/0 или ∞ − ∞ после "
    "потери точности или переполнения); точные значения даёт `--precision exact`."};
inline constexpr Phrase kNumericUnderflow{"Underflow", "アンダーフロー", "Исчезновение порядка"};
inline constexpr Phrase kNumericValuesUnderflow{
    "some values are below the normal range of {0} (subnormal, or flushed to 0): they keep few or "
    "none of their digits.",
    "一部の値は {0} の正規化数の範囲より小さい (非正規化数か 0): 正しい桁はほとんど残らない.",
    "некоторые значения меньше нормального диапазона {0} (субнормальные или обращены в 0): в них "
    "мало верных цифр или нет ни одной."};

struct NumericWarning {
  Said title;
  Said text;
};

struct NumericResult {
  Precision precision = Precision::Exact;
  // As solve reports them: doubles, plus exact values for the exact backend.
  Answers answers;
  // Each numeric answer's components at the backend's precision (long double holds float,
  // double and long double exactly; exact values with ~30 digits). A null answer is absent.
  std::vector<std::pair<std::string, std::vector<long double>>> raw;
  std::vector<NumericWarning> warnings;
  // Which formulation the numeric path used where it had a choice ("plane method", "barycentric").
  std::vector<Said> notes;

  const std::vector<long double>* find_raw(const std::string& name) const {
    for (const auto& [n, v] : raw)
      if (n == name) return &v;
    return nullptr;
  }
};

// How a problem's exact inputs fared when converted to a backend's scalar: some overflowed
// (infinite), or fell below the normal range (rounded to a subnormal number or flushed to 0).
// Either breaks the relative-error assumption of the predicates' bounds, so discrete answers
// then come from the exact inputs, and the answers warn.
struct InputRange {
  bool underflow = false;
  bool overflow = false;
  bool relative() const { return !underflow && !overflow; }
};

// A numeric solve prepared for one backend: the inputs already converted from exact, so run()
// is only the arithmetic (what `frustum bench accuracy` times) and result() packages the last run.
class NumericSolver {
 public:
  virtual ~NumericSolver() = default;
  virtual void run() = 0;
  virtual NumericResult result() const = 0;
};

// The usual adapter: In<T> holds the converted inputs, Core(In) → Out is the templated core,
// Report(In, Out) → NumericResult packages it.
template <typename In, typename Out, typename Core, typename Report>
class PreparedSolver final : public NumericSolver {
 public:
  PreparedSolver(In in, Core core, Report report)
      : in_(std::move(in)), core_(core), report_(report) {}
  void run() override { out_ = core_(in_); }
  NumericResult result() const override { return report_(in_, out_); }

 private:
  In in_;
  Core core_;
  Report report_;
  Out out_{};
};

template <typename In, typename Core, typename Report>
std::unique_ptr<NumericSolver> prepare(In in, Core core, Report report) {
  using Out = decltype(core(in));
  return std::make_unique<PreparedSolver<In, Out, Core, Report>>(std::move(in), core, report);
}

// Builds a NumericResult from values in scalar T.
template <typename T>
class NumericOut {
 public:
  explicit NumericOut(Precision p) { r_.precision = p; }

  void scalar(const std::string& name, const T& v) { put(name, Value::Shape::Scalar, 0, 0, {v}); }
  template <int N>
  void vector(const std::string& name, const Eigen::Matrix<T, N, 1>& v) {
    put(name, Value::Shape::Vector, 0, 0, std::vector<T>(v.data(), v.data() + N));
  }
  void vector(const std::string& name, const std::vector<T>& v) {
    put(name, Value::Shape::Vector, 0, 0, v);
  }
  void matrix(const std::string& name, const MatX<T>& m) {
    std::vector<T> row_major;
    for (int i = 0; i < m.rows(); ++i)
      for (int j = 0; j < m.cols(); ++j) row_major.push_back(m(i, j));
    put(name, Value::Shape::Matrix, static_cast<int>(m.rows()), static_cast<int>(m.cols()),
        row_major);
  }
  void rows(const std::string& name, const std::vector<std::vector<T>>& rows) {
    std::vector<T> flat;
    for (const auto& row : rows) flat.insert(flat.end(), row.begin(), row.end());
    put(name, Value::Shape::Matrix, static_cast<int>(rows.size()),
        rows.empty() ? 0 : static_cast<int>(rows[0].size()), flat);
  }
  void null(const std::string& name) { r_.answers.set(name, Value::null()); }
  void boolean(const std::string& name, bool b) { r_.answers.set(name, Value::boolean(b)); }
  void word(const std::string& name, const std::string& w) {
    r_.answers.set(name, Value::category(w));
  }
  void warn(Said title, Said text) { r_.warnings.push_back({std::move(title), std::move(text)}); }
  void note(Said text) { r_.notes.push_back(std::move(text)); }
  // A value whose true magnitude is below the normal range even where it came out 0 (a
  // product scaled back by a power of two): warned as underflow.
  void underflow() { underflow_ = true; }
  // The inputs' conversion (InputRange): warned once, before the values' own range warnings.
  // `discrete_exact`: the kind decides its discrete answers on the exact inputs (say so).
  void inputs(const InputRange& range, bool discrete_exact = true) {
    const std::string name(to_string(r_.precision));
    if (range.overflow)
      warn(say(kNumericInputsOverflow),
           say(discrete_exact ? kNumericInputsOverflowDecided : kNumericInputsOverflowMeaningless,
               name));
    if (range.underflow)
      warn(say(kNumericInputsUnderflow),
           say(discrete_exact ? kNumericInputsUnderflowDecided : kNumericInputsUnderflowFewDigits,
               name));
  }
  // A discrete answer decided by the exact fallback (predicates.hpp), in neutral words: `what`
  // is decided ("whether the normal is zero").
  void exact_decision(const Said& what) {
    note(say(kNumericDecidedByExactArithmetic, what, to_string(r_.precision)));
  }

  NumericResult take() {
    const std::string name(to_string(r_.precision));
    // The exact backend is not unlimited: its answers are printed as doubles too and are
    // refused beyond double's range.
    if (overflow_) warn(say(kNumericOverflow), say(kNumericValuesOverflow, name));
    if (not_a_number_) warn(say(kNumericNotANumber), say(kNumericValuesNotANumber, name));
    if (underflow_) warn(say(kNumericUnderflow), say(kNumericValuesUnderflow, name));
    return std::move(r_);
  }

 private:
  void put(const std::string& name, Value::Shape shape, int rows, int cols,
           const std::vector<T>& v) {
    Value value;
    value.shape = shape;
    value.rows = rows;
    value.cols = cols;
    std::vector<long double> raw;
    for (const T& x : v) {
      raw.push_back(to_long_double(x));
      if constexpr (std::is_same_v<T, Exact>) {
        value.exact.push_back(canonical(x));
        value.numbers.push_back(to_double(value.exact.back()));
      } else {
        value.numbers.push_back(static_cast<double>(x));
        // An infinity is an overflow; a NaN is an operation without a value (0/0 after a
        // cancellation, ∞ − ∞), which is no overflow by itself.
        overflow_ = overflow_ || std::isinf(x);
        not_a_number_ = not_a_number_ || std::isnan(x);
        underflow_ = underflow_ || (x != T(0) && std::abs(x) < std::numeric_limits<T>::min());
      }
    }
    r_.answers.set(name, value);
    r_.raw.emplace_back(name, std::move(raw));
  }

  NumericResult r_;
  bool overflow_ = false, underflow_ = false, not_a_number_ = false;
};

}  // namespace frustum
