// The nearest doubles to a crossing point from exact expansions (arithmetic/crossing_rounding.hpp)
// against the exact rational crossing rounded by MPFR, on random segments of every scale,
// near-parallel ones, crossings at exact ties between two doubles, and inputs of mixed
// magnitudes, where the method must either agree or decline. [Sh97] [MPFR]
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>

#include "arithmetic/crossing_rounding.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace mk {
namespace {

// The reference: the crossing in GMP rationals, rounded by MPFR.
Point reference(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
  const RationalPoint c = RationalKernel::crossing(RationalKernel::point(a0), RationalKernel::point(a1),
                                                   RationalKernel::point(b0), RationalKernel::point(b1));
  return {nearest_double(c.x), nearest_double(c.y)};
}

bool crosses_properly(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
  using R = RationalKernel;
  const auto o = [](const Point& p, const Point& q, const Point& r) {
    return R::orient2d(R::point(p), R::point(q), R::point(r));
  };
  const Sign s1 = o(a0, a1, b0), s2 = o(a0, a1, b1), s3 = o(b0, b1, a0), s4 = o(b0, b1, a1);
  return s1 != Sign::zero && s2 != Sign::zero && s3 != Sign::zero && s4 != Sign::zero && s1 != s2 && s3 != s4;
}

struct Tally {
  int decided = 0;
  int declined = 0;
  int extended = 0;  // decided by the extended-precision stage alone
};

void expect_same(const Point& got, const Point& want, const Point& a0, const Point& a1, const Point& b0,
                 const Point& b1) {
  ASSERT_EQ(std::bit_cast<std::uint64_t>(got.x), std::bit_cast<std::uint64_t>(want.x))
      << std::hexfloat << "a0 (" << a0.x << " " << a0.y << ") a1 (" << a1.x << " " << a1.y << ") b0 (" << b0.x
      << " " << b0.y << ") b1 (" << b1.x << " " << b1.y << "): " << got.x << " vs " << want.x;
  ASSERT_EQ(std::bit_cast<std::uint64_t>(got.y), std::bit_cast<std::uint64_t>(want.y))
      << std::hexfloat << "a0 (" << a0.x << " " << a0.y << ") a1 (" << a1.x << " " << a1.y << ") b0 (" << b0.x
      << " " << b0.y << ") b1 (" << b1.x << " " << b1.y << "): " << got.y << " vs " << want.y;
}

// Every stage against the reference: the extended-precision stage alone (when it decides),
// the later stages with tails (nearest_crossing with tails skips the first), and
// nearest_crossing without tails (all three in turn).
void check(const Point& a0, const Point& a1, const Point& b0, const Point& b1, Tally& t) {
  if (!crosses_properly(a0, a1, b0, b1)) return;
  const Point reference_point = reference(a0, a1, b0, b1);
  if (Point fast; crossing_rounding::nearest_crossing_extended(a0, a1, b0, b1, fast)) {
    ++t.extended;
    expect_same(fast, reference_point, a0, a1, b0, b1);
  }
  if (Point plain; nearest_crossing(a0, a1, b0, b1, plain)) expect_same(plain, reference_point, a0, a1, b0, b1);
  Point got, tail;
  double tail_err = 0;
  if (!nearest_crossing(a0, a1, b0, b1, got, &tail, &tail_err)) {
    ++t.declined;
    return;
  }
  ++t.decided;
  const Point want = reference(a0, a1, b0, b1);
  // The tails: within the stated bound of the exact remainder, and the bound below half an
  // ulp of the coordinate (else the tail says nothing).
  const RationalPoint exact = RationalKernel::crossing(RationalKernel::point(a0), RationalKernel::point(a1),
                                                       RationalKernel::point(b0), RationalKernel::point(b1));
  const mpq_class rx = exact.x - mpq_class(want.x), ry = exact.y - mpq_class(want.y);
  ASSERT_TRUE(std::isfinite(tail_err) && std::isfinite(tail.x) && std::isfinite(tail.y));
  EXPECT_LE(abs(mpq_class(tail.x) - rx), mpq_class(tail_err));
  EXPECT_LE(abs(mpq_class(tail.y) - ry), mpq_class(tail_err));
  const double scale = std::max({std::fabs(want.x), std::fabs(want.y), 0x1p-1000});
  EXPECT_LE(tail_err, scale * 0x1p-54 + 0x1p-1070) << std::hexfloat << tail_err << " at " << scale;
  expect_same(got, want, a0, a1, b0, b1);
}

// Random crossing segments at every scale 2^-1000 .. 2^1000 (all four points of one case
// share a magnitude): the method must decide every one of them, and agree; the floating-
// point filter decides almost all of them.
TEST(CrossingRounding, RandomSegmentsAtEveryScaleAgreeWithRationals) {
  std::mt19937_64 rng(20261124);
  std::printf("seed 20261124\n");
  crossing_rounding::counts = {};
  Tally t;
  for (int e = -1000; e <= 1000; e += 20) {
    for (int i = 0; i < 200; ++i) {
      const auto r = [&] { return test::random_double(rng, e - 3, e); };
      check({r(), r()}, {r(), r()}, {r(), r()}, {r(), r()}, t);
    }
  }
  EXPECT_GT(t.decided, 3000);  // about one random pair in five crosses
  EXPECT_EQ(t.declined, 0);
  const auto& n = crossing_rounding::counts;
  std::printf("extended %d of %d; with tails: filter %llu, exact %llu\n", t.extended, t.decided,
              static_cast<unsigned long long>(n.filter), static_cast<unsigned long long>(n.exact));
  EXPECT_GE(n.filter, 99 * (n.filter + n.exact) / 100);
#if defined(__x86_64__) || defined(__i386__)
  // x87's long double: the first stage is there and decides most random crossings (about 9
  // in 10: cancellation in D and in a0 + t da spends much of its 11 extra bits on these).
  EXPECT_TRUE(crossing_rounding::extended_precision_available());
  EXPECT_GE(t.extended, 85 * t.decided / 100);
#endif
}

// Crossings a fraction 2^-k of a gap off the midpoint between two doubles (k = 1 .. 80), at
// many scales and on both sides of zero, from a segment whose x steps by one ulp over a
// height of 2 and a horizontal segment at height 2^-k: the extended-precision stage decides
// the ones clear of the midpoint and declines the rest, never wrongly; every stage agrees.
TEST(CrossingRounding, NearMidpointsTheExtendedStageDecidesRightOrDeclines) {
  Tally t;
  int near_decided = 0, far_declined = 0;
  for (int e = -900; e <= 900; e += 37) {
    for (const double sign : {1.0, -1.0}) {
      for (int k = 1; k <= 80; ++k) {
        const double base = sign * std::ldexp(1.0 + (k % 7) * 0x1p-52, e);
        const double next = std::nextafter(base, sign * HUGE_VAL);
        const double h = std::ldexp(1.0, e);
        const double off = std::ldexp(h, -k);
        const Point a0{base, -h}, a1{next, h}, b0{-4 * h * sign, off}, b1{4 * h * sign, off};
        Point fast;
        const bool decided = crossing_rounding::nearest_crossing_extended(a0, a1, b0, b1, fast);
        near_decided += decided && k >= 12;
        far_declined += !decided && k <= 4;
        check(a0, a1, b0, b1, t);
      }
    }
  }
  std::printf("near midpoints: %d decided by the extended stage of %d\n", t.extended, t.decided);
  EXPECT_EQ(t.declined, 0);
  EXPECT_GT(t.extended, 0);
  EXPECT_EQ(far_declined, 0);  // a quarter gap off the midpoint and more: always decided
  EXPECT_EQ(near_decided, 0);  // 2^-12 of a gap and less: beyond its precision, never guessed
}

// Nearly parallel segments (the parameter t is ill-conditioned) and crossings close to an
// endpoint: still exact.
TEST(CrossingRounding, NearlyParallelAndNearEndpointCrossings) {
  std::mt19937_64 rng(11);
  Tally t;
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    const Point a0{u(rng), u(rng)};
    const Point a1{u(rng) + 3, u(rng)};
    const double eps = std::ldexp(1.0, -static_cast<int>(rng() % 50));
    // b runs along a, tilted by eps, through a point of a
    const double s = u(rng) * 0.5 + 0.5;
    const Point on{a0.x + s * (a1.x - a0.x), a0.y + s * (a1.y - a0.y)};
    const Point b0{on.x - 1, on.y - (a1.y - a0.y) / (a1.x - a0.x) - eps};
    const Point b1{on.x + 1, on.y + (a1.y - a0.y) / (a1.x - a0.x) + eps};
    check(a0, a1, b0, b1, t);
  }
  EXPECT_GT(t.decided, 15000);
  EXPECT_EQ(t.declined, 0);
}

// Crossings exactly halfway between two doubles, built from a segment whose x steps by one
// ulp over a height of 2 and a horizontal segment through its middle: ties go to the even
// neighbour, at every scale and on both sides of zero.
TEST(CrossingRounding, ExactTiesGoToEven) {
  Tally t;
  for (int e = -300; e <= 300; e += 7) {
    for (const double sign : {1.0, -1.0}) {
      for (int k = 0; k < 6; ++k) {
        const double base = sign * std::ldexp(1.0 + k * 0x1p-52, e);
        const double next = std::nextafter(base, sign * HUGE_VAL);
        const double h = std::ldexp(1.0, e);
        const Point a0{base, -h}, a1{next, h}, b0{-4 * h * sign, 0}, b1{4 * h * sign, 0};
        const auto exact_before = crossing_rounding::counts.exact;
        const int extended_before = t.extended;
        check(a0, a1, b0, b1, t);
        // A tie is never left to either filter: only exact arithmetic can tell it (check asks
        // twice: with tails and without).
        EXPECT_EQ(t.extended, extended_before);
        EXPECT_EQ(crossing_rounding::counts.exact, exact_before + 2);
        Point got;
        ASSERT_TRUE(nearest_crossing(a0, a1, b0, b1, got));
        const double even = (std::bit_cast<std::uint64_t>(base) & 1) == 0 ? base : next;
        EXPECT_EQ(got.x, even) << std::hexfloat << base;
        EXPECT_EQ(got.y, 0.0);
      }
    }
  }
  EXPECT_EQ(t.declined, 0);
}

// Inputs whose magnitudes differ by up to 2^900, crossing points near zero, and crossings in
// the subnormal range: whatever the method decides must be right; it may decline.
TEST(CrossingRounding, MixedMagnitudesDecideRightOrDecline) {
  std::mt19937_64 rng(5);
  Tally t;
  for (int i = 0; i < 20000; ++i) {
    const int e1 = static_cast<int>(rng() % 2000) - 1000;
    const int e2 = e1 - static_cast<int>(rng() % 900);
    const auto big = [&] { return test::random_double(rng, e1 - 2, e1); };
    const auto small = [&] { return test::random_double(rng, e2 - 2, e2); };
    check({big(), small()}, {-big(), small()}, {small(), big()}, {small(), -big()}, t);
  }
  for (int i = 0; i < 2000; ++i) {  // crossing exactly in the subnormal range
    const double tiny = std::ldexp(static_cast<double>(rng() % 1000 + 1), -1074);
    check({-1, tiny}, {1, tiny}, {tiny, -1}, {tiny, 1}, t);
  }
  std::printf("mixed magnitudes: %d decided, %d declined\n", t.decided, t.declined);
  EXPECT_GT(t.decided, 1000);
}

}  // namespace
}  // namespace mk
