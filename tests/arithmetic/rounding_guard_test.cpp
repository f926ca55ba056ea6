// The rounding guard sets a mode and restores the caller's; code inside it really rounds
// in that mode (the compiler neither folds nor hoists the operations); the interval
// filter leaves the caller's mode as it found it. [BMP06]
#include "arithmetic/rounding_guard.hpp"

#include <gtest/gtest.h>

#include <cfenv>
#include <stdexcept>

#include "arithmetic/interval_filter.hpp"

namespace {

TEST(arith_rounding_guard, sets_and_restores_the_mode) {
  ASSERT_EQ(std::fegetround(), FE_TONEAREST);
  {
    mk::RoundingGuard up(FE_UPWARD);
    EXPECT_EQ(std::fegetround(), FE_UPWARD);
    {
      mk::RoundingGuard down(FE_DOWNWARD);
      EXPECT_EQ(std::fegetround(), FE_DOWNWARD);
    }
    EXPECT_EQ(std::fegetround(), FE_UPWARD);
  }
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

TEST(arith_rounding_guard, restores_the_mode_when_an_exception_leaves) {
  try {
    mk::RoundingGuard up(FE_UPWARD);
    throw std::runtime_error("leave");
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

TEST(arith_rounding_guard, operations_inside_round_in_the_guarded_mode) {
  // 1/3 with literal operands: without opaque() the compiler would fold both quotients to
  // the round-to-nearest value and they would be equal.
  double up = 0.0;
  double down = 0.0;
  {
    mk::RoundingGuard g(FE_UPWARD);
    up = mk::RoundingGuard::opaque(1.0) / mk::RoundingGuard::opaque(3.0);
  }
  {
    mk::RoundingGuard g(FE_DOWNWARD);
    down = mk::RoundingGuard::opaque(1.0) / mk::RoundingGuard::opaque(3.0);
  }
  EXPECT_LT(down, up);
  EXPECT_EQ(std::nextafter(down, 1.0), up);
}

TEST(arith_rounding_guard, interval_evaluation_encloses_and_leaves_the_mode) {
  // 0.1 + 0.2 is inexact: the interval evaluation must straddle the rounded sum.
  mk::interval_filter::Interval sum;
  {
    mk::RoundingGuard g(FE_UPWARD);
    sum = mk::interval_filter::Interval(mk::RoundingGuard::opaque(0.1)) +
          mk::interval_filter::Interval(mk::RoundingGuard::opaque(0.2));
  }
  EXPECT_LT(sum.lower(), sum.upper());
  EXPECT_LE(sum.lower(), 0.1 + 0.2);
  EXPECT_GE(sum.upper(), 0.1 + 0.2);
  // A call that reaches the interval stage (nearly collinear points) keeps the mode.
  EXPECT_EQ(mk::interval_filter::orient2d(0.1, 0.1, 0.3, 0.3, 0.7, 0.7000000000000001), 1);
  EXPECT_EQ(std::fegetround(), FE_TONEAREST);
}

}  // namespace
