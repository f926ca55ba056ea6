// The escalating-precision stage of the interval predicates: the cross product of two
// difference vectors evaluated over MPFR numbers of a fixed precision, rounded once when
// the differences are exact at that precision, else in interval arithmetic with every bound
// rounded outward by MPFR's directed rounding. [MK89 §3.3] (interval arithmetic with a
// multiprecision fallback) [MPFR] [BMP06]
// Preconditions: finite double inputs; MPFR's exponent range at least that of its default
// build (products of doubles need exponents in [-2148, 2048]); Bits >= 53, so that every
// double converts exactly; 64-bit GMP limbs.
//
// When the stage decides. A non-zero double is m 2^(e - 52) with 2^52 <= |m| < 2^53 (e
// taken as -1022 for subnormals), so its lowest set bit is worth at least 2^(e - 52). For a
// difference a - b of doubles with exponents e_a >= e_b (or b = 0), every bit lies between
// 2^(e_a + 1) and 2^(e_b - 52): the difference has at most e_a - e_b + 54 significant bits,
// and MPFR computes it exactly at precision p when it has at most p bits, for which
// e_a - e_b <= p - 54 suffices. A product of exact values with s and t significant bits
// has at most s + t bits, so when all four differences are exact, their products are exact
// at 2p bits, and comparing them (mpfr_cmp, exact) gives D's sign, zero included: MPFR's
// exponent range has no underflow or overflow at these magnitudes. (Products rounded to p
// bits would be exact only for s + t <= p, two 64-bit differences at 128 bits, and would
// prove a zero only then; mpfr_fmms, which rounds x1 x2 - x3 x4 once, would serve too, but
// measured slower than two exact products and a comparison.) So:
//  - at 128 bits, every input whose differences have at most 128 bits each is decided,
//    degenerate or not: exponent spreads of at most 74 inside each difference, which covers
//    every input whose non-zero coordinates on each axis lie within a factor 2^74 of each
//    other in magnitude (and every difference that is an exact double);
//  - at 256 bits, every input whose differences have at most 256 bits: spreads up to 202;
//  - beyond, a difference of doubles needs up to 2^10 + 2^10 + 54 (about 2100) bits: the
//    differences are enclosed in intervals rounded outward, multiplied and subtracted in
//    interval arithmetic, and the stage decides when the enclosure excludes zero, which
//    happens for non-degenerate inputs and, when D = 0, only if a product's exact factor is
//    zero (1e-300 next to 1e300 on a line is not decided). Those go on to the exact stage.
// Cost: the doubles become MPFR numbers without a call (mpfr_custom_init_set on their bits),
// so the decided path is four mpfr_sub, two mpfr_mul and one mpfr_cmp, and a call
// allocates nothing.
#pragma once

#include <gmp.h>
#include <mpfr.h>

#include <bit>
#include <cstddef>
#include <cstdint>

namespace mk::mpfr_interval {

static_assert(GMP_NUMB_BITS == 64, "a double's significand is placed in one 64-bit limb");

// An MPFR number of `Bits` bits whose significand lives in the object. Not copyable: the
// mpfr_t points into the object itself.
template <mpfr_prec_t Bits>
class StackFloat {
 public:
  StackFloat() { mpfr_custom_init_set(x_, MPFR_ZERO_KIND, 0, Bits, limbs_); }
  StackFloat(const StackFloat&) = delete;
  StackFloat& operator=(const StackFloat&) = delete;
  mpfr_ptr get() { return x_; }
  mpfr_srcptr get() const { return x_; }

  // Sets the value to the double v (finite), exactly, from its bits. MPFR's significand is
  // in [1/2, 1): a normal v = 1.f 2^(field - 1023) is (1.f / 2) 2^(field - 1022), and a
  // subnormal v = frac 2^-1074 is normalised by its leading zeros.
  void set(double v) {
    static_assert(Bits >= 53);
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const int sign = (bits >> 63) != 0 ? -1 : 1;
    const auto field = static_cast<int>((bits >> 52) & 0x7ff);
    const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
    for (std::size_t i = 0; i + 1 < limb_count; ++i) limbs_[i] = 0;
    if (field == 0 && fraction == 0) {
      mpfr_custom_init_set(x_, sign * MPFR_ZERO_KIND, 0, Bits, limbs_);
      return;
    }
    std::uint64_t top;
    mpfr_exp_t exponent;
    if (field == 0) {
      const int zeros = std::countl_zero(fraction);
      top = fraction << zeros;
      exponent = 64 - zeros - 1074;
    } else {
      top = (fraction | (std::uint64_t{1} << 52)) << 11;
      exponent = field - 1022;
    }
    limbs_[limb_count - 1] = static_cast<mp_limb_t>(top);
    mpfr_custom_init_set(x_, sign * MPFR_REGULAR_KIND, exponent, Bits, limbs_);
  }

 private:
  static constexpr std::size_t limb_count = (Bits + GMP_NUMB_BITS - 1) / GMP_NUMB_BITS;
  mp_limb_t limbs_[limb_count];
  mpfr_t x_;
};

// [lo, hi], both bounds MPFR numbers of `Bits` bits.
template <mpfr_prec_t Bits>
struct Interval {
  StackFloat<Bits> lo, hi;
};

// r = a x b for intervals, each bound a product of one bound of a and one of b chosen by
// the signs (nine cases; when both straddle zero, the extremes of two candidates each way).
template <mpfr_prec_t Bits>
void product(Interval<Bits>& r, const Interval<Bits>& x, const Interval<Bits>& y) {
  auto mul = [](StackFloat<Bits>& out, const StackFloat<Bits>& a, const StackFloat<Bits>& b, mpfr_rnd_t mode) {
    mpfr_mul(out.get(), a.get(), b.get(), mode);
  };
  const int xl = mpfr_sgn(x.lo.get()), xh = mpfr_sgn(x.hi.get());
  const int yl = mpfr_sgn(y.lo.get()), yh = mpfr_sgn(y.hi.get());
  const StackFloat<Bits>*lo_x, *lo_y, *hi_x, *hi_y;
  if (xl >= 0) {  // x >= 0
    if (yl >= 0) {
      lo_x = &x.lo, lo_y = &y.lo, hi_x = &x.hi, hi_y = &y.hi;
    } else if (yh <= 0) {
      lo_x = &x.hi, lo_y = &y.lo, hi_x = &x.lo, hi_y = &y.hi;
    } else {
      lo_x = &x.hi, lo_y = &y.lo, hi_x = &x.hi, hi_y = &y.hi;
    }
  } else if (xh <= 0) {  // x <= 0
    if (yl >= 0) {
      lo_x = &x.lo, lo_y = &y.hi, hi_x = &x.hi, hi_y = &y.lo;
    } else if (yh <= 0) {
      lo_x = &x.hi, lo_y = &y.hi, hi_x = &x.lo, hi_y = &y.lo;
    } else {
      lo_x = &x.lo, lo_y = &y.hi, hi_x = &x.lo, hi_y = &y.lo;
    }
  } else {  // x straddles zero
    if (yl >= 0) {
      lo_x = &x.lo, lo_y = &y.hi, hi_x = &x.hi, hi_y = &y.hi;
    } else if (yh <= 0) {
      lo_x = &x.hi, lo_y = &y.lo, hi_x = &x.lo, hi_y = &y.lo;
    } else {
      StackFloat<Bits> other;
      mul(r.lo, x.lo, y.hi, MPFR_RNDD);
      mul(other, x.hi, y.lo, MPFR_RNDD);
      mpfr_min(r.lo.get(), r.lo.get(), other.get(), MPFR_RNDN);
      mul(r.hi, x.lo, y.lo, MPFR_RNDU);
      mul(other, x.hi, y.hi, MPFR_RNDU);
      mpfr_max(r.hi.get(), r.hi.get(), other.get(), MPFR_RNDN);
      return;
    }
  }
  mul(r.lo, *lo_x, *lo_y, MPFR_RNDD);
  mul(r.hi, *hi_x, *hi_y, MPFR_RNDU);
}

// The sign of (q1 - p1) x (q2 - p2) if an evaluation at `Bits` bits proves it, 2 if not.
template <mpfr_prec_t Bits>
int cross_sign(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x, double q2y) {
  const double minuend[4] = {q1x, q2y, q1y, q2x};
  const double subtrahend[4] = {p1x, p2y, p1y, p2x};
  StackFloat<53> a[4], b[4];
  StackFloat<Bits> x[4];
  bool exact = true;
  for (int i = 0; i < 4; ++i) {
    a[i].set(minuend[i]);
    b[i].set(subtrahend[i]);
    exact = (mpfr_sub(x[i].get(), a[i].get(), b[i].get(), MPFR_RNDN) == 0) && exact;
  }
  if (exact) {  // exact products of at most 2 Bits bits, compared exactly
    StackFloat<2 * Bits> left, right;
    mpfr_mul(left.get(), x[0].get(), x[1].get(), MPFR_RNDN);
    mpfr_mul(right.get(), x[2].get(), x[3].get(), MPFR_RNDN);
    const int c = mpfr_cmp(left.get(), right.get());
    return (c > 0) - (c < 0);
  }
  // Some difference is rounded: enclose each in [down, up] and evaluate D in intervals.
  Interval<Bits> in[4];
  for (int i = 0; i < 4; ++i) {
    mpfr_sub(in[i].lo.get(), a[i].get(), b[i].get(), MPFR_RNDD);
    mpfr_sub(in[i].hi.get(), a[i].get(), b[i].get(), MPFR_RNDU);
  }
  Interval<Bits> left, right;
  product(left, in[0], in[1]);
  product(right, in[2], in[3]);
  // D in [left.lo - right.hi, left.hi - right.lo], each bound rounded outward.
  StackFloat<Bits> lo, hi;
  mpfr_sub(lo.get(), left.lo.get(), right.hi.get(), MPFR_RNDD);
  mpfr_sub(hi.get(), left.hi.get(), right.lo.get(), MPFR_RNDU);
  const int lo_sign = mpfr_sgn(lo.get());
  const int hi_sign = mpfr_sgn(hi.get());
  if (lo_sign > 0) return 1;
  if (hi_sign < 0) return -1;
  if (lo_sign == 0 && hi_sign == 0) return 0;  // [0, 0]: both products had a zero factor
  return 2;
}

}  // namespace mk::mpfr_interval
