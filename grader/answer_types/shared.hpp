// What several answer types say alike: the hints for typing a vector or a list of points, and
// why a quiz cannot ask for a set of labels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "solver/util/said.hpp"

namespace frustum::answer_shared {

inline constexpr Phrase kVectorSuchAs{"a vector such as [1, -2, sqrt(3)/2]",
                                      "[1, -2, sqrt(3)/2] のようなベクトル",
                                      "вектор, например [1, -2, sqrt(3)/2]"};
inline constexpr Phrase kPointsInOrder{
    "points in order, such as [[0, 0], [4, 0], [0, 3]], or none",
    "[[0, 0], [4, 0], [0, 3]] のように順に並べた点, または none",
    "точки по порядку, например [[0, 0], [4, 0], [0, 3]], или none"};
inline constexpr Phrase kLabelSetAnyOrder{"a set of labels is right in any order",
                                          "ラベルの集合はどの順でも正しい",
                                          "множество меток верно в любом порядке"};

// The key's numbers, each a field.
inline QuizAsk numbers_asked(const Value& key) {
  QuizAsk a;
  a.numbers = key;
  return a;
}
// The key's numbers, each a field, as a type's quiz form.
inline QuizAsk ask_numbers(const AnswerSpec&, const Value& key, const Conventions&) {
  return numbers_asked(key);
}
// A choice among `words`, `right` the key's.
inline QuizAsk chosen_among(std::vector<std::string> words, std::string right) {
  QuizAsk a;
  a.field = QuizAsk::Field::Choice;
  a.words = std::move(words);
  a.right = std::move(right);
  return a;
}
// Why no quiz field can ask for it.
inline QuizAsk refused(const Phrase& why) {
  QuizAsk a;
  a.refused = say(why);
  return a;
}

// Readers several types use as they are: a list of numbers (a vector), rows of a matrix (with
// the answer's stand-in for +∞), a list of vertices, a list of words.
inline Said read_vector(const YAML::Node& node, const AnswerSpec&, AnswerReading& in,
                        ParsedAnswer& p) {
  const reading::Numbers n = reading::read_numbers(node, in.budget);
  if (!n.error.empty()) return n.error;
  p.value = Value::vector(n.values);
  return {};
}
inline Said read_rows_of(const YAML::Node& node, bool vertices, double infinity, AnswerReading& in,
                         ParsedAnswer& p) {
  const reading::Rows rows = reading::read_rows(node, vertices, in.budget, infinity);
  if (!rows.error.empty()) return rows.error;
  p.value = Value::matrix(rows.values);
  return {};
}
inline Said read_matrix(const YAML::Node& node, const AnswerSpec& spec, AnswerReading& in,
                        ParsedAnswer& p) {
  return read_rows_of(node, false, spec.infinity, in, p);
}
inline Said read_vertices(const YAML::Node& node, const AnswerSpec&, AnswerReading& in,
                          ParsedAnswer& p) {
  return read_rows_of(node, true, 0, in, p);
}
inline Said read_words(const YAML::Node& node, const AnswerSpec& spec, AnswerReading&,
                       ParsedAnswer& p) {
  std::vector<std::string> words;
  if (Said error = reading::read_word_list(node, spec.unordered_pairs, words); !error.empty())
    return error;
  p.value = Value::word_list(words);
  return {};
}

}  // namespace frustum::answer_shared
