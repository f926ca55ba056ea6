// Inputs and oracles shared by the tests of the rounded output's validity
// (rounded_validity_test, rounding_boxes_test, separation_rules_test): near-degenerate
// random triangles, random stars, a result's cycles with every vertex rounded to its
// nearest double, and exact tests of whether boxes meet. [MK89 §3.3] (rounded output)
// Preconditions: none.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "arithmetic/kernels/exact_kernel.hpp"
#include "core/boolean_op.hpp"
#include "core/box_certificate.hpp"

namespace mk::test {

// Triangles of nearly collinear points a few ulps apart (whose crossings often round onto
// each other's edges) and plain random triangles.
inline Polygon random_triangle(std::mt19937_64& rng, bool near_degenerate) {
  std::uniform_real_distribution<double> u(-1, 1);
  Polygon p;
  if (!near_degenerate) {
    p.rings.push_back({{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}});
    return p;
  }
  const double x0 = u(rng), y0 = u(rng);
  const double dx = u(rng), dy = u(rng);
  const auto ulps = [&](double v) { return std::nextafter(v, v + static_cast<double>(rng() % 7) - 3); };
  p.rings.push_back({{x0, y0}, {ulps(x0 + dx), ulps(y0 + dy)}, {x0 + 0.5 * dx + 1e-15 * u(rng), y0 + 0.5 * dy}});
  return p;
}

// The result's cycles, every vertex rounded to its nearest double.
inline std::vector<std::vector<Point>> round_result(const BooleanResult<ExactKernel>& r) {
  std::vector<std::vector<Point>> out;
  for (const auto& c : r.cycles) {
    out.emplace_back();
    for (const int id : c.vertices) out.back().push_back(ExactKernel::approx(r.vertex(id)));
  }
  return out;
}

inline std::uint64_t test_seed(std::uint64_t fallback) {
  const char* env = std::getenv("MK_TEST_SEED");
  const std::uint64_t seed = env ? std::strtoull(env, nullptr, 10) : fallback;
  std::printf("seed %llu (set MK_TEST_SEED to change)\n", static_cast<unsigned long long>(seed));
  return seed;
}

// Exactly: whether v's box meets the convex hull of a's and b's boxes (the region the edge
// sweeps while its ends move within their boxes). By separating axes: two convex regions
// are apart when some normal of an edge of either separates them, here x, y and the
// normals of the hull's edges.
inline bool meets_exactly(const detail::RoundedVertexBox& v, const detail::RoundedVertexBox& a, const detail::RoundedVertexBox& b) {
  struct Q {
    mpq_class x, y;
  };
  const auto corners = [](const detail::RoundedVertexBox& c) {
    const mpq_class x(c.at.x), y(c.at.y), rx(c.rx), ry(c.ry);
    return std::vector<Q>{{x - rx, y - ry}, {x + rx, y - ry}, {x + rx, y + ry}, {x - rx, y + ry}};
  };
  std::vector<Q> pts = corners(a);
  for (const Q& q : corners(b)) pts.push_back(q);
  const std::vector<Q> box = corners(v);
  // The hull, counterclockwise (Andrew's monotone chain, exact).
  std::sort(pts.begin(), pts.end(), [](const Q& p, const Q& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  const auto cross = [](const Q& o, const Q& p, const Q& q) -> mpq_class { return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x); };
  std::vector<Q> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t floor = hull.size();
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Q& p = pass == 0 ? pts[i] : pts[pts.size() - 1 - i];
      while (hull.size() >= floor + 2 && sgn(cross(hull[hull.size() - 2], hull.back(), p)) <= 0) hull.pop_back();
      hull.push_back(p);
    }
    hull.pop_back();
  }
  // Along x and y.
  mpq_class hx0 = hull[0].x, hx1 = hull[0].x, hy0 = hull[0].y, hy1 = hull[0].y;
  for (const Q& h : hull) hx0 = std::min(hx0, h.x), hx1 = std::max(hx1, h.x), hy0 = std::min(hy0, h.y), hy1 = std::max(hy1, h.y);
  if (box[2].x < hx0 || box[0].x > hx1 || box[2].y < hy0 || box[0].y > hy1) return false;
  // Along each hull edge's outward normal: the box wholly beyond the edge's line.
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Q& p = hull[i];
    const Q& q = hull[(i + 1) % hull.size()];
    if (p.x == q.x && p.y == q.y) continue;
    bool beyond = true;
    for (const Q& c : box) beyond = beyond && sgn(cross(p, q, c)) < 0;
    if (beyond) return false;
  }
  return true;
}

inline bool ends_meet_exactly(const detail::RoundedVertexBox& a, const detail::RoundedVertexBox& b) {
  const mpq_class tx = mpq_class(a.rx) + mpq_class(b.rx), ty = mpq_class(a.ry) + mpq_class(b.ry);
  return abs(mpq_class(a.at.x) - mpq_class(b.at.x)) <= tx && abs(mpq_class(a.at.y) - mpq_class(b.at.y)) <= ty;
}

// A star-shaped ring of n vertices at random angles and radii about c (bench's star).
inline std::vector<Point> star_ring(std::mt19937_64& rng, int n, Point c) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (auto& a : angles) a = 2 * std::numbers::pi * u(rng);
  std::sort(angles.begin(), angles.end());
  std::vector<Point> ring;
  for (const double a : angles) {
    const double radius = 50 + 50 * u(rng);
    ring.push_back({c.x + radius * std::cos(a), c.y + radius * std::sin(a)});
  }
  return ring;
}

}  // namespace mk::test
