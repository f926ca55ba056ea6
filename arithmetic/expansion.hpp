// Exact floating-point expansion arithmetic: the error-free transformations and expansion
// algorithms of [Sh97 §2] (two-sum, fast-two-sum, two-product, grow, sum, scale, compress),
// written here from the published method.
// Preconditions: IEEE 754 binary64, round-to-nearest-even (the default mode), no
// flush-to-zero or denormals-are-zero; no result overflows; the error term of every
// two_product is representable (no underflow below 2^-1074: adaptive.hpp only calls these
// on inputs in a range that guarantees it). Compile with -ffp-contract=off (mkbool_arith
// sets it): a fused a*b+c would break the error-free transformations.
//
// An expansion is a sum of doubles e[0] + e[1] + ... + e[n-1], stored in increasing order of
// magnitude, whose components do not overlap (the lowest set bit of each component lies
// above the highest bit of every smaller one). Its value is the exact real sum; its sign
// is the sign of its largest non-zero component.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>

namespace mk::expansion {

// hi + lo equals the exact result of the operation; hi is the rounded result.
struct TwoTerm {
  double hi;
  double lo;
};

// [Sh97 Thm 6] a + b when |a| >= |b| (or a == 0): three operations instead of six.
constexpr TwoTerm fast_two_sum(double a, double b) {
  const double hi = a + b;
  const double b_virtual = hi - a;
  return {hi, b - b_virtual};
}

// [Sh97 Thm 7] a + b for any two doubles (Knuth): the roundoff is recovered from both
// operands, so no magnitude order is needed.
constexpr TwoTerm two_sum(double a, double b) {
  const double hi = a + b;
  const double b_virtual = hi - a;
  const double a_virtual = hi - b_virtual;
  return {hi, (a - a_virtual) + (b - b_virtual)};
}

// The roundoff of hi = fl(a - b): a - b == hi + two_diff_tail(a, b, hi) exactly. Separate
// from two_diff because the predicates compute hi first and need the tail only when the
// fast stages fail.
constexpr double two_diff_tail(double a, double b, double hi) {
  const double b_virtual = a - hi;
  const double a_virtual = hi + b_virtual;
  return (a - a_virtual) + (b_virtual - b);
}

constexpr TwoTerm two_diff(double a, double b) {
  const double hi = a - b;
  return {hi, two_diff_tail(a, b, hi)};
}

// [Sh97 §2.6] a * b exactly as hi + lo. Shewchuk splits the operands (Dekker); a fused
// multiply-add gives the same error term in one instruction: fma computes a*b - hi with a
// single rounding, and that value is representable, so it is exact.
inline TwoTerm two_product(double a, double b) {
  const double hi = a * b;
  return {hi, std::fma(a, b, -hi)};
}

// [Sh97 Thm 17] Veltkamp's split: a = hi + lo exactly, hi and lo each fitting in 26
// significant bits (the sign supplies the 27th), so that products of parts are exact.
// Precondition: |a| <= 2^996 (the scaled value (2^27 + 1) a stays finite).
struct Split {
  double hi;
  double lo;
};
constexpr Split split(double a) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double a_big = c - a;
  const double hi = c - a_big;
  return {hi, a - hi};
}

// [Sh97 Thm 18] a * b exactly as hi + lo by Dekker's method: the product of the split parts
// with every step exact. Same result as two_product, in plain operations: without a
// hardware fma at compile time (the portable build), std::fma is a call into libm, which
// costs more than these 17 operations and forces the caller to spill its registers.
// Preconditions: |a|, |b| <= 2^996 and |a b| <= 2^1021, so that no step overflows (the
// parts exceed a, b by a factor of at most 1 + 2^-26); a and b are integer multiples of
// 2^-511, so that every part, product of parts and partial sum is a multiple of 2^-1022:
// each non-zero intermediate is then normal, no step underflows, and Shewchuk's proof,
// which assumes no underflow, applies. (A multiple of g = 2^-k rounds to a multiple of g;
// adaptive_bounds.hpp uses the same fact.) The expansion stages of adaptive.hpp meet both
// on their scaled inputs; tests/arithmetic/expansion_test.cpp checks the edges.
constexpr TwoTerm two_product_split(double a, double b) {
  const double hi = a * b;
  const Split as = split(a);
  const Split bs = split(b);
  const double err1 = hi - as.hi * bs.hi;
  const double err2 = err1 - as.lo * bs.hi;
  const double err3 = err2 - as.hi * bs.lo;
  return {hi, as.lo * bs.lo - err3};
}

// [Sh97 §2.7] (a1 + a0) - (b1 + b0) as a four-component expansion, least significant first.
// Built from two grow steps: subtract b0, then b1, each with a chain of two-sums.
inline std::array<double, 4> two_two_diff(double a1, double a0, double b1, double b0) {
  std::array<double, 4> x{};
  // (a1 + a0) - b0 = j + t + x[0]
  const TwoTerm i = two_diff(a0, b0);
  x[0] = i.lo;
  const TwoTerm j = two_sum(a1, i.hi);
  // (j + t) - b1 = x[3] + x[2] + x[1]
  const TwoTerm k = two_diff(j.lo, b1);
  x[1] = k.lo;
  const TwoTerm top = two_sum(j.hi, k.hi);
  x[2] = top.lo;
  x[3] = top.hi;
  return x;
}

// [Sh97 Thm 10, GROW-EXPANSION with zero elimination] h = e + b. h needs e.size() + 1
// slots; returns the number of components written. Any nonoverlapping e.
inline std::size_t grow_expansion(std::span<const double> e, double b, std::span<double> h) {
  std::size_t n = 0;
  double q = b;
  for (const double component : e) {
    const TwoTerm s = two_sum(q, component);
    q = s.hi;
    if (s.lo != 0.0) h[n++] = s.lo;
  }
  if (q != 0.0 || n == 0) h[n++] = q;
  return n;
}

// [Sh97 Thm 13, FAST-EXPANSION-SUM with zero elimination] h = e + f. Merges the components
// of e and f by magnitude and sweeps them with one running sum; h needs e.size() + f.size()
// slots. Requires round-to-even ties and strongly nonoverlapping inputs (every expansion
// built by the functions of this file is). Returns the number of components written; an
// exact zero is returned as the single component 0.
inline std::size_t expansion_sum(std::span<const double> e, std::span<const double> f,
                                 std::span<double> h) {
  std::size_t ie = 0;
  std::size_t jf = 0;
  // Next component of the merge in increasing magnitude.
  auto next = [&]() -> double {
    if (jf == f.size() || (ie < e.size() && std::fabs(e[ie]) <= std::fabs(f[jf]))) return e[ie++];
    return f[jf++];
  };
  const std::size_t total = e.size() + f.size();
  if (total == 0) {
    h[0] = 0.0;
    return 1;
  }
  std::size_t n = 0;
  double q = next();
  if (total > 1) {
    // The two smallest components: the second has the larger magnitude, as fast_two_sum needs.
    const TwoTerm s = fast_two_sum(next(), q);
    q = s.hi;
    h[n] = s.lo;
    n += (s.lo != 0.0);
  }
  for (std::size_t k = 2; k < total; ++k) {
    const TwoTerm s = two_sum(q, next());
    q = s.hi;
    // Zero elimination without a branch: whether a roundoff is zero depends on the data
    // and would mispredict often; the slot is written always and kept if non-zero.
    h[n] = s.lo;
    n += (s.lo != 0.0);
  }
  if (q != 0.0 || n == 0) h[n++] = q;
  return n;
}

// [Sh97 Thm 19, SCALE-EXPANSION with zero elimination] h = b * e. h needs 2 * e.size()
// slots (at least 1). Each component's product is split exactly, and the pieces are
// folded into the running sum in order of magnitude.
inline std::size_t scale_expansion(std::span<const double> e, double b, std::span<double> h) {
  std::size_t n = 0;
  if (e.empty()) {
    h[0] = 0.0;
    return 1;
  }
  TwoTerm p = two_product(e[0], b);
  double q = p.hi;
  if (p.lo != 0.0) h[n++] = p.lo;
  for (std::size_t i = 1; i < e.size(); ++i) {
    p = two_product(e[i], b);
    const TwoTerm s = two_sum(q, p.lo);
    if (s.lo != 0.0) h[n++] = s.lo;
    // p.hi dominates s.hi: the product of a larger component against the running sum of
    // the smaller ones.
    const TwoTerm t = fast_two_sum(p.hi, s.hi);
    if (t.lo != 0.0) h[n++] = t.lo;
    q = t.hi;
  }
  if (q != 0.0 || n == 0) h[n++] = q;
  return n;
}

// [Sh97 §2.8, COMPRESS] The same value with as few components as the two sweeps find, the
// largest component then approximating the whole value to within one ulp. A downward
// sweep gathers each run of components whose sum fits in one double; an upward sweep
// re-splits what remains so the result is nonoverlapping again. h needs e.size() slots
// (at least 1); e must be nonempty and nonoverlapping. h may alias e.
inline std::size_t compress(std::span<const double> e, std::span<double> h) {
  const std::size_t m = e.size();
  if (m == 0) {
    h[0] = 0.0;
    return 1;
  }
  // Downward sweep: g[bottom..m-1] holds the gathered sums, the largest at the top.
  std::size_t bottom = m - 1;
  double q = e[m - 1];
  for (std::size_t i = m - 1; i-- > 0;) {
    const TwoTerm s = fast_two_sum(q, e[i]);
    if (s.lo != 0.0) {
      h[bottom--] = s.hi;
      q = s.lo;
    } else {
      q = s.hi;
    }
  }
  h[bottom] = q;
  // Upward sweep: emit the roundoff of each addition, least significant first.
  std::size_t top = 0;
  q = h[bottom];
  for (std::size_t i = bottom + 1; i < m; ++i) {
    const TwoTerm s = fast_two_sum(h[i], q);
    if (s.lo != 0.0) h[top++] = s.lo;
    q = s.hi;
  }
  h[top++] = q;
  return top;
}

// [Sh97 §2.8] The floating-point sum of the components, smallest first: an approximation of
// the value, used by the adaptive stages before the exact answer is needed.
inline double estimate(std::span<const double> e) {
  double q = 0.0;
  for (const double component : e) q += component;
  return q;
}

// The exact sign of the value: the sign of the largest non-zero component, because the
// components below it sum to less than its lowest set bit.
inline int sign(std::span<const double> e) {
  for (std::size_t i = e.size(); i-- > 0;) {
    if (e[i] > 0.0) return 1;
    if (e[i] < 0.0) return -1;
  }
  return 0;
}

}  // namespace mk::expansion
