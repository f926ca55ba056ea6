// The box certificate of rounded output (core/rounding_boxes.hpp): its floating-point
// separation tests never clear a pair that meets (against exact rational arithmetic, on
// pairs at the edge of touching); it never certifies a rounding the full OGC check finds
// invalid (near-degenerate triangles, where rounding breaks hundreds of results); its grid
// finds every pair all pairs would; and it certifies large random results (stars), as the
// full check finds them, on any number of threads.
// [HP02] (vertices away from edges they are not on) [GM98] [Sh97] [OGC06-103 §6.1.11]
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"
#include "core/ogc_validity.hpp"
#include "core/rounding_boxes.hpp"
#include "core/rounding_motion.hpp"
#include "core/to_output.hpp"
#include "tests/core/rounding_cases.hpp"

namespace mk {
namespace {

using test::ends_meet_exactly;
using test::meets_exactly;
using test::random_triangle;
using test::round_result;
using test::test_seed;

using detail::RoundedVertexBox;

TEST(RoundingBoxes, NextUpIsNextafter) {
  const double values[] = {0.0, -0.0, 1.0, -1.0, 0x1p-1074, -0x1p-1074, 0x1p-1022, DBL_MAX, -DBL_MAX, 3.7e-310, -2.5, HUGE_VAL, -HUGE_VAL};
  for (const double v : values) {
    EXPECT_EQ(detail::next_up(v), std::nextafter(v, HUGE_VAL)) << v;
    EXPECT_EQ(detail::next_down(v), std::nextafter(v, -HUGE_VAL)) << v;
  }
  EXPECT_TRUE(std::isnan(detail::next_up(std::nan(""))));
}

TEST(RoundingBoxes, SeparationIsNeverClaimedForBoxesThatMeet) {
  std::mt19937_64 rng(test_seed(29));
  std::uniform_real_distribution<double> u(-1, 1);
  // Half-sizes from none to large, in ulps of the coordinates and beyond.
  const auto half = [&] {
    const int k = static_cast<int>(rng() % 4);
    return k == 0 ? 0.0 : std::ldexp(1.0 + u(rng) * 0.5, -static_cast<int>(rng() % 60) - 4);
  };
  const double nudges[] = {-1e-9, -1e-15, -1e-16, 0, 1e-16, 1e-15, 1e-13, 1e-9};
  int cleared = 0, far_cleared = 0, far = 0;
  for (int i = 0; i < 40000; ++i) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 40) - 20);
    RoundedVertexBox a{{u(rng) * scale, u(rng) * scale}, half(), half()};
    RoundedVertexBox b{{u(rng) * scale, u(rng) * scale}, half(), half()};
    if (i % 5 == 0) b.at.y = a.at.y;  // level and vertical edges
    if (i % 7 == 0) b.at.x = a.at.x;
    RoundedVertexBox v{{0, 0}, half(), half()};
    const double tx = v.rx + std::max(a.rx, b.rx), ty = v.ry + std::max(a.ry, b.ry);
    const double nudge = nudges[rng() % std::size(nudges)];
    const double s = rng() % 3 == 0 ? static_cast<double>(rng() % 2) : (u(rng) + 1) / 2;
    const double dx = b.at.x - a.at.x, dy = b.at.y - a.at.y;
    const bool side = rng() % 2 == 0;
    if (side) {
      // On the widened segment's side, nudged in or out along the normal.
      const double len = std::hypot(dx, dy);
      if (len == 0) continue;
      const double reach = (std::abs(dx) * ty + std::abs(dy) * tx) / len;
      const double off = reach * (1 + nudge) + nudge * scale;
      v.at = {a.at.x + s * dx - dy / len * off, a.at.y + s * dy + dx / len * off};
    } else {
      // By an end's corner, nudged.
      const RoundedVertexBox& e = s < 0.5 ? a : b;
      v.at = {e.at.x + (tx + nudge * scale) * (rng() % 2 ? 1 : -1) * (1 + nudge), e.at.y + (ty + nudge * scale) * (rng() % 2 ? 1 : -1)};
    }
    const bool clear = detail::clear_of_edge(v, a, b);
    const bool meets = meets_exactly(v, a, b);
    ASSERT_FALSE(clear && meets) << "case " << i;
    cleared += clear;
    if (side && nudge >= 1e-9) {
      ++far;
      far_cleared += clear;
    }
    ASSERT_FALSE(detail::ends_apart(a, b) && ends_meet_exactly(a, b)) << "case " << i;
  }
  std::printf("cleared %d, nudged out from a side by 1e-9: %d of %d\n", cleared, far_cleared, far);
  EXPECT_GT(far_cleared, far * 9 / 10);  // the margins cost nothing visible at 1e-9
}

// A star-shaped polygon of n vertices about c.
Polygon random_star(std::mt19937_64& rng, int n, Point c) {
  Polygon p;
  p.rings.push_back(test::star_ring(rng, n, c));
  return p;
}

struct Verdicts {
  bool grid = false;       // the certificate, pairs from the grid
  bool all_pairs = false;  // the certificate, every pair
  bool full = false;       // the full OGC check of the rounded polygons
};

Verdicts verdicts(const BooleanResult<ExactKernel>& r, bool with_all_pairs, unsigned threads = 1) {
  const auto rounded = round_result(r);
  const auto polygon_cycles = result_polygon_cycles(r);
  std::vector<RoundedVertexBox> boxes;
  std::vector<std::array<int, 2>> edges;
  detail::rounded_vertex_boxes(r, rounded, polygon_cycles, boxes, edges);
  Verdicts v;
  v.grid = detail::boxes_keep_topology(boxes, edges, false, threads);
  v.all_pairs = with_all_pairs && detail::boxes_keep_topology(boxes, edges, true);
  MultiPolygon polygons;
  for (const auto& cycles : polygon_cycles) {
    OgcPolygon p{rounded[static_cast<std::size_t>(cycles[0])], {}};
    for (std::size_t h = 1; h < cycles.size(); ++h) p.holes.push_back(rounded[static_cast<std::size_t>(cycles[h])]);
    polygons.push_back(std::move(p));
  }
  v.full = check_ogc_validity<ExactKernel>(polygons).valid();
  return v;
}

TEST(RoundingBoxes, NeverCertifiesWhatTheFullCheckFindsInvalid) {
  std::mt19937_64 rng(test_seed(17));
  int certified = 0, refused_invalid = 0, refused_valid = 0;
  for (int i = 0; i < 3000; ++i) {
    const bool degenerate = i % 2 == 0;
    const Polygon a = random_triangle(rng, degenerate);
    const Polygon b = random_triangle(rng, degenerate);
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
      Options opt;
      opt.op = op;
      opt.regular = i % 3 != 0;
      BooleanResult<ExactKernel> r;
      try {
        r = boolean_op<ExactKernel>(a, b, opt);
      } catch (const InvalidInput&) {
        continue;  // a triangle collapsed to a segment
      }
      const Verdicts v = verdicts(r, true);
      ASSERT_EQ(v.grid, v.all_pairs) << "case " << i << " op " << operation_name(op);
      ASSERT_TRUE(!v.grid || v.full) << "case " << i << " op " << operation_name(op);
      // What to_output reports: the certificates, then the full check.
      bool collapsed = false;  // a two-sided part rounded to one point
      for (const auto& c : r.cycles) {
        collapsed = collapsed || (c.vertices.size() == 2 && ExactKernel::approx(r.vertex(c.vertices[0])) ==
                                                                 ExactKernel::approx(r.vertex(c.vertices[1])));
      }
      ASSERT_EQ((to_output<ExactKernel, ExactKernel>(r, false).rounded_valid), std::optional<bool>(v.full && !collapsed))
          << "case " << i << " op " << operation_name(op);
      (v.grid ? certified : v.full ? refused_valid : refused_invalid) += 1;
    }
  }
  std::printf("certified %d, refused and invalid %d, refused and valid %d\n", certified, refused_invalid, refused_valid);
  EXPECT_GT(refused_invalid, 50);  // the near-degenerate cases do break under rounding
  EXPECT_GT(certified, 2000);
}

// Shared edges and touching corners, regular and not: nothing moves, and the certificate's
// verdict must be the full check's (the exact result is valid: its precondition).
TEST(RoundingBoxes, TouchingShapesAgreeWithTheFullCheck) {
  const auto square = [](double x0, double y0, double x1, double y1) {
    Polygon p;
    p.rings.push_back({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
    return p;
  };
  const Polygon shapes[] = {square(0, 0, 2, 2), square(2, 0, 4, 2), square(2, 2, 4, 4), square(0, 0, 1, 1),
                            square(1, 0, 2, 1), square(0.5, 0.5, 1.5, 1.5), square(0, 0, 2, 1)};
  for (const Polygon& a : shapes) {
    for (const Polygon& b : shapes) {
      for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference, Operation::symmetric_difference}) {
        for (const bool regular : {true, false}) {
          Options opt;
          opt.op = op;
          opt.regular = regular;
          const Verdicts v = verdicts(boolean_op<ExactKernel>(a, b, opt), true);
          EXPECT_EQ(v.grid, v.all_pairs);
          EXPECT_EQ(v.grid, v.full) << operation_name(op) << (regular ? "" : " (non-regular)");
        }
      }
    }
  }
}

// Many input points and few crossings (the certificate then lists the edges at crossings
// in the grid and each still vertex looks in its cell): a ring of 2000 points crossed by a
// triangle whose edge passes a few ulps from one of them, or through it.
TEST(RoundingBoxes, FewCrossingsAmongManyPointsAgreeWithAllPairs) {
  std::mt19937_64 rng(test_seed(53));
  std::uniform_real_distribution<double> u(0, 1);
  int certified = 0, refused = 0;
  for (int i = 0; i < 60; ++i) {
    Polygon ring;
    ring.rings.emplace_back();
    const int n = 2000;
    for (int k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * k / n;
      const double radius = 10 * (1 + 0.05 * u(rng));
      ring.rings.back().push_back({radius * std::cos(t), radius * std::sin(t)});
    }
    const Point near = ring.rings.back()[static_cast<std::size_t>(rng() % n)];
    const int ulps = static_cast<int>(rng() % 9) - 4;
    Point through = near;
    for (int k = 0; k < std::abs(ulps); ++k) through.y = std::nextafter(through.y, ulps > 0 ? HUGE_VAL : -HUGE_VAL);
    Polygon tri;
    // The edge far -> inside passes `through` (up to its own rounding).
    const Point d{2 * near.x + 0.37, 2 * near.y - 0.11};
    const Point far{through.x + d.x, through.y + d.y}, inside{through.x - 0.5 * d.x, through.y - 0.5 * d.y};
    tri.rings.push_back({far, inside, {inside.x + 0.3, inside.y - 0.2}});
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference}) {
      Options opt;
      opt.op = op;
      BooleanResult<ExactKernel> r;
      try {
        r = boolean_op<ExactKernel>(ring, tri, opt);
      } catch (const InvalidInput&) {
        continue;
      }
      const Verdicts v = verdicts(r, true);
      ASSERT_EQ(v.grid, v.all_pairs) << "case " << i << " op " << operation_name(op);
      ASSERT_TRUE(!v.grid || v.full) << "case " << i << " op " << operation_name(op);
      (v.grid ? certified : refused) += 1;
    }
  }
  std::printf("certified %d, refused %d\n", certified, refused);
  EXPECT_GT(certified, 0);
}

TEST(RoundingBoxes, StarsAreCertifiedOnAnyNumberOfThreads) {
  std::mt19937_64 rng(test_seed(41));
  for (const int n : {300, 3000}) {
    const Polygon a = random_star(rng, n, {0, 0});
    const Polygon b = random_star(rng, n, {30, 10});
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference}) {
      Options opt;
      opt.op = op;
      const BooleanResult<ExactKernel> r = boolean_op<ExactKernel>(a, b, opt);
      const Verdicts one = verdicts(r, n <= 300);
      EXPECT_TRUE(one.full);
      EXPECT_TRUE(one.grid) << "n " << n << " op " << operation_name(op);
      if (n <= 300) {
        EXPECT_TRUE(one.all_pairs);
      }
      EXPECT_EQ(verdicts(r, false, 2).grid, one.grid);
      std::printf("n %d %s: %d crossings\n", n, std::string(operation_name(op)).c_str(), static_cast<int>(r.stats.crossings));
    }
  }
}

// A lattice of 130 x 130 squares (67,600 moved vertices and edges: the grid's lists are
// made in bands of rows on several threads) whose vertex boxes keep clear of the other
// squares, then with one square's upper right corner moved right onto the corner of the
// square beside it, in every row of squares (so at every band's edges): the same verdict on
// 1 and 2 threads (and 3 in some rows), and the one the construction gives (the corners
// meet; in the last column there is no square beside it and the result stays valid).
TEST(RoundingBoxes, LargeLatticesTheSameVerdictOnAnyNumberOfThreads) {
  std::mt19937_64 rng(test_seed(83));
  constexpr int side = 130;
  std::vector<RoundedVertexBox> boxes;
  std::vector<std::array<int, 2>> edges;
  for (int i = 0; i < side; ++i) {
    for (int j = 0; j < side; ++j) {
      const int first = static_cast<int>(boxes.size());
      const double x = i, y = j;  // a square of side 0.75 at (x, y), 0.25 from its neighbours
      for (const Point p : {Point{x, y}, Point{x + 0.75, y}, Point{x + 0.75, y + 0.75}, Point{x, y + 0.75}}) {
        boxes.push_back({p, 0x1p-40, 0x1p-40});
      }
      for (int k = 0; k < 4; ++k) edges.push_back({first + k, first + (k + 1) % 4});
    }
  }
  for (const unsigned threads : {1u, 2u, 3u}) EXPECT_TRUE(detail::boxes_keep_topology(boxes, edges, false, threads));
  int last_column = 0;
  for (int j = 0; j < side; ++j) {
    const int i = j % 16 == 5 ? side - 1 : static_cast<int>(rng() % (side - 1));
    last_column += i == side - 1;
    const std::size_t corner = static_cast<std::size_t>(4 * (i * side + j) + 2);
    const RoundedVertexBox kept = boxes[corner];
    boxes[corner].at.x += 0.25;  // onto the upper left corner of square (i + 1, j)
    const bool expected = i == side - 1;
    for (const unsigned threads : {1u, 2u, 3u}) {
      if (threads == 3 && j % 8 != 0) continue;
      EXPECT_EQ(detail::boxes_keep_topology(boxes, edges, false, threads), expected)
          << "square " << i << " " << j << ", " << threads << " threads";
    }
    boxes[corner] = kept;
  }
  EXPECT_GE(last_column, 8);
}

// Long, shallow edges (each crossing a row of many cells, cut into a few long pieces, see
// boxes_keep_topology) with moved vertices at chosen distances from their middles, above a
// lattice of small squares that fills the grid: the grid's verdict is every pair's.
TEST(RoundingBoxes, LongShallowEdgesAgreeWithAllPairs) {
  std::mt19937_64 rng(test_seed(97));
  std::uniform_real_distribution<double> u(0, 1);
  int certified = 0, refused = 0;
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<RoundedVertexBox> boxes;
    std::vector<std::array<int, 2>> edges;
    for (int i = 0; i < 40; ++i) {
      for (int j = 0; j < 10; ++j) {
        const int first = static_cast<int>(boxes.size());
        const double x = 25 * i, y = 20 + 8 * j;
        for (const Point p : {Point{x, y}, Point{x + 3, y}, Point{x + 3, y + 3}, Point{x, y + 3}}) boxes.push_back({p, 0x1p-30, 0x1p-30});
        for (int k = 0; k < 4; ++k) edges.push_back({first + k, first + (k + 1) % 4});
      }
    }
    for (int e = 0; e < 6; ++e) {
      // An edge from x = 0 to x = 1000 rising by up to 25 (a few rows of cells) in its band
      // of y below the lattice, its ends not moved.
      const double y0 = -200 + 30 * e, rise = 25 * u(rng);
      const int a = static_cast<int>(boxes.size());
      boxes.push_back({{0, y0}, 0, 0});
      boxes.push_back({{1000, y0 + rise}, 0, 0});
      edges.push_back({a, a + 1});
      // A short moved edge whose first end lies at distance d from the long edge's line near
      // a point t along it, with a box of half-size h: met when d is within about h.
      const double t = u(rng), h = std::ldexp(1.0, -20 - static_cast<int>(rng() % 6));
      const double d = h * (rng() % 3 == 0 ? 0.5 : 1.5) * (rng() % 2 == 0 ? 1 : -1);
      const Point p{1000 * t, y0 + rise * t + d};
      const int c = static_cast<int>(boxes.size());
      boxes.push_back({p, h, h});
      boxes.push_back({{p.x + 0.5, p.y + (d > 0 ? 0.5 : -0.5)}, h, h});
      edges.push_back({c, c + 1});
    }
    const bool grid = detail::boxes_keep_topology(boxes, edges, false, 1 + trial % 2);
    ASSERT_EQ(grid, detail::boxes_keep_topology(boxes, edges, true)) << "trial " << trial;
    (grid ? certified : refused) += 1;
  }
  EXPECT_GT(certified, 0);
  EXPECT_GT(refused, 0);
}

// points_clear_of_edges (rule I of the rounding certificate): points of two stars, scaled
// by 1, 2^-400 or 2^400 (products of differences stay normal), with boxes of one half-size
// h, against the stars' edges, and extra points put at a few multiples of h from random
// edges (along the normal from a point of the edge, or just beyond an end along its line:
// boxes meet up to 2h); also points on one horizontal or vertical line (a grid of one row
// or one column) with a path along them. Whenever it clears them, no point's box meets the
// hull of an edge it does not end (exact rational arithmetic on every pair whose bounds are
// not apart); whenever the general certificate over all pairs clears them, it does too;
// and both outcomes occur. (Visiting every other row is caught here.)
TEST(RoundingBoxes, PointsClearOfEdgesNeverClearsWhatMeets) {
  std::mt19937_64 rng(test_seed(41));
  std::uniform_real_distribution<double> u(0, 1);
  int certified = 0, refused = 0;
  long exact_pairs = 0;
  for (int trial = 0; trial < 36; ++trial) {
    const double scale = trial % 3 == 0 ? 1.0 : (trial % 3 == 1 ? 0x1p-400 : 0x1p400);
    std::vector<Point> points;
    std::vector<std::array<int, 2>> edges;
    const auto add_ring = [&](const std::vector<Point>& ring) {
      const int first = static_cast<int>(points.size());
      for (const Point& p : ring) points.push_back({p.x * scale, p.y * scale});
      const int n = static_cast<int>(ring.size());
      for (int k = 0; k < n; ++k) edges.push_back({first + k, first + (k + 1) % n});
    };
    const int layout = trial % 4;
    if (layout < 3) {
      add_ring(test::star_ring(rng, 150, {0, 0}));
      add_ring(test::star_ring(rng, 150, {30, 10}));
    } else {  // one line: a path along it
      const bool vertical = trial % 8 == 3;
      const int first = static_cast<int>(points.size());
      for (int k = 0; k < 200; ++k) {
        const double t = (k + 0.5 * u(rng)) * scale;
        points.push_back(vertical ? Point{7 * scale, t} : Point{t, -3 * scale});
        if (k > 0) edges.push_back({first + k - 1, first + k});
      }
    }
    const double h = std::ldexp(scale, -40 + static_cast<int>(rng() % 12));
    const std::size_t planted = layout == 0 ? 0 : 1 + rng() % 2;
    for (std::size_t i = 0; i < planted; ++i) {
      const auto& [ia, ib] = edges[rng() % edges.size()];
      const Point a = points[static_cast<std::size_t>(ia)], b = points[static_cast<std::size_t>(ib)];
      const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
      const double d = h * std::array<double, 6>{0.3, 1.5, 2.5, 3, 10, 1000}[rng() % 6];
      if (rng() % 4 == 0) {  // beyond b along the line
        points.push_back({b.x + dx / len * d, b.y + dy / len * d});
      } else {
        const double t = u(rng);
        points.push_back({a.x + t * dx - dy / len * d, a.y + t * dy + dx / len * d});
      }
    }
    const bool cleared = detail::points_clear_of_edges(points, h, edges, 1 + trial % 2);
    std::vector<RoundedVertexBox> boxes;
    for (const Point& p : points) boxes.push_back({p, h, h});
    if (detail::boxes_keep_topology(boxes, edges, true)) {
      EXPECT_TRUE(cleared) << "trial " << trial;
    }
    if (cleared) {
      for (const auto& [ia, ib] : edges) {
        const auto& a = boxes[static_cast<std::size_t>(ia)];
        const auto& b = boxes[static_cast<std::size_t>(ib)];
        const detail::BoxBounds hull = detail::hull_bounds(detail::vertex_bounds(a), detail::vertex_bounds(b));
        for (std::size_t k = 0; k < boxes.size(); ++k) {
          if (static_cast<int>(k) == ia || static_cast<int>(k) == ib || detail::bounds_apart(detail::vertex_bounds(boxes[k]), hull)) {
            continue;
          }
          ++exact_pairs;
          ASSERT_FALSE(meets_exactly(boxes[k], a, b)) << "trial " << trial << ": point " << k << " meets edge " << ia << "-" << ib;
        }
      }
    }
    (cleared ? certified : refused) += 1;
  }
  std::printf("cleared %d, refused %d; %ld pairs checked exactly\n", certified, refused, exact_pairs);
  EXPECT_GT(certified, 0);
  EXPECT_GT(refused, 0);
}

// The exact certificate of few crossings (rounding_motion.hpp) over a result of many input
// points whose crossings lie on opposite sides of it: a ring of 3000 points, and two thin
// triangles outside it, each with an edge along the ring's tangent at a ring point p and a
// few ulps from p (p pokes through it or not: a cap of three points within ulps of each
// other, which rounding may collapse). The certificate's verdict (what to_output reports)
// must be the full check's, valid or not. One ring in four has 20000 points, enough for the
// certificate's pass over the edges to split over two threads (the caps then fall in
// different blocks): its verdict must not depend on the number of threads.
TEST(RoundingBoxes, CrossingsOnOppositeSidesAgreeWithTheFullCheck) {
  std::mt19937_64 rng(test_seed(71));
  std::uniform_real_distribution<double> u(0, 1);
  int valid = 0, invalid = 0, cases = 0, large_valid = 0, large_invalid = 0;
  for (int i = 0; i < 60; ++i) {
    Polygon ring;
    ring.rings.emplace_back();
    const bool large = i % 4 == 0;
    const std::size_t n = large ? 20000 : 3000;
    static_assert(20000 > kParallelWork);
    for (std::size_t k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * static_cast<double>(k) / n;
      const double radius = 10 * (1 + 0.05 * u(rng));
      ring.rings.back().push_back({radius * std::cos(t), radius * std::sin(t)});
    }
    const auto& pts = ring.rings.back();
    // A point bulging out of the chord of its neighbours, from `start` on.
    const auto bulging = [&](std::size_t start) {
      for (std::size_t k = start;; k = (k + 1) % n) {
        const Point& a = pts[(k + n - 1) % n];
        const Point& b = pts[(k + 1) % n];
        const Point& c = pts[k];
        if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) < 0) return k;  // c right of a->b: outward (ccw ring)
      }
    };
    Polygon caps;
    for (const std::size_t at : {bulging(rng() % n), bulging((rng() % n + n / 2) % n)}) {
      const Point& a = pts[(at + n - 1) % n];
      const Point& b = pts[(at + 1) % n];
      Point p = pts[at];
      const int ulps = static_cast<int>(rng() % 7) - 3;
      const Point out{p.x / 10, p.y / 10};  // outward, about unit length
      for (int k = 0; k < std::abs(ulps); ++k) {
        p.x = std::nextafter(p.x, (ulps > 0) == (out.x > 0) ? HUGE_VAL : -HUGE_VAL);
        p.y = std::nextafter(p.y, (ulps > 0) == (out.y > 0) ? HUGE_VAL : -HUGE_VAL);
      }
      const Point d{b.x - a.x, b.y - a.y};  // the tangent (the neighbours' chord)
      caps.rings.push_back({{p.x - 20 * d.x, p.y - 20 * d.y}, {p.x + 20 * d.x, p.y + 20 * d.y}, {p.x + out.x, p.y + out.y}});
    }
    for (const Operation op : {Operation::intersection, Operation::union_, Operation::difference}) {
      Options opt;
      opt.op = op;
      BooleanResult<ExactKernel> r;
      try {
        r = boolean_op<ExactKernel>(ring, caps, opt);
      } catch (const InvalidInput&) {
        continue;
      }
      ++cases;
      ASSERT_LE(r.arrangement.num_crossings(), static_cast<int>(kFewCrossingsForExactCertificate));
      const Verdicts v = verdicts(r, false);
      ASSERT_EQ((to_output<ExactKernel, ExactKernel>(r, false).rounded_valid), std::optional<bool>(v.full))
          << "case " << i << " op " << operation_name(op);
      (v.full ? valid : invalid) += 1;
      if (large) {
        ASSERT_EQ((to_output<ExactKernel, ExactKernel>(r, false, 2).rounded_valid), std::optional<bool>(v.full))
            << "case " << i << " op " << operation_name(op);
        const auto rounded = round_result(r);
        const std::size_t few = kFewCrossingsForExactCertificate;
        const bool one = rounding_keeps_topology(r, rounded, few, 1);
        ASSERT_EQ(rounding_keeps_topology(r, rounded, few, 2), one) << "case " << i << " op " << operation_name(op);
        ASSERT_TRUE(!one || v.full) << "case " << i << " op " << operation_name(op);
        (v.full ? large_valid : large_invalid) += 1;
      }
    }
  }
  std::printf("cases %d: valid %d, invalid %d; of 20000 points: valid %d, invalid %d\n", cases, valid, invalid, large_valid,
              large_invalid);
  EXPECT_GT(cases, 150);
  EXPECT_GT(valid, 0);
  EXPECT_GT(invalid, 0);
  EXPECT_GT(large_valid, 0);
  EXPECT_GT(large_invalid, 0);
}
}  // namespace
}  // namespace mk
