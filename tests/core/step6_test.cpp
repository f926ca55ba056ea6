// Step 6's turning number taken in parts: a long cycle's parts are summed on threads, and
// every split of a cycle, at a turn past east included, gives the turns of the whole.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/step6_construct.hpp"

namespace mk {
namespace {

// A closed polyline of n points going `winds` times around the origin (counterclockwise
// when positive), and its directions point to point, the last back to the first.
struct Wound {
  std::vector<Point> points;
  std::vector<Direction> dirs;
};

Wound wound_circle(int n, int winds) {
  Wound w;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * winds * i / n;
    w.points.push_back({1000 * std::cos(angle), 1000 * std::sin(angle)});
  }
  for (int i = 0; i < n; ++i) w.dirs.push_back({i, (i + 1) % n});
  return w;
}

template <class K>
void expect_turns(int n, int winds) {
  const Wound w = wound_circle(n, winds);
  const DirectionOrder<K> order(w.points);
  const std::size_t size = w.dirs.size();
  ASSERT_EQ(detail::turns_after(order, w.dirs, 0, size), winds);
  for (const unsigned threads : {1u, 2u, 5u}) {
    EXPECT_EQ(detail::turning_number(order, w.dirs, threads), winds) << threads << " threads";
  }
  // A split just before, at and just after each turn past east, where the parts meet.
  int wraps_seen = 0;
  for (std::size_t i = 0; i < size; ++i) {
    if (detail::turns_after(order, w.dirs, i, i + 1) == 0) continue;
    ++wraps_seen;
    for (const std::size_t cut : {i, i + 1, i + 2}) {
      if (cut > size) continue;
      EXPECT_EQ(detail::turns_after(order, w.dirs, 0, cut) + detail::turns_after(order, w.dirs, cut, size), winds)
          << "cut at " << cut;
    }
  }
  EXPECT_EQ(wraps_seen, std::abs(winds));
}

TEST(TurningNumber, PartsOnThreadsSumToTheWholeExact) {
  expect_turns<ExactKernel>(200003, 3);
  expect_turns<ExactKernel>(150001, -2);
  expect_turns<ExactKernel>(70001, 1);
}

TEST(TurningNumber, PartsOnThreadsSumToTheWholeRounded) {
  expect_turns<DoubleKernel>(200003, 3);
  expect_turns<DoubleKernel>(150001, -2);
}

}  // namespace
}  // namespace mk
