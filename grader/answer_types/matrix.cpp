// A matrix, or a list of points (one per row), judged entry by entry; each row at its own scale.
#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kRowsSuchAs{
    "rows such as [[1, 0, 2], [0, 1, 3]]: a matrix row by row, or one point per row",
    "[[1, 0, 2], [0, 1, 3]] のような行の並び: 行ごとの行列, または 1 行に 1 点",
    "строки, например [[1, 0, 2], [0, 1, 3]]: матрица по строкам или по точке в строке"};

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  return compare_components(expected, got, r, {nullptr, true, false});
}

bool holds_infinity(const AnswerSpec& spec) { return spec.infinity != 0; }
bool holds_points(const AnswerSpec& spec) { return spec.infinity == 0; }

}  // namespace

AnswerType matrix_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Matrix;
  t.syntax = {
      {"matrix",
       R"md(a list of rows, each a list or a string of numbers; an empty pixel's depth, +∞, written `inf`, `∞`, `infinity` or `1e30` (the key's stand-in))md",
       R"md(`depth: [[0.5, inf], [1, 1]]`)md", holds_infinity},
      {"point list",
       R"md(a list of rows in order (each a list, or one string such as `"(0, 4), (8, 8)"`): points; [r, g, b, depth] per queried pixel (render). The `points` of transform and look_at also take one point as a flat list or a column (`[6, 8]`, `[[6], [8]]`) and points in homogeneous coordinates, read as (x/w, y/w, z/w) (`[[1, 3, 3, 1]]`; w = 0 is a direction, not a point))md",
       R"md(`points: [[3, 4], [2, 5/2]]`)md", holds_points}};
  t.read = read_matrix;
  t.compare = compare_with_key;
  t.quiz = ask_numbers;
  t.typed_hint = &kRowsSuchAs;
  return t;
}

}  // namespace frustum
