// Error bounds of the staged adaptive predicates (stages A, B, C) and the input range in
// which the expansion stages are exact, each constant with its derivation. [Sh97 §4.2-4.3]
// Preconditions: IEEE 754 binary64, round-to-nearest-even, gradual underflow (no FTZ/DAZ),
// every operation rounded on its own (-ffp-contract=off, set by mkbool_arith).
// tests/arithmetic/bounds_test.cpp re-derives every constant and checks each inequality
// below in exact rational arithmetic.
//
// ---- The shape -----------------------------------------------------------------------
// Both predicates are the sign of D = X1 X2 - X3 X4, where each X_k = a_k - b_k is an exact
// difference of two input doubles (arithmetic/formulas.hpp, cross_of_differences):
//   X1 = q1x - p1x, X2 = q2y - p2y, X3 = q1y - p1y, X4 = q2x - p2x;
// orient2d(a, b, c) is the case p1 = p2 = a, q1 = b, q2 = c. The program computes
//   x_k = fl(X_k), t_k = X_k - x_k (exact tail), l = fl(x1 x2), r = fl(x3 x4),
//   det = fl(l - r), S = |l| + |r|, s = fl(S).
//
// ---- Facts used (u = 2^-53, eta = 2^-1075, half the smallest subnormal) --------------
//  F1  A rounded result z' = fl(z) that is normal: |z' - z| <= u |z'| and |z' - z| <= u |z|.
//  F2  fl(a + b), fl(a - b) of doubles obey F1 even below 2^-1022 (such sums are exact), and
//      fl(a - b) = 0 only if a = b: the sign of a difference is never lost.
//  F3  fl(a * b) = a b + f with |f| <= u |fl(a b)| + eta (eta only when the result underflows).
//  F4  |t_k| <= u |x_k| (F1 with F2).
#pragma once

namespace mk::adaptive {

// Unit roundoff of binary64 with rounding to nearest: half an ulp of 1.
inline constexpr double epsilon = 0x1p-53;

// ---- Stage A: valid for every finite input -------------------------------------------
// X1 X2 - x1 x2 = x1 t2 + t1 x2 + t1 t2, so |X1 X2 - x1 x2| <= (2u + u^2)|x1 x2| (F4).
// By F3, |x1 x2| <= (1 + u)|l| + eta and |x1 x2 - l| <= u |l| + eta. Hence
//   |X1 X2 - l| <= theta |l| + (1 + u)^2 eta,   theta = 3u + 3u^2 + u^3,
// the same for X3 X4 and r, and with F2 for the last subtraction:
//   |D - det| <= u |det| + theta S + 2 (1 + u)^2 eta.                              (A1)
// The sign of det is the sign of D once |D - det| < |det|, i.e. once
//   (1 - u)|det| > theta S + 2 (1 + u)^2 eta.                                       (A2)
// The program accepts when |det| > e = fl(fl(bound_a * s) + bound_a_floor). By F2, F3:
// s >= S / (1 + u), fl(bound_a * s) >= bound_a s / (1 + u) - eta, e >= (that + floor)/(1 + u).
// So |det| > e implies (A2) when
//   bound_a (1 - u) / (1 + u)^3 >= theta                                            (A3)
//   (bound_a_floor - eta)(1 - u) / (1 + u) >= 2 (1 + u)^2 eta.                     (A4)
// (A3): (3u + 16u^2)(1 - u) = 3u + 13u^2 - 16u^3 against (3u + 3u^2 + u^3)(1 + u)^3
// = 3u + 12u^2 + O(u^3): true with u^2 to spare. This is Shewchuk's ccwerrboundA.
// (A4) holds for any floor above a few eta; the floor is what makes stage A valid below
// 2^-1022, where products lose relative accuracy. Overflow needs no test: an infinite
// difference or product makes s infinite or NaN, and then |det| > e is false.
inline constexpr double bound_a = (3.0 + 16.0 * epsilon) * epsilon;
inline constexpr double bound_a_floor = 0x1p-1022;

// ---- The range of the expansion stages -----------------------------------------------
// Stages B, C and the exact stage assume that no operation underflows or overflows. That
// holds when every input coordinate v is 0 or safe_min <= |v| <= safe_max:
//  - such a v is a multiple of 2^-452 (its ulp is at least 2^(-400-52)); so are the
//    differences x_k and their tails t_k;
//  - every product of two of them is a multiple of 2^-904, and so is every sum, every
//    two_product error term and every rounded result built from them (rounding a multiple
//    of a power of two g >= 2^-1074 gives a multiple of g). Every non-zero intermediate is
//    therefore at least 2^-904 in magnitude: normal, F1 holds, error terms are exact;
//  - the bound products bound_b * s, bound_c * s, bound_c_result * |det| are at least
//    2^-904 * 2^-103 when non-zero: normal too;
//  - |x_k| <= 2^501, products <= 2^1003, and the 16 components of the exact stage sum to
//    at most 2^1008 in absolute value: no overflow.
// The products are Dekker's (expansion.hpp, two_product_split), whose preconditions follow:
// every factor is an x_k or t_k, a multiple of 2^-452 (so of 2^-511) of magnitude at most
// 2^501 <= 2^996, and every product is at most 2^1003 <= 2^1021.
// Inputs outside the range are scaled by a power of two into it when their magnitudes span
// less than safe_max / safe_min (scaling by 2^k is exact for normal results and keeps the
// sign), else decided with GMP.
inline constexpr double safe_min = 0x1p-400;
inline constexpr double safe_max = 0x1p500;

// ---- Stage B: the exact determinant of the rounded differences -----------------------
// B = x1 x2 - x3 x4 = (l + l') - (r + r') exactly, as four components b0..b3 from
// two_two_diff (expansion.hpp); det_B = fl(((b0 + b1) + b2) + b3). Within the safe range:
//  - D - B = x1 t2 + t1 x2 + t1 t2 - (x3 t4 + t3 x4 + t3 t4), so
//    |D - B| <= (2u + u^2)(|x1 x2| + |x3 x4|) <= (2u + 3u^2 + u^3) S   (|x1 x2| <= (1+u)|l|);
//  - the components of two_two_diff obey |b0| <= u^2 (1 + u) S, |b1| <= u S (1 + 2u + 3u^2),
//    |b2| <= u |b3|; the three roundings of the estimate then give
//    |B - det_B| <= (u + u^2 + 3u^3)|det_B| + (2u^2 + 9u^3) S.
// Together, with cubic terms rounded up generously:
//   |D - det_B| <= (u + u^2 + 4u^3)|det_B| + (2u + 5u^2 + 16u^3) S.                 (B1)
// The program accepts when |det_B| > fl(bound_b * s) >= bound_b S / (1 + u)^2, which
// implies |det_B| > |D - det_B| when
//   bound_b (1 - u - u^2 - 4u^3) / (1 + u)^2 >= 2u + 5u^2 + 16u^3.                  (B2)
// bound_b = (2 + 12u)u gives 2u + 6u^2 + O(u^3) on the left: true with u^2 to spare. This
// is Shewchuk's ccwerrboundB. If every tail t_k is zero, B = D and its sign is final.
inline constexpr double bound_b = (2.0 + 12.0 * epsilon) * epsilon;

// ---- Stage C: first-order tail correction --------------------------------------------
// D = B + K + Q with K = x1 t2 + t1 x2 - x3 t4 - t3 x4 (first order) and
// Q = t1 t2 - t3 t4 (second order, |Q| <= u^2 (1 + u) S). The program computes
// K' = fl(fl(fl(x1 t2) + fl(t1 x2)) - fl(fl(x3 t4) + fl(t3 x4))) and det_C = fl(det_B + K').
//  - the terms of K sum in absolute value to at most 2u (1 + u) S, and each passes three
//    roundings: |K - K'| <= ((1 + u)^3 - 1) 2u (1 + u) S <= (6u^2 + 12u^3) S;
//  - |det_B| <= (1 + u)|det_C| + |K'| with |K'| <= 2u (1 + u)^4 S, so (B1)'s estimate term
//    becomes |B - det_B| <= (u + 2u^2 + 5u^3)|det_C| + (4u^2 + 19u^3) S;
//  - the last rounding adds u |det_C|.
// Together:  |D - det_C| <= (2u + 2u^2 + 5u^3)|det_C| + (11u^2 + 33u^3) S.         (C1)
// The program accepts when |det_C| > e = fl(fl(bound_c * s) + fl(bound_c_result * |det_C|)),
// and e >= bound_c S / (1 + u)^3 + bound_c_result |det_C| / (1 + u)^2 bounds (C1) when
//   bound_c / (1 + u)^3 >= 11u^2 + 40u^3,                                           (C2)
//   bound_c_result / (1 + u)^2 >= 2u + 2u^2 + 8u^3.                                 (C3)
// Shewchuk's stage C uses (9 + 64u)u^2 and (3 + 8u)u; our accounting of the estimate
// (the 2u^2 S of stage B carried into C) is coarser, so the S coefficient here is 12u^2.
// The difference only moves a few near-degenerate inputs on to the exact stage.
inline constexpr double bound_c = (12.0 + 64.0 * epsilon) * epsilon * epsilon;
inline constexpr double bound_c_result = (3.0 + 8.0 * epsilon) * epsilon;

}  // namespace mk::adaptive
