// Fill rules, union-all, intersection-all and make-valid on hand-derived cases: a bowtie, a
// pentagram under evenodd and nonzero, overlapping multipolygon parts, rings traced twice or
// repeating a vertex, each area derived here from the winding numbers of its faces; and the
// errors of the options. Every exact kernel must give the derived area exactly; inexact
// kernels run for the record. [BRIEF §1, extended by issue 13]
// Preconditions: none.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "api/mkbool.hpp"
#include "core/canonical.hpp"

namespace mk {
namespace {

std::vector<std::string> exact_kernels() {
  std::vector<std::string> out;
  for (const auto k : kernel_names()) {
    if (is_exact_kernel(k)) out.emplace_back(k);
  }
  return out;
}

BooleanOptions with(FillRule rule, const std::string& kernel, Operation op = Operation::union_) {
  BooleanOptions o;
  o.op = op;
  o.kernel = kernel;
  o.fill_rule = rule;
  o.area_exact = true;
  return o;
}

mpq_class area_of(const BooleanOutput& r) { return mpq_class(r.stats.area_exact.value()); }

MultiPolygon one(const Ring& r) { return {OgcPolygon{r, {}}}; }

// The bowtie (0 0, 2 2, 2 0, 0 2) crosses itself at (1 1): its left triangle runs
// counterclockwise (winding +1), its right one clockwise (-1), each of area 1.
TEST(FillRules, BowtieAreasFollowTheWindingNumbersOfItsTwoTriangles) {
  const MultiPolygon bowtie = one({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    EXPECT_EQ(area_of(make_valid(bowtie, with(FillRule::evenodd, k))), 2);
    EXPECT_EQ(area_of(make_valid(bowtie, with(FillRule::nonzero, k))), 2);
    const BooleanOutput pos = make_valid(bowtie, with(FillRule::positive, k));
    EXPECT_EQ(area_of(pos), 1);
    ASSERT_EQ(pos.output.polygons.size(), 1u);
    EXPECT_EQ(pos.output.polygons[0].shell.size(), 3u);
    for (const Point& p : pos.output.polygons[0].shell) EXPECT_LE(p.x, 1.0);  // the left triangle
    EXPECT_EQ(area_of(make_valid(bowtie, with(FillRule::negative, k))), 1);
    EXPECT_EQ(pos.stats.crossings, 1u);
  }
}

// The pentagram (0 0, 2 6, 4 0, -1 4, 5 4) runs clockwise: its five tips wind -1 and its
// inner pentagon -2. Its signed area is -16 = -(tips + 2 P), where P is the pentagon's area,
// whose corners are where its edges' lines meet: y = 3x, y = 12 - 3x, y = (16 - 4x)/5,
// y = 4 and y = 4x/5.
TEST(FillRules, PentagramUnderEvenoddLosesItsInnerPentagon) {
  const MultiPolygon star = one({{0, 0}, {2, 6}, {4, 0}, {-1, 4}, {5, 4}});
  const std::vector<std::pair<mpq_class, mpq_class>> pentagon{{mpq_class(16, 19), mpq_class(48, 19)},
                                                              {mpq_class(4, 3), 4},
                                                              {mpq_class(8, 3), 4},
                                                              {mpq_class(60, 19), mpq_class(48, 19)},
                                                              {2, mpq_class(8, 5)}};
  mpq_class twice = 0;
  for (std::size_t i = 0; i < pentagon.size(); ++i) {
    const auto& [x0, y0] = pentagon[i];
    const auto& [x1, y1] = pentagon[(i + 1) % pentagon.size()];
    twice += x0 * y1 - x1 * y0;
  }
  const mpq_class p = abs(twice) / 2;
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    EXPECT_EQ(area_of(make_valid(star, with(FillRule::evenodd, k))), 16 - 2 * p);
    EXPECT_EQ(area_of(make_valid(star, with(FillRule::nonzero, k))), 16 - p);
    EXPECT_EQ(area_of(make_valid(star, with(FillRule::negative, k))), 16 - p);
    const BooleanOutput positive = make_valid(star, with(FillRule::positive, k));
    EXPECT_TRUE(positive.output.polygons.empty());
    EXPECT_EQ(make_valid(star, with(FillRule::evenodd, k)).output.polygons.size(), 5u);  // the tips
  }
}

// Two 2 x 2 squares overlapping in a unit square, one given clockwise, and a disjoint
// unit square: the union rule turns them all counterclockwise.
TEST(FillRules, OverlappingPartsUnionAndIntersect) {
  const MultiPolygon parts{{{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {}},
                           {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}, {}},
                           {{{5, 5}, {6, 5}, {6, 6}, {5, 6}}, {}}};
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    BooleanOptions o;
    o.kernel = k;
    o.area_exact = true;
    const BooleanOutput u = union_all(parts, o);
    EXPECT_EQ(area_of(u), 8);
    EXPECT_EQ(u.output.polygons.size(), 2u);
    const MultiPolygon first_two(parts.begin(), parts.begin() + 2);
    EXPECT_EQ(area_of(intersection_all(first_two, o)), 1);
    EXPECT_TRUE(intersection_all(parts, o).output.polygons.empty());
    // Read together by nonzero without turning them, the clockwise square cancels the other
    // where they overlap: 4 - 1 + 4 - 1 + 1.
    EXPECT_EQ(area_of(union_all(parts, with(FillRule::nonzero, k))), 7);
    EXPECT_EQ(area_of(union_all(parts, with(FillRule::positive, k))), 3 + 1);
  }
}

// A square traced twice winds 2 around its inside; a figure eight repeating the vertex
// (2 2) makes two counterclockwise loops that touch there.
TEST(FillRules, RingsTracedTwiceAndRepeatingAVertex) {
  const MultiPolygon twice = one({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const MultiPolygon eight = one({{0, 0}, {2, 0}, {2, 2}, {4, 2}, {4, 4}, {2, 4}, {2, 2}, {0, 2}});
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    EXPECT_TRUE(make_valid(twice, with(FillRule::evenodd, k)).output.polygons.empty());
    EXPECT_EQ(area_of(make_valid(twice, with(FillRule::nonzero, k))), 1);
    EXPECT_TRUE(make_valid(twice, with(FillRule::negative, k)).output.polygons.empty());
    const BooleanOutput e = make_valid(eight, with(FillRule::evenodd, k));
    EXPECT_EQ(area_of(e), 8);
    EXPECT_EQ(e.output.rounded_valid, std::optional<bool>(true));
  }
}

// Three edges through one crossing point: the bowtie's diagonals cross at (1 1), where the
// vertical edge of the triangle T = (1 -1, 1 3, -1 1) (counterclockwise, area 4) passes
// too; the bowtie's left triangle (area 1, winding +1) lies in T with two corners on T's
// edges, its right triangle (area 1, winding -1) outside. Windings: 2 in the left triangle,
// 1 in the rest of T, -1 in the right triangle.
TEST(FillRules, ThreeEdgesThroughOneCrossing) {
  const MultiPolygon rings{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}, {}}, {{{1, -1}, {1, 3}, {-1, 1}}, {}}};
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    EXPECT_EQ(area_of(make_valid(rings, with(FillRule::nonzero, k))), 5);
    EXPECT_EQ(area_of(make_valid(rings, with(FillRule::evenodd, k))), 3 + 1);
    EXPECT_EQ(area_of(make_valid(rings, with(FillRule::positive, k))), 4);
    EXPECT_EQ(area_of(make_valid(rings, with(FillRule::negative, k))), 1);
    EXPECT_EQ(make_valid(rings, with(FillRule::nonzero, k)).stats.crossings, 1u);  // one point, found thrice
  }
}

// A shell given clockwise and its hole counterclockwise: the union rule turns both, so the
// hole is cut out; positive (rings as given) keeps only the hole.
TEST(FillRules, UnionRuleOrientsShellsAndHolesAsOgcReadsThem) {
  const MultiPolygon framed{{{{0, 0}, {0, 4}, {4, 4}, {4, 0}}, {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}}};
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    EXPECT_EQ(area_of(make_valid(framed, with(FillRule::union_, k))), 12);
    EXPECT_EQ(area_of(make_valid(framed, with(FillRule::positive, k))), 0);
    EXPECT_EQ(area_of(make_valid(framed, with(FillRule::negative, k))), 12);
    EXPECT_EQ(area_of(make_valid(framed, with(FillRule::evenodd, k))), 12);
  }
}

// A result in a form two paths must give identically: its irreducible polygons (types and
// exact vertices, each cycle from its least rotation) and its lower-dimensional parts.
struct Canonical {
  std::vector<CanonicalCycle<std::string>> cycles;
  std::vector<std::pair<Point, Point>> dangling_edges;
  std::vector<Point> isolated_points;
  bool operator==(const Canonical&) const = default;
};

Canonical canonical_result(const Output& o) {
  Canonical c;
  for (const auto& cycle : o.irreducible) {
    auto& [type, vs] = c.cycles.emplace_back();
    type = cycle.type;
    for (std::size_t i = 0; i < cycle.vertices.size(); ++i) vs.push_back(cycle.exact[2 * i] + " " + cycle.exact[2 * i + 1]);
  }
  c.cycles = canonical(std::move(c.cycles));
  const auto less = [](const Point& p, const Point& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); };
  for (auto [p, q] : o.dangling_edges) c.dangling_edges.push_back(less(q, p) ? std::pair{q, p} : std::pair{p, q});
  std::sort(c.dangling_edges.begin(), c.dangling_edges.end(),
            [&](const auto& e, const auto& f) { return less(e.first, f.first) || (!less(f.first, e.first) && less(e.second, f.second)); });
  c.isolated_points = o.isolated_points;
  std::sort(c.isolated_points.begin(), c.isolated_points.end(), less);
  return c;
}

// On valid input, a fill rule that reads it as OGC does changes nothing: the same result
// (the same exact cycles, the lower-dimensional parts included) for every operation, regular
// and not, on a square with a hole and a square across it, and on squares that overlap,
// touch along edges and touch at corners.
TEST(FillRules, ValidInputGivesWhatTheDefaultPathGives) {
  const auto square = [](double x0, double y0, double x1, double y1) {
    return OgcPolygon{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}};
  };
  const MultiPolygon shapes[] = {{{{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{1, 1}, {1, 3}, {3, 3}, {3, 1}}}}},
                                 {square(2, -1, 5, 2)},
                                 {square(0, 0, 2, 2)},
                                 {square(2, 0, 4, 2)},
                                 {square(2, 2, 4, 4)},
                                 {square(1, 0, 2, 1)},
                                 {square(0.5, 0.5, 1.5, 1.5)},
                                 {square(0, 0, 2, 1)}};
  int with_lower_dimensional_parts = 0;
  for (const auto& k : exact_kernels()) {
    for (const MultiPolygon& a : shapes) {
      for (const MultiPolygon& b : shapes) {
        for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference,
                                   Operation::symmetric_difference}) {
          for (const bool regular : {true, false}) {
            SCOPED_TRACE(k + " " + std::string(operation_name(op)) + (regular ? "" : " non-regular"));
            BooleanOptions plain;
            plain.op = op;
            plain.kernel = k;
            plain.regular = regular;
            plain.exact_coordinates = true;
            const BooleanOutput expected = compute(to_polygon(a), to_polygon(b), plain);
            with_lower_dimensional_parts += !expected.output.dangling_edges.empty() || !expected.output.isolated_points.empty();
            for (const FillRule rule : {FillRule::union_, FillRule::evenodd}) {
              BooleanOptions o = plain;
              o.fill_rule = rule;
              const BooleanOutput got = compute(fill_rule_polygon(a, rule), fill_rule_polygon(b, rule), o);
              EXPECT_EQ(canonical_result(got.output), canonical_result(expected.output));
            }
          }
        }
      }
    }
  }
  EXPECT_GT(with_lower_dimensional_parts, 0);
}

// Non-regular results with fill rules: the closed-set operation of the regions' closures
// [BRIEF §1]. Hand-derived: where two regions only touch, their intersection is the shared
// edge (a two-sided part) or the shared corner (a one-sided part), whatever the rings'
// crossings elsewhere; the difference and the union keep no lower-dimensional part there.
BooleanOptions non_regular(FillRule rule, const std::string& kernel, Operation op) {
  BooleanOptions o = with(rule, kernel, op);
  o.regular = false;
  return o;
}

TEST(FillRules, NonRegularKeepsWhereTheRegionsOnlyTouch) {
  const Polygon square{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, PolygonType::island};
  const Polygon beside{{{{1, 0}, {2, 0}, {2, 1}, {1, 1}}}, PolygonType::island};
  const Polygon corner{{{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}, PolygonType::island};
  // The bowtie's right triangle (1 1, 2 2, 2 0) has the edge x = 2 that the square beside it
  // runs along the other way.
  const Polygon bowtie{{{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}, PolygonType::island};
  const Polygon right{{{{2, 0}, {3, 0}, {3, 2}, {2, 2}}}, PolygonType::island};
  for (const auto& k : exact_kernels()) {
    for (const FillRule rule : {FillRule::evenodd, FillRule::nonzero}) {
      SCOPED_TRACE(k + " rule " + std::to_string(static_cast<int>(rule)));
      const BooleanOutput edge = compute(square, beside, non_regular(rule, k, Operation::intersection));
      EXPECT_TRUE(edge.output.polygons.empty());
      ASSERT_EQ(edge.output.dangling_edges.size(), 1u);
      const auto [p, q] = edge.output.dangling_edges[0];
      EXPECT_EQ(std::min(p.y, q.y), 0.0);
      EXPECT_EQ(std::max(p.y, q.y), 1.0);
      EXPECT_EQ(p.x, 1.0);
      EXPECT_EQ(q.x, 1.0);
      EXPECT_TRUE(edge.output.isolated_points.empty());
      EXPECT_EQ(area_of(edge), 0);
      EXPECT_TRUE(compute(square, beside, with(rule, k, Operation::intersection)).output.dangling_edges.empty());

      const BooleanOutput point = compute(square, corner, non_regular(rule, k, Operation::intersection));
      EXPECT_TRUE(point.output.polygons.empty());
      EXPECT_TRUE(point.output.dangling_edges.empty());
      ASSERT_EQ(point.output.isolated_points.size(), 1u);
      EXPECT_EQ(point.output.isolated_points[0], (Point{1, 1}));

      const BooleanOutput touch = compute(bowtie, right, non_regular(rule, k, Operation::intersection));
      EXPECT_TRUE(touch.output.polygons.empty());
      ASSERT_EQ(touch.output.dangling_edges.size(), 1u);
      EXPECT_EQ(touch.output.dangling_edges[0].first.x, 2.0);
      EXPECT_EQ(touch.output.dangling_edges[0].second.x, 2.0);
      EXPECT_TRUE(touch.output.isolated_points.empty());
      for (const Operation op : {Operation::union_, Operation::difference}) {
        const BooleanOutput r = compute(bowtie, right, non_regular(rule, k, op));
        EXPECT_TRUE(r.output.dangling_edges.empty()) << operation_name(op);
        EXPECT_TRUE(r.output.isolated_points.empty()) << operation_name(op);
        EXPECT_EQ(area_of(r), op == Operation::union_ ? 4 : 2) << operation_name(op);
      }
    }
  }
}

// A ring's edges are in its region's closure only where a side of them is filled: a square
// traced twice is empty under evenodd (wound twice) and whole under nonzero, so the square
// beside it meets it in their shared edge under nonzero only.
TEST(FillRules, NonRegularClosureIsOfTheFilledRegionNotOfTheRings) {
  const Polygon twice{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}}}, PolygonType::island};
  const Polygon beside{{{{1, 0}, {2, 0}, {2, 1}, {1, 1}}}, PolygonType::island};
  for (const auto& k : exact_kernels()) {
    SCOPED_TRACE(k);
    const BooleanOutput even = compute(twice, beside, non_regular(FillRule::evenodd, k, Operation::intersection));
    EXPECT_TRUE(even.output.polygons.empty());
    EXPECT_TRUE(even.output.dangling_edges.empty());
    EXPECT_TRUE(even.output.isolated_points.empty());
    const BooleanOutput nonzero = compute(twice, beside, non_regular(FillRule::nonzero, k, Operation::intersection));
    EXPECT_TRUE(nonzero.output.polygons.empty());
    EXPECT_EQ(nonzero.output.dangling_edges.size(), 1u);
    // Symmetric difference of closed sets: (A - int B) u (B - int A) keeps the shared edge
    // inside the union of the two squares; no part of it is lower-dimensional.
    const BooleanOutput sym = compute(twice, beside, non_regular(FillRule::nonzero, k, Operation::symmetric_difference));
    EXPECT_EQ(area_of(sym), 2);
    EXPECT_TRUE(sym.output.dangling_edges.empty());
  }
}

TEST(FillRules, InexactKernelsRunOrFailCleanly) {
  const MultiPolygon star = one({{0, 0}, {2, 6}, {4, 0}, {-1, 4}, {5, 4}});
  for (const auto k : kernel_names()) {
    if (is_exact_kernel(k)) continue;
    try {
      const BooleanOutput r = make_valid(star, with(FillRule::evenodd, std::string(k)));
      std::cout << k << ": pentagram evenodd area " << r.stats.area.value_or(-1) << "\n";  // recorded
    } catch (const KernelFailure& e) {
      std::cout << k << ": " << e.what() << "\n";
    }
  }
}

TEST(FillRules, BadOptionsAndInputAreErrors) {
  const Polygon square{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, PolygonType::island};
  EXPECT_THROW(intersection_all({}, with(FillRule::union_, "exact")), InvalidInput);
  EXPECT_THROW(union_all(one({{0, 0}, {1, 0}, {1, std::numeric_limits<double>::quiet_NaN()}}), with(FillRule::union_, "exact")),
               InvalidInput);
  EXPECT_THROW(make_valid(one({{0, 0}, {1, 0}, {1, 1}}), with(FillRule::evenodd, "no-such-kernel")), std::invalid_argument);
  EXPECT_TRUE(union_all({}, with(FillRule::union_, "exact")).output.polygons.empty());
}

}  // namespace
}  // namespace mk
