// Exact orientation predicates on doubles the way the paper proposes, interval arithmetic
// with a multiprecision fallback, in stages of escalating precision: a semi-static
// floating-point filter, Boost.Interval arithmetic on doubles under directed rounding,
// interval arithmetic over 128-bit and then 256-bit MPFR numbers (mpfr_interval.hpp, which
// says which inputs each precision decides), and exact GMP integers when every interval
// contains zero. [MK89 §3.3] [BMP06] [MPFR] [Sh97 §4.2]
// Preconditions: finite inputs; IEEE 754 binary64 with gradual underflow (no FTZ/DAZ);
// the caller's rounding mode is round-to-nearest (the filter's bound assumes it; the
// interval stage sets its own mode through RoundingGuard and restores the caller's);
// -ffp-contract=off (mkbool_arith sets it). Exact for every finite input.
#pragma once

#include <algorithm>
#include <cfenv>
#include <cmath>

#include <boost/numeric/interval.hpp>

#include "arithmetic/mpfr_interval.hpp"
#include "arithmetic/predicates_counters.hpp"
#include "arithmetic/predicates_gmp.hpp"
#include "arithmetic/rounding_guard.hpp"
#include "arithmetic/formulas.hpp"

namespace mk::interval_filter {

// ---- The semi-static filter bound ----------------------------------------------------
// Notation and facts F1-F4 as in adaptive_bounds.hpp (u = 2^-53, eta = 2^-1075). The
// filter computes det exactly as stage A does, so (A1) holds whenever l and r are finite:
//   |D - det| <= u |det| + theta S + 2 (1 + u)^2 eta,  theta = 3u + 3u^2 + u^3.
// Instead of S it uses the magnitudes of the differences: with mx = max(|x1|, |x4|) (the
// x differences), my = max(|x2|, |x3|) (the y differences) and m = mx my (exact),
// |l| <= (1 + u)|x1 x2| + eta <= (1 + u) m + eta (F3), and likewise |r|, so
//   |D - det| <= u |det| + 2 theta (1 + u) m + (2 theta + 2 (1 + u)^2) eta.          (S0)
// The program computes m' = fl(mx my), e = fl(fl(semi_static_bound m') + semi_static_floor)
// and accepts when |det| > e. The bound is derived for intermediate results that neither
// overflow nor underflow, and stays valid outside that range for these reasons:
//  - overflow: if m' is finite, m < DBL_MAX + ulp/2, so every |x_i x_j| <= m rounds to a
//    finite l or r, and (S0) holds; det itself may overflow, but fl keeps the sign of
//    l - r, which (S0) ties to D. If m' is infinite or NaN (an infinite difference), so is
//    e, and |det| > e is false: the call goes on to the interval stage.
//  - underflow: products below 2^-1022 lose up to eta each; (S0) already counts it, and
//    the floor, like stage A's, covers those eta terms (and the rounding of m' and e
//    below 2^-1022: m' >= m/(1 + u) - eta, fl(C m') >= C m'/(1 + u) - eta).
// Then e >= C m/(1 + u)^3 + (floor - eta (1 + C/(1 + u)))/(1 + u), and |det| > e implies
// |det| > |D - det| when
//   C (1 - u) / (1 + u)^3 >= 2 theta (1 + u)                                         (S1)
//   (floor - eta (1 + C/(1 + u))) (1 - u) / (1 + u) >= (2 theta + 2 (1 + u)^2) eta.  (S2)
// (S1): the right side is 6u + 12u^2 + O(u^3), the left (6 + 40u)u (1 - 4u + ...) =
// 6u + 16u^2 + O(u^3). tests/arithmetic/bounds_test.cpp checks (S1) and (S2) in exact
// rational arithmetic. Without range tests the filter costs, beside the naive formula,
// four absolute values, two maxima and the bound itself: in scalar form about twice the
// floating-point operations of the naive sign, which in a loop bound by floating-point
// throughput measured 1.5-1.7x the naive predicate. cross_sign below therefore evaluates the
// x and y halves as two-lane vectors (see Pair).
inline constexpr double semi_static_bound = (6.0 + 40.0 * 0x1p-53) * 0x1p-53;
inline constexpr double semi_static_floor = 0x1p-1022;

// Boost.Interval without per-operation mode switches: the guard sets rounding upward once,
// and rounded_arith_opp gets each lower bound as -((-x) op y) rounded up. No NaN checks:
// every endpoint comes from finite doubles (see interval_sign).
using Interval = boost::numeric::interval<
    double, boost::numeric::interval_lib::policies<
                boost::numeric::interval_lib::save_state_nothing<
                    boost::numeric::interval_lib::rounded_arith_opp<double>>,
                boost::numeric::interval_lib::checking_no_nan<
                    double, boost::numeric::interval_lib::checking_no_empty<double>>>>;

namespace detail {

// The sign of (q1 - p1) x (q2 - p2) if an interval evaluation proves it, 2 if the interval
// contains zero and is not [0, 0]. Overflow only widens the enclosure: a bound that
// overflows rounds outward to an infinity, and Boost's case split multiplies an infinite
// endpoint only by a non-zero one, so no NaN arises from finite inputs; the NaN test below
// is a second line of defence.
inline int interval_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                         double q2x, double q2y) {
  Interval det;
  {
    RoundingGuard upward(FE_UPWARD);
    auto in = [](double v) { return Interval(RoundingGuard::opaque(v)); };
    det = formula::cross_of_differences<Interval>(in(p1x), in(p1y), in(q1x), in(q1y), in(p2x),
                                                  in(p2y), in(q2x), in(q2y));
  }
  const double lo = det.lower();
  const double hi = det.upper();
  if (std::isnan(lo) || std::isnan(hi)) return 2;
  if (lo > 0.0) return 1;
  if (hi < 0.0) return -1;
  if (lo == 0.0 && hi == 0.0) return 0;  // the enclosure [0, 0] proves D = 0
  return 2;
}

[[gnu::noinline]] inline int cross_sign_slow(double p1x, double p1y, double q1x, double q1y,
                                             double p2x, double p2y, double q2x, double q2y,
                                             PredicateKind kind) {
  // A zero difference vector (its rounded coordinates are zero only when exact) makes D zero.
  // Counted as the filter's decision.
  if ((q1x == p1x && q1y == p1y) || (q2x == p2x && q2y == p2y)) return 0;
  const auto decided = [kind](PredicateStage stage, int sign) {
    PredicateCounters::decide(PredicateMethod::interval, kind, stage);
    return sign;
  };
  if (const int s = interval_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y); s != 2) {
    return decided(PredicateStage::interval, s);
  }
  if (const int s = mpfr_interval::cross_sign<128>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y); s != 2) {
    return decided(PredicateStage::mpfr_128, s);
  }
  if (const int s = mpfr_interval::cross_sign<256>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y); s != 2) {
    return decided(PredicateStage::mpfr_256, s);
  }
  return decided(PredicateStage::gmp, gmp::cross_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y));
}

// Two doubles in one register (SSE2 on x86-64, NEON on AArch64), through the GCC/Clang
// vector extension: +, -, * act lane by lane with the rounding of the scalar operation, so
// a formula evaluated on pairs gives bit for bit the scalar results, two at a time.
typedef double Pair __attribute__((vector_size(16)));
typedef long long PairBits __attribute__((vector_size(16)));

inline Pair abs_lanes(Pair v) {
  const PairBits magnitude_bits{0x7fffffffffffffffLL, 0x7fffffffffffffffLL};
  return reinterpret_cast<Pair>(reinterpret_cast<PairBits>(v) & magnitude_bits);
}

// The filter on pairs: a point's coordinates are adjacent in memory, so (x1, x3) = q1 - p1
// and (x4, x2) = q2 - p2 are one vector subtraction each; one product gives (l, r), and one
// absolute value and one maximum per pair give (max(|x1|, |x4|), max(|x3|, |x2|)). Every
// lane computes exactly the scalar value the derivation above names (x_k, l, r, det, m, e).
inline int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                      double q2x, double q2y, PredicateKind kind) {
  PredicateCounters::call(PredicateMethod::interval, kind);
  const Pair x1_x3 = Pair{q1x, q1y} - Pair{p1x, p1y};
  const Pair x4_x2 = Pair{q2x, q2y} - Pair{p2x, p2y};
  const Pair l_r = x1_x3 * Pair{x4_x2[1], x4_x2[0]};
  const double det = l_r[0] - l_r[1];  // formula::cross_of_differences, operation by operation
  const Pair a = abs_lanes(x1_x3);
  const Pair b = abs_lanes(x4_x2);
  const Pair largest = a > b ? a : b;  // lane-wise max
  const double m = largest[0] * largest[1];
  const double bound = semi_static_bound * m + semi_static_floor;  // (S1), (S2)
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

}  // namespace mk::interval_filter
