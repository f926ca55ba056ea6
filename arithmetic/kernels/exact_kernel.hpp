// ExactKernel: exact decisions on input points by adaptive predicates, and crossing points
// kept implicit (their two defining segments) with a rigorous interval box; comparisons of
// implicit points are filtered by the boxes and decided exactly with GMP when they overlap.
// [At20] (indirect predicates) [Sh97] [MK89 §3.3]
// Preconditions: finite double input. Crossings are made only for segments that cross
// properly (so the denominator is never zero).
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cfenv>
#include <cmath>
#include <string>
#include <string_view>

#include "arithmetic/adaptive.hpp"
#include "arithmetic/crossing_rounding.hpp"
#include "arithmetic/interval_filter.hpp"
#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/predicates_gmp.hpp"
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
    if (!ok) {  // no useful box yet: every comparison would go to the exact stage
      v.lo = {-HUGE_VAL, -HUGE_VAL};
      v.hi = {HUGE_VAL, HUGE_VAL};
    }
    if (!ok || is_wide(v.lo[0], v.hi[0]) || is_wide(v.lo[1], v.hi[1])) tighten(v);
    return v;
  }
  // Whether [lo, hi] spans more than about 16 ulps of its bounds: the crossing of nearly
  // parallel segments, whose denominator cancels (rotated lattice parts sharing lines make
  // many). Their boxes overlapped so often that sorting went to the exact stage for most
  // comparisons.
  static bool is_wide(double lo, double hi) { return !(hi - lo <= 0x1p-48 * std::max(std::fabs(lo), std::fabs(hi))); }
  // The box around the crossing's nearest doubles p (from exact expansions): the crossing
  // lies within half a gap of p, so between p's neighbours; kept only where narrower.
  static void tighten(Vertex& v) {
    mk::Point p;
    if (!nearest_crossing(v.a0, v.a1, v.b0, v.b1, p)) return;
    const double c[2] = {p.x, p.y};
    for (int axis = 0; axis < 2; ++axis) {
      v.lo[axis] = std::max(v.lo[axis], std::nextafter(c[axis], -HUGE_VAL));
      v.hi[axis] = std::min(v.hi[axis], std::nextafter(c[axis], HUGE_VAL));
    }
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

  // The exact stage without rationals. A vertex as homogeneous integer coordinates
  // (X, Y) / D, D > 0, over the doubles of all the vertices one predicate compares, scaled
  // to integers by one power of two (gmp::scaled_integers): a crossing's coordinates are
  // degree-3 forms over a degree-2 denominator, a point's its own coordinates over 1, so
  // every vertex is scaled by the same factor and the predicates' signs do not change.
  // Integers need no gcd after each operation, which the rationals of exact() do: a set of
  // nearly collinear shared edges (rotated lattice parts) made the rationals' gcds most of a
  // union-all's time.
  struct Homogeneous {
    mpz_class x, y, d;
  };
  // Into thread-local integers reused from call to call (their limbs stay allocated): the
  // exact stage runs often on such inputs, and allocation was most of its cost.
  template <std::size_t K>
  static const std::array<Homogeneous, K>& homogeneous(const std::array<const Vertex*, K>& vs) {
    thread_local std::array<mpz_class, 8 * K> z;
    thread_local std::array<mpz_class, 6> t;
    thread_local std::array<Homogeneous, K> out;
    std::array<double, 8 * K> in{};
    std::size_t n = 0;
    for (const Vertex* v : vs) {
      for (const Point* p : {&v->a0, &v->a1, &v->b0, &v->b1}) {
        in[n++] = p->x;
        in[n++] = p->y;
        if (!v->is_crossing) break;
      }
    }
    gmp::scaled_integers(in.data(), n, z.data());
    const auto at = [&](std::size_t i) { return z[i].get_mpz_t(); };
    mpz_ptr dax = t[0].get_mpz_t(), day = t[1].get_mpz_t(), dbx = t[2].get_mpz_t(), dby = t[3].get_mpz_t();
    mpz_ptr diff = t[4].get_mpz_t(), num = t[5].get_mpz_t();
    std::size_t i = 0;
    for (std::size_t k = 0; k < K; ++k) {
      mpz_ptr x = out[k].x.get_mpz_t(), y = out[k].y.get_mpz_t(), d = out[k].d.get_mpz_t();
      if (!vs[k]->is_crossing) {
        mpz_set(x, at(i));
        mpz_set(y, at(i + 1));
        mpz_set_ui(d, 1);
        i += 2;
        continue;
      }
      const mpz_srcptr a0x = at(i), a0y = at(i + 1), a1x = at(i + 2), a1y = at(i + 3);
      const mpz_srcptr b0x = at(i + 4), b0y = at(i + 5), b1x = at(i + 6), b1y = at(i + 7);
      i += 8;
      // As formula::line_crossing: a0 + t (a1 - a0), t = N / D, N = (b0 - a0) x db, D = da x db.
      mpz_sub(dax, a1x, a0x);
      mpz_sub(day, a1y, a0y);
      mpz_sub(dbx, b1x, b0x);
      mpz_sub(dby, b1y, b0y);
      mpz_mul(d, dax, dby);
      mpz_submul(d, day, dbx);
      mpz_sub(diff, b0x, a0x);
      mpz_mul(num, diff, dby);
      mpz_sub(diff, b0y, a0y);
      mpz_submul(num, diff, dbx);
      mpz_mul(x, a0x, d);  // X = a0x D + N dax, Y = a0y D + N day
      mpz_addmul(x, num, dax);
      mpz_mul(y, a0y, d);
      mpz_addmul(y, num, day);
      if (mpz_sgn(d) < 0) {
        mpz_neg(d, d);
        mpz_neg(x, x);
        mpz_neg(y, y);
      }
    }
    return out;
  }

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
    const std::array<Homogeneous, 2>& h = homogeneous<2>({&u, &v});
    thread_local mpz_class lhs, rhs;
    // cu / du - cv / dv, times du dv > 0
    mpz_mul(lhs.get_mpz_t(), (axis == 0 ? h[0].x : h[0].y).get_mpz_t(), h[1].d.get_mpz_t());
    mpz_mul(rhs.get_mpz_t(), (axis == 0 ? h[1].x : h[1].y).get_mpz_t(), h[0].d.get_mpz_t());
    return sign_of(mpz_cmp(lhs.get_mpz_t(), rhs.get_mpz_t()));
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
    // (b - a) x (c - a) with each point (X, Y) / D, times Da^2 Db Dc > 0.
    const auto& [ha, hb, hc] = homogeneous<3>({&a, &b, &c});
    const mpz_class bx = hb.x * ha.d - ha.x * hb.d, by = hb.y * ha.d - ha.y * hb.d;
    const mpz_class cx = hc.x * ha.d - ha.x * hc.d, cy = hc.y * ha.d - ha.y * hc.d;
    return sign_of(cmp(bx * cy, by * cx));
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
