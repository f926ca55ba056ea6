// The rational kernel over its three number types (GMP's mpq_class, Boost's mpq_rational
// over GMP, Boost's header-only cpp_rational): exact conversion of every kind of double, the
// same exact text, the same nearest double (MPFR), and the same predicate signs as the mpq
// reference. [MK89 §3.3] [MPFR]
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <iostream>
#include <random>
#include <vector>

#include "arithmetic/exact_reference.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/kernels/rational_mp_kernels.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace {

using mk::test::hex;

template <class K>
class RationalKernels : public ::testing::Test {};
using Kernels = ::testing::Types<mk::RationalKernel, mk::RationalMpKernel, mk::RationalCppKernel>;
struct Name {
  template <class K>
  static std::string GetName(int) {
    std::string n(K::name);
    for (char& c : n) c = c == '-' ? '_' : c;
    return n;
  }
};
TYPED_TEST_SUITE(RationalKernels, Kernels, Name);

std::vector<double> special_doubles() {
  std::vector<double> v{0.0,     -0.0,     1.0,       -1.0,      0.1,      -0.3,     1e-300,   -1e300,
                        DBL_MAX, -DBL_MAX, DBL_MIN,   -DBL_MIN,  0x1p-1074, -0x1p-1074, 0x1.8p-1070, 0x1p52,
                        0x1p53 + 2, 1.0 / 3.0};
  std::mt19937_64 rng(7001);
  for (int i = 0; i < 200; ++i) v.push_back(mk::test::random_double(rng, -1074, 1023));
  return v;
}

TYPED_TEST(RationalKernels, ConvertsEveryDoubleExactlyWithGmpsText) {
  using K = TypeParam;
  for (const double d : special_doubles()) {
    const auto p = K::point({d, -d});
    const auto text = K::exact_coordinates(p);
    EXPECT_EQ(text[0], mpq_class(d).get_str()) << hex(d);
    EXPECT_EQ(text[1], mpq_class(-d).get_str()) << hex(d);
    EXPECT_EQ(K::approx(p).x, d) << hex(d);  // a double rounds to itself
  }
}

// Crossing points have arbitrary rationals as coordinates: their text and nearest double
// must be those of mpq_class (reduced fractions; MPFR's correct rounding, ties to even,
// subnormals, overflow to infinity).
TYPED_TEST(RationalKernels, CrossingsMatchMpqExactlyAndRoundTheSame) {
  using K = TypeParam;
  using R = mk::RationalKernel;
  std::mt19937_64 rng(7002);
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const int scale = std::uniform_int_distribution<int>(-1070, 1020)(rng);
    double v[8];
    for (double& x : v) x = mk::test::random_double(rng, scale - 3, scale);
    const mk::Point a0{v[0], v[1]}, a1{v[2], v[3]}, b0{v[4], v[5]}, b1{v[6], v[7]};
    // Only segments that cross properly (the kernel's precondition).
    const int s0 = mk::reference::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]);
    const int s1 = mk::reference::orient2d(v[0], v[1], v[2], v[3], v[6], v[7]);
    const int s2 = mk::reference::orient2d(v[4], v[5], v[6], v[7], v[0], v[1]);
    const int s3 = mk::reference::orient2d(v[4], v[5], v[6], v[7], v[2], v[3]);
    if (s0 * s1 >= 0 || s2 * s3 >= 0) continue;
    ++checked;
    const auto want = R::crossing(R::point(a0), R::point(a1), R::point(b0), R::point(b1));
    const auto got = K::crossing(K::point(a0), K::point(a1), K::point(b0), K::point(b1));
    ASSERT_EQ(K::exact_coordinates(got), R::exact_coordinates(want)) << i;
    const mk::Point g = K::approx(got), w = R::approx(want);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(g.x), std::bit_cast<std::uint64_t>(w.x)) << i << " " << hex(g.x);
    ASSERT_EQ(std::bit_cast<std::uint64_t>(g.y), std::bit_cast<std::uint64_t>(w.y)) << i << " " << hex(g.y);
  }
  std::cout << K::name << ": " << checked << " crossings (seed 7002)\n";
  EXPECT_GT(checked, 300);
}

TYPED_TEST(RationalKernels, QuotientsOfHugeAndTinyValues) {
  using K = TypeParam;
  // Crossing of the diagonals of a square of side DBL_MAX: x = 0, but through a quotient of
  // huge values; and of a tiny square near the subnormal range.
  for (const double s : {DBL_MAX / 2, 0x1p-1070}) {
    const auto c = K::crossing(K::point({-s, -s}), K::point({s, s}), K::point({-s, s}), K::point({s, -s}));
    EXPECT_EQ(K::approx(c).x, 0.0);
    EXPECT_EQ(K::approx(c).y, 0.0);
  }
  // A crossing near the top of the range (a crossing lies in its segments' box, so it never
  // rounds to infinity; the quotient's terms are far beyond the range).
  using R = mk::RationalKernel;
  const mk::Point a0{DBL_MAX / 3, -1}, a1{DBL_MAX, 1}, b0{DBL_MAX / 2, 1}, b1{DBL_MAX * 0.9, -1};
  const auto far = K::crossing(K::point(a0), K::point(a1), K::point(b0), K::point(b1));
  const auto r = R::crossing(R::point(a0), R::point(a1), R::point(b0), R::point(b1));
  EXPECT_EQ(K::exact_coordinates(far), R::exact_coordinates(r));
  EXPECT_EQ(K::approx(far).x, R::approx(r).x);
  EXPECT_EQ(K::approx(far).y, R::approx(r).y);
  EXPECT_TRUE(std::isfinite(K::approx(far).x));
}

TYPED_TEST(RationalKernels, PredicatesEqualTheReference) {
  using K = TypeParam;
  std::mt19937_64 rng(7003);
  for (int i = 0; i < 4000; ++i) {
    double v[8];
    if (i % 2 == 0) {
      for (double& x : v) x = mk::test::random_double(rng, -1074, 1023);
    } else {  // collinear on integer lines: zeros
      const double t = std::uniform_int_distribution<int>(-50, 50)(rng);
      const double u = std::uniform_int_distribution<int>(-50, 50)(rng);
      v[0] = 3, v[1] = 5, v[2] = 3 + 2 * t, v[3] = 5 + 7 * t, v[4] = 3 + 2 * u, v[5] = 5 + 7 * u;
      v[6] = 1 + 2 * u, v[7] = 7 * u;
    }
    const auto p = [&](int k) { return K::point({v[k], v[k + 1]}); };
    ASSERT_EQ(static_cast<int>(K::orient2d(p(0), p(2), p(4))), mk::reference::orient2d(v[0], v[1], v[2], v[3], v[4], v[5]))
        << i;
    ASSERT_EQ(static_cast<int>(K::orient_vectors(p(0), p(2), p(4), p(6))),
              mk::reference::orient_vectors(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]))
        << i;
    ASSERT_EQ(static_cast<int>(K::compare_x(p(0), p(2))), (v[0] > v[2]) - (v[0] < v[2])) << i;
  }
}

}  // namespace
