// The work budget of exact arithmetic: canonical() on hostile values stops within its budget
// and stays exact and equal; budgets belong to one call, never to the process.
#include "solver/core/work_budget.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "solver/core/exact.hpp"
#include "solver/util/expression.hpp"
#include "test_util.hpp"

namespace frustum {
namespace {

using GiNaC::ex;

ex value_of(const std::string& text) {
  const ExpressionResult r = parse_expression(text);
  EXPECT_TRUE(r) << text << ": " << r.error.en();
  return r ? *r.value : ex(0);
}

const std::string kEightRoots =
    "1/(sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7)+sqrt(11)+sqrt(13)+sqrt(17)+sqrt(19))";

TEST(WorkBudget, SpendsUntilTheLimitThenRefusesAndStaysExceeded) {
  WorkBudget b(100);
  EXPECT_TRUE(b.spend(60));
  EXPECT_FALSE(b.spend(50));  // would pass the limit: nothing taken
  EXPECT_TRUE(b.exceeded());
  EXPECT_EQ(b.used(), 60);
  EXPECT_TRUE(b.spend(40));  // what is left can still be spent
  EXPECT_FALSE(b.spend(std::nan("")));
  EXPECT_TRUE(b.exceeded());
}

TEST(WorkBudget, ProductCostGrowsWithTermsAndDigits) {
  const ex small = value_of("sqrt(2)+sqrt(3)").expand();
  const ex many = value_of("sqrt(2)+sqrt(3)+sqrt(5)+sqrt(7)").expand();
  const ex big = value_of("10^300*sqrt(2)+sqrt(3)").expand();
  EXPECT_LT(product_cost(small, small), product_cost(many, many));
  EXPECT_LT(product_cost(small, small), product_cost(big, big));
  EXPECT_LT(normal_cost(small), normal_cost(many));
}

TEST(WorkBudget, CanonicalOverItsBudgetIsExactAndEqual) {
  // A tiny budget cannot pay for rationalising 1/(1 + √2); the value comes back unchanged.
  const ex e = value_of("1/(1+sqrt(2))");
  WorkBudget tiny(5);
  const ex partial = canonical(e, tiny);
  EXPECT_TRUE(tiny.exceeded());
  EXPECT_NEAR(to_double(partial), std::sqrt(2.0) - 1, 1e-15);
  // The default budget does it: √2 − 1.
  WorkBudget normal;
  EXPECT_TRUE(canonical(e, normal).is_equal(canonical(value_of("sqrt(2)-1"))));
  EXPECT_FALSE(normal.exceeded());
}

TEST(WorkBudget, RationalisingEightRootsStopsWithinTheBudget) {
  // 1/(√2 + √3 + … + √19): each rationalising round multiplied the terms, and a second
  // canonical() of the result ran for minutes. Every call now stays within its budget.
  const ex e = value_of(kEightRoots);
  const double v = to_double(e);
  WorkBudget first;
  const ex once = canonical(e, first);
  EXPECT_LE(first.used(), first.limit());
  WorkBudget second;
  const ex twice = canonical(once, second);
  EXPECT_LE(second.used(), second.limit());
  EXPECT_NEAR(to_double(once), v, 1e-15);
  EXPECT_NEAR(to_double(twice), v, 1e-15);
}

TEST(WorkBudget, BudgetsBelongToOneCall) {
  // Exhausting one budget (and canonical()'s own default ones) leaves every later call its
  // full budget: nothing is kept between calls.
  WorkBudget spent(1);
  (void)canonical(value_of(kEightRoots), spent);
  EXPECT_TRUE(spent.exceeded());
  (void)canonical(value_of(kEightRoots));
  WorkBudget fresh;
  EXPECT_TRUE(
      canonical(value_of("1/(1+sqrt(2))"), fresh).is_equal(canonical(value_of("sqrt(2)-1"))));
  EXPECT_FALSE(fresh.exceeded());
}

// canonical(original) as `c` kept the value (to within 10⁻⁹, relative).
void expect_same_value(const ex& original, const ex& c, const std::string& what) {
  const double before = to_double(original), after = to_double(c);
  EXPECT_NEAR(after, before, 1e-9 * std::max(1.0, std::abs(before))) << what;
}

TEST(WorkBudget, FuzzedSlowInputsStayWithinTheBudgetKeepTheirValueAndStaySmall) {
  // Every input the fuzzer found slow (fuzz/corpus/fuzz_expression/slow-*, timeout-*; nested
  // roots took 1 to 17 s): the canonical form is reached within the budget, keeps the value
  // and stays a small tree, so evaluating it stays cheap. One of them, nested fractions over
  // sums with π and roots, once came back as a tree of 1.2 million nodes (its normal()
  // underpriced 17 times, its expand() repeating the common denominator under each of 488
  // terms), and evaluating it took longer than the canonical form itself.
  int checked = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(test::source_path("fuzz/corpus/fuzz_expression"))) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("slow-", 0) != 0 && name.rfind("timeout-", 0) != 0) continue;
    const std::string text = test::read_file(entry.path());
    ASSERT_FALSE(text.empty()) << name;
    const ExpressionResult r = parse_expression(text);
    if (!r) continue;  // refused by the parser's own limits
    ++checked;
    WorkBudget budget;
    const ex c = canonical(*r.value, budget);
    EXPECT_LE(budget.used(), budget.limit()) << name;
    EXPECT_LE(tree_nodes(c), kMaxExactNodes) << name;
    expect_same_value(*r.value, c, name);
  }
  EXPECT_GE(checked, 10);
}

// Nested fractions over sums of π, square roots and integers: the shape of the fuzzer's slow
// finds, drawn at random.
std::string random_fraction(std::mt19937& rng, int depth) {
  const auto pick = [&rng](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  const auto integer = [&] { return std::to_string(1 + pick(30)); };
  if (depth == 0) {
    switch (pick(4)) {
      case 0:
        return integer();
      case 1:
        return "sqrt(" + std::to_string(2 + pick(200)) + ")";
      case 2:
        return "(" + integer() + "*pi+" + integer() + ")";
      default:
        return "(sqrt(" + integer() + "/" + integer() + ")-" + integer() + ")";
    }
  }
  const std::string a = random_fraction(rng, depth - 1), b = random_fraction(rng, depth - 1);
  switch (pick(4)) {
    case 0:
      return "(" + a + "+" + b + ")";
    case 1:
      return integer() + "/(" + a + "+" + b + ")";
    case 2:
      return "(" + a + ")^2/(" + b + "+" + integer() + ")";
    default:
      return "(" + a + "-" + b + ")^3/" + integer();
  }
}

TEST(WorkBudget, RandomNestedFractionsKeepTheirValueInASmallTree) {
  // Property over many such values: the canonical form keeps the value, stays within the
  // budget and stays a tree small enough to evaluate cheaply (kMaxExactNodes).
  std::mt19937 rng(20261202);
  int exceeded = 0, parsed = 0;
  for (int i = 0; i < 60; ++i) {
    const std::string text = random_fraction(rng, 1 + i % 4);
    const ExpressionResult r = parse_expression(text);
    if (!r) {  // refused by the parser's own limits, with a reason
      EXPECT_FALSE(r.error.empty()) << text;
      continue;
    }
    ++parsed;
    WorkBudget budget;
    const ex c = canonical(*r.value, budget);
    exceeded += budget.exceeded();
    EXPECT_LE(budget.used(), budget.limit()) << text;
    EXPECT_LE(tree_nodes(c), kMaxExactNodes) << text;
    ASSERT_TRUE(is_real_constant(c)) << text;
    expect_same_value(*r.value, c, text);
  }
  EXPECT_GE(parsed, 40);
  EXPECT_GT(exceeded, 0);  // the draw reaches the budget, so the property is tested there too
}

TEST(WorkBudget, NormalisingIsPricedByItsCommonDenominator) {
  // The same sum of fractions over one denominator and over six: normal() multiplies every
  // numerator by the other denominators, and its price says so.
  const ex one = value_of("1/(1+sqrt(2)+pi)+2/(1+sqrt(2)+pi)+3/(1+sqrt(2)+pi)").expand();
  const ex six = value_of(
                     "1/(1+sqrt(2)+pi)+1/(1+sqrt(3)+pi)+1/(1+sqrt(5)+pi)+1/(1+sqrt(7)+pi)+"
                     "1/(1+sqrt(11)+pi)+1/(1+sqrt(13)+pi)")
                     .expand();
  EXPECT_GE(normal_cost(six), 20 * normal_cost(one));
  // A value with no sum in a denominator is priced as before: nodes times (1 + atoms).
  const GiNaC::symbol x("x"), y("y");
  EXPECT_DOUBLE_EQ(normal_cost(x + y), 3 * 3);
}

TEST(WorkBudget, TreeNodesCountSharedSubexpressionsWhereverTheyOccur) {
  // The sum, the 1, and two powers of a base and an exponent each: 1 + 1 + 2·3 = 8.
  const ex d = value_of("1+sqrt(2)+sqrt(3)");
  EXPECT_DOUBLE_EQ(tree_nodes(d), 8);
  const ex twice = GiNaC::pow(d, -1) + 2 * GiNaC::pow(d, -1) * GiNaC::symbol("x");
  EXPECT_GT(tree_nodes(twice), 2 * tree_nodes(d));
}

}  // namespace
}  // namespace frustum
