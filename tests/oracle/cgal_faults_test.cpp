// CGAL 5.5's faults that the differential test works around (cgal_reference.hpp), shown on
// their smallest cases: the workaround must give CGAL's answer on a configuration it
// handles, equal to mkbool's exact one; whether CGAL still has each fault is printed.
// [BRIEF §1] (../shared/design/public-failure-reports.md, "a known fault of the exact oracle")
// Preconditions: CGAL 5.5 (Debian 12).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"
#include "tests/oracle/cgal_reference.hpp"
#include "tests/oracle/checks.hpp"
#include "tests/oracle/membership.hpp"

namespace mk::oracle {
namespace {

// Two squares crossing, rotated by (3/5, 4/5) (times 5) and scaled by 2^k: exact doubles.
Polygon rotated_square(double x0, double y0, double s, int k) {
  Ring r;
  for (const auto& [x, y] : {std::pair{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}}) {
    r.push_back({std::ldexp(3 * x - 4 * y, k), std::ldexp(4 * x + 3 * y, k)});
  }
  return {{r}, PolygonType::island};
}

TEST(CgalFaults, LineCrossingBeyondTheIntervalRangeIsHandedToCgalScaledDown) {
  const auto corner = [](const Polygon& p, std::size_t i) { return QPoint{Q(p.rings[0][i].x), Q(p.rings[0][i].y)}; };
  const Polygon a = rotated_square(0, 0, 2, 400), b = rotated_square(1, 1, 2, 400);
  const Polygon a0 = rotated_square(0, 0, 2, 0), b0 = rotated_square(1, 1, 2, 0);
  // A's top edge and B's left edge cross at (1, 2) before the rotation.
  const bool fault = epeck_misses_line_crossing(corner(a, 3), corner(a, 2), corner(b, 0), corner(b, 3));
  std::cout << "CGAL's Epeck misses the crossing of two lines at 2^400: " << (fault ? "yes (the fault)" : "no")
            << "\n";
  EXPECT_FALSE(epeck_misses_line_crossing(corner(a0, 3), corner(a0, 2), corner(b0, 0), corner(b0, 3)));
  // mkbool at 2^400 equals CGAL at 2^0, scaled: the intersection is the unit square times 25.
  const Options opt{Operation::intersection, true};
  const auto r = boolean_op<RationalKernel>(a, b, opt);
  ASSERT_EQ(r.cycles.size(), 1u);
  Q scale = 1;
  for (int i = 0; i < 800; ++i) scale *= 2;
  const std::optional<Q> cgal = CgalSet::of(region_of(a0)).apply(Operation::intersection, CgalSet::of(region_of(b0))).area();
  ASSERT_TRUE(cgal.has_value());
  EXPECT_EQ(*cgal, 25);
  EXPECT_EQ(typed_result_area(r), *cgal * scale);
}

// public-failure-reports.md: a hole of B touching B's shell at (0, 0), which lies on an
// edge of A. GEOS, Boost.Geometry and Clipper give 45.
TEST(CgalFaults, HoleTouchingItsShellAtAVertexIsNeverGivenToCgalAsAPolygonWithHoles) {
  const Polygon a{{{{2, 0}, {2, 4}, {-2, 4}, {-6, 2}, {-6, 0}, {-4, -4}, {0, -4}, {2, -4}}}, PolygonType::island};
  const Polygon b{{{{4, 0}, {0, 4}, {0, 2}, {-2, 6}, {-6, 0}, {0, -6}, {2, -4}, {6, -2}}, {{2, 2}, {0, 0}, {2, 0}}},
                  PolygonType::island};
  const Region ra = region_of(a), rb = region_of(b);
  const Q naive = area_through_polygons_with_holes(Operation::intersection, ra, rb);
  std::cout << "CGAL through Polygon_with_holes_2: area " << naive << (naive != 45 ? " (the fault)" : "") << "\n";
  const std::optional<Q> cgal = CgalSet::of(ra).apply(Operation::intersection, CgalSet::of(rb)).area();
  ASSERT_TRUE(cgal.has_value());
  EXPECT_EQ(*cgal, 45);
  for (const bool regular : {true, false}) {
    const Options opt{Operation::intersection, regular};
    const auto r = boolean_op<RationalKernel>(a, b, opt);
    EXPECT_EQ(typed_result_area(r), 45);
    std::mt19937_64 rng(1);
    const Region rr = result_region(r);
    EXPECT_EQ(first_contradiction(Operation::intersection, regular, ra, rb, rr, sample_points(ra, rb, rr, rng, 40)),
              "");
  }
}

}  // namespace
}  // namespace mk::oracle
