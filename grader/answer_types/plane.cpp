// A plane: a, b, c, d of ax + by + cz = d, or its equation; right up to any non-zero factor.
#include <string>

#include "grader/answer_reading.hpp"
#include "grader/answer_type.hpp"
#include "grader/answer_types/shared.hpp"
#include "grader/compare_parts.hpp"
#include "solver/util/expression.hpp"

namespace frustum {

namespace {

using namespace comparing;
using namespace reading;
using namespace answer_shared;

constexpr Phrase kCannotReadPlane{"cannot read the plane '{0}': {1}",
                                  "平面 `{0}` を読めません: {1}",
                                  "не удаётся прочитать плоскость `{0}`: {1}"};
constexpr Phrase kPlaneIsEquationOrList{
    "a plane is an equation like 'x + y - z = -6' or a list [a, b, c, d]",
    "平面は 'x + y - z = -6' のような方程式か, リスト [a, b, c, d] で書きます",
    "плоскость — уравнение вида 'x + y - z = -6' или список [a, b, c, d]"};
constexpr Phrase kPlaneNotLinear{"the plane is not linear in {0}",
                                 "平面が {0} について線形ではありません",
                                 "плоскость не линейна по {0}"};
constexpr Phrase kPlaneCoefficientsNumbers{"the plane's coefficients must be numbers",
                                           "平面の係数は数でなければなりません",
                                           "коэффициенты плоскости должны быть числами"};
constexpr Phrase kPlaneHasFourCoefficients{
    "a plane has 4 coefficients [a, b, c, d] of ax + by + cz = d",
    "平面の係数は a·x + b·y + c·z = d の 4 つ [a, b, c, d] です",
    "у плоскости 4 коэффициента [a, b, c, d] уравнения a·x + b·y + c·z = d"};
constexpr Phrase kPlaneNeedsFour{"a plane has 4 coefficients", "平面の係数は 4 つです",
                                 "у плоскости 4 коэффициента"};
constexpr Phrase kSamePlane{
    "the same plane (equations agree up to a non-zero factor)",
    "同じ平面 (方程式が 0 でない定数倍を除いて一致)",
    "та же плоскость (уравнения совпадают с точностью до ненулевого множителя)"};
constexpr Phrase kPlaneUpToFactor{"a plane's equation is right up to any non-zero factor",
                                  "平面の方程式は 0 でない定数倍しても正しい",
                                  "уравнение плоскости верно с точностью до ненулевого множителя"};
constexpr Phrase kEquationSuchAs{"an equation such as x + y - z = -6",
                                 "x + y - z = -6 のような方程式",
                                 "уравнение, например x + y - z = -6"};

// "x + y − z = −6" → [a, b, c, d] of ax + by + cz = d.
Numbers read_plane_equation(const std::string& text, WorkBudget& budget) {
  Numbers out;
  ExpressionOptions opts;
  for (const char* name : {"x", "y", "z"}) opts.symbols.emplace(name, GiNaC::symbol(name));
  opts.allow_equation = true;
  opts.degree_sign = true;
  const ExpressionResult r = parse_expression(text, opts);
  if (!r) {
    out.error = say(kCannotReadPlane, excerpt(text), r.error);
    return out;
  }
  if (!r.equation) {
    out.error = say(kPlaneIsEquationOrList);
    return out;
  }
  const GiNaC::ex e = r.value->expand();
  GiNaC::exmap zero;
  GiNaC::ex linear = 0;
  for (const char* name : {"x", "y", "z"}) {
    const GiNaC::symbol& s = opts.symbols.at(name);
    if (e.degree(s) > 1) {
      out.error = say(kPlaneNotLinear, name);
      return out;
    }
    const GiNaC::ex c = e.coeff(s, 1);
    out.values.push_back(c);
    linear += c * s;
    zero[s] = 0;
  }
  const GiNaC::ex constant = e.subs(zero);
  if (!(e - linear - constant).expand().is_zero()) {
    out.error = say(kPlaneNotLinear, "x, y, z");
    return out;
  }
  for (const Exact& c : out.values)
    if (!is_real_constant(c)) {
      out.error = say(kPlaneCoefficientsNumbers);
      return out;
    }
  out.values.push_back(-constant);
  for (Exact& c : out.values) c = canonical(c, budget);
  if (budget.exceeded())
    for (Exact& c : out.values) c = exact_from_double(to_double(c));
  return out;
}

Said read_answer(const YAML::Node& node, const AnswerSpec&, AnswerReading& in, ParsedAnswer& p) {
  const bool equation = node.IsScalar() && node.Scalar().find('=') != std::string::npos;
  p.form = equation ? "equation" : "list";
  const Numbers n =
      equation ? read_plane_equation(node.Scalar(), in.budget) : read_numbers(node, in.budget);
  if (!n.error.empty()) return n.error;
  if (n.values.size() != 4) return say(kPlaneHasFourCoefficients);
  p.value = Value::vector(n.values);
  return {};
}

Comparison compare_with_key(const Value& expected, const Value& got, const AnswerRules& r) {
  if (got.numbers.size() != 4) return incorrect(say(kPlaneNeedsFour));
  if (multiple_of(expected, got, r) != Multiple::None) return correct(say(kSamePlane));
  return incorrect();
}

QuizAsk quiz_ask(const AnswerSpec&, const Value&, const Conventions&) {
  return refused(kPlaneUpToFactor);
}

// As its equation, the form a student writes.
MathText shown(const Value& value) {
  if (value.exact.size() != 4) return value.shown();
  return plane_equation(value.exact[0], value.exact[1], value.exact[2], value.exact[3]);
}

}  // namespace

AnswerType plane_answer_type() {
  AnswerType t;
  t.kind = AnswerKind::Plane;
  t.syntax = {
      {"plane",
       R"md(an equation in x, y, z, or [a, b, c, d] of ax + by + cz = d; any non-zero multiple)md",
       R"md(`"x + y - z = -6"`, `[1, 1, -1, -6]`)md"}};
  t.read = read_answer;
  t.compare = compare_with_key;
  t.quiz = quiz_ask;
  t.shown = shown;
  t.typed_hint = &kEquationSuchAs;
  t.componentwise = false;
  t.own_equals = true;
  return t;
}

}  // namespace frustum
