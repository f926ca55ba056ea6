// Test oracle: exact point membership by crossing parity and angular sectors (see
// membership.hpp). [BRIEF §1] [MK89 §2.2]
// Preconditions: see membership.hpp.
#include "tests/oracle/membership.hpp"

#include <algorithm>
#include <functional>

namespace mk::oracle {

namespace {

int sign(const Q& q) { return sgn(q); }

// a - b as an unreduced fraction (num, den > 0): no gcd, which is what rational arithmetic
// spends its time on here.
void difference(const Q& a, const Q& b, mpz_class& num, mpz_class& den) {
  num = a.get_num() * b.get_den() - b.get_num() * a.get_den();
  den = a.get_den() * b.get_den();
}

// Sign of (a - o) x (b - o), exactly, in integers.
int orient(const QPoint& o, const QPoint& a, const QPoint& b) {
  thread_local mpz_class ax, axd, ay, ayd, bx, bxd, by, byd, l, r;
  difference(a.x, o.x, ax, axd);
  difference(a.y, o.y, ay, ayd);
  difference(b.x, o.x, bx, bxd);
  difference(b.y, o.y, by, byd);
  // ax/axd * by/byd - ay/ayd * bx/bxd, over the positive denominator axd byd ayd bxd.
  l = ax * by;
  l *= ayd;
  l *= bxd;
  r = ay * bx;
  r *= axd;
  r *= byd;
  return cmp(l, r) > 0 ? 1 : (cmp(l, r) < 0 ? -1 : 0);
}

bool is_between(const Q& lo, const Q& hi, const Q& v) { return lo <= hi ? lo <= v && v <= hi : hi <= v && v <= lo; }

}  // namespace

// The box first: it rejects most pairs without arithmetic.
bool is_on_segment(const QPoint& a, const QPoint& b, const QPoint& p) {
  return is_between(a.x, b.x, p.x) && is_between(a.y, b.y, p.y) && orient(a, b, p) == 0;
}

namespace {

bool boxes_meet(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const auto lo = [](const Q& u, const Q& v) -> const Q& { return u < v ? u : v; };
  const auto hi = [](const Q& u, const Q& v) -> const Q& { return u < v ? v : u; };
  return lo(a.x, b.x) <= hi(c.x, d.x) && lo(c.x, d.x) <= hi(a.x, b.x) && lo(a.y, b.y) <= hi(c.y, d.y) &&
         lo(c.y, d.y) <= hi(a.y, b.y);
}

// Whether the closed segments ab and cd have a point in common.
bool segments_meet(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  if (!boxes_meet(a, b, c, d)) return false;
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && is_on_segment(a, b, c)) || (o2 == 0 && is_on_segment(a, b, d)) ||
         (o3 == 0 && is_on_segment(c, d, a)) || (o4 == 0 && is_on_segment(c, d, b));
}

struct Vec {
  Q x, y;
};

int half(const Vec& v) { return v.y > 0 || (v.y == 0 && v.x > 0) ? 0 : 1; }
int cross(const Vec& u, const Vec& v) { return sign(u.x * v.y - u.y * v.x); }
bool angle_less(const Vec& u, const Vec& v) { return half(u) != half(v) ? half(u) < half(v) : cross(u, v) > 0; }
bool same_direction(const Vec& u, const Vec& v) { return half(u) == half(v) && cross(u, v) == 0; }

// Calls f(a, b) for every edge of every ring of r (a two-point ring has one segment, met
// twice; repeated consecutive points make no edge).
template <class F>
void for_each_edge(const Region& r, F&& f) {
  for (const auto& ring : r.rings) {
    const std::size_t n = ring.size();
    if (n < 2) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const QPoint& a = ring[i];
      const QPoint& b = ring[(i + 1) % n];
      if (!(a == b)) f(a, b);
    }
  }
}

bool is_on_rings(const Region& r, const QPoint& p) {
  for (const auto& ring : r.rings) {
    if (ring.size() == 1 && ring[0] == p) return true;
  }
  bool on = false;
  for_each_edge(r, [&](const QPoint& a, const QPoint& b) { on = on || is_on_segment(a, b, p); });
  return on;
}

// A point of the open sector around p in direction d: p + t d for t = 1, 1/2, 1/4, ... until
// the segment from p to it meets no ring except at p (rings through p leave p along the
// sector's sides, not along d).
QPoint point_in_sector(const QPoint& p, const Vec& d, const std::vector<const Region*>& regions) {
  Q t = 1;
  for (;;) {
    const QPoint q{p.x + t * d.x, p.y + t * d.y};
    bool blocked = false;
    for (const Region* r : regions) {
      for (const auto& ring : r->rings) {
        if (ring.size() == 1 && is_on_segment(p, q, ring[0]) && !(ring[0] == p)) blocked = true;
      }
      for_each_edge(*r, [&](const QPoint& a, const QPoint& b) {
        if (!blocked && !is_on_segment(a, b, p) && segments_meet(a, b, p, q)) blocked = true;
      });
      if (blocked) break;
    }
    if (!blocked) return q;
    t /= 2;
  }
}

}  // namespace

QPoint point_left_of(const QPoint& a, const QPoint& b, const std::vector<const Region*>& regions) {
  return point_in_sector({(a.x + b.x) / 2, (a.y + b.y) / 2}, {a.y - b.y, b.x - a.x}, regions);
}

Region region_of(const BasicPolygon<QPoint>& p) { return {p.rings, p.type == PolygonType::hole}; }

Region region_of(const Polygon& p) {
  Region r;
  r.complement = p.type == PolygonType::hole;
  for (const auto& ring : p.rings) {
    QRing q;
    for (const auto& v : ring) q.push_back({Q(v.x), Q(v.y)});
    r.rings.push_back(std::move(q));
  }
  return r;
}

const char* location_name(Location l) {
  switch (l) {
    case Location::outside: return "outside";
    case Location::boundary: return "boundary";
    case Location::inside: return "inside";
  }
  return "?";
}

std::string show(const QPoint& p) {
  std::string s = "(";
  s.append(p.x.get_str()).append(", ").append(p.y.get_str()).append(")");
  return s;
}

bool face_is_in(const Region& r, const QPoint& q) {
  bool in = false;
  for (const auto& ring : r.rings) {
    if (ring.size() < 3) continue;
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const QPoint& a = ring[i];
      const QPoint& b = ring[(i + 1) % n];
      if ((a.y > q.y) == (b.y > q.y)) continue;
      // The edge crosses the horizontal line through q; it counts when it passes right of q.
      const int o = orient(a, b, q);
      if (b.y > a.y ? o > 0 : o < 0) in = !in;
    }
  }
  return in != r.complement;
}

Neighbourhood neighbourhood(const QPoint& p, const std::vector<const Region*>& regions) {
  Neighbourhood n{p, {}, {}};
  std::vector<Vec> dirs;
  for (const Region* r : regions) {
    n.on_rings.push_back(is_on_rings(*r, p));
    for_each_edge(*r, [&](const QPoint& a, const QPoint& b) {
      if (a == p) {
        dirs.push_back({b.x - a.x, b.y - a.y});
      } else if (b == p) {
        dirs.push_back({a.x - b.x, a.y - b.y});
      } else if (is_on_segment(a, b, p)) {
        dirs.push_back({b.x - a.x, b.y - a.y});
        dirs.push_back({a.x - b.x, a.y - b.y});
      }
    });
  }
  const bool on_any = std::find(n.on_rings.begin(), n.on_rings.end(), true) != n.on_rings.end();
  if (!on_any) {
    n.sector_points.push_back(p);
    return n;
  }
  std::sort(dirs.begin(), dirs.end(), angle_less);
  dirs.erase(std::unique(dirs.begin(), dirs.end(), same_direction), dirs.end());
  if (dirs.empty()) {  // p is an isolated point of some region: the face around it
    n.sector_points.push_back(point_in_sector(p, {1, 0}, regions));
    return n;
  }
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    const Vec& u = dirs[i];
    const Vec& v = dirs[(i + 1) % dirs.size()];
    Vec d;
    if (dirs.size() == 1) {
      d = {-u.x, -u.y};  // the whole turn but u
    } else if (cross(u, v) > 0) {
      d = {u.x + v.x, u.y + v.y};
    } else if (cross(u, v) < 0) {
      d = {-(u.x + v.x), -(u.y + v.y)};  // more than half a turn
    } else {
      d = {-u.y, u.x};  // exactly half a turn: u's left normal
    }
    n.sector_points.push_back(point_in_sector(p, d, regions));
  }
  return n;
}

Location locate(const Neighbourhood& n, const std::vector<const Region*>& regions, std::size_t i) {
  bool all = true, any = false;
  for (const QPoint& q : n.sector_points) {
    const bool in = face_is_in(*regions[i], q);
    all = all && in;
    any = any || in;
  }
  if (n.on_rings[i]) return all ? Location::inside : Location::boundary;
  return any ? Location::inside : Location::outside;
}

Location locate(const Region& r, const QPoint& p) {
  const std::vector<const Region*> one{&r};
  return locate(neighbourhood(p, one), one, 0);
}

bool face_in_result(Operation op, bool in_a, bool in_b) {
  switch (op) {
    case Operation::intersection: return in_a && in_b;
    case Operation::union_: return in_a || in_b;
    case Operation::difference: return in_a && !in_b;
    case Operation::symmetric_difference: return in_a != in_b;
  }
  return false;
}

bool in_closed_result(Operation op, bool in_a, bool int_a, bool in_b, bool int_b) {
  switch (op) {
    case Operation::intersection: return in_a && in_b;                                       // A n B
    case Operation::union_: return in_a || in_b;                                             // A u B
    case Operation::difference: return in_a && !int_b;                                      // A - int(B)
    case Operation::symmetric_difference: return (in_a && !int_b) || (in_b && !int_a);  // (A - int B) u (B - int A)
  }
  return false;
}

namespace {

Location expected_from(Operation op, bool regular, const Neighbourhood& n, const std::vector<const Region*>& regions) {
  if (regular) {
    bool all = true, any = false;
    for (const QPoint& q : n.sector_points) {
      const bool in = face_in_result(op, face_is_in(*regions[0], q), face_is_in(*regions[1], q));
      all = all && in;
      any = any || in;
    }
    return all ? Location::inside : (any ? Location::boundary : Location::outside);
  }
  const Location la = locate(n, regions, 0);
  const Location lb = locate(n, regions, 1);
  const bool in = in_closed_result(op, la != Location::outside, la == Location::inside, lb != Location::outside,
                                   lb == Location::inside);
  return in ? Location::inside : Location::outside;
}

}  // namespace

Location expected_location(Operation op, bool regular, const Region& a, const Region& b, const QPoint& p) {
  const std::vector<const Region*> regions{&a, &b};
  return expected_from(op, regular, neighbourhood(p, regions), regions);
}

std::vector<QPoint> sample_points(const Region& a, const Region& b, const Region& result, std::mt19937_64& rng,
                                  int random_count) {
  std::vector<QPoint> out;
  for (const Region* r : {&a, &b, &result}) {
    for (const auto& ring : r->rings) out.insert(out.end(), ring.begin(), ring.end());
  }
  // Crossings of A's edges with B's.
  std::vector<QPoint> crossings;
  for_each_edge(a, [&](const QPoint& p, const QPoint& q) {
    for_each_edge(b, [&](const QPoint& r, const QPoint& s) {
      const int o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p), o4 = orient(r, s, q);
      if (o1 * o2 >= 0 || o3 * o4 >= 0) return;
      const Q den = (q.x - p.x) * (s.y - r.y) - (q.y - p.y) * (s.x - r.x);
      const Q t = ((r.x - p.x) * (s.y - r.y) - (r.y - p.y) * (s.x - r.x)) / den;
      crossings.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
    });
  });
  out.insert(out.end(), crossings.begin(), crossings.end());
  // Pieces of each input edge between the points of A and B on it: their midpoints.
  std::vector<QPoint> points = crossings;
  for (const Region* r : {&a, &b}) {
    for (const auto& ring : r->rings) points.insert(points.end(), ring.begin(), ring.end());
  }
  for (const Region* r : {&a, &b}) {
    for_each_edge(*r, [&](const QPoint& p, const QPoint& q) {
      std::vector<Q> along;  // parameters along p -> q
      const bool by_x = p.x != q.x;
      for (const QPoint& v : points) {
        if (is_on_segment(p, q, v)) along.push_back(by_x ? (v.x - p.x) / (q.x - p.x) : (v.y - p.y) / (q.y - p.y));
      }
      std::sort(along.begin(), along.end());
      along.erase(std::unique(along.begin(), along.end()), along.end());
      for (std::size_t i = 0; i + 1 < along.size(); ++i) {
        const Q t = (along[i] + along[i + 1]) / 2;
        out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      }
    });
  }
  for_each_edge(result, [&](const QPoint& p, const QPoint& q) { out.push_back({(p.x + q.x) / 2, (p.y + q.y) / 2}); });
  // Random points: in the inputs' bounding box, and on random input edges.
  std::vector<std::pair<QPoint, QPoint>> edges;
  for (const Region* r : {&a, &b}) for_each_edge(*r, [&](const QPoint& p, const QPoint& q) { edges.push_back({p, q}); });
  if (!edges.empty()) {
    Q x0 = edges[0].first.x, x1 = x0, y0 = edges[0].first.y, y1 = y0;
    for (const auto& [p, q] : edges) {
      for (const QPoint* v : {&p, &q}) {
        x0 = std::min(x0, v->x), x1 = std::max(x1, v->x), y0 = std::min(y0, v->y), y1 = std::max(y1, v->y);
      }
    }
    std::uniform_int_distribution<int> unit(-8, 72);  // a margin of 1/8 around the box
    std::uniform_int_distribution<std::size_t> pick(0, edges.size() - 1);
    for (int i = 0; i < random_count; ++i) {
      if (i % 2 == 0) {
        out.push_back({x0 + (x1 - x0) * Q(unit(rng), 64), y0 + (y1 - y0) * Q(unit(rng), 64)});
      } else {
        const auto& [p, q] = edges[pick(rng)];
        const Q t(unit(rng) & 63, 64);
        out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
      }
    }
  }
  for (QPoint& p : out) {
    p.x.canonicalize();
    p.y.canonicalize();
  }
  const auto less = [](const QPoint& p, const QPoint& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
  std::sort(out.begin(), out.end(), less);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

std::string first_contradiction(Operation op, bool regular, const Region& a, const Region& b, const Region& result,
                                const std::vector<QPoint>& samples, SampleCounts* counts) {
  const std::vector<const Region*> regions{&a, &b, &result};
  for (const QPoint& p : samples) {
    const Neighbourhood n = neighbourhood(p, regions);
    const Location want = expected_from(op, regular, n, regions);
    const Location got = locate(n, regions, 2);
    if (counts) {
      ++counts->points;
      if (n.on_rings[0] && n.on_rings[1]) ++counts->on_both_boundaries;
    }
    const bool agree = regular ? got == want : (got != Location::outside) == (want != Location::outside);
    if (!agree) {
      return std::string(operation_name(op)) + (regular ? " regular" : " non-regular") + " at " + show(p) +
             ": A " + location_name(locate(n, regions, 0)) + ", B " + location_name(locate(n, regions, 1)) +
             ", so the result must be " + (regular ? location_name(want) : (want == Location::inside ? "in" : "out")) +
             ", but it is " + location_name(got);
    }
  }
  return {};
}

}  // namespace mk::oracle
