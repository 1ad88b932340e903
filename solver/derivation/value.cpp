#include "solver/derivation/value.hpp"

#include <string>
#include <unordered_set>
#include <vector>

#include "solver/derivation/vocabulary.hpp"

namespace frustum {

Value Value::scalar(const Exact& e) {
  Value v;
  v.shape = Shape::Scalar;
  v.exact = {canonical(e)};
  v.numbers = {to_double(v.exact[0])};
  return v;
}

Value Value::scalar(double d) {
  Value v;
  v.shape = Shape::Scalar;
  v.numbers = {d};
  return v;
}

Value Value::vector(const std::vector<Exact>& e) {
  Value v;
  v.shape = Shape::Vector;
  for (const Exact& x : e) {
    v.exact.push_back(canonical(x));
    v.numbers.push_back(to_double(v.exact.back()));
  }
  return v;
}

Value Value::vector(const std::vector<double>& d) {
  Value v;
  v.shape = Shape::Vector;
  v.numbers = d;
  return v;
}

Value Value::matrix(const std::vector<std::vector<Exact>>& rows) {
  Value v;
  v.shape = Shape::Matrix;
  v.rows = static_cast<int>(rows.size());
  v.cols = rows.empty() ? 0 : static_cast<int>(rows[0].size());
  for (const auto& row : rows)
    for (const Exact& x : row) {
      v.exact.push_back(canonical(x));
      v.numbers.push_back(to_double(v.exact.back()));
    }
  return v;
}

Value Value::boolean(bool b) {
  Value v;
  v.shape = Shape::Bool;
  v.flag = b;
  return v;
}

Value Value::category(std::string w) {
  Value v;
  v.shape = Shape::Word;
  v.word = std::move(w);
  return v;
}

Value Value::word_map(std::vector<std::pair<std::string, std::string>> entries) {
  Value v;
  v.shape = Shape::WordMap;
  v.entries = std::move(entries);
  return v;
}

Value Value::word_list(std::vector<std::string> words) {
  Value v;
  v.shape = Shape::WordList;
  v.words = std::move(words);
  return v;
}

Value Value::null() { return Value{}; }

namespace {

// Parts joined by commas, each word kept once, in linear time (`+=` looks every word up among
// all before it: quadratic for the 30 k edges of a large mesh).
MathText comma_joined(const std::vector<MathText>& parts) {
  MathText out;
  std::unordered_set<std::string> seen;
  for (const MathText& p : parts) {
    if (!out.empty()) {
      out.unicode += ", ";
      out.latex += ",\\; ";
    }
    out.unicode += p.unicode;
    out.latex += p.latex;
    for (const Said& w : p.words)
      if (seen.insert(w.en()).second) out.words.push_back(w);
  }
  return out;
}

}  // namespace

MathText Value::shown() const {
  if (!display.empty()) return display;
  switch (shape) {
    case Shape::Scalar:
      return exact.empty() ? number(numbers[0]) : frustum::exact(exact[0], true);
    case Shape::Vector: {
      if (!exact.empty()) return vec(exact, true);
      std::vector<MathText> entries;
      for (const double d : numbers) entries.push_back(number(d));
      return tuple_of(entries);
    }
    case Shape::Matrix: {
      // A numeric backend's matrix in decimals (its doubles as binary fractions would be exact
      // and unreadable: 3900231685776981/9007199254740992).
      std::vector<MathText> entries;
      for (std::size_t k = 0; k < numbers.size(); ++k)
        entries.push_back(exact.empty() ? number(numbers[k]) : frustum::exact(exact[k]));
      return matrix_of(entries, static_cast<std::size_t>(cols));
    }
    case Shape::Bool:
      return frustum::word(flag ? words::kTrue : words::kFalse);
    case Shape::Word:
      return frustum::word(words::vocabulary_word(word));
    case Shape::WordMap: {
      std::vector<MathText> parts;
      for (const auto& [k, v] : entries)
        parts.push_back(frustum::word(words::vocabulary_word(k)) + tex("\\colon ") +
                        frustum::word(words::vocabulary_word(v)));
      return comma_joined(parts);
    }
    case Shape::WordList: {
      if (words.empty()) return frustum::word(words::kNone);
      std::vector<MathText> parts;
      for (const auto& w : words) parts.push_back(frustum::word(words::vocabulary_word(w)));
      return comma_joined(parts);
    }
    case Shape::Null:
      return frustum::word(words::kNone);
  }
  return {};
}

void Answers::set(const std::string& name, Value v) {
  for (auto& [n, existing] : items_)
    if (n == name) {
      existing = std::move(v);
      return;
    }
  items_.emplace_back(name, std::move(v));
}

const Value* Answers::find(const std::string& name) const {
  for (const auto& [n, v] : items_)
    if (n == name) return &v;
  return nullptr;
}

}  // namespace frustum
