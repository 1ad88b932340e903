// A bound on the exact (symbolic) work one request may cost, and estimates of that work made
// before GiNaC does it. GiNaC's expand() and normal() cannot be interrupted, and multiplying
// sums out can take exponential time (1/(√2 + √3 + … + √19) rationalised is 2⁷ terms per
// round), so every such operation on untrusted input is priced first and skipped when its
// price does not fit. A budget is a value owned by one request (an answer, a given, one
// canonical() call): nothing here is shared between calls, so concurrent requests in one
// process cannot spend each other's budget.
#pragma once

#include <ginac/ginac.h>

namespace frustum {

// Work units (one node of one term meeting a term of another factor, see product_cost) that
// one answer or one given may spend: GiNaC does this many in a fraction of a second on sums of
// radicals, so this bounds one value's simplification to that, while the largest value a seed
// set needs costs far less (docs/reliability.md has both figures).
inline constexpr double kExactWorkDefault = 300'000;

class WorkBudget {
 public:
  explicit WorkBudget(double limit = kExactWorkDefault) : limit_(limit) {}

  // Takes `cost` before the operation it pays for. When it does not fit, takes nothing,
  // marks the budget exceeded and returns false: the caller skips the operation.
  [[nodiscard]] bool spend(double cost);

  bool exceeded() const { return exceeded_; }
  double used() const { return used_; }
  double limit() const { return limit_; }

 private:
  double limit_;
  double used_ = 0;
  bool exceeded_ = false;
};

// What exact work on a value can cost, read from GiNaC's form of it without expanding.
struct ExactSize {
  double terms = 1;  // bound on the terms of expand(e); +inf when beyond any budget
  double work = 1;   // bound on the term products expand(e) makes, over all subexpressions
  GiNaC::numeric max_exponent = 0;  // largest |rational exponent| in e
  long max_bits = 0;                // largest floor(log2) of a numerator or denominator in e
};
ExactSize exact_size(const GiNaC::ex& e);

// Terms of an expression already expanded (a sum's operands, else 1).
double term_count(const GiNaC::ex& expanded);

// Price of expand(a * b) for a and b already expanded: every term of one meets every term of
// the other, and each meeting costs about the size of the two terms (a term of a
// rationalised sum is a product of several radicals): T(a)·N(b) + T(b)·N(a), N the nodes,
// times W² for the W-word numbers in them (rationalising makes numbers of thousands of digits).
double product_cost(const GiNaC::ex& a, const GiNaC::ex& b);

// Price of e.normal() (with the expand() around it): N·W²·(1 + A)·√D. normal() takes gcds of
// polynomials whose variables are e's A distinct irrational atoms; measured, that cost grows
// with A far faster than expand()'s (a 200-term value with 1 000-digit numbers and five
// fourth roots ran for minutes). It brings every fraction over a common denominator, D the
// product of the terms of e's distinct sum denominators: nested fractions over sums with π and
// ten roots (a fuzzer's find) cost many times what N·W²·(1 + A) alone prices them at; √D
// matches three such shapes measured (1, 5 and 6 such denominators) within 2×.
double normal_cost(const GiNaC::ex& e);

// Nodes of e written out as a tree, each shared subexpression counted wherever it occurs
// (saturating): what evaluating, walking or printing e costs. expand() of n/d repeats d under
// every term of n, so a value whose shared graph is small can be a million nodes as a tree.
double tree_nodes(const GiNaC::ex& e);

// The most tree nodes a value canonical() hands back may have. Larger forms are not kept: the
// value stays in its last smaller form (at worst as given), with the budget marked exceeded,
// so what callers do next (walk it, test its sign, print it) stays cheap. No bundled problem's
// output and no test changed when it came in (tools/snapshot_outputs.sh: identical).
inline constexpr double kMaxExactNodes = 50'000;

}  // namespace frustum
