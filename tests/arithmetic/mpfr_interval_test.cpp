// The MPFR stages of the interval predicates on their own: they never give a wrong sign,
// and they decide every input, exactly degenerate ones included, whose four differences
// are exact at their precision, as mpfr_interval.hpp derives (a difference of doubles has
// at most e_a - e_b + 54 significant bits). [MPFR] [MK89 §3.3]
#include "arithmetic/mpfr_interval.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>

#include "arithmetic/exact_reference.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace {

using mk::mpfr_interval::cross_sign;
using mk::test::hex;
using mk::test::random_short_double;

// Significant bits of the exact difference a - b of two doubles (0 when a = b).
std::size_t difference_bits(double a, double b) {
  const mpq_class d = mpq_class(a) - mpq_class(b);  // a dyadic rational, canonical
  if (d == 0) return 0;
  const mpz_class& n = d.get_num();
  return mpz_sizeinbase(n.get_mpz_t(), 2) - mpz_scan1(n.get_mpz_t(), 0);
}

TEST(arith_mpfr_interval, difference_bits_follow_the_exponent_spread) {
  // 2^10 + (1 + 2^-52): bits from 2^10 down to 2^-52, 63 of them (e_a - e_b + 53 here; the
  // bound's extra bit is a carry, as in 2^10 + (2 - 2^-52)).
  EXPECT_EQ(difference_bits(1.0, 1.0), 0u);
  EXPECT_EQ(difference_bits(std::ldexp(1.0, 10), std::ldexp(-(1.0 + 0x1p-52), 0)), 63u);
  EXPECT_LE(difference_bits(1e300, -1e-300), 2048u + 54u);
  EXPECT_GT(difference_bits(1e300, -1e-300), 1900u);
}

// Three points on y = (k/3) x, at coordinates of 45 bits whose exponents spread over
// `spread` binades: orient2d is exactly zero, and the differences have rounded doubles.
struct Collinear {
  double ax, ay, bx, by, cx, cy;
};
Collinear collinear(std::mt19937_64& rng, int spread) {
  const double k = 2 * std::uniform_int_distribution<int>(1, 60)(rng) - 1;
  auto point = [&](double& x, double& y) {
    const double t = random_short_double(rng, 45, -spread / 2, spread - spread / 2);
    x = 3 * t;
    y = k * t;
  };
  Collinear c{};
  point(c.ax, c.ay);
  point(c.bx, c.by);
  point(c.cx, c.cy);
  return c;
}

template <mpfr_prec_t Bits>
void check_exactly_degenerate(int spread, std::size_t& expected_to_decide, std::size_t& decided_beyond) {
  std::mt19937_64 rng(6100 + static_cast<std::uint64_t>(spread));
  for (int i = 0; i < 2000; ++i) {
    const Collinear c = collinear(rng, spread);
    ASSERT_EQ(mk::reference::orient2d(c.ax, c.ay, c.bx, c.by, c.cx, c.cy), 0);
    // orient2d(a, b, c) = (b - a) x (c - a): the differences bx - ax, cy - ay, by - ay, cx - ax.
    const std::size_t widest = std::max({difference_bits(c.bx, c.ax), difference_bits(c.cy, c.ay),
                                         difference_bits(c.by, c.ay), difference_bits(c.cx, c.ax)});
    const int got = cross_sign<Bits>(c.ax, c.ay, c.bx, c.by, c.ax, c.ay, c.cx, c.cy);
    ASSERT_TRUE(got == 0 || got == 2) << Bits << " bits gave " << got << " on a zero: " << hex(c.ax) << " "
                                      << hex(c.ay) << " " << hex(c.bx) << " " << hex(c.by) << " " << hex(c.cx)
                                      << " " << hex(c.cy);
    if (widest <= Bits) {
      ++expected_to_decide;
      ASSERT_EQ(got, 0) << Bits << " bits, differences of up to " << widest << " bits: " << hex(c.ax)
                        << " " << hex(c.ay) << " " << hex(c.bx) << " " << hex(c.by) << " " << hex(c.cx) << " "
                        << hex(c.cy);
    } else if (got == 0) {
      ++decided_beyond;  // allowed only with a zero difference (see mpfr_interval.hpp)
    }
  }
}

TEST(arith_mpfr_interval, decides_every_zero_whose_differences_fit_its_precision) {
  std::cout << "seeds 6100 + spread\n";
  for (const int spread : {0, 40, 70, 100, 150, 250}) {
    std::size_t expected128 = 0, beyond128 = 0, expected256 = 0, beyond256 = 0;
    check_exactly_degenerate<128>(spread, expected128, beyond128);
    check_exactly_degenerate<256>(spread, expected256, beyond256);
    std::cout << "spread " << spread << ": within the bound at 128 bits " << expected128 << " of 2000 (" << beyond128
              << " more decided), at 256 bits " << expected256 << " (" << beyond256 << " more decided)\n";
    // The bound is met often enough to make the check meaningful at small spreads.
    // Coordinates of 45 bits within 2^spread: every difference within the bound up to
    // spread 128 - 47 at 128 bits and 256 - 47 at 256 bits (the factors 3 and k add up to
    // two binades); beyond, some are not, and then nothing decides them but GMP.
    if (spread <= 70) {
      EXPECT_EQ(expected128, 2000u);
    }
    if (spread <= 150) {
      EXPECT_EQ(expected256, 2000u);
    }
    if (spread >= 150) {
      EXPECT_LT(expected128 + beyond128, 2000u);
    }
  }
}

TEST(arith_mpfr_interval, exact_integer_differences_are_decided_at_128_bits) {
  // Collinear integer points: every difference is an exact double of at most 53 bits.
  std::mt19937_64 rng(6200);
  std::uniform_int_distribution<std::int64_t> base(-(std::int64_t{1} << 40), std::int64_t{1} << 40);
  std::uniform_int_distribution<std::int64_t> step(-1000, 1000);
  for (int i = 0; i < 2000; ++i) {
    const auto x0 = static_cast<double>(base(rng)), y0 = static_cast<double>(base(rng));
    const auto p = static_cast<double>(step(rng)), q = static_cast<double>(step(rng));
    const double s = static_cast<double>(step(rng)), t = static_cast<double>(step(rng));
    EXPECT_EQ(cross_sign<128>(x0, y0, x0 + s * p, y0 + s * q, x0, y0, x0 + t * p, y0 + t * q), 0);
  }
}

TEST(arith_mpfr_interval, wide_spreads_are_left_to_the_exact_stage) {
  // 1e300 - 1e-300 needs about 2050 bits: neither precision can prove the zero.
  EXPECT_EQ(cross_sign<128>(1e-300, 1e-300, 1e300, 1e300, 1e-300, 1e-300, -1e300, -1e300), 2);
  EXPECT_EQ(cross_sign<256>(1e-300, 1e-300, 1e300, 1e300, 1e-300, 1e-300, -1e300, -1e300), 2);
  // But a sign far from zero is decided whatever the spread.
  EXPECT_EQ(cross_sign<128>(1e-300, 1e-300, 1e300, 1e300, 1e-300, 1e-300, -1e300, 1e300), 1);
}

TEST(arith_mpfr_interval, tiny_signs_from_exact_differences) {
  // x1 x2 - x3 x4 with x1 = 1 + 2^-52, x2 = 1 - 2^-52 (product 1 - 2^-104), x3 = x4 = 1:
  // D = -2^-104, invisible in doubles, exact for fmms at 128 bits.
  const double u = 0x1p-52;
  EXPECT_EQ(mk::reference::orient_vectors(0, 0, 1 + u, 1, 0, 0, 1, 1 - u), -1);
  EXPECT_EQ(cross_sign<128>(0, 0, 1 + u, 1, 0, 0, 1, 1 - u), -1);
  EXPECT_EQ(cross_sign<256>(0, 0, 1 + u, 1, 0, 0, 1, 1 - u), -1);
}

TEST(arith_mpfr_interval, subnormal_and_huge_inputs_convert_exactly) {
  // Differences of subnormals are exact; D = 2^-1074 * 2^-1074 * (1 * 3 - 1 * 2) > 0.
  const double s = 0x1p-1074;
  EXPECT_EQ(cross_sign<128>(0, 0, s, s, 0, 0, 2 * s, 3 * s), 1);
  EXPECT_EQ(cross_sign<128>(0, 0, s, s, 0, 0, 3 * s, 3 * s), 0);
  EXPECT_EQ(cross_sign<128>(0, 0, 3 * s, 2 * s, 0, 0, 3 * s, 3 * s), 1);
  // Near the top of the range: differences overflow doubles but not MPFR.
  const double big = 0x1.fffffffffffffp1023;
  EXPECT_EQ(cross_sign<128>(-big, -big, big, big, -big, big, big, -big), -1);
  EXPECT_EQ(cross_sign<128>(-big, -big, big, big, -big, -big, big, big), 0);
  // Negative zero is zero.
  EXPECT_EQ(cross_sign<128>(-0.0, 0.0, 1, 0, 0.0, -0.0, 0, 1), 1);
}

}  // namespace
