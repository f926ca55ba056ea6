// Exact orientation predicates on doubles by adaptive-precision expansion arithmetic:
// Shewchuk's staged orient2d (filter A, expansion stages B and C, exact expansion stage),
// written here for the cross product of two difference vectors, with a GMP last resort for
// inputs whose magnitudes span too many binades for expansions. [Sh97 §4.3] Past filter A,
// inputs with rounded differences go first to an exact stage in 128-bit fixed point, which
// decides every input whose axes each span less than about 2^69, much faster than the
// expansions (see "The fixed-point exact stage"). Needs __int128 (GCC, Clang; 64-bit).
// Preconditions: finite inputs; IEEE 754 binary64 in round-to-nearest-even, no
// flush-to-zero (-ffast-math breaks it); -ffp-contract=off (mkbool_arith sets it).
// Exact for every finite input: subnormals, values near DBL_MAX, mixed magnitudes.
// The error bounds and the range argument are derived in adaptive_bounds.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
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
// (Dekker's product instead of the fma, a libm call in the portable build, measured slower
// here: two calls cost less than two splits and the range tests they need.)
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

// ---- The fixed-point exact stage ------------------------------------------------------
// D = X1 X2 - X3 X4 has integer coefficients, so it can be evaluated exactly in integers
// once each axis is put on an integer grid. For one axis, let M be the largest magnitude
// among its inputs, e = exponent(M) (2^e <= M < 2^(e + 1)), g = 2^(e - 121). When
// M >= 2^-902 and every non-zero input v of the axis has |v| >= 2^(e - 69):
//  - v is normal with exponent at least e - 69, so its last bit is worth at least
//    2^(e - 121) = g: V = v / g is an integer, and |V| <= M / g < 2^122. The program
//    computes V = v * 2^(121 - e) in floating point, exactly (a power of two between
//    2^-902 and 2^1023; no result underflows, since |V| >= 2^52, or overflows);
//  - V = h 2^61 + l with h = trunc(V 2^-61) and l = V - h 2^61, both computed exactly:
//    V 2^-61 is a scaling, its truncation an integer of at most 53 significant bits, and
//    l holds the bits of V below 2^61, at most 53 of them (or l = V when h = 0). So
//    |h| < 2^61, |l| < 2^61, and the conversions to 64-bit integers are exact; they
//    truncate, so the rounding mode plays no role.
// A difference X = V_q - V_p is then xh 2^61 + xl with |xh|, |xl| < 2^62 (int64). Every
// product in D pairs an x difference (X1, X4) with a y difference (X2, X3), so the two
// grids multiply into one: D / (gx gy) = A 2^122 + B 2^61 + C, with
//   A = xh1 xh2 - xh3 xh4,  B = xh1 xl2 + xl1 xh2 - xh3 xl4 - xl3 xh4,  C = xl1 xl2 - xl3 xl4,
// each product below 2^124, so |A|, |C| < 2^125, |B| < 2^126: exact in 128-bit integers.
// Carrying C's and then B's bits above 2^61 upwards (C = c' 2^61 + c'', 0 <= c'' < 2^61,
// B' = B + c' < 2^127, A' = A + (B' >> 61) < 2^126) leaves
//   D / (gx gy) = A' 2^122 + (B' mod 2^61) 2^61 + c'', the last two terms in [0, 2^122),
// so the sign of D is the sign of A', or + when A' = 0 and a low part is non-zero.
// Inputs it refuses (an axis with a non-zero input below 2^(e - 69), or whose largest input
// is below 2^-902) go on to the expansion stages, which handle every span. For the inputs
// it accepts it replaces stages B, C and the sixteen-component expansion sum (whose merge
// by magnitude mispredicts its branches) at a fraction of their cost. No operation below
// depends on the rounding mode. tests/arithmetic/fixed_point_test.cpp checks both sides of
// every limit named here.
namespace fixed_point {

__extension__ typedef __int128 Int128;

// The inputs of one axis as h 2^61 + l on the axis's grid, or false when the axis spans
// too far (see above).
template <std::size_t N>
inline bool axis_to_grid(const std::array<double, N>& v, std::array<std::int64_t, N>& high,
                         std::array<std::int64_t, N>& low) {
  double largest = 0.0;
  for (const double x : v) largest = std::max(largest, std::fabs(x));
  if (largest == 0.0) largest = 1.0;  // an axis of zeros: any grid will do
  if (!(largest >= 0x1p-902)) return false;
  const auto e = static_cast<std::int64_t>(std::bit_cast<std::uint64_t>(largest) >> 52) - 1023;
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(121 - e + 1023) << 52);
  const double smallest_allowed = std::bit_cast<double>(static_cast<std::uint64_t>(e - 69 + 1023) << 52);
  int refused = 0;  // counted without branches: one test per axis instead of one per input
  for (const double x : v) refused += static_cast<int>(x != 0.0) & static_cast<int>(std::fabs(x) < smallest_allowed);
  if (refused != 0) return false;
  for (std::size_t i = 0; i < N; ++i) {
    const double grid_value = v[i] * scale;
    const auto h = static_cast<std::int64_t>(grid_value * 0x1p-61);
    high[i] = h;
    low[i] = static_cast<std::int64_t>(grid_value - static_cast<double>(h) * 0x1p61);
  }
  return true;
}

// Sign of (xh1 2^61 + xl1)(xh2 2^61 + xl2) - (xh3 2^61 + xl3)(xh4 2^61 + xl4) for limbs
// below 2^62 in magnitude.
inline int limbs_sign(std::int64_t xh1, std::int64_t xl1, std::int64_t xh2, std::int64_t xl2, std::int64_t xh3,
                      std::int64_t xl3, std::int64_t xh4, std::int64_t xl4) {
  auto mul = [](std::int64_t a, std::int64_t b) { return static_cast<Int128>(a) * b; };
  const Int128 a = mul(xh1, xh2) - mul(xh3, xh4);
  const Int128 b = mul(xh1, xl2) + mul(xl1, xh2) - mul(xh3, xl4) - mul(xl3, xh4);
  const Int128 c = mul(xl1, xl2) - mul(xl3, xl4);
  constexpr Int128 low_mask = (Int128{1} << 61) - 1;
  const Int128 b_carried = b + (c >> 61);  // >> of a signed value: floor division (C++20)
  const Int128 a_carried = a + (b_carried >> 61);
  const bool low_nonzero = ((b_carried & low_mask) | (c & low_mask)) != 0;
  if (a_carried != 0) return a_carried > 0 ? 1 : -1;
  return low_nonzero ? 1 : 0;
}

// The sign of D, or 2 when an axis spans too far. SharedOrigin: p2 = p1 (orient2d), so
// each axis has three inputs instead of four.
template <bool SharedOrigin>
inline int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x,
                      double q2y) {
  if constexpr (SharedOrigin) {
    std::array<std::int64_t, 3> xh, xl, yh, yl;
    if (!axis_to_grid<3>({p1x, q1x, q2x}, xh, xl) || !axis_to_grid<3>({p1y, q1y, q2y}, yh, yl)) return 2;
    return limbs_sign(xh[1] - xh[0], xl[1] - xl[0], yh[2] - yh[0], yl[2] - yl[0], yh[1] - yh[0], yl[1] - yl[0],
                      xh[2] - xh[0], xl[2] - xl[0]);
  } else {
    std::array<std::int64_t, 4> xh, xl, yh, yl;
    if (!axis_to_grid<4>({p1x, q1x, p2x, q2x}, xh, xl) || !axis_to_grid<4>({p1y, q1y, p2y, q2y}, yh, yl)) {
      return 2;
    }
    return limbs_sign(xh[1] - xh[0], xl[1] - xl[0], yh[3] - yh[2], yl[3] - yl[2], yh[1] - yh[0], yl[1] - yl[0],
                      xh[3] - xh[2], xl[3] - xl[2]);
  }
}

}  // namespace fixed_point

// Stages B, C and the exact stage on inputs already in the safe range.
template <bool SharedOrigin>
inline int cross_sign_expansion(const CrossInput& in, PredicateKind kind) {
  using namespace mk::expansion;
  // Stage B: B = x1 x2 - x3 x4 exactly, from the rounded differences. Dekker's product is
  // exact here: the scaled inputs meet its preconditions (adaptive_bounds.hpp, safe range).
  const double x1 = in.q1x - in.p1x;
  const double x2 = in.q2y - in.p2y;
  const double x3 = in.q1y - in.p1y;
  const double x4 = in.q2x - in.p2x;
  const double t1 = two_diff_tail(in.q1x, in.p1x, x1);
  const double t2 = two_diff_tail(in.q2y, in.p2y, x2);
  const double t3 = two_diff_tail(in.q1y, in.p1y, x3);
  const double t4 = two_diff_tail(in.q2x, in.p2x, x4);
  const TwoTerm left = two_product_split(x1, x2);
  const TwoTerm right = two_product_split(x3, x4);
  const double detsum = std::fabs(left.hi) + std::fabs(right.hi);
  const std::array<double, 4> b = two_two_diff(left.hi, left.lo, right.hi, right.lo);
  double det = estimate(b);
  if (std::fabs(det) > bound_b * detsum) {
    PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::expansion_b);
    return sign_of(det);
  }
  // Exact differences (reached here only after scaling): B is D itself.
  if (t1 == 0.0 && t2 == 0.0 && t3 == 0.0 && t4 == 0.0) {
    PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::expansion_b);
    return sign(b);
  }

  // Stage C: add the first-order tail terms in floating point.
  det += (x1 * t2 + t1 * x2) - (x3 * t4 + t3 * x4);
  const double bound = bound_c * detsum + bound_c_result * std::fabs(det);
  if (std::fabs(det) > bound) {
    PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::expansion_c);
    return sign_of(det);
  }

  // Exact stage: D = B + (t1 x2 - t3 x4) + (x1 t2 - x3 t4) + (t1 t2 - t3 t4), each bracket
  // an exact four-component expansion; brackets whose tails are zero are skipped.
  PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::expansion_exact);
  std::array<double, 16> buffer_a;
  std::array<double, 16> buffer_b;
  double* sum = buffer_a.data();
  double* spare = buffer_b.data();
  std::copy(b.begin(), b.end(), sum);
  std::size_t n = b.size();
  auto add_bracket = [&](double p, double q, double r, double s) {
    const TwoTerm pq = two_product_split(p, q);
    const TwoTerm rs = two_product_split(r, s);
    const std::array<double, 4> u = two_two_diff(pq.hi, pq.lo, rs.hi, rs.lo);
    n = expansion_sum(std::span<const double>(sum, n), u, std::span<double>(spare, n + u.size()));
    std::swap(sum, spare);
  };
  if (t1 != 0.0 || t3 != 0.0) add_bracket(t1, x2, t3, x4);
  if (t2 != 0.0 || t4 != 0.0) add_bracket(x1, t2, x3, t4);
  if ((t1 != 0.0 && t2 != 0.0) || (t3 != 0.0 && t4 != 0.0)) add_bracket(t1, t2, t3, t4);
  return sign(std::span<const double>(sum, n));
}

// Inputs whose axes spread too far for the fixed-point stage: scaled into the safe range,
// then stages B, C and the exact expansion stage, or GMP if even scaling cannot help.
template <bool SharedOrigin>
[[gnu::noinline]] int cross_sign_wide(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                                      double q2x, double q2y, PredicateKind kind) {
  CrossInput in{p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y};
  if (!fit_into_safe_range(in)) {
    PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::gmp);
    return gmp::cross_sign(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
  }
  return cross_sign_expansion<SharedOrigin>(in, kind);
}

// Everything after stage A; out of line so that the filter stays small enough to inline at
// every call site. The inputs come as scalars (in registers), not as a struct the caller
// would have to store. SharedOrigin: p2 = p1 (orient2d).
template <bool SharedOrigin>
[[gnu::noinline]] int cross_sign_slow(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                                      double q2x, double q2y, PredicateKind kind) {
  const double x1 = q1x - p1x;
  const double x2 = q2y - p2y;
  const double x3 = q1y - p1y;
  const double x4 = q2x - p2x;
  // Exact differences: decide them before any expansion is built. The four tests make one
  // branch (& of ints rather than &&): a single difference is often exact when the others
  // are not, and four branches would each mispredict.
  const int exact = static_cast<int>(expansion::two_diff_tail(q1x, p1x, x1) == 0.0) &
                    static_cast<int>(expansion::two_diff_tail(q2y, p2y, x2) == 0.0) &
                    static_cast<int>(expansion::two_diff_tail(q1y, p1y, x3) == 0.0) &
                    static_cast<int>(expansion::two_diff_tail(q2x, p2x, x4) == 0.0);
  if (exact != 0) {
    const int s = exact_differences_sign(x1, x2, x3, x4);
    if (s != 2) {
      PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::expansion_b);
      return s;
    }
  }
  // Rounded differences: D is almost always exactly zero here (collinear points), which no
  // floating-point stage can prove; go straight to the exact stage, in integers if it fits.
  // Stages B and C would decide only the rare D within a few u S of zero but not at it.
  const int s = fixed_point::cross_sign<SharedOrigin>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
  if (s != 2) {
    PredicateCounters::decide(PredicateMethod::adaptive, kind, PredicateStage::fixed_point);
    return s;
  }
  return cross_sign_wide<SharedOrigin>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, kind);
}

// Stage A: the plain formula (bit for bit the naive double evaluation) accepted when its
// magnitude exceeds the bound (A1)-(A4) of adaptive_bounds.hpp; decides almost every call
// on non-degenerate input.
template <bool SharedOrigin>
inline int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x,
                      double q2y, PredicateKind kind) {
  PredicateCounters::call(PredicateMethod::adaptive, kind);
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
  return cross_sign_slow<SharedOrigin>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, kind);
}

}  // namespace detail

// Sign of (b - a) x (c - a): +1 when a, b, c turn counterclockwise, -1 clockwise, 0 collinear.
inline int orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return detail::cross_sign<true>(ax, ay, bx, by, ax, ay, cx, cy, PredicateKind::orient2d);
}

// Sign of (q1 - p1) x (q2 - p2): +1 when direction q2 - p2 turns left from q1 - p1.
inline int orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y,
                          double q2x, double q2y) {
  return detail::cross_sign<false>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y, PredicateKind::orient_vectors);
}

}  // namespace mk::adaptive
