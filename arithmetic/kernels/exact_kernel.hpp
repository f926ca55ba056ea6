// ExactKernel: exact decisions on input points by adaptive predicates, and crossing points
// kept implicit (their two defining segments) with a rigorous interval box; comparisons of
// implicit points are filtered by the boxes and decided exactly with GMP when they overlap.
// [At20] (indirect predicates) [Sh97] [MK89 §3.3]
// Preconditions: finite double input. Crossings are made only for segments that cross
// properly (so the denominator is never zero).
#pragma once

#include <gmpxx.h>

#include <array>
#include <cfenv>
#include <cmath>
#include <string>
#include <string_view>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/crossing_rounding.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/rounding_guard.hpp"
#include "kernel/kernel.hpp"

namespace mk {

// An input point (a0 alone) or the crossing of segments a0a1 and b0b1, with a box that
// certainly contains it.
struct ExactVertex {
  Point a0, a1, b0, b1;
  std::array<double, 2> lo{};
  std::array<double, 2> hi{};
  bool is_crossing = false;
};

struct ExactKernel {
  using Point = mk::Point;
  using Vertex = ExactVertex;
  static constexpr std::string_view name = "exact";
  static constexpr bool is_exact = true;

  static Point point(const mk::Point& p) { return p; }
  static Sign compare_x(const Point& a, const Point& b) { return a.x < b.x ? Sign::negative : (b.x < a.x ? Sign::positive : Sign::zero); }
  static Sign compare_y(const Point& a, const Point& b) { return a.y < b.y ? Sign::negative : (b.y < a.y ? Sign::positive : Sign::zero); }
  static Sign orient2d(const Point& a, const Point& b, const Point& c) {
    return static_cast<Sign>(adaptive::orient2d(a.x, a.y, b.x, b.y, c.x, c.y));
  }
  static Sign orient_vectors(const Point& p1, const Point& q1, const Point& p2, const Point& q2) {
    return static_cast<Sign>(adaptive::orient_vectors(p1.x, p1.y, q1.x, q1.y, p2.x, p2.y, q2.x, q2.y));
  }
  static Vertex vertex(const Point& p) {
    Vertex v;
    v.a0 = p;
    v.lo = {p.x, p.y};
    v.hi = {p.x, p.y};
    return v;
  }

  // The box: a0 + t (a1 - a0) with t = ((b0 - a0) x db) / (da x db), in interval arithmetic
  // under upward rounding (Boost.Interval through the interval filter's policy).
  static Vertex crossing(const Point& a0, const Point& a1, const Point& b0, const Point& b1) {
    Vertex v;
    v.a0 = a0;
    v.a1 = a1;
    v.b0 = b0;
    v.b1 = b1;
    v.is_crossing = true;
    using I = interval_filter::Interval;
    bool ok = true;
    {
      RoundingGuard guard(FE_UPWARD);
      const auto in = [](double x) { return I(RoundingGuard::opaque(x)); };
      const I dax = in(a1.x) - in(a0.x), day = in(a1.y) - in(a0.y);
      const I dbx = in(b1.x) - in(b0.x), dby = in(b1.y) - in(b0.y);
      const I num = (in(b0.x) - in(a0.x)) * dby - (in(b0.y) - in(a0.y)) * dbx;
      const I den = dax * dby - day * dbx;
      if (boost::numeric::zero_in(den)) {
        ok = false;
      } else {
        const I t = num / den;
        const I x = in(a0.x) + t * dax;
        const I y = in(a0.y) + t * day;
        volatile double l0 = x.lower(), h0 = x.upper(), l1 = y.lower(), h1 = y.upper();
        v.lo = {l0, l1};
        v.hi = {h0, h1};
        ok = std::isfinite(v.lo[0]) && std::isfinite(v.hi[0]) && std::isfinite(v.lo[1]) && std::isfinite(v.hi[1]);
      }
    }
    if (!ok) {  // no useful box: every comparison goes to the exact stage
      v.lo = {-HUGE_VAL, -HUGE_VAL};
      v.hi = {HUGE_VAL, HUGE_VAL};
    }
    return v;
  }

  // Whether two crossings are of the same two segments (each given either way round, in
  // either order): then they are the same point, without rationals. A ring against itself,
  // or rings sharing edges, find each crossing several times.
  static bool same_segments(const Vertex& u, const Vertex& v) {
    const auto same = [](const Point& p0, const Point& p1, const Point& q0, const Point& q1) {
      return (p0 == q0 && p1 == q1) || (p0 == q1 && p1 == q0);
    };
    return (same(u.a0, u.a1, v.a0, v.a1) && same(u.b0, u.b1, v.b0, v.b1)) ||
           (same(u.a0, u.a1, v.b0, v.b1) && same(u.b0, u.b1, v.a0, v.a1));
  }

  // The box the vertex certainly lies in (VertexBoxes): an input point's is the point.
  static std::array<double, 4> vertex_box(const Vertex& v) { return {v.lo[0], v.lo[1], v.hi[0], v.hi[1]}; }

  static RationalPoint exact(const Vertex& v) {
    if (!v.is_crossing) return RationalKernel::point(v.a0);
    return RationalKernel::crossing(RationalKernel::point(v.a0), RationalKernel::point(v.a1),
                                    RationalKernel::point(v.b0), RationalKernel::point(v.b1));
  }

  // Compares coordinate `axis` (0 = x, 1 = y): by the boxes when they separate, exactly
  // otherwise.
  static Sign compare_coordinate(int axis, const Vertex& u, const Vertex& v) {
    if (u.hi[axis] < v.lo[axis]) return Sign::negative;
    if (v.hi[axis] < u.lo[axis]) return Sign::positive;
    if (!u.is_crossing && !v.is_crossing) return Sign::zero;  // equal doubles
    if (u.is_crossing && v.is_crossing && same_segments(u, v)) return Sign::zero;  // one crossing found twice
    const RationalPoint eu = exact(u);
    const RationalPoint ev = exact(v);
    return sign_of(axis == 0 ? cmp(eu.x, ev.x) : cmp(eu.y, ev.y));
  }
  static Sign compare_vertices(const Vertex& u, const Vertex& v) {
    const Sign s = compare_coordinate(0, u, v);
    return s != Sign::zero ? s : compare_coordinate(1, u, v);
  }
  // Along s -> d the coordinate that varies most orders the points; the boxes of crossings
  // on one edge separate along it unless the crossings are very close.
  static Sign compare_along(const Point& s, const Point& d, const Vertex& u, const Vertex& v) {
    const double dx = d.x - s.x;
    const double dy = d.y - s.y;
    const int axis = std::abs(dx) >= std::abs(dy) ? 0 : 1;
    const bool ascending = axis == 0 ? dx > 0 : dy > 0;
    const Sign c = compare_coordinate(axis, u, v);
    return ascending ? c : -c;
  }
  // Three vertices, crossings among them: by interval arithmetic over their boxes when its
  // sign is certain (a few ulps wide, they decide all but nearly collinear triples: a
  // result's hole assignment asks this of its crossings), exactly otherwise.
  static Sign orient_vertices(const Vertex& a, const Vertex& b, const Vertex& c) {
    if (!a.is_crossing && !b.is_crossing && !c.is_crossing) return orient2d(a.a0, b.a0, c.a0);
    if (const Sign s = orient_boxes(a, b, c); s != Sign::zero) return s;
    return RationalKernel::orient2d(exact(a), exact(b), exact(c));
  }
  // The sign of (b - a) x (c - a) for every choice of points in the three boxes, or zero
  // when the boxes leave it open. Boxes within 2^500 of the origin only: their differences'
  // products then stay finite and no interval bound becomes NaN (the policy does not check).
  static Sign orient_boxes(const Vertex& a, const Vertex& b, const Vertex& c) {
    constexpr double limit = 0x1p500;
    for (const Vertex* v : {&a, &b, &c}) {
      if (!(std::fabs(v->lo[0]) < limit && std::fabs(v->hi[0]) < limit && std::fabs(v->lo[1]) < limit &&
            std::fabs(v->hi[1]) < limit)) {
        return Sign::zero;
      }
    }
    using I = interval_filter::Interval;
    RoundingGuard guard(FE_UPWARD);
    const auto x = [](const Vertex& v) { return I(RoundingGuard::opaque(v.lo[0]), RoundingGuard::opaque(v.hi[0])); };
    const auto y = [](const Vertex& v) { return I(RoundingGuard::opaque(v.lo[1]), RoundingGuard::opaque(v.hi[1])); };
    const I d = (x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a));
    volatile double lower = d.lower(), upper = d.upper();
    return lower > 0 ? Sign::positive : (upper < 0 ? Sign::negative : Sign::zero);
  }
  // Nearest doubles: from exact expansions when the magnitudes allow (almost always), else
  // from the exact rational.
  static mk::Point approx(const Vertex& v) {
    if (!v.is_crossing) return v.a0;
    if (mk::Point p; nearest_crossing(v.a0, v.a1, v.b0, v.b1, p)) return p;
    const RationalPoint e = exact(v);
    return {RationalKernel::to_nearest(e.x), RationalKernel::to_nearest(e.y)};
  }
  static std::array<std::string, 2> exact_coordinates(const Vertex& v) {
    return RationalKernel::exact_coordinates(exact(v));
  }
};

}  // namespace mk
