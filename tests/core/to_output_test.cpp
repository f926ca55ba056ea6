// Output assembly: irreducible polygons into OGC polygons-with-holes through the inclusion
// forest, non-regular parts, and the exact validity check of rounded output.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/to_output.hpp"
#include "named_cases.hpp"
#include "tests/core/rounding_cases.hpp"

namespace mk::test {
namespace {

Output run(const Polygon& a, const Polygon& b, Operation op, bool regular = true) {
  return to_output<ExactKernel, ExactKernel>(
      boolean_op<ExactKernel>(a, b, Options{op, regular, EfOrganisation::hash, PairSearch::sweep}));
}

TEST(ToOutput, HoleAssignedToItsShell) {
  // A square with a square hole, minus nothing but a far-away square: one polygon, one hole.
  const Output out = run(island({box(0, 0, 10, 10), box(2, 2, 4, 4)}), island({box(20, 0, 21, 1)}), Operation::difference);
  ASSERT_EQ(out.polygons.size(), 1u);
  EXPECT_EQ(out.polygons[0].holes.size(), 1u);
  EXPECT_TRUE(out.rounded_valid.value_or(false));
}

TEST(ToOutput, IslandInsideHoleInsideIsland) {
  // Three levels: the inner island is its own polygon, the hole belongs to the outer one.
  const Output out = run(island({box(0, 0, 10, 10), box(2, 2, 8, 8), box(4, 4, 6, 6)}), island({}), Operation::union_);
  ASSERT_EQ(out.polygons.size(), 2u);
  std::size_t holes = 0;
  for (const auto& p : out.polygons) holes += p.holes.size();
  EXPECT_EQ(holes, 1u);
  for (const auto& p : out.polygons) {
    if (!p.holes.empty()) {
      EXPECT_EQ(p.shell.size(), 4u);
    }
  }
}

TEST(ToOutput, HoleTouchingShellAtAVertex) {
  const Output out = run(island({box(0, 0, 4, 4)}), island({{{0, 0}, {2, 1}, {1, 2}}}), Operation::difference);
  ASSERT_EQ(out.polygons.size(), 1u);
  EXPECT_EQ(out.polygons[0].holes.size(), 1u);
}

TEST(ToOutput, NonRegularPartsAndUnbounded) {
  const Output touch = run(island({box(0, 0, 1, 1)}), island({box(1, 1, 2, 2)}), Operation::intersection, false);
  EXPECT_TRUE(touch.polygons.empty());
  ASSERT_EQ(touch.isolated_points.size(), 1u);
  EXPECT_EQ(touch.isolated_points[0], (Point{1, 1}));
  const Output edge = run(island({box(0, 0, 1, 1)}), island({box(1, 0, 2, 1)}), Operation::intersection, false);
  EXPECT_EQ(edge.dangling_edges.size(), 1u);
  const Output unbounded = run(hole_type({box(0, 0, 2, 2)}), hole_type({box(1, 1, 3, 3)}), Operation::union_);
  EXPECT_TRUE(unbounded.unbounded);
  EXPECT_TRUE(unbounded.polygons.empty());
  EXPECT_EQ(unbounded.irreducible.size(), 1u);
  EXPECT_EQ(unbounded.irreducible[0].type, PolygonType::hole);
}

TEST(ToOutput, ExactCoordinatesOfCrossings) {
  const Output out = run(island({{{0, 0}, {2, 0}, {1, 1}}}), island({{{1, 0}, {2, -1}, {3, 0}, {2, 1}}}), Operation::intersection);
  ASSERT_EQ(out.irreducible.size(), 1u);
  const auto& e = out.irreducible[0].exact;
  EXPECT_NE(std::find(e.begin(), e.end(), "3/2"), e.end());
  EXPECT_NE(std::find(e.begin(), e.end(), "1/2"), e.end());
}

TEST(ToOutput, RoundedValidityIsCheckedExactly) {
  EXPECT_TRUE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {1, 0}, {0, 1}}}));
  // Two rings touching at a vertex are valid; crossing edges, a vertex inside another's
  // edge, and a collapsed ring are not.
  EXPECT_TRUE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {1, 0}, {1, 1}}, {{1, 1}, {2, 1}, {2, 2}}}));
  EXPECT_FALSE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}));
  EXPECT_FALSE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {2, 0}, {1, 1}}, {{1, 0}, {1, -1}, {2, -1}}}));
  EXPECT_FALSE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {0, 0}, {1, 1}}}));
  // A near-degenerate case: the rounded point 0.1 + 0.2 lies off the line through its
  // neighbours, which only an exact test sees.
  EXPECT_TRUE(is_valid_rounded_output<ExactKernel>({{{0, 0}, {0.1 + 0.2, 0.3}, {1, 1}, {0, 1}}}));
}

// Whether d is a nearest double to q (ties either way), decided exactly against its two
// neighbours: independent of how the kernel rounds.
bool is_nearest_double(double d, const mpq_class& q) {
  if (!std::isfinite(d)) return false;
  const mpq_class gap = abs(q - mpq_class(d));
  for (const double n : {std::nextafter(d, -HUGE_VAL), std::nextafter(d, HUGE_VAL)}) {
    if (std::isfinite(n) && abs(q - mpq_class(n)) < gap) return false;
  }
  return true;
}

// rounded_cycles walks the cycles' vertices in parts numbered across the cycles, fetching
// ahead: on one thread and on two, with and without the boxes' half-sizes, every vertex of
// every cycle gets the nearest doubles of its exact position (checked exactly), for results
// of many small cycles (two stars) and of one long cycle (a ring of 20000 points and a
// triangle), each more vertices than a phase needs to go on threads.
TEST(ToOutput, RoundedCyclesAreTheNearestDoublesOnAnyNumberOfThreads) {
  std::mt19937_64 rng(test_seed(29));
  std::uniform_real_distribution<double> u(0, 1);
  const auto ring = [&](std::size_t n, double spread, double turn) {
    std::vector<Point> pts;
    for (std::size_t k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n) + turn;
      const double radius = 10 * (1 + spread * u(rng));
      pts.push_back({radius * std::cos(t), radius * std::sin(t)});
    }
    return pts;
  };
  struct Input {
    Polygon a, b;
    Operation op;
  };
  std::vector<Input> inputs;
  inputs.push_back({island({ring(8000, 0.6, 0)}), island({ring(8000, 0.6, 0.001)}), Operation::symmetric_difference});
  inputs.push_back({island({ring(20000, 0.05, 0)}), island({{{0, 0}, {30, 1}, {29, 3}}}), Operation::difference});
  for (const auto& [a, b, op] : inputs) {
    Options opt;
    opt.op = op;
    const BooleanResult<ExactKernel> r = boolean_op<ExactKernel>(a, b, opt);
    std::size_t vertices = 0;
    for (const auto& c : r.cycles) vertices += c.vertices.size();
    ASSERT_GT(vertices, kParallelWork);
    RoundingHalves halves;
    const std::vector<std::vector<std::vector<Point>>> made{detail::rounded_cycles(r, 1), detail::rounded_cycles(r, 2),
                                                            detail::rounded_cycles(r, 2, &halves)};
    for (const auto& rounded : made) {
      ASSERT_EQ(rounded.size(), r.cycles.size());
      for (std::size_t c = 0; c < r.cycles.size(); ++c) {
        ASSERT_EQ(rounded[c].size(), r.cycles[c].vertices.size());
        for (std::size_t k = 0; k < rounded[c].size(); ++k) {
          const RationalPoint e = ExactKernel::exact(r.vertex(r.cycles[c].vertices[k]));
          ASSERT_TRUE(is_nearest_double(rounded[c][k].x, e.x) && is_nearest_double(rounded[c][k].y, e.y))
              << "cycle " << c << " vertex " << k << " of " << r.cycles.size() << " cycles";
        }
      }
    }
    EXPECT_EQ(halves.sizes.size(), vertices);
    std::printf("%zu cycles, %zu vertices, %d crossings\n", r.cycles.size(), vertices, r.arrangement.num_crossings());
  }
}

}  // namespace
}  // namespace mk::test
