// Correct rounding of rationals to doubles (arithmetic/nearest_double.hpp) against an
// independent exact computation: the two neighbouring doubles of a value are built from the
// bit pattern, the midpoint between them is exact in GMP, and the expected double follows
// from comparing the value with that midpoint and, at a tie, from the parity of the last
// significand bit read off the bit pattern. [MPFR] [IEEE754 §4.3.1]
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/nearest_double.hpp"

namespace mk {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

bool is_even(double d) { return (std::bit_cast<std::uint64_t>(d) & 1u) == 0; }

// The next double above a positive finite d, from the bit pattern (not nextafter).
double up(double d) { return std::bit_cast<double>(std::bit_cast<std::uint64_t>(d) + 1); }

mpq_class q(double d) { return mpq_class(d); }
mpq_class midpoint(double lo, double hi) { return (q(lo) + q(hi)) / 2; }

// For consecutive positive doubles lo < hi: the tie, just below it and just above it, and
// the negated values.
void expect_rounding_between(double lo, double hi) {
  ASSERT_LT(lo, hi);
  const mpq_class m = midpoint(lo, hi);
  const mpq_class eps = (q(hi) - q(lo)) / 1024;
  const double tie = is_even(lo) ? lo : hi;
  EXPECT_EQ(nearest_double(m), tie) << lo;
  EXPECT_EQ(nearest_double(m - eps), lo) << lo;
  EXPECT_EQ(nearest_double(m + eps), hi) << lo;
  EXPECT_EQ(nearest_double(-m), -tie) << lo;
  EXPECT_EQ(nearest_double(-(m - eps)), -lo) << lo;
  EXPECT_EQ(nearest_double(-(m + eps)), -hi) << lo;
  EXPECT_EQ(nearest_double(q(lo)), lo);
  EXPECT_EQ(nearest_double(q(hi)), hi);
}

TEST(NearestDouble, ExactDoublesAndZero) {
  EXPECT_EQ(nearest_double(0), 0.0);
  EXPECT_FALSE(std::signbit(nearest_double(0)));
  for (const double d : {1.0, -1.0, 0.1, kMax, -kMax, kTiny, -kTiny, 1e-300, 3.0 * kTiny}) {
    EXPECT_EQ(nearest_double(q(d)), d);
  }
}

// Around every power of two from the smallest subnormal to 2^1023: the neighbours below (at
// half the spacing, except in the subnormal range) and above.
TEST(NearestDouble, TiesAndNeighboursAroundEveryPowerOfTwo) {
  for (int e = -1074; e <= 1023; ++e) {
    const double p = std::ldexp(1.0, e);
    if (e > -1074) {
      const double below = std::bit_cast<double>(std::bit_cast<std::uint64_t>(p) - 1);
      expect_rounding_between(below, p);
    }
    if (e < 1023 || p < kMax) expect_rounding_between(p, up(p));
  }
}

// The subnormal range, where the last significand bit is not frexp's: 3 * 2^-1074 is odd,
// so the tie between it and 4 * 2^-1074 goes up, and the tie between 2 and 3 goes down.
TEST(NearestDouble, SubnormalTiesGoToEven) {
  const mpq_class t = q(kTiny);
  EXPECT_EQ(nearest_double(t * 7 / 2), 4 * kTiny);
  EXPECT_EQ(nearest_double(t * 5 / 2), 2 * kTiny);
  EXPECT_EQ(nearest_double(t / 2), 0.0);           // a tie between 0 and 2^-1074: 0 is even
  EXPECT_EQ(nearest_double(t * 3 / 4), kTiny);     // above the tie
  EXPECT_EQ(nearest_double(t / 4), 0.0);
  EXPECT_EQ(nearest_double(-t / 4), 0.0);
  EXPECT_TRUE(std::signbit(nearest_double(-t / 4)));  // rounds to -0, as IEEE 754 does
  std::mt19937_64 rng(20261124);
  for (int i = 0; i < 20000; ++i) {
    const std::uint64_t bits = rng() % (std::uint64_t{1} << 53);  // up to the second binade
    const double lo = std::bit_cast<double>(bits);
    expect_rounding_between(lo, up(lo));
  }
}

// Random doubles of every magnitude: random points between each and its upper neighbour.
TEST(NearestDouble, RandomValuesBetweenNeighbours) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> pattern(1, std::bit_cast<std::uint64_t>(kMax) - 1);
  for (int i = 0; i < 20000; ++i) {
    const double lo = std::bit_cast<double>(pattern(rng));
    const double hi = up(lo);
    const mpq_class width = q(hi) - q(lo);
    const mpq_class frac(static_cast<unsigned long>(rng() % 1000 + 1), 1001u);  // in (0, 1)
    const mpq_class v = q(lo) + width * frac;
    const double expected = frac * 2 < 1 ? lo : (frac * 2 > 1 ? hi : (is_even(lo) ? lo : hi));
    ASSERT_EQ(nearest_double(v), expected) << lo << " + " << frac.get_str() << " ulp";
  }
}

// Beyond the largest double: the tie DBL_MAX + ulp/2 and everything above round to
// infinity, just below it to DBL_MAX; never a crash (issue 10: the old conversion trapped).
TEST(NearestDouble, OverflowRoundsToInfinity) {
  const mpq_class half_ulp = q(std::ldexp(1.0, 970));  // ulp(DBL_MAX) = 2^971
  EXPECT_EQ(nearest_double(q(kMax) + half_ulp), kInf);
  EXPECT_EQ(nearest_double(q(kMax) + half_ulp - 1), kMax);
  EXPECT_EQ(nearest_double(-(q(kMax) + half_ulp)), -kInf);
  mpq_class huge = q(kMax);
  huge *= huge;  // about 3.2e616
  EXPECT_EQ(nearest_double(huge), kInf);
  EXPECT_EQ(nearest_double(-huge), -kInf);
  EXPECT_EQ(RationalKernel::to_nearest(huge), kInf);
  EXPECT_EQ(nearest_double(1 / huge), 0.0);
}

// The conversion leaves MPFR's exponent range as it found it.
TEST(NearestDouble, RestoresTheExponentRange) {
  const mpfr_exp_t emin = mpfr_get_emin();
  const mpfr_exp_t emax = mpfr_get_emax();
  (void)nearest_double(mpq_class(1, 3));
  EXPECT_EQ(mpfr_get_emin(), emin);
  EXPECT_EQ(mpfr_get_emax(), emax);
}

}  // namespace
}  // namespace mk
