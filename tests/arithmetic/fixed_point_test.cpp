// The fixed-point exact stage of adaptive.hpp (integers on a per-axis grid) called directly,
// on any input, against the mpq reference: it must be exact wherever it accepts, accept
// exactly its documented range (each axis within 2^69 of its largest magnitude, largest at
// least 2^-902, zeros anywhere), and, reached through adaptive::orient2d, decide collinear
// points with rounded differences at spreads around that limit. Also the expansion path
// called directly on every kind of input, since the predicate itself now sends it only the
// inputs the fixed-point stage refuses. [Sh97 §4.3]
#include <gtest/gtest.h>

#include <array>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <limits>
#include <random>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_reference.hpp"
#include "tests/arithmetic/predicate_checker.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace {

using mk::test::hex;
using mk::test::PredicateChecker;
using mk::test::random_double;
using mk::test::random_short_double;
namespace fixed = mk::adaptive::detail::fixed_point;

int fixed_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return fixed::cross_sign<true>(ax, ay, bx, by, ax, ay, cx, cy);
}
int fixed_orient_vectors(double p1x, double p1y, double q1x, double q1y, double p2x, double p2y, double q2x,
                         double q2y) {
  return fixed::cross_sign<false>(p1x, p1y, q1x, q1y, p2x, p2y, q2x, q2y);
}

// Compares the stage with the reference where it accepts; returns whether it accepted.
bool agrees_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  const int got = fixed_orient2d(ax, ay, bx, by, cx, cy);
  if (got == 2) return false;
  EXPECT_EQ(got, mk::reference::orient2d(ax, ay, bx, by, cx, cy))
      << hex(ax) << " " << hex(ay) << " " << hex(bx) << " " << hex(by) << " " << hex(cx) << " " << hex(cy);
  return true;
}
bool agrees_orient_vectors(const std::array<double, 8>& v) {
  const int got = fixed_orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]);
  if (got == 2) return false;
  EXPECT_EQ(got, mk::reference::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]))
      << hex(v[0]) << " " << hex(v[1]) << " " << hex(v[2]) << " " << hex(v[3]) << " " << hex(v[4]) << " "
      << hex(v[5]) << " " << hex(v[6]) << " " << hex(v[7]);
  return true;
}

// Random coordinates, one exponent window per axis (width 0..75 binades, anywhere from the
// subnormals to DBL_MAX), some zeros and negative zeros; then the same points moved onto a
// line (collinear, D = 0) and one ulp off it (D tiny, so the carries of the low limbs decide).
TEST(arith_fixed_point, exact_wherever_it_accepts) {
  const std::uint64_t seed = 7001;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> top(-1000, 1023), width(0, 75), eighth(0, 7);
  int accepted = 0;
  int total = 0;
  for (int k = 0; k < 200000; ++k) {
    const int ex = top(rng), wx = width(rng), ey = top(rng), wy = width(rng);
    std::array<double, 8> v{};
    for (std::size_t i = 0; i < 8; ++i) {
      const bool x_axis = i % 2 == 0;
      const int e = x_axis ? ex : ey;
      const int w = x_axis ? wx : wy;
      const int pick = eighth(rng);
      v[i] = pick == 0 ? 0.0 : pick == 1 ? -0.0 : random_double(rng, std::max(e - w, -1074), std::min(e, 1023));
    }
    total += 2;
    accepted += agrees_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    accepted += agrees_orient_vectors(v);
    // Collinear: (3x, k x) for x of 45 bits in a window; rounded differences in general.
    const double slope = 2 * (k % 60) + 1;
    const int e = std::uniform_int_distribution<int>(-900, 1000)(rng);
    std::array<double, 8> c{};
    for (std::size_t i = 0; i < 8; i += 2) {
      const double x = random_short_double(rng, 45, e - wx, e);
      c[i] = 3 * x;
      c[i + 1] = slope * x;
    }
    total += 4;
    accepted += agrees_orient2d(c[0], c[1], c[2], c[3], c[4], c[5]);
    accepted += agrees_orient_vectors(c);
    c[5] = std::nextafter(c[5], (k % 2) ? HUGE_VAL : -HUGE_VAL);
    c[6] = std::nextafter(c[6], (k % 3) ? HUGE_VAL : -HUGE_VAL);
    accepted += agrees_orient2d(c[0], c[1], c[2], c[3], c[4], c[5]);
    accepted += agrees_orient_vectors(c);
    if (::testing::Test::HasFailure()) return;
  }
  std::cout << accepted << " of " << total << " calls accepted\n";
  EXPECT_GT(accepted, total / 3);
}

// The acceptance boundary, checked on both sides, with the result on the accepted side.
TEST(arith_fixed_point, accepts_exactly_its_documented_range) {
  const double below_one = std::nextafter(1.0, 0.0);
  for (const int e : {-902, -901, -500, -1, 0, 1, 52, 700, 1023}) {
    const double largest = std::ldexp(1.5, e);
    const double lowest_allowed = std::ldexp(1.0, e - 69);
    const double just_below = std::ldexp(below_one, e - 69);
    const double mid = std::ldexp(1.25, e - 30);
    // One axis at the boundary, the other with y = 1, 2, 3-like values.
    EXPECT_TRUE(agrees_orient2d(largest, 1.0, lowest_allowed, 2.0, -mid, 3.5)) << e;
    EXPECT_TRUE(agrees_orient2d(0.0, 1.0, lowest_allowed, -0.0, largest, 3.0)) << e;
    EXPECT_TRUE(agrees_orient2d(1.0, largest, -0.0, -lowest_allowed, 3.0, mid)) << e;
    // Both axes at the boundary.
    EXPECT_TRUE(agrees_orient2d(largest, mid, lowest_allowed, largest, -mid, lowest_allowed)) << e;
    EXPECT_TRUE(agrees_orient_vectors({largest, mid, -lowest_allowed, mid, mid, -largest, 0.0, lowest_allowed})) << e;
    EXPECT_EQ(fixed_orient2d(largest, mid, just_below, largest, -mid, mid), 2) << e;  // x axis too wide
    EXPECT_EQ(fixed_orient2d(largest, largest, mid, just_below, -mid, mid), 2) << e;  // y axis too wide
    EXPECT_EQ(fixed_orient_vectors(largest, 1.0, mid, 1.0, mid, 1.0, just_below, 1.0), 2) << e;
  }
  // The largest magnitude of an axis must be at least 2^-902; an axis of zeros is accepted.
  const double tiny = std::ldexp(1.0, -902);
  EXPECT_TRUE(agrees_orient2d(tiny, 1.0, -tiny, 2.0, 0.0, 3.0));
  EXPECT_EQ(fixed_orient2d(std::nextafter(tiny, 0.0), 1.0, 0.0, 2.0, 0.0, 3.0), 2);
  EXPECT_EQ(fixed_orient2d(0.0, 1.0, 0.0, 2.0, 0.0, 3.0), 0);
  EXPECT_TRUE(agrees_orient2d(-0.0, 1.0, 0.0, -0.0, 5.0, 0.0));  // D = 5
  EXPECT_EQ(fixed_orient2d(-0.0, 1.0, 0.0, -0.0, -0.0, 7.0), 0);
  EXPECT_EQ(fixed_orient_vectors(0.0, 1.0, -0.0, 2.0, 0.0, 3.0, 0.0, -7.0), 0);
  // Subnormals are refused (below 2^-902 or, next to a larger value, off the grid).
  const double denorm_min = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(fixed_orient2d(denorm_min, 1.0, 0.0, 2.0, 0.0, 3.0), 2);
  EXPECT_EQ(fixed_orient2d(DBL_MIN, 1.0, 0.0, 2.0, tiny, 3.0), 2);
  // Near overflow: differences and products far beyond DBL_MAX are exact in integers.
  EXPECT_TRUE(agrees_orient2d(DBL_MAX, DBL_MAX, -DBL_MAX, -DBL_MAX, 0x1p1000, 0x1p1000));
  EXPECT_TRUE(agrees_orient2d(DBL_MAX, -DBL_MAX, -DBL_MAX, DBL_MAX, 0x1p960, std::nextafter(-0x1p960, 0.0)));
  EXPECT_TRUE(agrees_orient_vectors({-DBL_MAX, DBL_MAX, DBL_MAX, -DBL_MAX, DBL_MAX, DBL_MAX, -DBL_MAX, -DBL_MAX}));
  EXPECT_TRUE(agrees_orient_vectors({-DBL_MAX, DBL_MAX, DBL_MAX, -DBL_MAX, DBL_MAX, std::nextafter(DBL_MAX, 0.0),
                                     -DBL_MAX, -DBL_MAX}));
}

// Through the whole predicate: collinear points with rounded differences whose axes spread
// from 60 to 80 binades, so that some calls take the fixed-point stage and the others the
// expansion stages, at scales from near underflow to near overflow.
TEST(arith_fixed_point, collinear_points_on_both_sides_of_the_spread_limit) {
  const std::uint64_t seed = 7002;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  PredicateChecker check("collinear_spread_60_80");
  for (int k = 0; k < 40000; ++k) {
    const double slope = 2 * std::uniform_int_distribution<int>(1, 60)(rng) - 1;
    const int e = std::uniform_int_distribution<int>(-860, 1000)(rng);
    const int spread = std::uniform_int_distribution<int>(60, 80)(rng);
    std::array<double, 4> x{};
    for (double& xi : x) xi = random_short_double(rng, 45, e - spread, e);
    if (k % 5 == 0) x[k % 4] = 0.0;
    ASSERT_EQ(check.orient2d(3 * x[0], slope * x[0], 3 * x[1], slope * x[1], 3 * x[2], slope * x[2]), 0);
    ASSERT_EQ(check.orient_vectors(3 * x[0], slope * x[0], 3 * x[1], slope * x[1], 3 * x[2], slope * x[2],
                                   3 * x[3], slope * x[3]),
              0);
    check.orient2d(3 * x[0], slope * x[0], 3 * x[1], slope * x[1], 3 * x[2], std::nextafter(slope * x[2], 0.0));
  }
  check.expect_no_disagreement();
}

// The expansion path (safe-range scaling, stages B and C, the exact expansion stage, GMP)
// is now reached only by inputs the fixed-point stage refuses; called directly here, it must
// stay exact on every input, including those that normally never reach it.
TEST(arith_fixed_point, expansion_stages_stay_exact_on_every_input) {
  const std::uint64_t seed = 7003;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> top(-1074, 1023), width(0, 120);
  auto wide_orient2d = [](double ax, double ay, double bx, double by, double cx, double cy) {
    return mk::adaptive::detail::cross_sign_wide<true>(ax, ay, bx, by, ax, ay, cx, cy, mk::PredicateKind::orient2d);
  };
  auto wide_orient_vectors = [](const std::array<double, 8>& v) {
    return mk::adaptive::detail::cross_sign_wide<false>(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7],
                                                        mk::PredicateKind::orient_vectors);
  };
  for (int k = 0; k < 60000; ++k) {
    const int e = top(rng), w = width(rng);
    std::array<double, 8> v{};
    for (double& x : v) x = random_double(rng, std::max(e - w, -1074), e);
    // Random, then collinear with rounded differences, then one ulp off that line.
    ASSERT_EQ(wide_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]), mk::reference::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
    ASSERT_EQ(wide_orient_vectors(v), mk::reference::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
    const double slope = 2 * (k % 60) + 1;
    const int ec = std::uniform_int_distribution<int>(-900, 1000)(rng);
    for (std::size_t i = 0; i < 8; i += 2) {
      const double x = random_short_double(rng, 45, ec - std::min(w, 80), ec);
      v[i] = 3 * x;
      v[i + 1] = slope * x;
    }
    ASSERT_EQ(wide_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]), 0) << hex(v[0]) << " " << hex(v[2]) << " " << hex(v[4]);
    ASSERT_EQ(wide_orient_vectors(v), 0);
    v[5] = std::nextafter(v[5], (k % 2) ? HUGE_VAL : -HUGE_VAL);
    ASSERT_EQ(wide_orient2d(v[0], v[1], v[2], v[3], v[4], v[5]), mk::reference::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]));
    ASSERT_EQ(wide_orient_vectors(v), mk::reference::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]));
  }
}

}  // namespace
