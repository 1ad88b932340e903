// Exact values: canonical form with simplified radicals, sign, and conversions.
#include "solver/core/exact.hpp"

#include <cln/integer.h>
#include <cln/rational.h>
#include <cln/real.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "solver/core/rational_power.hpp"
#include "solver/core/trig_radicals.hpp"
#include "solver/core/work_budget.hpp"

namespace frustum {
namespace {

using GiNaC::ex;
using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// Radicands are factored by trial division only below this bound; with divisors up to
// kTrialLimit the cofactor then has at most two prime factors, so one square test finishes.
constexpr std::uint64_t kFactorLimit = 1'000'000'000'000'000;  // 10^15
constexpr std::uint64_t kTrialLimit = 100'000;
// Above kFactorLimit only divisors below this are tried (radicands are at most kMaxRadicandBits).
constexpr std::uint64_t kSmallPrimeLimit = 1'000;
// Radicals beyond this size (and beyond kMaxSimplifiedRootIndex) are left as GiNaC holds them
// (bounded work on hostile input).
constexpr std::uintptr_t kMaxRadicandBits = 4096;
// canonical() repeats its pass until nothing changes; two passes suffice in practice.
constexpr int kMaxCanonicalPasses = 4;
// A denominator a + b·√k loses one square root per conjugate multiplication; at most this many.
constexpr int kMaxRationalizeRounds = 4;
// exact_sign() refines at these precisions (decimal digits) before trying exact zero.
constexpr long kSignDigits[] = {30, 60, 120, 240};
constexpr long kGuardDigits = 10;

// m = coeff^index * radicand.
struct RootSplit {
  cln::cl_I coeff;
  cln::cl_I radicand;
};

cln::cl_I to_cl_i(const numeric& n) { return cln::the<cln::cl_I>(n.to_cl_N()); }

// cln::expt_pos requires a positive exponent.
cln::cl_I int_power(const cln::cl_I& base, unsigned exponent) {
  return exponent == 0 ? cln::cl_I(1) : cln::expt_pos(base, exponent);
}

// Splits the largest index-th power out of m >= 1, or leaves m whole when it is too big to
// factor quickly.
RootSplit split_root(const cln::cl_I& m, unsigned index) {
  if (m >= cln::cl_I(kFactorLimit)) {
    // Too big to factor, but the small primes still come out: decimal inputs make radicands of
    // 2^a·5^b times a little more (√(2·10^63) = 2^32·5^31·√5).
    cln::cl_I rest = m, coeff = 1, radicand = 1;
    for (std::uint64_t p = 2; p < kSmallPrimeLimit; p += (p == 2 ? 1 : 2)) {
      const cln::cl_I divisor(p);
      unsigned count = 0;
      while (cln::zerop(cln::mod(rest, divisor))) {
        rest = cln::exquo(rest, divisor);
        ++count;
      }
      coeff *= int_power(divisor, count / index);
      radicand *= int_power(divisor, count % index);
    }
    if (rest < cln::cl_I(kFactorLimit)) {
      const RootSplit small = split_root(rest, index);
      return {coeff * small.coeff, radicand * small.radicand};
    }
    cln::cl_I root;
    if (cln::rootp(rest, index, &root)) return {coeff * root, radicand};
    return {coeff, radicand * rest};
  }
  std::uint64_t n = cln::cl_I_to_UQ(m);
  cln::cl_I coeff = 1;
  cln::cl_I radicand = 1;
  // Trial division up to the cube root: what is left then has at most two prime factors.
  std::uint64_t p = 2;
  for (; p <= kTrialLimit && p * p * p <= n; p += (p == 2 ? 1 : 2)) {
    unsigned count = 0;
    while (n % p == 0) {
      n /= p;
      ++count;
    }
    if (count == 0) continue;
    coeff *= int_power(cln::cl_I(p), count / index);
    radicand *= int_power(cln::cl_I(p), count % index);
  }
  if (n > 1) {
    // Every prime factor of n is at least p, and p^3 > n (or p > 10^5 and n < 10^15), so n is
    // q, q*r or q^2: only a square can still be taken out.
    cln::cl_I rest(n);
    cln::cl_I root;
    if (index == 2 && cln::sqrtp(rest, &root)) {
      coeff *= root;
    } else {
      radicand *= rest;
    }
  }
  return {coeff, radicand};
}

// Lowers the root index when the radicand is itself a power: 4^(1/6) = 2^(1/3).
void reduce_index(cln::cl_I& radicand, unsigned& index) {
  for (unsigned k = 2; k <= index; ++k) {
    cln::cl_I root;
    if (index % k == 0 && cln::rootp(radicand, k, &root)) {
      radicand = root;
      index /= k;
      k = 1;
    }
  }
}

// coeff * radicand^(1/index) as a GiNaC value (radicand >= 1).
ex make_radical(const numeric& coeff, cln::cl_I radicand, unsigned index) {
  reduce_index(radicand, index);
  if (radicand == 1 || index == 1) return coeff * numeric(cln::cl_N(radicand));
  return coeff * GiNaC::pow(ex(numeric(cln::cl_N(radicand))), ex(numeric(1, long(index))));
}

bool is_positive_rational(const ex& e) {
  if (!is_a<numeric>(e)) return false;
  const numeric& n = ex_to<numeric>(e);
  return n.is_rational() && n.is_positive();
}

bool is_proper_fraction_exponent(const ex& e) {
  if (!is_a<numeric>(e)) return false;
  const numeric& n = ex_to<numeric>(e);
  return n.is_rational() && !n.is_integer() && n.denom() <= numeric(long(kMaxSimplifiedRootIndex));
}

// (a/b)^(p/r) = (a/b)^k * c * d^(1/r) / b with d r-th-power free, where p = k*r + s,
// 0 < s < r and a^s * b^(r-s) = c^r * d. The denominator is rationalised on the way.
ex simplify_power(const ex& e) {
  const ex& base = e.op(0);
  const ex& exponent = e.op(1);
  if (!is_positive_rational(base) || !is_proper_fraction_exponent(exponent)) return e;
  const numeric& q = ex_to<numeric>(base);
  const numeric& x = ex_to<numeric>(exponent);
  const cln::cl_I a = to_cl_i(q.numer());
  const cln::cl_I b = to_cl_i(q.denom());
  const cln::cl_I p = to_cl_i(x.numer());
  const unsigned r = unsigned(cln::cl_I_to_UQ(to_cl_i(x.denom())));
  const cln::cl_I k = cln::floor1(p, cln::cl_I(r));
  const unsigned s = unsigned(cln::cl_I_to_UQ(p - k * cln::cl_I(r)));

  const std::uintptr_t bits_a = cln::integer_length(a);
  const std::uintptr_t bits_b = cln::integer_length(b);
  if (s * bits_a + (r - s) * bits_b > kMaxRadicandBits) return e;
  if (k != 0 && cln::abs(k) * cln::cl_I(bits_a + bits_b) > cln::cl_I(kMaxRadicandBits)) return e;

  const cln::cl_I m = int_power(a, s) * int_power(b, r - s);
  const RootSplit split = split_root(m, r);
  const numeric whole =
      q.power(numeric(cln::cl_N(k))) * numeric(cln::cl_N(split.coeff)) / numeric(cln::cl_N(b));
  return make_radical(whole, split.radicand, r);
}

// The integer radicand and index of d^(1/r) as canonical() leaves it, if e is one.
bool as_simple_radical(const ex& e, cln::cl_I& radicand, unsigned& index) {
  if (!is_a<GiNaC::power>(e)) return false;
  const ex& base = e.op(0);
  const ex& exponent = e.op(1);
  if (!is_a<numeric>(base) || !ex_to<numeric>(base).is_pos_integer()) return false;
  if (!is_proper_fraction_exponent(exponent) || !ex_to<numeric>(exponent).numer().is_equal(1))
    return false;
  radicand = to_cl_i(ex_to<numeric>(base));
  index = unsigned(cln::cl_I_to_UQ(to_cl_i(ex_to<numeric>(exponent).denom())));
  return true;
}

// Merges radicals of equal index in a product: sqrt(2)*sqrt(6) = 2*sqrt(3).
ex combine_radicals(const ex& e) {
  std::map<unsigned, std::vector<cln::cl_I>> groups;
  ex rest = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    cln::cl_I radicand;
    unsigned index = 0;
    if (as_simple_radical(e.op(i), radicand, index)) {
      groups[index].push_back(radicand);
    } else {
      rest *= e.op(i);
    }
  }
  bool changed = false;
  ex radicals = 1;
  for (const auto& group : groups) {
    const unsigned index = group.first;
    const std::vector<cln::cl_I>& radicands = group.second;
    const auto keep = [&] {
      for (const cln::cl_I& d : radicands)
        radicals *= GiNaC::pow(ex(numeric(cln::cl_N(d))), ex(numeric(1, long(index))));
    };
    if (radicands.size() < 2) {
      keep();
      continue;
    }
    std::uintptr_t bits = 0;
    for (const cln::cl_I& d : radicands) bits += cln::integer_length(d);
    if (bits > kMaxRadicandBits) {
      keep();
      continue;
    }
    cln::cl_I coeff = 1;
    cln::cl_I product = 1;
    if (index == 2) {
      // Square-free inputs stay square-free without factoring: ab = g^2 (a/g)(b/g).
      for (const cln::cl_I& d : radicands) {
        const cln::cl_I g = cln::gcd(product, d);
        coeff *= g;
        product = cln::exquo(product, g) * cln::exquo(d, g);
      }
    } else {
      for (const cln::cl_I& d : radicands) product *= d;
    }
    if (index != 2 && product >= cln::cl_I(kFactorLimit)) {
      keep();
      continue;
    }
    const RootSplit split = split_root(product, index);
    radicals *= make_radical(numeric(cln::cl_N(coeff * split.coeff)), split.radicand, index);
    changed = true;
  }
  return changed ? rest * radicals : e;
}

// Bottom-up pass that rewrites radicals of rationals (children first, so sin(sqrt(12))
// and sums of products are reached), and sines, cosines and tangents of multiples of π/24 as
// radicals (trig_radicals.hpp).
struct SimplifyRadicals : GiNaC::map_function {
  ex operator()(const ex& e) override {
    const ex mapped = e.map(*this);
    if (ex radical; trig_radical(mapped, radical)) return radical;
    if (is_a<GiNaC::power>(mapped)) return simplify_power(mapped);
    if (is_a<GiNaC::mul>(mapped)) return combine_radicals(mapped);
    return mapped;
  }
};

// GiNaC's working precision is a process-wide setting; restore it whatever happens.
class DigitsGuard {
 public:
  explicit DigitsGuard(long digits) : saved_(GiNaC::Digits) { GiNaC::Digits = digits; }
  ~DigitsGuard() { GiNaC::Digits = saved_; }
  DigitsGuard(const DigitsGuard&) = delete;
  DigitsGuard& operator=(const DigitsGuard&) = delete;

 private:
  long saved_;
};

// e.evalf() with each shared subexpression evaluated once. GiNaC's evalf walks e as a tree,
// and a value whose denominators were rationalised shares its subexpressions so much that the
// tree holds hundreds of thousands of nodes where the value has a few thousand (an answer a
// fuzzer found took seconds to evaluate under the sanitizers). Each node is
// evaluated as evalf() does it (its operands first, then the node); the memo keeps every node
// it has seen alive, so that no address is reused by a temporary while the walk goes on.
class SharedEvalf : public GiNaC::map_function {
 public:
  ex operator()(const ex& e) override {
    if (e.nops() == 0) return e.evalf();  // numbers, constants, symbols
    const GiNaC::basic* key = &ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(key); it != memo_.end()) return it->second.second;
    // A power keeps a numeric exponent exact, as power::evalf does ((−2.5)² stays real).
    ex value = is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1))
                   ? GiNaC::pow((*this)(e.op(0)), e.op(1)).evalf()
                   : e.map(*this).evalf();
    memo_.emplace(key, std::make_pair(e, value));
    return value;
  }

 private:
  std::unordered_map<const GiNaC::basic*, std::pair<ex, ex>> memo_;
};

// A real numeric approximation of e at the current precision, if there is one. `evalf` (when
// given) carries what was evaluated over several calls at the same precision.
bool evaluate_real(const ex& e, numeric& value, SharedEvalf* evalf = nullptr) {
  SharedEvalf own;
  const ex v = (evalf ? *evalf : own)(e);
  if (!is_a<numeric>(v) || !ex_to<numeric>(v).is_real()) return false;
  value = ex_to<numeric>(v);
  return true;
}

// A real constant (not a number already) evaluated until two precisions agree: first with 40
// digits and 80, then with twice as many each time while the two leave the reals or differ in
// their first 24 digits. arccos(1/√(1 + 10⁻⁶⁰)) rounds its argument to 1 or above at 40 digits
// (0 or not real) and at 80 digits is only partly cancelled; at 160 and 320 it is 10⁻³⁰ both
// times. False when no precision up to kMaxEvaluationDigits gives a real; if the reals never
// agree, the last is taken (a value that cancels below every precision, such as a sum that is 0
// but not simplified to 0).
constexpr long kFirstEvaluationDigits = 40;
constexpr long kMaxEvaluationDigits = 5120;

bool evaluate_real_with_digits_to_spare(const ex& e, numeric& value) {
  const numeric agreement("1e-24");
  std::optional<numeric> previous;
  bool real = false;
  for (long digits = kFirstEvaluationDigits; digits <= kMaxEvaluationDigits; digits *= 2) {
    try {
      const DigitsGuard guard(digits);
      numeric current;
      if (!evaluate_real(e, current)) {
        previous.reset();
        continue;
      }
      real = true;
      value = current;
      // Two zeros may be a cancellation that more digits undo: they do not count as agreeing.
      if (previous && !current.is_zero() &&
          GiNaC::abs(current - *previous) <= agreement * GiNaC::abs(current))
        return true;
      previous = current;
    } catch (const std::exception&) {
      // A pole or a domain error at this precision: more digits may settle it.
      previous.reset();
    }
  }
  return real;
}

// Nearest double of a rational, subnormals included (CLN's conversion flushes them to zero):
// below 2^-1022 the doubles are the multiples of 2^-1074, so round q·2^1074 to an integer,
// ties to even.
double rational_to_double(const numeric& q) {
  if (q.is_integer()) return q.to_double();  // correctly rounded by CLN
  static const numeric kMinNormal = numeric(2).power(-1022);
  if (GiNaC::abs(q) >= kMinNormal) return q.to_double();
  const numeric scaled = GiNaC::abs(q) * numeric(2).power(1074);
  const numeric num = scaled.numer(), den = scaled.denom();
  numeric whole = GiNaC::iquo(num, den);
  const numeric twice_rem = 2 * (num - whole * den);
  if (twice_rem > den || (twice_rem == den && !whole.is_even())) whole += 1;
  const double magnitude = std::ldexp(whole.to_double(), -1074);
  return q.is_negative() ? -magnitude : magnitude;
}

// The square root √k (k a positive integer) inside e with the smallest k, if there is one.
// Chosen by value, not by position: GiNaC orders terms by hashes that differ from run to run
// (they include addresses), and the first root found would make the rounds, their cost and
// the result's form differ between two runs on the same input.
bool find_square_root(const ex& e, ex& root) {
  bool found = false;
  cln::cl_I smallest;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    cln::cl_I radicand;
    unsigned index = 0;
    if (as_simple_radical(*it, radicand, index) && index == 2 && (!found || radicand < smallest)) {
      root = *it;
      smallest = radicand;
      found = true;
    }
  }
  return found;
}

// Rationalises a denominator that is a sum with square roots, one root per round:
// n / (a + b·√k) = n·(a − b·√k) / (a² − b²·k), so 1/(1 + 2√3) becomes (2√3 − 1)/11.
// Each round's products are priced before they are expanded: a denominator with r roots
// multiplies the numerator's terms by up to 2^r (1/(√2 + √3 + … + √19) ran for minutes).
// When the budget cannot pay for a round, e comes back as it was, not half rationalised.
ex rationalize_denominator(const ex& e, WorkBudget& budget) {
  if (!budget.spend(exact_size(e).work)) return e;
  const ex parts = e.numer_denom();
  ex num = parts.op(0).expand(), den = parts.op(1).expand();
  bool changed = false;
  for (int round = 0; round < kMaxRationalizeRounds && is_a<GiNaC::add>(den); ++round) {
    ex root;
    if (!find_square_root(den, root)) break;
    const GiNaC::symbol s;
    if (!budget.spend(term_count(den))) return e;
    const ex d = den.subs(root == s).expand();
    // A root nested in another (√(8√8 − 1) − 1) is not a polynomial in s: GiNaC's degree()
    // would throw (found by fuzz_expression), and there is no conjugate to multiply by.
    if (!d.is_polynomial(s) || d.degree(s) != 1 || d.ldegree(s) < 0) break;
    const ex a = d.coeff(s, 0).expand(), b = d.coeff(s, 1).expand();
    const ex conjugate = (a - b * root).expand();
    if (!budget.spend(product_cost(num, conjugate) + product_cost(a, a) + product_cost(b, b)))
      return e;
    num = (num * conjugate).expand();
    den = (a * a - b * b * root * root).expand();
    changed = true;
  }
  return changed ? num / den : e;
}

// ---- Zero of nested square roots (GiNaC does not denest √(5 + 2√6) = √2 + √3) ----

// ⌈log10 |x|⌉ of a positive numeric of any size (x.to_double() over- or underflows beyond
// 10^±308), from its numerator's and denominator's bit lengths (a float is made rational).
long decimal_exponent(const numeric& x) {
  const numeric q = x.is_rational() ? x : numeric(cln::rational(cln::the<cln::cl_R>(x.to_cl_N())));
  const double bits = static_cast<double>(cln::integer_length(to_cl_i(q.numer()))) -
                      static_cast<double>(cln::integer_length(to_cl_i(q.denom())));
  return static_cast<long>(std::ceil(bits * 0.30102999566398120)) + 1;
}

// Square roots nested this deep in number, or polynomials of this degree or this many terms,
// are not attempted.
constexpr std::size_t kMaxZeroProofRadicals = 6;
constexpr int kMaxZeroProofDegree = 64;
constexpr std::size_t kMaxZeroProofTerms = 4000;

bool is_half_power(const ex& e) {
  if (!is_a<GiNaC::power>(e) || !is_a<numeric>(e.op(1))) return false;
  const numeric& q = ex_to<numeric>(e.op(1));
  return q.is_rational() && !q.is_integer();
}

// A sum holding a root whose radicand holds another root: the form whose zero canonical()
// cannot see (sums of roots of rationals it reduces itself).
bool has_nested_root(const ex& e) {
  if (!is_a<GiNaC::add>(e)) return false;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it)
    if (is_half_power(*it))
      for (auto in = it->op(0).preorder_begin(); in != it->op(0).preorder_end(); ++in)
        if (is_half_power(*in)) return true;
  return false;
}

// Replaces every square root √b by a symbol y (inner roots first), recording y² = b.
struct RootsToSymbols : GiNaC::map_function {
  std::vector<std::pair<ex, GiNaC::symbol>> roots;  // (radicand in earlier symbols, y)
  std::vector<ex> values;                           // the roots themselves, for evaluation
  bool unsupported = false;                         // a root other than a square root

  ex operator()(const ex& e) override {
    if (!is_half_power(e)) return e.map(*this);
    const numeric& q = ex_to<numeric>(e.op(1));
    if (q.denom() != 2) {
      unsupported = true;
      return e;
    }
    const ex base = (*this)(e.op(0));
    for (const auto& [b, y] : roots)
      if (b.is_equal(base)) return GiNaC::pow(y, q.numer());
    roots.emplace_back(base, GiNaC::symbol());
    values.push_back(GiNaC::sqrt(e.op(0)));
    return GiNaC::pow(roots.back().second, q.numer());
  }
};

// Proves e = 0 for a real constant built from rationals and square roots (nested or not):
// its numerator N in symbols yᵢ = √bᵢ is a root of R(x) = res_{y₁}(…res_{yₘ}(x − N, yₘ² − bₘ)…,
// y₁² − b₁) ∈ Q[x]. When R(x) = xᵏ·S(x) with k ≥ 1, every non-zero root of S has
// |x| ≥ |s₀|/(|s₀| + max|sᵢ|) (Cauchy's bound on the reversed polynomial); N evaluated well
// inside that bound is therefore 0. False when unproven (too many roots, other radicals).
// The resultant of r and a·y² − b in y, up to a factor free of the other symbols' roots: r
// reduced modulo y² = b/a is U + V·y, and the product of its values at y = ±√(b/a), cleared of
// a's powers, is a·U'² − b·V'² (U' = a^m·U, V' = a^m·V, m = ⌊deg r / 2⌋). It vanishes wherever r
// does at either root, so the value N stays a root in x. A few products, where GiNaC's resultant
// takes the determinant of a Sylvester matrix, whose elimination swelled to seconds on some
// answers depending on the order GiNaC keeps terms in (a fuzzer's find).
ex eliminate_square_root(const ex& r, const GiNaC::symbol& y, const ex& a, const ex& b) {
  const int n = r.degree(y);
  const int m = n / 2;
  ex u = 0, v = 0;
  for (int k = 0; k <= n; ++k) {
    const ex c = r.coeff(y, k);
    if (c.is_zero()) continue;
    const int half = k / 2;  // y^k = (b/a)^half · y^(k mod 2)
    (k % 2 == 0 ? u : v) += c * GiNaC::pow(b, half) * GiNaC::pow(a, m - half);
  }
  return (a * u * u - b * v * v).expand();
}

// The sign of a real constant built from rationals and square roots (nested or not), decided
// through the polynomial R above whatever the value's size: its numerator N is a root of R, and
// every root of R other than 0 has |x| ≥ |r_k|/(|r_k| + max|rᵢ|) (r_k the lowest non-zero
// coefficient), so N evaluated to a tenth of that bound is 0 when it is below the tenth and has
// the evaluation's sign otherwise. The denominator's sign is decided the same way. nullopt when
// unproven (too many roots, other radicals, a polynomial beyond the bounds).
std::optional<int> radical_sign(const Exact& e, int depth = 0) {
  if (is_a<numeric>(e) && ex_to<numeric>(e).is_rational()) return exact_sign(e);
  RootsToSymbols to_symbols;
  const ex in_symbols = to_symbols(e);
  if (to_symbols.unsupported || to_symbols.roots.empty() ||
      to_symbols.roots.size() > kMaxZeroProofRadicals)
    return std::nullopt;
  // GiNaC's normal() can throw from inside its gcd ("heur_gcd: not an integer polynomial",
  // seen on radical inputs in one run of many): the sign is then unproven, never an error.
  ex parts;
  try {
    parts = in_symbols.normal().numer_denom();
  } catch (const std::exception&) {
    return std::nullopt;
  }
  const ex numerator = parts.op(0).expand();
  const GiNaC::symbol x;
  ex r = (x - numerator).expand();
  for (std::size_t i = to_symbols.roots.size(); i-- > 0;) {
    const auto& [base, y] = to_symbols.roots[i];
    ex base_parts;
    try {
      base_parts = base.normal().numer_denom();
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (is_a<GiNaC::add>(r) && r.nops() > kMaxZeroProofTerms) return std::nullopt;
    r = eliminate_square_root(r, y, base_parts.op(1), base_parts.op(0));
    if (!r.is_polynomial(x) || r.degree(x) > kMaxZeroProofDegree) return std::nullopt;
  }
  for (const auto& [base, y] : to_symbols.roots)
    if (r.has(y)) return std::nullopt;
  if (r.is_zero()) return std::nullopt;
  const int k = r.ldegree(x);
  numeric low = GiNaC::abs(ex_to<numeric>(r.coeff(x, k))), high = 0;
  for (int i = k + 1; i <= r.degree(x); ++i) {
    const ex c = r.coeff(x, i);
    if (!is_a<numeric>(c)) return std::nullopt;
    high = std::max(high, GiNaC::abs(ex_to<numeric>(c)));
  }
  const numeric separation = low / (low + high);
  // N at enough digits to resolve a tenth of the separation, counted from the size of N's terms
  // (its rounding is relative to them): a solid scaled by 10¹⁰⁰ needs a hundred digits more per
  // degree than the same at size 1, and the proof must not fail for lack of them.
  GiNaC::exmap values;
  for (std::size_t i = 0; i < to_symbols.roots.size(); ++i)
    values[to_symbols.roots[i].second] = to_symbols.values[i];
  const ex n = numerator.subs(values);
  numeric terms_size = 1;
  {
    const DigitsGuard guard(kSignDigits[0]);
    if (is_a<GiNaC::add>(n))
      for (std::size_t i = 0; i < n.nops(); ++i)
        if (numeric term; evaluate_real(n.op(i), term)) terms_size += GiNaC::abs(term);
  }
  const long digits = 30 + decimal_exponent(terms_size) - decimal_exponent(separation);
  if (digits > kMaxEvaluationDigits) return std::nullopt;
  numeric value;
  {
    const DigitsGuard guard(digits);
    if (!evaluate_real(n, value)) return std::nullopt;
  }
  int numerator_sign = 0;
  if (GiNaC::abs(value) * 10 < separation) {
    if (k == 0) return std::nullopt;  // 0 is not a root of R: the bound was not met
    numerator_sign = 0;
  } else if (GiNaC::abs(value) * 10 >= separation * 9) {
    numerator_sign = value.is_positive() ? 1 : -1;
  } else {
    return std::nullopt;
  }
  if (numerator_sign == 0) return 0;
  const ex denominator = parts.op(1);
  if (is_a<numeric>(denominator)) return numerator_sign * exact_sign(denominator);
  if (depth > 0) return std::nullopt;
  const std::optional<int> d = radical_sign(denominator.subs(values).expand(), depth + 1);
  if (!d || *d == 0) return std::nullopt;
  return numerator_sign * *d;
}

// Proves e = 0 (radical_sign), after one evaluation that shows most values are far from 0.
bool proven_zero(const Exact& e) {
  {
    const DigitsGuard guard(kSignDigits[0]);
    numeric approx, magnitude = 0;
    SharedEvalf evalf;  // the terms' parts were evaluated with the whole
    if (!evaluate_real(e, approx, &evalf)) return false;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      numeric term;
      if (evaluate_real(e.op(i), term, &evalf)) magnitude += GiNaC::abs(term);
    }
    if (GiNaC::abs(approx) > magnitude / numeric(10).power(kSignDigits[0] / 2)) return false;
  }
  const std::optional<int> sign = radical_sign(e);
  return sign && *sign == 0;
}

// False, with the budget marked exceeded, when x is too large a tree to keep (kMaxExactNodes).
bool small_enough(const ex& x, WorkBudget& budget) {
  return tree_nodes(x) <= kMaxExactNodes || budget.spend(std::numeric_limits<double>::infinity());
}

// One pass of canonical(): radicals simplified, fractions collected, the sum flattened.
bool simplify_pass(ex& current, WorkBudget& budget) {
  if (!budget.spend(normal_cost(current))) return false;
  SimplifyRadicals simplify;
  // normal() cancels sqrt(3)*sqrt(3) and collects fractions; expand() flattens the result
  // into a sum of terms.
  try {
    current = simplify(current).normal().expand();
  } catch (const std::exception&) {  // normal()'s gcd may throw: the last form is kept
    return false;
  }
  return true;
}

// The canonical form of c·k^(±1/2) (c rational, k a positive integer below kFactorLimit), the
// shape of most unit vectors and lengths, straight from k's square part: c·s·√r or c·s·√r / k
// for k = s²·r. canonical(e, budget) reaches the same value by its passes (exact_test compares
// the two); false for any other shape.
bool canonical_simple_root(const ex& e, ex& out) {
  RationalPower parts;
  if (!rational_power(e, parts)) return false;
  const numeric& c = parts.c;
  const numeric& k = parts.base;
  const int root_sign = square_root_sign(parts.exponent);
  const bool inverse = root_sign < 0;
  if (root_sign == 0 || !k.is_pos_integer() || k >= numeric(static_cast<long>(kFactorLimit)))
    return false;
  const RootSplit split = split_root(to_cl_i(k), 2);
  // c·√k with k square-free is already canonical: e itself, not built again.
  if (!inverse && split.coeff == 1) {
    out = e;
    return true;
  }
  numeric whole = c * numeric(cln::cl_N(split.coeff));
  if (inverse) whole = whole / k;
  out = make_radical(whole, split.radicand, 2);
  return true;
}

// True when e is already canonical as a sum of rationals and c·√k (c rational, k a square-free
// integer below kTrialLimit², so split_root finishes by trial division), with at most one term
// per radical, which GiNaC's sums keep collected: the shape of a depth interpolated between
// vertices with one square root among them. canonical(e, budget) returns such a sum unchanged
// (exact_test compares the two); the z-buffer canonicalised 65,536 of them, each through the
// whole pass, in seconds.
bool canonical_sum_of_square_roots(const ex& e) {
  if (!is_a<GiNaC::add>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    const ex& term = e.op(i);
    if (is_rational(term)) continue;
    RationalPower parts;
    if (!rational_power(term, parts) || parts.exponent != numeric(1, 2) ||
        !parts.base.is_pos_integer() ||
        parts.base >= numeric(static_cast<long>(kTrialLimit * kTrialLimit)))
      return false;
    if (split_root(to_cl_i(parts.base), 2).coeff != 1) return false;
  }
  return true;
}

}  // namespace

Exact canonical(const Exact& e) {
  if (ex simple; canonical_simple_root(e, simple)) return simple;
  if (canonical_sum_of_square_roots(e)) return e;
  WorkBudget budget;
  return canonical(e, budget);
}

Exact canonical(const Exact& e, WorkBudget& budget) {
  // A rational is already canonical (most typed answers and most inputs are).
  if (is_rational(e)) return e;
  // Every step is priced before it runs, and its result is kept only while it is a small
  // enough tree: otherwise the last form kept is returned (at worst e itself).
  if (!budget.spend(exact_size(e).work)) return e;
  const ex expanded = e.expand();
  if (!small_enough(expanded, budget) || !budget.spend(normal_cost(expanded))) return e;
  // normal() may throw from inside GiNaC's gcd ("heur_gcd: not an integer polynomial", seen
  // on radical inputs in one run of many): the value is then kept in the form it came in.
  ex current;
  try {
    current = expanded.normal();
  } catch (const std::exception&) {
    return e;
  }
  if (!small_enough(current, budget)) return e;
  for (int pass = 0; pass < kMaxCanonicalPasses; ++pass) {
    ex next = current;
    if (!simplify_pass(next, budget) || !small_enough(next, budget)) return current;
    if (next.is_equal(current)) break;
    current = next;
  }
  if (!has_symbol(current) && has_nested_root(current) && proven_zero(current)) return 0;
  if (!has_symbol(current)) {
    ex rationalized = rationalize_denominator(current, budget);
    if (!rationalized.is_equal(current)) {
      if (!budget.spend(exact_size(rationalized).work)) return current;
      rationalized = rationalized.expand();
      if (small_enough(rationalized, budget) && simplify_pass(rationalized, budget) &&
          small_enough(rationalized, budget))
        current = rationalized;
    }
  }
  return current;
}

bool has_symbol(const Exact& e) {
  // Each shared subexpression once: a value built by repeated substitution (a point clipped
  // three times) is a small graph whose tree, walked in preorder, is exponentially large.
  std::unordered_set<const GiNaC::basic*> seen;
  std::vector<ex> stack{e};
  while (!stack.empty()) {
    const ex x = stack.back();
    stack.pop_back();
    if (is_a<GiNaC::symbol>(x) || is_a<GiNaC::wildcard>(x)) return true;
    if (!seen.insert(&ex_to<GiNaC::basic>(x)).second) continue;
    for (std::size_t i = 0; i < x.nops(); ++i) stack.push_back(x.op(i));
  }
  return false;
}

bool is_rational(const Exact& e) { return is_a<numeric>(e) && ex_to<numeric>(e).is_rational(); }

bool rational_times_square_root(const Exact& e, numeric& c, Exact& root) {
  if (is_rational(e)) {
    c = ex_to<numeric>(e);
    root = 1;
    return true;
  }
  RationalPower parts;
  if (!rational_power(e, parts) || !parts.base.is_pos_integer() ||
      square_root_sign(parts.exponent) != 1)
    return false;
  c = parts.c;
  root = is_a<GiNaC::power>(e) ? e : GiNaC::pow(ex(parts.base), ex(parts.exponent));
  return true;
}

bool is_real_constant(const Exact& e) {
  if (is_a<numeric>(e)) return ex_to<numeric>(e).is_real();
  if (has_symbol(e)) return false;
  if (is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e) || is_a<GiNaC::matrix>(e)) return false;
  numeric value;
  try {
    if (evaluate_real(e, value)) return true;
  } catch (const std::exception&) {
    // Settled with more digits below.
  }
  // Rounding at the default precision can leave the reals (arccos of a value just below 1).
  return evaluate_real_with_digits_to_spare(e, value);
}

namespace {

// c·root with root = k^(±1/2), c and k = a/b rational (a unit vector's component, a length), to
// within a relative 2⁻¹²⁸, as a rational: √k = √(ab)/b and √(ab) = ⌊√(ab·4^m)⌋/2^m with ab·4^m ≥
// 2²⁵⁶. The same accuracy as the evaluation to 40 digits below, without evaluating a tree.
// num/den (den > 0) rounded to the nearest double (ties to even) when that is a normal
// double, without reducing the fraction: a quotient of 55 or 56 bits, its last bit set when
// the division leaves a remainder, so that the one rounding to 53 bits is the right one.
bool quotient_to_double(const cln::cl_I& num, const cln::cl_I& den, double& out) {
  if (cln::zerop(num)) {
    out = 0;
    return true;
  }
  const cln::cl_I magnitude = cln::abs(num);
  const long shift = 55 - (static_cast<long>(cln::integer_length(magnitude)) -
                           static_cast<long>(cln::integer_length(den)));
  const cln::cl_I scaled_num = shift > 0 ? magnitude << shift : magnitude;
  const cln::cl_I scaled_den = shift < 0 ? den << -shift : den;
  const cln::cl_I_div_t division = cln::floor2(scaled_num, scaled_den);
  std::uint64_t q = cln::cl_I_to_UQ(division.quotient);
  if (!cln::zerop(division.remainder)) q |= 1;
  // 2^54 <= q < 2^57 and the quotient is q·2^-shift: normal when its exponent is above -1022.
  if (64 - std::countl_zero(q) - 1 - shift < -1021) return false;
  const double rounded = std::ldexp(static_cast<double>(q), static_cast<int>(-shift));
  if (!std::isfinite(rounded)) return false;
  out = cln::minusp(num) ? -rounded : rounded;
  return true;
}

// c·root with root = k^(±1/2), c and k = a/b rational (a unit vector's component, a length), to
// within a relative 2⁻¹²⁸, as the quotient of two integers: √k = √(ab)/b and √(ab) =
// ⌊√(ab·4^m)⌋/2^m with ab·4^m ≥ 2²⁵⁶. The same accuracy as the evaluation to 40 digits below,
// without evaluating a tree.
bool square_root_multiple(const RationalPower& e, cln::cl_I& num, cln::cl_I& den) {
  const int root_sign = square_root_sign(e.exponent);
  const bool inverse = root_sign < 0;
  if (root_sign == 0) return false;
  const numeric& k = e.base;
  const cln::cl_I a = to_cl_i(k.numer()), b = to_cl_i(k.denom());
  const cln::cl_I n = a * b;
  const std::uintptr_t bits = cln::integer_length(n);
  if (bits > kMaxRadicandBits) return false;
  const std::uintptr_t m = bits >= 256 ? 0 : (256 - bits + 1) / 2;
  cln::cl_I r;
  cln::isqrt(n << (2 * m), &r);
  num = to_cl_i(e.c.numer()) * r;
  den = to_cl_i(e.c.denom()) * ((inverse ? a : b) << m);
  return true;
}

}  // namespace

double to_double(const Exact& e) {
  // Rationals convert exactly rounded; anything else is evaluated with digits to spare so
  // the double is the nearest one.
  if (is_a<numeric>(e) && ex_to<numeric>(e).is_real() && ex_to<numeric>(e).is_rational())
    return rational_to_double(ex_to<numeric>(e));
  RationalPower parts;
  const bool multiple = rational_power(e, parts);
  if (cln::cl_I num, den; multiple && square_root_multiple(parts, num, den)) {
    if (double value; quotient_to_double(num, den, value)) return value;
    return rational_to_double(numeric(cln::cl_N(num)) / numeric(cln::cl_N(den)));
  }
  // Not a real constant: a symbol, or no precision gives a real (the evaluation below says so;
  // is_real_constant would evaluate once more first).
  if (!multiple && (has_symbol(e) || is_a<GiNaC::relational>(e) || is_a<GiNaC::lst>(e) ||
                    is_a<GiNaC::matrix>(e)))
    return std::numeric_limits<double>::quiet_NaN();
  numeric value;
  return evaluate_real_with_digits_to_spare(e, value) ? value.to_double()
                                                      : std::numeric_limits<double>::quiet_NaN();
}

GiNaC::numeric rational_near(const Exact& e) {
  if (is_rational(e)) return ex_to<numeric>(e);
  if (!is_real_constant(e)) throw std::domain_error("rational_near: not a real constant");
  numeric value;
  if (!evaluate_real_with_digits_to_spare(e, value))
    throw std::domain_error("rational_near: not real");
  if (value.is_rational()) return value;
  // A CLN float is a dyadic rational: take it exactly.
  return numeric(cln::rational(cln::the<cln::cl_R>(value.to_cl_N())));
}

int exact_sign(const Exact& e) {
  if (is_a<numeric>(e) && ex_to<numeric>(e).is_real()) {
    const numeric& n = ex_to<numeric>(e);
    return n.is_zero() ? 0 : (n.is_positive() ? 1 : -1);
  }
  // A root of a rational times a rational: the coefficient's sign, without evaluating the root
  // (what the general route below concludes from the factors' signs).
  if (RationalPower parts; rational_power(e, parts)) return parts.c.is_positive() ? 1 : -1;
  if (!is_real_constant(e)) throw std::domain_error("exact_sign: not a real constant");
  // Products and powers by their factors' signs: no cancellation there, so √2·10⁻³⁰⁰ is
  // decided however small it is, and only sums are refined numerically.
  if (is_a<GiNaC::mul>(e)) {
    int sign = 1;
    for (std::size_t i = 0; i < e.nops() && sign != 0; ++i) sign *= exact_sign(e.op(i));
    return sign;
  }
  if (is_a<GiNaC::power>(e) && is_a<numeric>(e.op(1)) && ex_to<numeric>(e.op(1)).is_rational()) {
    const numeric& q = ex_to<numeric>(e.op(1));
    const int base = exact_sign(e.op(0));
    if (!q.is_integer()) return base;  // a real root: its base is ≥ 0 (is_real_constant)
    return q.is_even() ? (base != 0 ? 1 : 0) : base;
  }

  // Cancellation between the terms of a sum costs precision in proportion to their size.
  const ex expanded = e.expand();
  for (const long digits : kSignDigits) {
    const DigitsGuard guard(digits);
    numeric value;
    if (!evaluate_real(expanded, value)) throw std::domain_error("exact_sign: not real");
    // Relative to the terms' size, not to 1: the sign of a sum of terms of 10⁻³⁰⁰ is decided
    // as that of terms of 1 (a solid scaled by 10⁻¹⁰⁰ was refused where one of size 1 solves).
    numeric scale = GiNaC::abs(value);
    if (is_a<GiNaC::add>(expanded)) {
      numeric sum = 0;
      for (std::size_t i = 0; i < expanded.nops(); ++i) {
        numeric term;
        if (evaluate_real(expanded.op(i), term)) sum += GiNaC::abs(term);
      }
      if (sum > scale) scale = sum;
    }
    const numeric bound = numeric(1) / numeric(10).power(digits - kGuardDigits) * scale;
    if (GiNaC::abs(value) > bound) return value.is_positive() ? 1 : -1;
  }
  // Exactly: the canonical form (a rational, or 0), else the root-separation bound, which
  // decides any sum of up to kMaxZeroProofRadicals square roots whatever its size.
  const ex simplest = canonical(e);
  if (is_rational(simplest)) return exact_sign(simplest);
  if (const std::optional<int> sign = radical_sign(trig_to_radicals(expanded).expand()))
    return *sign;
  throw UndecidedSign("the sign of a value that is 0 to " +
                      std::to_string(kSignDigits[std::size(kSignDigits) - 1] - kGuardDigits) +
                      " digits could not be proven: exact arithmetic cannot tell whether it is 0 "
                      "(write the given numbers as decimals or simpler radicals)");
}

Exact exact_from_double(double v) {
  if (!std::isfinite(v)) throw std::domain_error("exact_from_double: not a finite number");
  int exponent = 0;
  const double fraction = std::frexp(v, &exponent);  // v = fraction * 2^exponent
  constexpr int kMantissaBits = std::numeric_limits<double>::digits;
  // fraction * 2^53 is an integer (subnormals too: frexp normalises them).
  const auto mantissa = static_cast<long long>(std::ldexp(fraction, kMantissaBits));
  return numeric(mantissa) * numeric(2).power(exponent - kMantissaBits);
}

}  // namespace frustum

namespace frustum {

Exact exact_acos(const Exact& c) {
  // The angles of the unit circle a course uses; GiNaC leaves acos(sqrt(2)/2) unevaluated.
  using GiNaC::numeric;
  const Exact r2 = GiNaC::sqrt(Exact(2)) / 2, r3 = GiNaC::sqrt(Exact(3)) / 2;
  const std::pair<Exact, Exact> table[] = {{1, 0},
                                           {r3, GiNaC::Pi / 6},
                                           {r2, GiNaC::Pi / 4},
                                           {numeric(1, 2), GiNaC::Pi / 3},
                                           {0, GiNaC::Pi / 2},
                                           {numeric(-1, 2), 2 * GiNaC::Pi / 3},
                                           {-r2, 3 * GiNaC::Pi / 4},
                                           {-r3, 5 * GiNaC::Pi / 6},
                                           {-1, GiNaC::Pi}};
  const Exact cc = canonical(c);
  for (const auto& [value, angle] : table)
    if (canonical(cc - value).is_zero()) return angle;
  return GiNaC::acos(cc);
}

}  // namespace frustum
