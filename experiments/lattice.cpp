// Exact integer-lattice geometry for the degenerate generators. [MK89 §2.2]
// Preconditions: coordinates below 2^30 in magnitude (see lattice.hpp).
#include "experiments/lattice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace mk::experiments {

std::int64_t uniform(std::mt19937_64& rng, std::int64_t lo, std::int64_t hi) {
  // Rejection sampling rather than std::uniform_int_distribution, whose algorithm differs
  // between standard libraries: a seed must give the same case everywhere.
  const std::uint64_t span = static_cast<std::uint64_t>(hi - lo) + 1;
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % span;
  std::uint64_t v = 0;
  do {
    v = rng();
  } while (v >= limit);
  return lo + static_cast<std::int64_t>(v % span);
}

std::int64_t twice_area(const IRing& r) {
  std::int64_t a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const IPoint& p = r[i];
    const IPoint& q = r[(i + 1) % r.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

IRing convex_hull(std::vector<IPoint> pts) {
  std::sort(pts.begin(), pts.end(), [](IPoint a, IPoint b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return {};
  IRing hull(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {  // lower chain
    while (k >= 2 && orient(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
    while (k >= t && orient(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  if (hull.size() < 3) return {};
  return hull;
}

IRing random_convex(std::mt19937_64& rng, IPoint centre, std::int64_t radius, int count) {
  for (Attempts t("random_convex");; t.next()) {
    std::vector<IPoint> pts;
    for (int i = 0; i < std::max(count, 3); ++i) {
      pts.push_back({centre.x + uniform(rng, -radius, radius), centre.y + uniform(rng, -radius, radius)});
    }
    IRing h = convex_hull(pts);
    if (h.size() >= 3) return h;
  }
}

IRing random_star(std::mt19937_64& rng, IPoint centre, int rmin, int rmax, int count) {
  // Work in doubled coordinates so that the centre (c + 1/2) is a lattice point; no input
  // vertex can then lie in the centre's direction from another (odd offsets in both axes
  // still allow it, so same-direction pairs are merged below).
  const IPoint c2{2 * centre.x + 1, 2 * centre.y + 1};
  Attempts attempts("random_star");
  for (int tries = 0;; ++tries) {
    attempts.next();
    const int n = count + tries / 8;
    std::vector<IPoint> pts;
    for (int i = 0; i < n; ++i) {
      // A random direction and an integer radius; the vertex is rounded to the lattice.
      const double t = 6.283185307179586 * static_cast<double>(rng() >> 11) * 0x1p-53;
      const double r = static_cast<double>(uniform(rng, rmin, rmax));
      const IPoint p{centre.x + static_cast<std::int64_t>(std::llround(0.5 + r * std::cos(t))),
                     centre.y + static_cast<std::int64_t>(std::llround(0.5 + r * std::sin(t)))};
      pts.push_back(p);
    }
    const auto dir = [&](IPoint p) { return IPoint{2 * p.x - c2.x, 2 * p.y - c2.y}; };
    const auto half = [](IPoint d) { return d.y > 0 || (d.y == 0 && d.x > 0) ? 0 : 1; };
    const auto cross = [](IPoint a, IPoint b) { return a.x * b.y - a.y * b.x; };
    std::sort(pts.begin(), pts.end(), [&](IPoint a, IPoint b) {
      const IPoint da = dir(a), db = dir(b);
      if (half(da) != half(db)) return half(da) < half(db);
      return cross(da, db) > 0;
    });
    IRing out;
    for (const IPoint p : pts) {
      if (!out.empty() && half(dir(out.back())) == half(dir(p)) && cross(dir(out.back()), dir(p)) == 0) continue;
      out.push_back(p);
    }
    if (out.size() >= 2 && half(dir(out.back())) == half(dir(out.front())) &&
        cross(dir(out.back()), dir(out.front())) == 0) {
      out.pop_back();
    }
    bool simple = out.size() >= 3;
    for (std::size_t i = 0; simple && i < out.size(); ++i) {
      simple = cross(dir(out[i]), dir(out[(i + 1) % out.size()])) > 0;  // every gap below pi
    }
    if (simple) return out;
  }
}

bool is_strictly_inside_convex(const IRing& r, IPoint q) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    if (orient(r[i], r[(i + 1) % r.size()], q) <= 0) return false;
  }
  return true;
}

bool is_on_ring(const IRing& r, IPoint q) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    const IPoint a = r[i], b = r[(i + 1) % r.size()];
    if (orient(a, b, q) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
        std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y)) {
      return true;
    }
  }
  return false;
}

bool segments_meet(IPoint a, IPoint b, IPoint c, IPoint d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  const auto on = [](IPoint p, IPoint q, IPoint r) {  // r on closed pq, given collinear
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  return (o1 == 0 && on(a, b, c)) || (o2 == 0 && on(a, b, d)) || (o3 == 0 && on(c, d, a)) ||
         (o4 == 0 && on(c, d, b));
}

bool rings_meet(const IRing& r, const IRing& s) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    for (std::size_t j = 0; j < s.size(); ++j) {
      if (segments_meet(r[i], r[(i + 1) % r.size()], s[j], s[(j + 1) % s.size()])) return true;
    }
  }
  return false;
}

bool is_strictly_inside(const IRing& outer, const IRing& inner) {
  return !rings_meet(outer, inner) && is_inside_ring(outer, inner[0]);
}

bool is_inside_ring(const IRing& r, IPoint q) {
  bool in = false;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const IPoint a = r[i], b = r[(i + 1) % r.size()];
    if ((a.y > q.y) != (b.y > q.y)) {
      // x of the crossing > q.x, decided by the sign of an orientation (no division).
      const int o = orient(a, b, q);
      if (b.y > a.y ? o > 0 : o < 0) in = !in;
    }
  }
  return in;
}

IPoint random_point_left_of(std::mt19937_64& rng, IPoint a, IPoint b, IPoint near, std::int64_t reach) {
  for (Attempts t("random_point_left_of");; t.next()) {
    const IPoint p{near.x + uniform(rng, -reach, reach), near.y + uniform(rng, -reach, reach)};
    if (orient(a, b, p) > 0) return p;
  }
}

IPoint LatticeMap::operator()(IPoint p) const {
  IPoint q = p;
  if (symmetry & 1) q = {-q.x, q.y};
  if (symmetry & 2) q = {q.y, q.x};
  if (symmetry & 4) q = {-q.x, -q.y};
  return q + shift;
}

LatticeMap random_lattice_map(std::mt19937_64& rng, std::int64_t max_shift) {
  LatticeMap m;
  m.symmetry = static_cast<int>(uniform(rng, 0, 7));
  m.shift = {uniform(rng, -max_shift, max_shift), uniform(rng, -max_shift, max_shift)};
  return m;
}

IRing apply(const LatticeMap& m, const IRing& r) {
  IRing out;
  for (const IPoint p : r) out.push_back(m(p));
  return out;
}

IRing scaled(const IRing& r, std::int64_t s) {
  IRing out;
  for (const IPoint p : r) out.push_back(s * p);
  return out;
}

IRing translated(const IRing& r, IPoint d) {
  IRing out;
  for (const IPoint p : r) out.push_back(p + d);
  return out;
}

IRing reversed(IRing r) {
  std::reverse(r.begin(), r.end());
  return r;
}

IRing point_reflected(const IRing& r, IPoint twice_centre) {
  IRing out;
  for (const IPoint p : r) out.push_back(twice_centre - p);
  return out;
}

IRing rotated90(const IRing& r, IPoint c) {
  IRing out;
  for (const IPoint p : r) out.push_back({c.x - (p.y - c.y), c.y + (p.x - c.x)});
  return out;
}

IRing shifted_start(const IRing& r, std::size_t k) {
  IRing out;
  for (std::size_t i = 0; i < r.size(); ++i) out.push_back(r[(i + k) % r.size()]);
  return out;
}

Ring to_ring(const IRing& r) {
  Ring out;
  for (const IPoint p : r) out.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
  return out;
}

Polygon island(std::vector<IRing> rings) {
  Polygon p;
  for (const auto& r : rings) p.rings.push_back(to_ring(r));
  return p;
}

Polygon hole_type(std::vector<IRing> rings) {
  Polygon p = island(std::move(rings));
  p.type = PolygonType::hole;
  return p;
}

}  // namespace mk::experiments
