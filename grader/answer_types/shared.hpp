// What several answer types say alike: the hints for typing a vector or a list of points, and
// why a quiz cannot ask for a set of labels.
#pragma once

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
// Why no quiz field can ask for it.
inline QuizAsk refused(const Phrase& why) {
  QuizAsk a;
  a.refused = say(why);
  return a;
}

}  // namespace frustum::answer_shared
