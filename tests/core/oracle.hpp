// The core tests' view of the independent oracle (tests/oracle/membership.hpp): exact
// locations in inputs and results, and exact areas by the project's one shoelace, computed
// without the core.
#pragma once

#include <gmpxx.h>

#include <random>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "arithmetic/shoelace.hpp"
#include "core/boolean_op.hpp"
#include "tests/oracle/membership.hpp"

namespace mk::test {

using Q = mpq_class;
using QPoint = RationalPoint;
using QRing = std::vector<QPoint>;
using oracle::Location;

inline QPoint qp(double x, double y) { return {Q(x), Q(y)}; }

inline Q cross(const QPoint& o, const QPoint& a, const QPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

inline bool on_segment(const QPoint& a, const QPoint& b, const QPoint& p) { return oracle::is_on_segment(a, b, p); }

// The location of p in a polygon of the paper's model.
inline Location locate(const std::vector<QRing>& rings, PolygonType type, const QPoint& p) {
  return oracle::locate(oracle::Region{rings, type == PolygonType::hole}, p);
}

inline std::vector<QRing> to_qrings(const Polygon& p) { return oracle::region_of(p).rings; }

inline std::vector<QRing> result_rings(const BooleanResult<RationalKernel>& r) {
  std::vector<QRing> out;
  for (const auto& c : r.cycles) {
    QRing q;
    for (const int v : c.vertices) q.push_back(r.vertex(v));
    out.push_back(q);
  }
  return out;
}

inline Location locate(const BooleanResult<RationalKernel>& r, const QPoint& p) {
  return locate(result_rings(r), r.unbounded ? PolygonType::hole : PolygonType::island, p);
}

// Area of a bounded polygon of the paper's model: rings at even nesting depth add, odd
// subtract; a ring's depth is decided at the midpoint of one of its edges on no other ring.
inline Q area(const std::vector<QRing>& rings) {
  Q total = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (rings[i].size() < 3) continue;
    int depth = 0;
    for (std::size_t j = 0; j < rings.size(); ++j) {
      if (j == i || rings[j].size() < 3) continue;
      const oracle::Region other{{rings[j]}, false};
      for (std::size_t k = 0; k < rings[i].size(); ++k) {
        const QPoint& a = rings[i][k];
        const QPoint& b = rings[i][(k + 1) % rings[i].size()];
        const Location l = oracle::locate(other, {(a.x + b.x) / 2, (a.y + b.y) / 2});
        if (l == Location::boundary) continue;
        if (l == Location::inside) ++depth;
        break;
      }
    }
    const Q a = abs(twice_signed_area<Q>(rings[i])) / 2;
    total += depth % 2 == 0 ? a : Q(-a);
  }
  return total;
}

// Area of a bounded result from its typed cycles: islands add, holes subtract.
inline Q area(const BooleanResult<RationalKernel>& r) {
  std::vector<std::size_t> index(r.cycles.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  const std::vector<QRing> rings = result_rings(r);
  return typed_area<Q>(
      index, [&](std::size_t i) -> const QRing& { return rings[i]; },
      [&](std::size_t i) { return r.cycles[i].type == PolygonType::island; });
}

// The result fed back as an input polygon (the paper's model keeps types and degenerate parts).
inline BasicPolygon<RationalPoint> as_input(const BooleanResult<RationalKernel>& r) {
  BasicPolygon<RationalPoint> p;
  p.type = r.unbounded ? PolygonType::hole : PolygonType::island;
  p.rings = result_rings(r);
  return p;
}

// Random star-shaped polygon with integer vertices around (cx + 0.5, cy + 0.5): simple by
// construction (vertices sorted by exact angle, one per direction).
inline Ring random_star_once(std::mt19937_64& rng, double cx, double cy, int rmin, int rmax, int n) {
  std::uniform_int_distribution<int> rad(rmin, rmax);
  std::uniform_real_distribution<double> ang(0, 6.283185307179586);
  struct P {
    Q dx, dy;
    double x, y;
  };
  std::vector<P> pts;
  const Q ox = Q(cx) + Q(1, 2);
  const Q oy = Q(cy) + Q(1, 2);
  for (int i = 0; i < n; ++i) {
    const double t = ang(rng);
    const double r = rad(rng);
    const double x = std::round(cx + 0.5 + r * std::cos(t));
    const double y = std::round(cy + 0.5 + r * std::sin(t));
    pts.push_back({Q(x) - ox, Q(y) - oy, x, y});
  }
  const auto half = [](const P& p) { return p.dy > 0 || (p.dy == 0 && p.dx > 0) ? 0 : 1; };
  std::sort(pts.begin(), pts.end(), [&](const P& a, const P& b) {
    if (half(a) != half(b)) return half(a) < half(b);
    return a.dx * b.dy - a.dy * b.dx > 0;
  });
  Ring out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (i > 0 && half(pts[i]) == half(pts[i - 1]) && pts[i].dx * pts[i - 1].dy - pts[i].dy * pts[i - 1].dx == 0) {
      continue;  // same direction: keep one
    }
    out.push_back({pts[i].x, pts[i].y});
  }
  // Simple only when the centre sees every edge turning left (gaps below pi).
  const QPoint c{ox, oy};
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& p = out[i];
    const auto& q = out[(i + 1) % out.size()];
    if (out.size() < 3 || cross(c, qp(p.x, p.y), qp(q.x, q.y)) <= 0) return {};
  }
  return out;
}

inline Ring random_star(std::mt19937_64& rng, double cx, double cy, int rmin, int rmax, int n) {
  for (int tries = 0; tries < 100; ++tries) {
    Ring r = random_star_once(rng, cx, cy, rmin, rmax, n + tries / 10);
    if (!r.empty()) return r;
  }
  return {};
}

}  // namespace mk::test
