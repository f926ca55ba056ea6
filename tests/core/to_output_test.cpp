// Output assembly: irreducible polygons into OGC polygons-with-holes through the inclusion
// forest, non-regular parts, and the exact validity check of rounded output.
#include <gtest/gtest.h>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/to_output.hpp"
#include "named_cases.hpp"

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

}  // namespace
}  // namespace mk::test
