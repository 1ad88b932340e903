// A unit vector: a vector of length 1, component by component.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"
#include "solver/util/exact_format.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kDirectionRightLengthIs{
    "the direction is right but the length is {0} — a unit vector has length 1 (divide by the "
    "length)",
    "向きは正しいが長さが {0} です — 単位ベクトルの長さは 1 (長さで割る)",
    "направление верное, но длина {0} — у единичного вектора длина 1 (разделите на длину)"};
constexpr Phrase kNotNormalised{"not normalised", "正規化していない", "не нормирован"};

// The right direction at another length is named (not normalised); the opposite one too.
std::optional<Comparison> another_length(const Value& expected, const Value& got,
                                         const ComponentJudge&, const AnswerRules& r) {
  const Multiple m = multiple_of(expected, got, r);
  if (m == Multiple::Positive) {
    // The student's own length (multiple_of's ratio is taken between rescaled vectors).
    Comparison c = incorrect(say(kDirectionRightLengthIs, format_approx(length_of(got))));
    c.mistake = say(kNotNormalised);
    return c;
  }
  if (m == Multiple::Negative) return incorrect(say(kPointsTheOppositeWay));
  return std::nullopt;
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_components(expected, got, r, {another_length, false, false});
}

}  // namespace

AnswerType unit_vector_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::UnitVector;
  t.syntax = {{"unit vector", R"md(a vector of length 1)md",
               R"md(`["sqrt(3)/3", "sqrt(3)/3", "-sqrt(3)/3"]`, `"1/sqrt(3)*(1, 1, -1)"`)md"}};
  t.read = read_vector;
  t.compare = compare_with_key;
  t.quiz = ask_numbers;
  t.typed_hint = &kVectorSuchAs;
  return t;
}

}  // namespace frustum
