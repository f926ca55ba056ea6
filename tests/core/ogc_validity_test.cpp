// The exact OGC validity check (core/ogc_validity.hpp): one hand-made case per rule of
// GEOS's isValid, each with the defect it must report, and the same check over rational
// points. The comparison with GEOS itself on random polygons is in tests/api.
// [OGC06-103 §6.1.11]
#include <gtest/gtest.h>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/ogc_validity.hpp"

namespace mk {
namespace {

Ring ring(std::initializer_list<Point> pts) { return Ring(pts); }
Ring square(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

OgcDefect defect(const MultiPolygon& mp) { return check_ogc_validity<ExactKernel>(mp).defect; }

TEST(OgcValidity, ValidShapes) {
  EXPECT_EQ(defect({}), OgcDefect::none);
  EXPECT_EQ(defect({{square(0, 0, 1, 1), {}}}), OgcDefect::none);
  // Clockwise, with a redundant collinear vertex and a repeated point (ignored, as GEOS does).
  EXPECT_EQ(defect({{ring({{0, 0}, {0, 2}, {2, 2}, {2, 2}, {2, 1}, {2, 0}}), {}}}), OgcDefect::none);
  // A hole touching its shell at one vertex, and another hole touching that hole at a point.
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {ring({{0, 5}, {4, 8}, {4, 2}}), ring({{4, 2}, {6, 2}, {6, 1}})}}}),
            OgcDefect::none);
  // Three holes meeting at one point: the touch point joins them without a cycle.
  EXPECT_EQ(defect({{square(0, 0, 10, 10),
                     {ring({{5, 5}, {7, 8}, {7, 6}}), ring({{5, 5}, {7, 4}, {7, 2}}), ring({{5, 5}, {3, 4}, {3, 2}})}}}),
            OgcDefect::none);
  // A vertex of a hole inside an edge of the shell.
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {ring({{5, 0}, {6, 2}, {4, 2}})}}}), OgcDefect::none);
  // Two parts touching at two points, and a part inside another's hole touching it.
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {}}, {ring({{10, 0}, {20, 0}, {20, 10}, {10, 10}, {15, 5}}), {}}}),
            OgcDefect::none);
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {square(2, 2, 8, 8)}}, {ring({{2, 2}, {8, 5}, {5, 8}}), {}}}),
            OgcDefect::none);
}

TEST(OgcValidity, EachRuleBroken) {
  EXPECT_EQ(defect({{ring({{0, 0}, {1, 0}, {0, 0}}), {}}}), OgcDefect::too_few_points);
  EXPECT_EQ(defect({{ring({{0, 0}, {1, 0}, {1, 0}, {0, 0}}), {}}}), OgcDefect::too_few_points);
  EXPECT_EQ(defect({{ring({{0, 0}, {HUGE_VAL, 0}, {0, 1}}), {}}}), OgcDefect::invalid_coordinate);
  // A bow tie, a spike folding back over its own edge, a zero-area ring.
  EXPECT_EQ(defect({{ring({{0, 0}, {2, 2}, {2, 0}, {0, 2}}), {}}}), OgcDefect::self_intersection);
  EXPECT_EQ(defect({{ring({{0, 0}, {4, 0}, {2, 0}, {2, 2}}), {}}}), OgcDefect::self_intersection);
  EXPECT_EQ(defect({{ring({{0, 0}, {1, 0}, {2, 0}}), {}}}), OgcDefect::self_intersection);
  // A vertical edge crossing a sloped one, and two vertical edges overlapping.
  EXPECT_EQ(defect({{square(0, 0, 4, 4), {ring({{2, -1}, {2, 1}, {3, 1}})}}}), OgcDefect::self_intersection);
  EXPECT_EQ(defect({{square(0, 0, 4, 4), {ring({{0, 1}, {0, 2}, {1, 2}})}}}), OgcDefect::self_intersection);
  // A shell touching itself at a vertex (two lobes: GEOS wants two polygons).
  EXPECT_EQ(defect({{ring({{0, 0}, {10, 0}, {5, 5}, {10, 10}, {0, 10}, {5, 5}}), {}}}),
            OgcDefect::ring_self_intersection);
  // A shell whose vertex lies inside its own edge (an inverted hole).
  EXPECT_EQ(defect({{ring({{0, 0}, {10, 0}, {10, 10}, {5, 0}, {0, 10}}), {}}}), OgcDefect::ring_self_intersection);
  // A hole touching its shell at two points (two pieces of interior).
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {ring({{0, 5}, {5, 10}, {10, 5}, {5, 0}})}}}),
            OgcDefect::disconnected_interior);
  // Holes touching each other and the shell in a cycle.
  EXPECT_EQ(defect({{square(0, 0, 10, 10),
                     {ring({{0, 5}, {4, 8}, {4, 2}}), ring({{4, 8}, {8, 8}, {8, 6}}), ring({{4, 2}, {8, 4}, {8, 2}}),
                      ring({{8, 6}, {8, 4}, {10, 5}})}}}),
            OgcDefect::disconnected_interior);
  EXPECT_EQ(defect({{square(0, 0, 4, 4), {square(5, 5, 6, 6)}}}), OgcDefect::hole_outside_shell);
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {square(1, 1, 9, 9), square(2, 2, 3, 3)}}}), OgcDefect::nested_holes);
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {}}, {square(2, 2, 3, 3), {}}}), OgcDefect::nested_shells);
  // Two parts sharing an edge, or crossing at a shared vertex without crossing edges.
  EXPECT_EQ(defect({{square(0, 0, 1, 1), {}}, {square(1, 0, 2, 1), {}}}), OgcDefect::self_intersection);
  EXPECT_EQ(defect({{ring({{0, 0}, {2, 0}, {2, 2}, {0, 2}}), {}}, {ring({{1, 1}, {3, 0}, {3, 3}}), {}}}),
            OgcDefect::self_intersection);
  EXPECT_EQ(defect({{ring({{0, 0}, {2, -1}, {4, 0}, {2, 1}}), {}}, {ring({{2, -1}, {3, 2}, {1, 2}}), {}}}),
            OgcDefect::self_intersection);
  // A part nested in another, touching it at a vertex.
  EXPECT_EQ(defect({{square(0, 0, 10, 10), {}}, {ring({{0, 0}, {3, 1}, {1, 3}}), {}}}), OgcDefect::nested_shells);
}

TEST(OgcValidity, RationalPointsAndWhereItFailed) {
  using R = RationalKernel;
  RingSet<RationalPoint> in;
  const mpq_class third(1, 3);
  in.add_ring({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 0, 0);
  in.add_ring({{third, third}, {2 * third, third}, {third, 2 * third}}, 0, 1);
  EXPECT_TRUE(check_ogc_validity<R>(in).valid());
  // A second hole touching the first at a vertex is fine; sharing its edge is not.
  RingSet<RationalPoint> touching = in;
  touching.add_ring({{2 * third, third}, {mpq_class(3, 4), mpq_class(1, 2)}, {mpq_class(3, 4), mpq_class(1, 4)}}, 0, 2);
  EXPECT_TRUE(check_ogc_validity<R>(touching).valid());
  in.add_ring({{third, third}, {third, 2 * third}, {mpq_class(1, 4), mpq_class(1, 2)}}, 0, 2);
  EXPECT_EQ(check_ogc_validity<R>(in).defect, OgcDefect::self_intersection);
  const OgcValidity v = check_ogc_validity<ExactKernel>(MultiPolygon{{square(0, 0, 4, 4), {square(5, 5, 6, 6)}}});
  EXPECT_EQ(v.polygon, 0);
  EXPECT_EQ(v.ring, 1);
  EXPECT_NE(v.why().find("hole outside shell"), std::string::npos);
}

}  // namespace
}  // namespace mk
