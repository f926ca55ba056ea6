// Test oracle: exact point location in input polygons and in results, and exact areas,
// computed independently of the algorithm (plain crossing parity over rings, GMP rationals).
#pragma once

#include <gmpxx.h>

#include <random>
#include <vector>

#include "arithmetic/kernels/rational_kernel.hpp"
#include "core/boolean_op.hpp"

namespace mk::test {

using Q = mpq_class;
using QPoint = RationalPoint;
using QRing = std::vector<QPoint>;

enum class Location { outside, boundary, inside };

inline QPoint qp(double x, double y) { return {Q(x), Q(y)}; }

inline Q cross(const QPoint& o, const QPoint& a, const QPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// p on the closed segment ab.
inline bool on_segment(const QPoint& a, const QPoint& b, const QPoint& p) {
  if (cross(a, b, p) != 0) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Crossing parity of a ray to +x from p (p not on the ring).
inline bool ring_contains(const QRing& r, const QPoint& p) {
  bool in = false;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const QPoint& a = r[i];
    const QPoint& b = r[(i + 1) % n];
    if ((a.y > p.y) != (b.y > p.y)) {
      const Q x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (x > p.x) in = !in;
    }
  }
  return in;
}

inline bool ring_touches(const QRing& r, const QPoint& p) {
  if (r.size() == 1) return r[0] == p;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    if (on_segment(r[i], r[(i + 1) % n], p)) return true;
  }
  return false;
}

// The location of p in a polygon of the paper's model: FAR by the parity of the rings
// around p (nesting), hole type complemented, boundary when p is on any ring.
inline Location locate(const std::vector<QRing>& rings, PolygonType type, const QPoint& p) {
  bool in = false;
  for (const auto& r : rings) {
    if (ring_touches(r, p)) return Location::boundary;
    if (r.size() >= 3 && ring_contains(r, p)) in = !in;
  }
  if (type == PolygonType::hole) in = !in;
  return in ? Location::inside : Location::outside;
}

inline std::vector<QRing> to_qrings(const Polygon& p) {
  std::vector<QRing> out;
  for (const auto& r : p.rings) {
    QRing q;
    for (const auto& v : r) q.push_back(qp(v.x, v.y));
    out.push_back(q);
  }
  return out;
}

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

inline Q signed_area(const QRing& r) {
  Q a = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    a += r[i].x * r[(i + 1) % n].y - r[(i + 1) % n].x * r[i].y;
  }
  return a / 2;
}

// Area of a bounded polygon of the paper's model: rings at even nesting depth add, odd subtract.
inline Q area(const std::vector<QRing>& rings) {
  Q total = 0;
  for (std::size_t i = 0; i < rings.size(); ++i) {
    if (rings[i].size() < 3) continue;
    // Depth: rings containing an interior point of one of ring i's edges not on them.
    int depth = 0;
    for (std::size_t j = 0; j < rings.size(); ++j) {
      if (j == i || rings[j].size() < 3) continue;
      for (std::size_t k = 0; k < rings[i].size(); ++k) {
        const QPoint& a = rings[i][k];
        const QPoint& b = rings[i][(k + 1) % rings[i].size()];
        const QPoint m{(a.x + b.x) / 2, (a.y + b.y) / 2};
        if (ring_touches(rings[j], m)) continue;
        if (ring_contains(rings[j], m)) ++depth;
        break;
      }
    }
    const Q a = abs(signed_area(rings[i]));
    total += depth % 2 == 0 ? a : Q(-a);
  }
  return total;
}

inline Q area(const BooleanResult<RationalKernel>& r) {
  Q total = 0;
  for (const auto& c : r.cycles) {
    if (c.vertices.size() < 3) continue;
    QRing q;
    for (const int v : c.vertices) q.push_back(r.vertex(v));
    const Q a = abs(signed_area(q));
    total += c.type == PolygonType::island ? a : Q(-a);
  }
  return total;
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
