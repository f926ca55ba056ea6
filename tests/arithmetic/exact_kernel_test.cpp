// The exact kernel's orientation of three vertices among which are crossings
// (ExactKernel::orient_vertices): decided from the crossings' interval boxes when their sign
// is certain, exactly otherwise; it must equal the orientation of the exact rational points
// on random crossings at every scale, on crossings exactly collinear (three segments
// crossing one line: zero, which the boxes never claim) and on such triples moved by an ulp;
// and its comparison of crossings found twice from the same two segments, given in any order.
// [BMP06] (interval filters) [MK89 §3.3]
// Preconditions: none.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "tests/arithmetic/test_support.hpp"

namespace mk {
namespace {

using Vx = ExactKernel::Vertex;

Sign exact_orientation(const Vx& a, const Vx& b, const Vx& c) {
  return RationalKernel::orient2d(ExactKernel::exact(a), ExactKernel::exact(b), ExactKernel::exact(c));
}

// The crossing of segments p0p1 and q0q1 (which cross properly), as the kernel makes it.
Vx crossing(const Point& p0, const Point& p1, const Point& q0, const Point& q1) { return ExactKernel::crossing(p0, p1, q0, q1); }

// Two segments of size about 2^(e+1) that cross properly near c: p0p1 and q0q1.
struct CrossingSegments {
  Point p0, p1, q0, q1;
};
CrossingSegments segments_crossing_near(const Point& c, int e) {
  const double s = std::ldexp(1.0, e + 1);
  return {{c.x - s, c.y - s * 0.25}, {c.x + s, c.y + s * 0.25}, {c.x - s * 0.5, c.y + s}, {c.x + s * 0.375, c.y - s}};
}

struct Tally {
  int by_boxes = 0;
  int exactly = 0;
};

void check(const Vx& a, const Vx& b, const Vx& c, Tally& t, const char* what, int i) {
  const Sign expected = exact_orientation(a, b, c);
  const Sign boxes = ExactKernel::orient_boxes(a, b, c);
  // When the boxes return zero the first assertion holds trivially: the second, on the whole
  // filtered orientation, is then the one with teeth.
  ASSERT_TRUE(boxes == Sign::zero || boxes == expected) << what << " case " << i;
  ASSERT_EQ(ExactKernel::orient_vertices(a, b, c), expected) << what << " case " << i;
  (boxes == Sign::zero ? t.exactly : t.by_boxes) += 1;
}

TEST(ExactKernelOrientation, RandomCrossingsAtEveryScale) {
  std::mt19937_64 rng(31);
  Tally t;
  for (int i = 0; i < 20000; ++i) {
    const int e = static_cast<int>(rng() % 800) - 400;
    const auto r = [&] { return test::random_double(rng, e - 2, e); };
    // Segments through a common region: each vertex a crossing of a random segment with the
    // segment (-s, 0) (s, 0) turned by a random angle, or an input point.
    const auto vertex = [&]() -> Vx {
      if (rng() % 4 == 0) return ExactKernel::vertex({r(), r()});
      const auto [p0, p1, q0, q1] = segments_crossing_near({r(), r()}, e);
      return crossing(p0, p1, q0, q1);
    };
    const Vx a = vertex(), b = vertex(), c = vertex();
    if (!a.is_crossing && !b.is_crossing && !c.is_crossing) continue;
    check(a, b, c, t, "random", i);
  }
  std::printf("by the boxes %d, exactly %d\n", t.by_boxes, t.exactly);
  EXPECT_GT(t.by_boxes, 10000);
}

TEST(ExactKernelOrientation, CollinearCrossingsAndOneUlpAway) {
  std::mt19937_64 rng(32);
  Tally t;
  int zeros = 0;
  for (int i = 0; i < 5000; ++i) {
    const int e = static_cast<int>(rng() % 200) - 100;
    const auto r = [&] { return test::random_double(rng, e - 3, e); };
    // The line p -> q, and three segments crossing it: their crossings lie on it exactly.
    Point p{r(), r()}, q{r(), r()};
    if (p.x == q.x && p.y == q.y) continue;
    const Point d{q.x - p.x, q.y - p.y};
    Vx on[3];
    for (int k = 0; k < 3; ++k) {
      const double s = 0.2 + 0.3 * k;
      const Point m{p.x + s * d.x, p.y + s * d.y};  // near the line (rounded), not on it
      const Point n{-d.y, d.x};                      // across it
      on[k] = crossing(p, q, {m.x - n.x, m.y - n.y}, {m.x + n.x, m.y + n.y});
    }
    check(on[0], on[1], on[2], t, "collinear", i);
    zeros += exact_orientation(on[0], on[1], on[2]) == Sign::zero;
    // The line's end moved by an ulp for the third crossing: no longer collinear, nearly.
    Point q2 = q;
    q2.y = std::nextafter(q2.y, (rng() & 1) ? HUGE_VAL : -HUGE_VAL);
    const Point m{p.x + 0.7 * d.x, p.y + 0.7 * d.y};
    const Vx off = crossing(p, q2, {m.x + d.y, m.y - d.x}, {m.x - d.y, m.y + d.x});
    check(on[0], on[1], off, t, "one ulp away", i);
    // An input point on the line's end with two crossings on the line.
    check(on[0], on[2], ExactKernel::vertex(q), t, "with the line's end", i);
  }
  std::printf("by the boxes %d, exactly %d, collinear triples %d\n", t.by_boxes, t.exactly, zeros);
  EXPECT_GT(zeros, 4000);  // the boxes never decide those: the exact stage says zero
  EXPECT_GT(t.exactly, 4000);
}

TEST(ExactKernelComparison, OneCrossingFoundTwiceIsOnePoint) {
  std::mt19937_64 rng(33);
  int distinct_checked = 0;
  for (int i = 0; i < 5000; ++i) {
    const int e = static_cast<int>(rng() % 400) - 200;
    const auto r = [&] { return test::random_double(rng, e - 2, e); };
    const auto [p0, p1, q0, q1] = segments_crossing_near({r(), r()}, e);
    const Vx u = crossing(p0, p1, q0, q1);
    for (const Vx& v : {crossing(q0, q1, p0, p1), crossing(p1, p0, q1, q0), crossing(q1, q0, p0, p1)}) {
      ASSERT_TRUE(ExactKernel::same_segments(u, v)) << "case " << i;
      ASSERT_EQ(ExactKernel::compare_vertices(u, v), Sign::zero) << "case " << i;
    }
    // Another segment through the same crossing point's neighbourhood: not the same pair,
    // decided as the rationals say.
    const Point q2{q1.x, std::nextafter(q1.y, HUGE_VAL)};
    const Vx w = crossing(p0, p1, q0, q2);
    ASSERT_FALSE(ExactKernel::same_segments(u, w));
    const Sign expected = RationalKernel::compare_vertices(ExactKernel::exact(u), ExactKernel::exact(w));
    ASSERT_EQ(ExactKernel::compare_vertices(u, w), expected) << "case " << i;
    distinct_checked += expected != Sign::zero;
  }
  EXPECT_GT(distinct_checked, 4000);
}

// Nearly parallel segments (a lattice line and its copy turned by a rounded angle) cross at
// points whose interval boxes are wide; the kernel then tightens them from the nearest
// doubles. Every box must contain the exact crossing, and the orders and orientations of
// such crossings, of crossings a few ulps apart and of the segments' own end points must
// be what the rationals say, at every scale and with the coordinates' magnitudes far apart
// (the exact stage scales all of a predicate's doubles by one power of two).
TEST(ExactKernelComparison, NearlyParallelCrossingsAndMixedMagnitudes) {
  std::mt19937_64 rng(34);
  int tightened = 0, compared = 0, decided_exactly = 0;
  Tally orientations;
  for (int i = 0; i < 4000; ++i) {
    const int e = static_cast<int>(rng() % 1200) - 600;
    const double s = std::ldexp(1.0, e);
    // A segment p0p1 and its copy turned about a point of it by about 2^-40 radians.
    const Point p0{test::random_double(rng, e - 2, e), test::random_double(rng, e - 2, e)};
    const Point p1{p0.x + s * (1 + 0.25 * (rng() % 4)), p0.y + s * 0.5 * (rng() % 3)};
    const double angle = std::ldexp(1.0 + (rng() % 1024) / 1024.0, -40 - static_cast<int>(rng() % 8));
    const double f = 0.1 + 0.8 * (rng() % 1000) / 1000.0;
    const Point c{p0.x + f * (p1.x - p0.x), p0.y + f * (p1.y - p0.y)};
    const auto turned = [&](const Point& p, double a) {
      const double dx = p.x - c.x, dy = p.y - c.y;
      return Point{c.x + dx * std::cos(a) - dy * std::sin(a), c.y + dx * std::sin(a) + dy * std::cos(a)};
    };
    const Point q0 = turned(p0, angle), q1 = turned(p1, angle);
    const Point r0 = turned(p0, -angle * 0.75), r1 = turned(p1, -angle * 0.75);
    if (RationalKernel::orient2d(RationalKernel::point(p0), RationalKernel::point(p1), RationalKernel::point(q0)) ==
            RationalKernel::orient2d(RationalKernel::point(p0), RationalKernel::point(p1), RationalKernel::point(q1)) ||
        RationalKernel::orient2d(RationalKernel::point(p0), RationalKernel::point(p1), RationalKernel::point(r0)) ==
            RationalKernel::orient2d(RationalKernel::point(p0), RationalKernel::point(p1), RationalKernel::point(r1))) {
      continue;  // rounding made them miss each other: no proper crossing
    }
    const Vx u = crossing(p0, p1, q0, q1), w = crossing(p0, p1, r0, r1);
    for (const Vx* v : {&u, &w}) {
      const RationalPoint x = ExactKernel::exact(*v);
      ASSERT_TRUE(mpq_class(v->lo[0]) <= x.x && x.x <= mpq_class(v->hi[0]) && mpq_class(v->lo[1]) <= x.y &&
                  x.y <= mpq_class(v->hi[1]))
          << "case " << i << ": the box misses the crossing";
      tightened += v->hi[0] <= std::nextafter(std::nextafter(v->lo[0], HUGE_VAL), HUGE_VAL);
    }
    // Far from the first segment's scale: a point 2^300 times larger or smaller.
    const double far = std::ldexp(1.0, (rng() & 1) ? 300 : -300);
    // The crossing's nearest doubles and their neighbours: inside its box, for the exact stage.
    const Point n = ExactKernel::approx(u);
    const Vx others[] = {w,
                         ExactKernel::vertex(p0),
                         ExactKernel::vertex(c),
                         ExactKernel::vertex({c.x * far, c.y}),
                         ExactKernel::vertex(n),
                         ExactKernel::vertex({std::nextafter(n.x, HUGE_VAL), n.y}),
                         ExactKernel::vertex({n.x, std::nextafter(n.y, -HUGE_VAL)})};
    for (const Vx& o : others) {
      const Sign expected = RationalKernel::compare_vertices(ExactKernel::exact(u), ExactKernel::exact(o));
      ASSERT_EQ(ExactKernel::compare_vertices(u, o), expected) << "case " << i;
      ASSERT_EQ(ExactKernel::compare_vertices(o, u), -expected) << "case " << i;
      ++compared;
      decided_exactly += u.hi[0] >= o.lo[0] && o.hi[0] >= u.lo[0] && u.hi[1] >= o.lo[1] && o.hi[1] >= u.lo[1];
    }
    check(u, w, ExactKernel::vertex(p1), orientations, "nearly parallel", i);
    check(u, ExactKernel::vertex(n), ExactKernel::vertex({c.x * far, c.y * far}), orientations, "far", i);
  }
  std::printf("%d boxes two ulps wide, %d comparisons, %d with overlapping boxes; orientations by the boxes %d, exactly %d\n",
              tightened, compared, decided_exactly, orientations.by_boxes, orientations.exactly);
  EXPECT_GT(tightened, 2000);
  EXPECT_GT(decided_exactly, 2000);
}

}  // namespace
}  // namespace mk
