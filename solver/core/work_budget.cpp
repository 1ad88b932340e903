#include "solver/core/work_budget.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>

namespace frustum {

namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// Estimates beyond this are "more than any budget": +inf, so sums of them stay comparable.
constexpr double kSaturated = 1e15;

// Number of terms of (t_1 + ... + t_m)^k expanded: C(m + k - 1, k), saturating.
double multinomial_terms(double m, double k) {
  if (m <= 1) return 1;
  if (!std::isfinite(m)) return m;
  double terms = 1;
  for (double i = 1; i <= k; ++i) {
    terms = terms * (m - 1 + i) / i;
    if (terms > kSaturated) return std::numeric_limits<double>::infinity();
  }
  return terms;
}

void merge(ExactSize& into, const ExactSize& part) {
  into.work += part.work;
  into.max_exponent = std::max(into.max_exponent, part.max_exponent);
  into.max_bits = std::max(into.max_bits, part.max_bits);
}

template <class T>
using ExMap = std::unordered_map<ex, T, std::hash<ex>, GiNaC::ex_is_equal>;

// Sizes of subexpressions, each computed once: GiNaC shares equal subexpressions, and a
// value nested a few levels deep (roots of sums of roots) walked as a tree is exponentially
// larger than the shared graph that holds it (a 200-term value found while bounding canonical()
// takes a noticeable fraction of a second to walk as a tree).
class SizeOf {
 public:
  ExactSize operator()(const ex& e) {
    if (const auto it = memo_.find(e); it != memo_.end()) return it->second;
    const ExactSize size = compute(e);
    memo_.emplace(e, size);
    return size;
  }

 private:
  // Upper bounds measured on GiNaC's own form of e: the parse structure is not enough, since
  // GiNaC turns (√(x+y+z+1))^1024 into (x+y+z+1)^512. A fractional power s^(p/q) counts as
  // s^ceil(p/q): raised to n later it becomes s^(np/q), never more terms than that.
  ExactSize compute(const ex& e) {
    if (is_a<GiNaC::add>(e) || is_a<GiNaC::mul>(e)) {
      const bool product = is_a<GiNaC::mul>(e);
      ExactSize total{product ? 1.0 : 0.0, 0, 0, 0};
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const ExactSize part = (*this)(e.op(i));
        total.terms = product ? total.terms * part.terms : total.terms + part.terms;
        merge(total, part);
      }
      if (product) total.work += total.terms;
      return total;
    }
    if (is_a<GiNaC::power>(e)) {
      ExactSize base = (*this)(e.op(0));
      const ex& exponent = e.op(1);
      if (!is_a<numeric>(exponent) || !ex_to<numeric>(exponent).is_rational()) {
        merge(base, (*this)(exponent));
        base.terms = 1;
        return base;
      }
      const numeric k = GiNaC::abs(ex_to<numeric>(exponent));
      const numeric whole = GiNaC::iquo(k.numer() + k.denom() - 1, k.denom());  // ceil(k)
      const double n = whole > numeric(1'000'000) ? 1e6 : whole.to_double();
      base.terms = multinomial_terms(base.terms, n);
      base.work += base.terms;
      base.max_exponent = std::max(base.max_exponent, k);
      return base;
    }
    if (is_a<numeric>(e)) {
      const numeric& n = ex_to<numeric>(e);
      const long bits =
          n.is_rational() ? std::max(n.numer().int_length(), n.denom().int_length()) : 0;
      return {1, 1, 0, std::max(bits - 1, 0L)};
    }
    // Symbols are one term. A function is one term too, but a power can unwrap it
    // (abs(s)^2 = s^2), so its terms are those of its argument.
    ExactSize atom{1, 1, 0, 0};
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ExactSize part = (*this)(e.op(i));
      atom.terms *= part.terms;
      merge(atom, part);
    }
    return atom;
  }

  ExMap<ExactSize> memo_;
};

// What walking, multiplying and normalising e costs: its nodes written out as a tree (each
// shared subexpression counted wherever it occurs, but visited once), its largest number, its
// distinct irrational atoms (the variables of the polynomials normal() takes gcds of) and its
// distinct denominators that are sums (the factors of the common denominator normal() builds).
class Shape {
 public:
  explicit Shape(const ex& e) { nodes_ = visit(e); }

  double nodes() const { return nodes_; }
  // CLN's multiplications and gcds of n-word numbers cost about n² word operations.
  double word_factor() const {
    const double words = 1 + static_cast<double>(max_bits_) / 64;
    return words * words;
  }
  double atoms() const { return static_cast<double>(atoms_.size()); }
  // The product of the terms of e's distinct sum denominators: a bound on the terms of the
  // common denominator that normal() multiplies every numerator by.
  double denominator_terms() const {
    double product = 1;
    for (const auto& [denominator, terms] : denominators_)
      product = std::min(product * terms, kSaturated);
    return product;
  }

 private:
  double visit(const ex& e) {
    if (const auto it = memo_.find(e); it != memo_.end()) return it->second;
    if (is_a<numeric>(e)) {
      const numeric& n = ex_to<numeric>(e);
      if (n.is_rational())
        max_bits_ =
            std::max({max_bits_, long(n.numer().int_length()), long(n.denom().int_length())});
    } else if (!is_a<GiNaC::add>(e) && !is_a<GiNaC::mul>(e) &&
               !(is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) &&
                 ex_to<numeric>(e.op(1)).is_integer())) {
      atoms_.emplace(e, 0.0);
    }
    if (is_a<GiNaC::power>(e) && is_a<GiNaC::add>(e.op(0)) && is_a<numeric>(e.op(1)) &&
        ex_to<numeric>(e.op(1)).is_negative())
      denominators_.emplace(e.op(0), static_cast<double>(e.op(0).nops()));
    double n = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) n = std::min(n + visit(e.op(i)), kSaturated);
    memo_.emplace(e, n);
    return n;
  }

  ExMap<double> memo_;
  ExMap<double> atoms_;
  ExMap<double> denominators_;
  long max_bits_ = 0;
  double nodes_ = 0;
};

}  // namespace

bool WorkBudget::spend(double cost) {
  // NaN (an estimate of nothing sensible) never fits.
  if (!(cost <= limit_ - used_)) {
    exceeded_ = true;
    return false;
  }
  used_ += cost;
  return true;
}

ExactSize exact_size(const ex& e) { return SizeOf()(e); }

double term_count(const ex& expanded) {
  return is_a<GiNaC::add>(expanded) ? static_cast<double>(expanded.nops()) : 1.0;
}

double product_cost(const ex& a, const ex& b) {
  const Shape sa(a), sb(b);
  return (term_count(a) * sb.nodes() + term_count(b) * sa.nodes()) *
         std::max(sa.word_factor(), sb.word_factor());
}

double normal_cost(const ex& e) {
  const Shape s(e);
  return s.nodes() * s.word_factor() * (1 + s.atoms()) * std::sqrt(s.denominator_terms());
}

double tree_nodes(const ex& e) { return Shape(e).nodes(); }

}  // namespace frustum
