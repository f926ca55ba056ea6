// What the candidate-pair search assumes of kernels whose points are doubles (core/pairs.hpp,
// CandidatePairs::kPlainY): it caches a point's y and compares it with `<` instead of
// calling the kernel's compare_y. Every such kernel must order y exactly as `<` does, on
// any doubles: signed zeros, subnormals, neighbours an ulp apart, the largest values.
// [MK89 §3.3] (the kernels' predicates)
// Preconditions: none.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <random>
#include <type_traits>
#include <vector>

#include "tests/core/kernel_types.hpp"

namespace mk::test {
namespace {

template <class K>
class PlainY : public ::testing::Test {};

using DoublePointKernels =
#ifdef MK_WITH_CGAL
    ::testing::Types<ExactKernel, DoubleKernel, IntervalKernel, AdaptiveKernel, CgalKernel>;
#else
    ::testing::Types<ExactKernel, DoubleKernel, IntervalKernel, AdaptiveKernel>;
#endif
TYPED_TEST_SUITE(PlainY, DoublePointKernels, KernelName);

TYPED_TEST(PlainY, CompareYIsTheDoublesOrder) {
  using K = TypeParam;
  static_assert(std::is_same_v<typename K::Point, mk::Point>, "the search caches y only for double points");
  std::vector<double> ys{0.0, -0.0, DBL_MIN, -DBL_MIN, DBL_TRUE_MIN, -DBL_TRUE_MIN, DBL_MAX, -DBL_MAX, 1.0,
                         std::nextafter(1.0, 2.0), std::nextafter(1.0, 0.0), -1.0, 1e-300, 1e300};
  std::mt19937_64 rng(41);
  for (int i = 0; i < 200; ++i) {
    const double y = std::ldexp(static_cast<double>(rng() >> 11), static_cast<int>(rng() % 200) - 150);
    ys.push_back((rng() & 1) ? -y : y);
    ys.push_back(std::nextafter(ys.back(), HUGE_VAL));
  }
  for (const double a : ys) {
    for (const double b : ys) {
      const Sign expected = a < b ? Sign::negative : (b < a ? Sign::positive : Sign::zero);
      ASSERT_EQ(K::compare_y(K::point({0.5, a}), K::point({-3.0, b})), expected) << a << " " << b;
    }
  }
}

}  // namespace
}  // namespace mk::test
