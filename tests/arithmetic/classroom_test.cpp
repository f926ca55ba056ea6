// The classroom examples [KMPSY08 §4]: orient2d(p', q, r) over 256 x 256 grids of
// neighbouring doubles p'. The naive double formula gets many signs wrong there (counted by
// kind and printed: these grids really are hard); adaptive and interval must get none.
#include <gtest/gtest.h>

#include <iostream>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/exact_reference.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/predicates_classroom.hpp"
#include "arithmetic/predicates_naive.hpp"

namespace {

namespace classroom = mk::classroom;

void run_grid(const classroom::Grid& g) {
  classroom::SignErrorCounts naive;
  classroom::SignErrorCounts adaptive;
  classroom::SignErrorCounts interval;
  std::size_t positive = 0, negative = 0, zero = 0;
  classroom::for_each_point(g, [&](int, int, double px, double py) {
    const int exact = mk::reference::orient2d(px, py, g.qx, g.qy, g.rx, g.ry);
    (exact > 0 ? positive : exact < 0 ? negative : zero) += 1;
    naive.add(mk::naive::orient2d(px, py, g.qx, g.qy, g.rx, g.ry), exact);
    adaptive.add(mk::adaptive::orient2d(px, py, g.qx, g.qy, g.rx, g.ry), exact);
    interval.add(mk::interval_filter::orient2d(px, py, g.qx, g.qy, g.rx, g.ry), exact);
  });
  std::cout << "grid " << g.name << ": exact signs +" << positive << " -" << negative << " 0:" << zero << "\n"
            << "  naive double wrong: " << naive.total() << " (sign flipped " << naive.sign_flipped
            << ", zero reported non-zero " << naive.zero_reported_nonzero << ", non-zero reported zero "
            << naive.nonzero_reported_zero << ")\n"
            << "  adaptive wrong: " << adaptive.total() << ", interval wrong: " << interval.total() << "\n";
  EXPECT_GT(naive.total(), 0u) << "grid " << g.name << " should defeat the naive formula";
  EXPECT_EQ(adaptive.total(), 0u) << "grid " << g.name;
  EXPECT_EQ(interval.total(), 0u) << "grid " << g.name;
}

TEST(arith_classroom, grid_a_half_half_12_24) { run_grid(classroom::grid_a); }

TEST(arith_classroom, grid_b_nearly_collinear_17_3) { run_grid(classroom::grid_b); }

TEST(arith_classroom, grid_points_step_one_ulp_at_a_time) {
  const auto xs = classroom::ulp_steps(0.5);
  EXPECT_EQ(xs[0], 0.5);
  EXPECT_EQ(xs[1], 0.5 + 0x1p-53);
  EXPECT_EQ(xs[255], 0.5 + 255 * 0x1p-53);
}

TEST(arith_classroom, classify_names_the_three_kinds_of_error) {
  using classroom::SignError;
  EXPECT_EQ(classroom::classify(1, 1), SignError::none);
  EXPECT_EQ(classroom::classify(1, -1), SignError::sign_flipped);
  EXPECT_EQ(classroom::classify(1, 0), SignError::zero_reported_nonzero);
  EXPECT_EQ(classroom::classify(0, -1), SignError::nonzero_reported_zero);
}

}  // namespace
