// Step 6's turning number taken in parts: a long cycle's parts are summed on threads, and
// every split of a cycle, at a turn past east included, gives the turns of the whole. Step
// 6 without choices (detail::forced_cycles): the cycles the walk makes, derived by hand,
// and a refusal wherever the walk would choose or fail.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "arithmetic/kernels/double_kernel.hpp"
#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/error.hpp"
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

// EF by hand: entries from -> to along the input edge from -> to, inserted in order.
HashEdgeTable table_of(const std::vector<std::pair<int, int>>& entries, int num_vertices) {
  HashEdgeTable ef(entries.size() + 8, num_vertices);
  for (const auto& [from, to] : entries) ef.insert(EfEntry{from, to, Direction{from, to}, true}, true);
  return ef;
}

std::vector<Direction> directions_along(const std::vector<int>& cycle) {
  std::vector<Direction> d;
  for (std::size_t k = 0; k < cycle.size(); ++k) d.push_back({cycle[k], cycle[(k + 1) % cycle.size()]});
  return d;
}

constexpr PolygonType kCcw = PolygonType::hole;  // a type Table 4 may give counterclockwise cycles

// Two squares whose entries are interleaved, one counterclockwise (0 1 2 3), one clockwise
// (4 7 6 5), and a fragment cancelled by its opposite: each cycle starts at its first entry
// in insertion order, the cycles in the order of those entries, as the walk makes them.
TEST(ForcedCycles, EachCycleFromItsFirstEntryInInsertionOrder) {
  const std::vector<Point> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {3, 0}, {3, 1}, {2, 1}, {5, 5}, {6, 6}};
  HashEdgeTable ef = table_of({{1, 2}, {8, 9}, {4, 7}, {2, 3}, {3, 0}, {9, 8}, {7, 6}, {0, 1}, {6, 5}, {5, 4}}, 10);
  const DirectionOrder<ExactKernel> order(pts);
  for (const unsigned threads : {1u, 2u, 3u}) {
    std::vector<ResultCycle> out;
    ASSERT_TRUE(detail::forced_cycles(order, ef, kCcw, threads, out)) << threads;
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].vertices, (std::vector<int>{1, 2, 3, 0}));
    EXPECT_TRUE(out[0].directions == directions_along({1, 2, 3, 0}));
    EXPECT_TRUE(out[0].counterclockwise);
    EXPECT_EQ(out[0].type, kCcw);
    EXPECT_EQ(out[1].vertices, (std::vector<int>{4, 7, 6, 5}));
    EXPECT_TRUE(out[1].directions == directions_along({4, 7, 6, 5}));
    EXPECT_FALSE(out[1].counterclockwise);
    EXPECT_EQ(out[1].type, opposite(kCcw));
  }
}

// A run of fragments (one entry through inner vertex 1) gives its inner vertex and the
// direction leaving it.
TEST(ForcedCycles, RunsBringTheirInnerVertices) {
  const std::vector<Point> pts{{0, 3}, {1, 3}, {2, 3}, {2, 4}, {0, 4}};
  HashEdgeTable ef(8, 5);
  ef.make_inner_room(1);
  ef.set_inner(0, 1, Direction{1, 2});
  ef.insert_run(EfEntry{0, 2, Direction{0, 1}, true}, 0, 1);
  for (const auto& [from, to] : std::vector<std::pair<int, int>>{{2, 3}, {3, 4}, {4, 0}}) {
    ef.insert(EfEntry{from, to, Direction{from, to}, true}, true);
  }
  std::vector<ResultCycle> out;
  ASSERT_TRUE(detail::forced_cycles(DirectionOrder<ExactKernel>(pts), ef, kCcw, 2, out));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].vertices, (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_TRUE(out[0].directions == directions_along({0, 1, 2, 3, 4}));
  EXPECT_TRUE(out[0].counterclockwise);
}

// Where the walk has a choice (two squares touching at vertex 2) or cannot close (two
// entries lead into vertex 1, whose one entry the triangle 0 1 2 takes), nothing is made.
TEST(ForcedCycles, RefusedWhereTheWalkWouldChooseOrFail) {
  const std::vector<Point> pts{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 1}, {2, 2}, {1, 2}};
  const DirectionOrder<ExactKernel> order(pts);
  std::vector<ResultCycle> out;
  HashEdgeTable touching = table_of({{0, 1}, {1, 2}, {2, 3}, {3, 0}, {2, 4}, {4, 5}, {5, 6}, {6, 2}}, 7);
  EXPECT_FALSE(detail::forced_cycles(order, touching, kCcw, 2, out));
  EXPECT_TRUE(out.empty());
  HashEdgeTable into_one = table_of({{0, 1}, {1, 2}, {2, 0}, {3, 1}}, 7);
  EXPECT_FALSE(detail::forced_cycles(order, into_one, kCcw, 2, out));
  EXPECT_TRUE(out.empty());
}

// A cycle whose edges cross without a vertex (turning number 0) is reported as the walk
// reports it.
TEST(ForcedCycles, ANonSimpleCycleIsReported) {
  const std::vector<Point> pts{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  HashEdgeTable bowtie = table_of({{0, 1}, {1, 2}, {2, 3}, {3, 0}}, 4);
  std::vector<ResultCycle> out;
  EXPECT_THROW(detail::forced_cycles(DirectionOrder<ExactKernel>(pts), bowtie, kCcw, 2, out), KernelFailure);
}

}  // namespace
}  // namespace mk
