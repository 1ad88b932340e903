// What the answer types' comparisons share (grader/answer_types/): verdicts with their reasons,
// exact equality, component windows, multiples of a vector, trivial answers, component credit,
// and list items as meant. Defined in compare.cpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "grader/compare.hpp"
#include "grader/tolerance.hpp"
#include "solver/util/said.hpp"

namespace frustum::comparing {

// Said by several types.
inline constexpr Phrase kExactlyEqual{"exactly equal", "完全に一致", "точно равно"};
inline constexpr Phrase kWithinTolerance{"within tolerance", "許容誤差内", "в пределах допуска"};
inline constexpr Phrase kEqual{"equal", "一致", "равно"};
inline constexpr Phrase kPointsTheOppositeWay{"it points the opposite way", "向きが逆です",
                                              "направлена в противоположную сторону"};

Comparison correct(Said why = {});
Comparison incorrect(Said why = {});

// Both exact and equal, component by component.
bool exactly_equal(const Value& a, const Value& b);
// The windows of each component of `expected` under the rules.
ComponentJudge judge_of(const Value& expected, const AnswerRules& r);
// Rows of `cols` numbers (a polygon's or a segment's vertices).
std::vector<std::vector<double>> rows_of(const Value& v);
// A value of `shape`'s shape holding `numbers` (no exact form).
Value numeric_value(const Value& shape, std::vector<double> numbers);
// Every component finite, and non-zero where its exact number is.
bool all_finite_and_faithful(const Value& v);

enum class Multiple { None, Positive, Negative };
// Is g a multiple k·e (k ≠ 0), each component of g judged against k·e? Both vectors are first
// scaled by powers of two; numbers beyond double range are compared exactly (g × e = 0).
Multiple multiple_of(const Value& expected, const Value& got, const AnswerRules& r,
                     double* k_out = nullptr);
// ‖v‖ of a vector answer: from its doubles, or from its exact components when a double
// overflowed (1e200 squared).
double length_of(const Value& v);

// The trivial answer (trivial.hpp) that `got` is as a whole, if any: a wrong answer equal to the
// zero vector, the identity, a list copied from the given or the transposed key.
// `up_to_scale`: a copy counts at any positive multiple (a homogeneous point).
std::optional<Comparison> trivial_match(const Value& expected, const Value& got,
                                        const ComponentJudge& judge, const AnswerRules& r,
                                        bool up_to_scale = false);

// What a type adds to the comparison component by component.
struct ComponentRules {
  // Another form as right as the key's, or a mistake the type recognises: tried when the
  // components are not all within their windows, before the trivial answers.
  std::optional<Comparison> (*also)(const Value& expected, const Value& got,
                                    const ComponentJudge& judge, const AnswerRules& r) = nullptr;
  bool credit = false;       // credit per component, when the set asks for partial credit
  bool up_to_scale = false;  // trivial copies at any positive multiple (trivial_match)
};
// One number: exactly equal, or within its window.
Comparison compare_number(const Value& expected, const Value& got, const AnswerRules& r);

// Same shape, then each component within its window; points written another way (one point as
// a column, homogeneous coordinates) are read as the rows they mean when the answer says so.
Comparison compare_components(const Value& expected, const Value& got, const AnswerRules& r,
                              const ComponentRules& rules);

// Words compared without case ("Background" is background), unless the expected words differ
// only by case (labels "a" and "A" of two polygons).
std::vector<std::string> folded(const std::vector<std::string>& words,
                                const std::vector<std::string>& expected);
// The student's list items as meant (list_items.hpp): split where one text separates them, and
// unordered pairs in the key's spelling.
std::vector<std::string> items_read(const Value& got, const Value& expected, const AnswerRules& r);
// A list answer with an item that cannot be one of its items (list_items.hpp) cannot be read:
// `unparseable` with the reason, never a wrong order or set.
std::optional<Comparison> unreadable_list(const std::vector<std::string>& items,
                                          const Value& expected, const AnswerRules& r);

}  // namespace frustum::comparing
