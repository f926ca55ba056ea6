// The project's one sector test (is_in_ccw_sweep, predicates/directions.hpp) through its
// users, DirectionOrder over edge directions (per question and as a Sector made once) and
// the inclusion forest's is_in_sector over vertices (crossings included), against angles
// compared in exact rationals here.
// [MK89 §4.3, Table 5] (angle rules, generalised)
#include <gtest/gtest.h>
#include <gmpxx.h>

#include <iostream>
#include <random>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/assemble.hpp"
#include "predicates/directions.hpp"

namespace mk {
namespace {

using Q = mpq_class;
struct Vec {
  Q x, y;
};

// Angle order from east, counterclockwise: the upper half [0, pi) first.
int half(const Vec& v) { return v.y > 0 || (v.y == 0 && v.x > 0) ? 0 : 1; }
int angle_cmp(const Vec& u, const Vec& v) {
  if (half(u) != half(v)) return half(u) < half(v) ? -1 : 1;
  return -sgn(u.x * v.y - u.y * v.x);
}
// The definition: d strictly inside the counterclockwise sweep from f to l (the whole turn
// less f when f and l point the same way), from angles measured counterclockwise from f.
bool expected(const Vec& f, const Vec& l, const Vec& d) {
  const auto from_f = [&](const Vec& v) {  // 0 for f's direction, then increasing
    const int c = angle_cmp(f, v);
    return c == 0 ? 0 : (c < 0 ? 1 : 2);  // 1: after f before the wrap, 2: after the wrap
  };
  if (angle_cmp(f, d) == 0) return false;
  if (angle_cmp(f, l) == 0) return true;
  const int rl = from_f(l), rd = from_f(d);
  if (rd != rl) return rd < rl;
  return angle_cmp(d, l) < 0;
}

TEST(Directions, TheSectorTestAgreesWithExactAnglesForEdgeDirectionsAndVertices) {
  const std::uint64_t seed = 77;
  std::cout << "seed " << seed << "\n";
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> coord(-3, 3);
  int checked = 0, inside = 0;
  for (int iter = 0; iter < 20000; ++iter) {
    // Directions from a common centre c to three points (small grid: many equal and
    // opposite directions).
    const Point c{double(coord(rng)), double(coord(rng))};
    Point p[3];
    for (auto& q : p) q = {double(coord(rng)), double(coord(rng))};
    if (p[0] == c || p[1] == c || p[2] == c) continue;
    const auto vec = [&](const Point& q) { return Vec{Q(q.x) - Q(c.x), Q(q.y) - Q(c.y)}; };
    const bool want = expected(vec(p[0]), vec(p[1]), vec(p[2]));
    // DirectionOrder: directions as pairs of input points.
    const std::vector<RationalPoint> points{RationalKernel::point(c), RationalKernel::point(p[0]),
                                            RationalKernel::point(p[1]), RationalKernel::point(p[2])};
    const DirectionOrder<RationalKernel> order(points);
    ASSERT_EQ(order.is_in_ccw_sector({0, 1}, {0, 2}, {0, 3}), want) << iter;
    // The sector made once (step 4's), with the test direction also as the same pair of
    // points as either end (never strictly inside).
    const DirectionOrder<RationalKernel>::Sector sector(order, {0, 1}, {0, 2});
    ASSERT_EQ(sector.contains({0, 3}), want) << iter;
    ASSERT_FALSE(sector.contains({0, 1})) << iter;
    ASSERT_EQ(sector.contains({0, 2}), order.is_in_ccw_sector({0, 1}, {0, 2}, {0, 2})) << iter;
    // is_in_sector: vertices, here with c a crossing point of two segments through it
    // (exact, implicit), wherever the directions from c are not parallel.
    const Point c2{2 * c.x, 2 * c.y};
    const ExactVertex centre = ExactKernel::crossing({0, 0}, c2, {c2.x, 0}, {0, c2.y});
    const bool through_crossing = c.x != 0 && c.y != 0;
    const ExactVertex v0 = ExactKernel::vertex(p[0]), v1 = ExactKernel::vertex(p[1]), v2 = ExactKernel::vertex(p[2]);
    if (angle_cmp(vec(p[0]), vec(p[1])) != 0 && angle_cmp(vec(p[0]), vec(p[2])) != 0 &&
        angle_cmp(vec(p[1]), vec(p[2])) != 0) {  // its precondition
      ASSERT_EQ(detail::is_in_sector<ExactKernel>(through_crossing ? centre : ExactKernel::vertex(c), v0, v1, v2), want)
          << iter;
    }
    ++checked;
    inside += want;
  }
  std::cout << checked << " sector questions, " << inside << " inside\n";
  EXPECT_GT(inside, checked / 5);
  EXPECT_LT(inside, checked * 4 / 5);
}

}  // namespace
}  // namespace mk
