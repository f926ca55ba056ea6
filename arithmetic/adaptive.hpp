// Exact orientation predicates on doubles by adaptive-precision expansion arithmetic:
// Shewchuk's staged orient2d (filter A, expansion stages B and C, exact expansion stage),
// written here for the cross product of two difference vectors, with a GMP last resort for
// inputs whose magnitudes span too many binades for expansions. [Sh97 §4.3]
// Preconditions: finite inputs; IEEE 754 binary64 in round-to-nearest-even, no
// flush-to-zero (-ffast-math breaks it); -ffp-contract=off (mkbool_arith sets it).
// Exact for every finite input: subnormals, values near DBL_MAX, mixed magnitudes.
// The error bounds and the range argument are derived in adaptive_bounds.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "arithmetic/adaptive_bounds.hpp"
#include "arithmetic/expansion.hpp"
#include "arithmetic/predicates_counters.hpp"
#include "arithmetic/predicates_gmp.hpp"

namespace mk::adaptive {
namespace detail {

// The eight inputs of (q1 - p1) x (q2 - p2), in the order of formula::cross_of_differences.
// orient2d(a, b, c) is {a, b, a, c}.
struct CrossInput {
  double p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y;
};

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// Multiplies every input by one power of two so that each non-zero input lies in
// [safe_min, safe_max], the range where the expansion stages cannot underflow or overflow
// (adaptive_bounds.hpp). Exact, because every scaled value is normal, and sign-preserving,
// because D scales by a positive factor. Returns false when the magnitudes span more than
// the range allows (for example 1e-300 next to 1e300).
inline bool fit_into_safe_range(CrossInput& in) {
  std::array<double*, 8> v{&in.p1x, &in.p1y, &in.q1x, &in.q1y, &in.p2x, &in.p2y, &in.q2x, &in.q2y};
  double largest = 0.0;
  double smallest = HUGE_VAL;
  for (const double* x : v) {
    const double m = std::fabs(*x);
    if (m == 0.0) continue;
    largest = std::max(largest, m);
    smallest = std::min(smallest, m);
  }
  if (largest == 0.0 || (smallest >= safe_min && largest <= safe_max)) return true;
  // Put the largest input just below 2^500; the smallest then stays at or above 2^-400
  // exactly when the exponents differ by at most 899.
  const int top = std::ilogb(largest);
  if (top - std::ilogb(smallest) > 899) return false;
  const int shift = 499 - top;
  for (double* x : v) *x = std::ldexp(*x, shift);
  return true;
}

// Exact differences, decided without expansions. [Sh97] builds B and leaves stage B when all
// tails are zero; deciding from l and r directly gives the same answer several times sooner
// (collinear input with integer-like coordinates is the common degenerate case). If every
// X_k = x_k, then D = L - R with
// L = x1 x2 and R = x3 x4 exact products, and l = fl(L), r = fl(R). Rounding is monotone:
// l > r forces L >= R, and L = R would force l = r, so l > r means D > 0 (and l < r, D < 0)
// for every finite input, overflow and underflow included. When l = r, D = (L - l) - (R - r)
// is the difference of the two products' rounding errors, exact from fma when neither
// error term underflows: |l| >= 2^-968 suffices (the factors' exponents then sum to at
// least -969, so the error term is a multiple of 2^-1073). Returns 2 when it cannot decide.
inline int exact_differences_sign(double x1, double x2, double x3, double x4) {
  const double l = x1 * x2;
  const double r = x3 * x4;
  if (l != r) return l > r ? 1 : -1;
  if (std::fabs(l) >= 0x1p-968 && std::fabs(l) <= 0x1p1023) {
    return sign_of(std::fma(x1, x2, -l) - std::fma(x3, x4, -r));
  }
  // l = r = 0 exactly because a factor on each side is zero: D = 0.
  if ((x1 == 0.0 || x2 == 0.0) && (x3 == 0.0 || x4 == 0.0)) return 0;
  return 2;
}

// Stages B, C and the exact stage on inputs already in the safe range.
inline int cross_sign_expansion(const CrossInput& in, PredicateKind kind) {
  using namespace mk::expansion;
  // Stage B: B = x1 x2 - x3 x4 exactly, from the rounded differences.
  const double x1 = in.q1x - in.p1x;
  const double x2 = in.q2y - in.p2y;
  const double x3 = in.q1y - in.p1y;
  const double x4 = in.q2x - in.p2x;
  const double t1 = two_diff_tail(in.q1x, in.p1x, x1);
  const double t2 = two_diff_tail(in.q2y, in.p2y, x2);
  const double t3 = two_diff_tail(in.q1y, in.p1y, x3);
  const double t4 = two_diff_tail(in.q2x, in.p2x, x4);
  const TwoTerm left = two_product(x1, x2);
  const TwoTerm right = two_product(x3, x4);
  const double detsum = std::fabs(left.hi) + std::fabs(right.hi);
  const std::array<double, 4> b = two_two_diff(left.hi, left.lo, right.hi, right.lo);
  double det = estimate(b);
  if (std::fabs(det) > bound_b * detsum) return sign_of(det);
  // Exact differences (reached here only after scaling): B is D itself.
  if (t1 == 0.0 && t2 == 0.0 && t3 == 0.0 && t4 == 0.0) return sign(b);

  // Stage C: add the first-order tail terms in floating point.
  PredicateCounters::count(PredicateMethod::adaptive, kind, PredicateStage::expansion_c);
  det += (x1 * t2 + t1 * x2) - (x3 * t4 + t3 * x4);
  const double bound = bound_c * detsum + bound_c_result * std::fabs(det);
  if (std::fabs(det) > bound) return sign_of(det);

  // Exact stage: D = B + (t1 x2 - t3 x4) + (x1 t2 - x3 t4) + (t1 t2 - t3 t4), each bracket
  // an exact four-component expansion; brackets whose tails are zero are skipped.
  PredicateCounters::count(PredicateMethod::adaptive, kind, PredicateStage::expansion_exact);
  std::array<double, 16> buffer_a;
  std::array<double, 16> buffer_b;
  double* sum = buffer_a.data();
  double* spare = buffer_b.data();
  std::copy(b.begin(), b.end(), sum);
  std::size_t n = b.size();
  auto add_bracket = [&](double p, double q, double r, double s) {
    const TwoTerm pq = two_product(p, q);
    const TwoTerm rs = two_product(r, s);
    const std::array<double, 4> u = two_two_diff(pq.hi, pq.lo, rs.hi, rs.lo);
    n = expansion_sum(std::span<const double>(sum, n), u, std::span<double>(spare, n + u.size()));
    std::swap(sum, spare);
  };
  if (t1 != 0.0 || t3 != 0.0) add_bracket(t1, x2, t3, x4);
  if (t2 != 0.0 || t4 != 0.0) add_bracket(x1, t2, x3, t4);
  if ((t1 != 0.0 && t2 != 0.0) || (t3 != 0.0 && t4 != 0.0)) add_bracket(t1, t2, t3, t4);
  return sign(std::span<const double>(sum, n));
}

// Everything after stage A; out of line so that the filter stays small enough to inline at
// every call site. The inputs come as scalars (in registers), not as a struct the caller
// would have to store.
[[gnu::noinline]] inline int cross_sign_slow(double p1x, double p1y, double q1x, double q1y, double p2x,
                                             double p2y, double q2x, double q2y, PredicateKind kind) {
  // Counted as reaching stage B: everything past the filter.
  PredicateCounters::count(PredicateMethod::adaptive, kind, PredicateStage::expansion_b);
  CrossInput in{p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y};
  const double x1 = q1x - p1x;
  const double x2 = q2y - p2y;
  const double x3 = q1y - p1y;
  const double x4 = q2x - p2x;
  // Exact differences: decide them before any expansion is built.
  if (expansion::two_diff_tail(q1x, p1x, x1) == 0.0 && expansion::two_diff_tail(q2y, p2y, x2) == 0.0 &&
      expansion::two_diff_tail(q1y, p1y, x3) == 0.0 && expansion::two_diff_tail(q2x, p2x, x4) == 0.0) {
    const int s = exact_differences_sign(x1, x2, x3, x4);
    if (s != 2) return s;
  }
  if (!fit_into_safe_range(in)) {
    PredicateCounters::count(PredicateMethod::adaptive, kind, PredicateStage::gmp);
    return gmp::cross_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
  }
  return cross_sign_expansion(in, kind);
}

// Stage A: the plain formula (bit for bit the naive double evaluation) accepted when its
// magnitude exceeds the bound (A1)-(A4) of adaptive_bounds.hpp; decides almost every call
// on non-degenerate input.
inline int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x,
                      double q2y, PredicateKind kind) {
  PredicateCounters::count(PredicateMethod::adaptive, kind, PredicateStage::filter);
  const double x1 = q1x - p1x;
  const double x2 = q2y - p2y;
  const double x3 = q1y - p1y;
  const double x4 = q2x - p2x;
  const double left = x1 * x2;
  const double right = x3 * x4;
  const double det = left - right;
  const double bound = bound_a * (std::fabs(left) + std::fabs(right)) + bound_a_floor;
  if (det > bound) return 1;
  if (-det > bound) return -1;
  return cross_sign_slow(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, kind);
}

}  // namespace detail

// Sign of (b - a) x (c - a): +1 when a, b, c turn counterclockwise, -1 clockwise, 0 collinear.
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return detail::cross_sign(ax, ay, bx, by, ax, ay, cx, cy, PredicateKind::orient2d);
}

// Sign of (q1 - p1) x (q2 - p2): +1 when direction q2 - p2 turns left from q1 - p1.
inline int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                          double q2x, double q2y) {
  return detail::cross_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, PredicateKind::orient_vectors);
}

}  // namespace mk::adaptive
