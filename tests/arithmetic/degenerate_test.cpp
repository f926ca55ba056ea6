// Exactly degenerate inputs (collinear points, parallel vectors, coincident points) and
// extreme magnitudes (subnormals, values near DBL_MAX, mixed): every exact method must
// equal the mpq reference. Each construction is checked to be exact by the reference
// itself before it is used. [Sh97 §4] [MK89 §3.3]
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

#include "tests/arithmetic/predicate_checker.hpp"

namespace {

using mk::test::PredicateChecker;
using mk::test::random_double;
using mk::test::random_short_double;

constexpr double denorm_min = std::numeric_limits<double>::denorm_min();

// collinear_exact: points base + t (p, q) on a line of slope q / p (not a dyadic number in
// general), integers below 2^31, scaled by 2^e from the subnormal range up to near
// overflow. Scaling integers by a power of two is exact, so the points are exactly
// collinear, and so are segments cut from the line and parallel copies of it.
TEST(arith_degenerate, collinear_points_on_integer_lines_at_every_scale) {
  const std::uint64_t seed = 3001;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("collinear_exact");
  std::uniform_int_distribution<long> base(-(1L << 30), 1L << 30);
  std::uniform_int_distribution<long> dir(-1000, 1000);
  std::uniform_int_distribution<long> step(-(1L << 20), 1L << 20);
  for (const int e : {-1074, -1060, -1000, -700, -60, 0, 40, 500, 950, 990}) {
    for (int k = 0; k < 3000; ++k) {
      const long x0 = base(rng), y0 = base(rng);
      long p = dir(rng), q = dir(rng);
      if (p == 0 && q == 0) p = 3;
      auto pt = [&](long t, double& x, double& y) {
        x = std::ldexp(static_cast<double>(x0 + t * p), e);
        y = std::ldexp(static_cast<double>(y0 + t * q), e);
      };
      double ax, ay, bx, by, cx, cy, dx, dy;
      pt(step(rng), ax, ay);
      pt(step(rng), bx, by);
      pt(step(rng), cx, cy);
      pt(step(rng), dx, dy);
      ASSERT_EQ(check.orient2d(ax, ay, bx, by, cx, cy), 0);
      ASSERT_EQ(check.orient_vectors(ax, ay, bx, by, cx, cy, dx, dy), 0);  // collinear segments
      // A parallel segment off the line: (c + w, d + w) for an integer offset w.
      const double wx = std::ldexp(static_cast<double>(base(rng) / 4), e);
      const double wy = std::ldexp(static_cast<double>(base(rng) / 4), e);
      ASSERT_EQ(check.orient_vectors(ax, ay, bx, by, cx + wx, cy + wy, dx + wx, dy + wy), 0);
      // And one step off the line (sideways to it unless the line is horizontal): never zero.
      if (q != 0 && (ax != bx || ay != by)) {
        ASSERT_NE(check.orient2d(ax, ay, bx, by, cx + std::ldexp(1.0, e), cy), 0);
      }
    }
  }
  check.expect_no_disagreement();
}

// collinear_exact with inexact differences: (3x, kx) lies on y = (k/3) x for every x; with
// x of 45 significant bits both coordinates are exact, but differences of points of
// different binades round, so the expansion stages C and exact are exercised.
TEST(arith_degenerate, collinear_points_with_non_representable_slope) {
  const std::uint64_t seed = 3002;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("collinear_slope_k_over_3");
  std::uniform_int_distribution<int> slope(1, 60);
  for (int k = 0; k < 60000; ++k) {
    const double kk = 2 * slope(rng) - 1;  // odd, so k/3 is not dyadic unless k is 3 * odd
    const int e = std::uniform_int_distribution<int>(-1029, 1000)(rng);
    const int spread = std::uniform_int_distribution<int>(0, 60)(rng);
    std::array<double, 4> x{};
    for (double& xi : x) xi = random_short_double(rng, 45, e - spread, e);
    const bool swap = (k % 2) == 1;
    auto px = [&](double t) { return swap ? kk * t : 3 * t; };
    auto py = [&](double t) { return swap ? 3 * t : kk * t; };
    ASSERT_EQ(check.orient2d(px(x[0]), py(x[0]), px(x[1]), py(x[1]), px(x[2]), py(x[2])), 0);
    ASSERT_EQ(check.orient_vectors(px(x[0]), py(x[0]), px(x[1]), py(x[1]), px(x[2]), py(x[2]), px(x[3]),
                                   py(x[3])),
              0);
  }
  check.expect_no_disagreement();
}

// vertex_on_edge: c = a + (b - a) / 2^j lies on segment ab; with 40-bit coordinates of one
// binade every step is exact.
TEST(arith_degenerate, points_on_segments) {
  const std::uint64_t seed = 3003;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("vertex_on_edge");
  for (int k = 0; k < 60000; ++k) {
    const int e = std::uniform_int_distribution<int>(-1000, 1000)(rng);
    const double ax = std::fabs(random_short_double(rng, 40, e, e));
    const double ay = std::fabs(random_short_double(rng, 40, e, e));
    const double bx = std::fabs(random_short_double(rng, 40, e, e));
    const double by = std::fabs(random_short_double(rng, 40, e, e));
    const int j = std::uniform_int_distribution<int>(1, 12)(rng);
    const double cx = ax + std::ldexp(bx - ax, -j);
    const double cy = ay + std::ldexp(by - ay, -j);
    ASSERT_EQ(check.orient2d(ax, ay, bx, by, cx, cy), 0);
    ASSERT_EQ(check.orient2d(cx, cy, ax, ay, bx, by), 0);
    ASSERT_EQ(check.orient_vectors(ax, ay, cx, cy, cx, cy, bx, by), 0);  // two halves of one edge
  }
  check.expect_no_disagreement();
}

// near_collinear at tiny scales: products of differences fall below 2^-1022 and lose
// relative accuracy, which is what the absolute floors of stage A and of the semi-static
// filter are for. A one-ulp move off the line changes D by about 2^(2e - 52), so scales
// 2^-530..2^-500 put D right at the subnormal products' rounding error.
TEST(arith_degenerate, nearly_collinear_points_with_subnormal_products) {
  const std::uint64_t seed = 3006;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("near_collinear_underflow");
  for (int k = 0; k < 100000; ++k) {
    const int e = std::uniform_int_distribution<int>(-530, -500)(rng);
    const int lo = e - 8;
    const double ax = random_double(rng, lo, e), ay = random_double(rng, lo, e);
    const double bx = random_double(rng, lo, e), by = random_double(rng, lo, e);
    const double t = std::uniform_real_distribution<double>(-2.0, 3.0)(rng);
    const double cx = ax + t * (bx - ax);
    const double cy = std::nextafter(ay + t * (by - ay), (k % 2) ? 1.0 : -1.0);
    check.orient2d(ax, ay, bx, by, cx, cy);
    check.orient_vectors(ax, ay, bx, by, cx, cy, cx + (bx - ax), cy + (by - ay));
  }
  check.expect_no_disagreement();
}

// Coincident points and zero, equal and opposite vectors, at extreme magnitudes.
TEST(arith_degenerate, coincident_points_and_zero_vectors) {
  const std::uint64_t seed = 3004;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("coincident");
  std::vector<double> values{0.0, -0.0, denorm_min, -denorm_min, DBL_MIN, 1.0, -1e300, DBL_MAX, -DBL_MAX};
  for (int k = 0; k < 200; ++k) values.push_back(random_double(rng, -1074, 1023));
  auto pick = [&]() { return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng)]; };
  for (int k = 0; k < 20000; ++k) {
    const double ax = pick(), ay = pick(), bx = pick(), by = pick();
    ASSERT_EQ(check.orient2d(ax, ay, ax, ay, bx, by), 0);
    ASSERT_EQ(check.orient2d(ax, ay, bx, by, ax, ay), 0);
    ASSERT_EQ(check.orient2d(ax, ay, bx, by, bx, by), 0);
    ASSERT_EQ(check.orient2d(ax, ay, ax, ay, ax, ay), 0);
    const double cx = pick(), cy = pick();
    ASSERT_EQ(check.orient_vectors(ax, ay, ax, ay, bx, by, cx, cy), 0);  // zero first vector
    ASSERT_EQ(check.orient_vectors(bx, by, cx, cy, ax, ay, ax, ay), 0);  // zero second vector
    ASSERT_EQ(check.orient_vectors(ax, ay, bx, by, ax, ay, bx, by), 0);  // the same vector
    ASSERT_EQ(check.orient_vectors(ax, ay, bx, by, bx, by, ax, ay), 0);  // opposite vectors
  }
  check.expect_no_disagreement();
}

// Every triple over a set of extreme values: subnormals, the normal boundary, 1e+-300,
// values near DBL_MAX whose differences and products overflow.
TEST(arith_degenerate, orient2d_all_triples_of_extreme_values) {
  const std::array<double, 9> v{0.0, denorm_min, -denorm_min, 3e-310, DBL_MIN, -1e-300, 1.0, -1e300, 1.7e308};
  PredicateChecker check("extreme_values_exhaustive");
  for (const double ax : v)
    for (const double ay : v)
      for (const double bx : v)
        for (const double by : v)
          for (const double cx : v)
            for (const double cy : v) check.orient2d(ax, ay, bx, by, cx, cy);
  check.expect_no_disagreement();
}

TEST(arith_degenerate, extreme_values_random_quadruples) {
  const std::uint64_t seed = 3005;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  const std::array<double, 16> v{0.0,    denorm_min, -denorm_min, 3e-310,  -2.5e-320, DBL_MIN, -DBL_MIN, 1e-300,
                                 -1e-150, 0.5,       1.0,         -1e150,  1e300,     1.7e308, -1.7e308, DBL_MAX};
  PredicateChecker check("extreme_values_orient_vectors");
  std::uniform_int_distribution<std::size_t> pick(0, v.size() - 1);
  for (int k = 0; k < 300000; ++k) {
    check.orient_vectors(v[pick(rng)], v[pick(rng)], v[pick(rng)], v[pick(rng)], v[pick(rng)], v[pick(rng)],
                         v[pick(rng)], v[pick(rng)]);
  }
  check.expect_no_disagreement();
}

// collinear_exact near overflow: points on y = x and y = 2x whose differences and products
// overflow, and on y = x / 3-like lines in the subnormal range.
TEST(arith_degenerate, collinear_points_near_overflow_and_underflow) {
  PredicateChecker check("collinear_extreme");
  const std::array<double, 8> big{DBL_MAX, -DBL_MAX, 1.7e308, -1e308, 1e300, -1e300, 0.25 * DBL_MAX, 1.0};
  for (const double a : big)
    for (const double b : big)
      for (const double c : big) {
        ASSERT_EQ(check.orient2d(a, a, b, b, c, c), 0);
        ASSERT_EQ(check.orient2d(a / 2, a, b / 2, b, c / 2, c), 0);
        ASSERT_EQ(check.orient_vectors(a, a, b, b, c, c, a, a), 0);
        check.orient2d(a, a, b, b, c, std::nextafter(c, 0.0));
      }
  const std::array<double, 6> tiny{denorm_min, 3 * denorm_min, -7 * denorm_min, 1e-310, -DBL_MIN, 0.0};
  for (const double a : tiny)
    for (const double b : tiny)
      for (const double c : tiny) {
        ASSERT_EQ(check.orient2d(3 * a, a, 3 * b, b, 3 * c, c), 0);
        check.orient2d(3 * a, a, 3 * b, b, 3 * c, c + denorm_min);
        check.orient2d(a, 1e300, b, -1e300, c, 1.0);  // mixed magnitudes
      }
  check.expect_no_disagreement();
}

}  // namespace
