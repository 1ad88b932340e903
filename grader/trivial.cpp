#include "grader/trivial.hpp"

#include <cmath>
#include <optional>

#include "solver/util/expression.hpp"

namespace frustum {

namespace {

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
  const std::size_t n = key.numbers.size();
  if (n < 2 || (key.shape != Value::Shape::Vector && key.shape != Value::Shape::Matrix)) return out;
  const auto add = [&](std::string name, std::string feedback, std::vector<double> numbers,
                       bool no_work = true) {
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
    add("identity matrix", "That is the identity matrix: it leaves every point where it is.",
        identity);
    if (kind == AnswerKind::Transform)
      add("transposed matrix (row- vs column-vector convention)",
          api == Api::DirectX
              ? "That is the transpose: the column-vector form p′ = M·p (as OpenGL writes it). "
                "With "
                "DirectX's row vectors p′ = p·M the translation stands in the bottom row."
              : "That is the transpose: the row-vector form p′ = p·M (as DirectX writes it). With "
                "column "
                "vectors p′ = M·p the translation stands in the last column.",
          transposed, false);
    else
      add("transposed matrix",
          "That is the transpose of the expected matrix: rows and columns swapped.", transposed,
          false);
  }
  add(square ? "zero matrix" : "zero vector", "Every entry is 0: that takes no computation.",
      std::vector<double>(n, 0.0));
  for (const GivenList& g : given) {
    std::vector<double> copy = g.value.numbers;
    if (copy.size() + 1 == n && (kind == AnswerKind::Point || kind == AnswerKind::Vector))
      copy.push_back(1);
    add("copied from the given",
        "That is " +
            (g.field.empty() ? std::string("the given") : "`" + g.field + "` from the problem") +
            ", copied unchanged: the answer is what the computation makes of it.",
        copy);
  }
  return out;
}

}  // namespace frustum
