// An answer's value as data: what `solve` reports and what the grader compares. Numbers keep
// both their exact form (when the inputs were exact) and their double.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "solver/core/matrix.hpp"
#include "solver/derivation/math_text.hpp"

namespace frustum {

struct Value {
  enum class Shape { Scalar, Vector, Matrix, Bool, Word, WordMap, WordList, Null };

  Shape shape = Shape::Null;
  std::vector<double> numbers;  // Scalar, Vector, Matrix (row by row)
  std::vector<Exact> exact;     // same layout; empty when the value is not exact
  int rows = 0, cols = 0;       // Matrix
  bool flag = false;            // Bool
  std::string word;             // Word
  std::vector<std::pair<std::string, std::string>> entries;  // WordMap, in order
  std::vector<std::string> words;                            // WordList
  MathText display;  // how to show it when not the default (a plane as its equation)

  // The value as written in a derivation: exact with decimals beside when it is exact.
  MathText shown() const;

  bool has_exact() const { return !exact.empty() || numbers.empty(); }

  static Value scalar(const Exact& e);
  static Value scalar(double v);
  static Value vector(const std::vector<Exact>& v);
  static Value vector(const std::vector<double>& v);
  template <int N>
  static Value vector(const Eigen::Matrix<Exact, N, 1>& v) {
    return vector(std::vector<Exact>(v.data(), v.data() + N));
  }
  static Value matrix(const std::vector<std::vector<Exact>>& rows);
  static Value boolean(bool b);
  static Value category(std::string w);
  static Value word_map(std::vector<std::pair<std::string, std::string>> entries);
  static Value word_list(std::vector<std::string> words);
  static Value null();
};

// Answers of one problem, in the kind's order.
class Answers {
 public:
  void set(const std::string& name, Value v);
  const Value* find(const std::string& name) const;
  const std::vector<std::pair<std::string, Value>>& items() const { return items_; }

 private:
  std::vector<std::pair<std::string, Value>> items_;
};

}  // namespace frustum
