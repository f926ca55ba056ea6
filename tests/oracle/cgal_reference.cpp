// CGAL's exact Boolean operations as an independent reference (see cgal_reference.hpp).
// [BRIEF §1] [MK89 §2.2]
// Preconditions: see cgal_reference.hpp.
#include "tests/oracle/cgal_reference.hpp"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <map>
#include <vector>

namespace mk::oracle {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point2 = K::Point_2;
using Polygon2 = CGAL::Polygon_2<K>;
using PolygonWithHoles2 = CGAL::Polygon_with_holes_2<K>;
using Set = CGAL::Polygon_set_2<K>;

// CGAL's exact number type here is mpq_class (CGAL_USE_GMPXX): conversions are exact.
Point2 to_cgal(const QPoint& p) { return Point2(K::FT(p.x), K::FT(p.y)); }
QPoint from_cgal(const Point2& p) { return {CGAL::exact(p.x()), CGAL::exact(p.y())}; }

}  // namespace

struct CgalSet::Impl {
  Set set;
};

CgalSet::CgalSet() : impl_(std::make_unique<Impl>()) {}
CgalSet::~CgalSet() = default;
CgalSet::CgalSet(const CgalSet& o) : impl_(std::make_unique<Impl>(*o.impl_)) {}
CgalSet& CgalSet::operator=(const CgalSet& o) {
  *impl_ = *o.impl_;
  return *this;
}

std::vector<QRing> simple_cycles(const QRing& ring) {
  std::vector<QRing> out;
  QRing path;
  const auto less = [](const QPoint& p, const QPoint& q) { return p.x != q.x ? p.x < q.x : p.y < q.y; };
  std::map<QPoint, std::size_t, decltype(less)> at(less);  // point -> its index in path
  for (std::size_t i = 0; i <= ring.size(); ++i) {
    const QPoint& v = ring[i % ring.size()];
    const auto it = at.find(v);
    if (it == at.end()) {
      at.emplace(v, path.size());
      path.push_back(v);
      continue;
    }
    // A loop closes at v: it leaves the path, v stays.
    QRing loop(path.begin() + static_cast<std::ptrdiff_t>(it->second), path.end());
    for (std::size_t k = it->second + 1; k < path.size(); ++k) at.erase(path[k]);
    path.resize(it->second + 1);
    out.push_back(std::move(loop));
  }
  return out;
}

CgalSet CgalSet::of(const Region& r) {
  CgalSet s;
  for (const QRing& ring : r.rings) {
    if (ring.size() < 3) continue;
    for (const QRing& cycle : simple_cycles(ring)) {
      if (cycle.size() < 3) continue;
      Polygon2 p;
      for (const QPoint& v : cycle) p.push_back(to_cgal(v));
      if (p.area() == 0) continue;
      if (!p.is_simple()) {
        std::string what = "a cycle that is not simple:";
        for (const QPoint& v : cycle) what.append(" ").append(show(v));
        throw CgalRegionError(what);
      }
      if (p.is_clockwise_oriented()) p.reverse_orientation();
      s.impl_->set.symmetric_difference(p);
    }
  }
  if (r.complement) s.impl_->set.complement();
  return s;
}

CgalSet CgalSet::apply(Operation op, const CgalSet& b) const {
  CgalSet out(*this);
  Set& s = out.impl_->set;
  switch (op) {
    case Operation::intersection: s.intersection(b.impl_->set); break;
    case Operation::union_: s.join(b.impl_->set); break;
    case Operation::difference: s.difference(b.impl_->set); break;
    case Operation::symmetric_difference: s.symmetric_difference(b.impl_->set); break;
  }
  return out;
}

CgalSet CgalSet::complement() const {
  CgalSet out(*this);
  out.impl_->set.complement();
  return out;
}

bool CgalSet::same_as(const CgalSet& other) const {
  Set x = impl_->set;
  x.symmetric_difference(other.impl_->set);
  return x.is_empty();
}

bool CgalSet::is_empty() const { return impl_->set.is_empty(); }

std::optional<Q> CgalSet::area() const {
  std::vector<PolygonWithHoles2> parts;
  impl_->set.polygons_with_holes(std::back_inserter(parts));
  Q total = 0;
  for (const auto& pwh : parts) {
    if (pwh.is_unbounded()) return std::nullopt;
    // Signed: CGAL runs outer boundaries counterclockwise and holes clockwise, and a
    // boundary that touches itself (a hole meeting its shell at a vertex) may not be simple,
    // so only the signed shoelace sum is its area.
    total += CGAL::exact(pwh.outer_boundary().area());
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) total += CGAL::exact(h->area());
  }
  return total;
}

Location CgalSet::locate(const QPoint& p) const {
  switch (impl_->set.oriented_side(to_cgal(p))) {
    case CGAL::ON_POSITIVE_SIDE: return Location::inside;
    case CGAL::ON_ORIENTED_BOUNDARY: return Location::boundary;
    default: return Location::outside;
  }
}

std::optional<QPoint> CgalSet::interior_point() const {
  std::vector<PolygonWithHoles2> parts;
  impl_->set.polygons_with_holes(std::back_inserter(parts));
  if (parts.empty()) return std::nullopt;
  // Bounded parts: step off an edge of the outer boundary towards its inside.
  for (const auto& pwh : parts) {
    if (pwh.is_unbounded()) continue;
    const Polygon2& outer = pwh.outer_boundary();
    const QPoint a = from_cgal(outer[0]);
    const QPoint b = from_cgal(outer[1]);
    const Q sign = outer.is_counterclockwise_oriented() ? 1 : -1;
    const QPoint m{(a.x + b.x) / 2, (a.y + b.y) / 2};
    const QPoint normal{sign * (a.y - b.y), sign * (b.x - a.x)};  // left of a -> b when counterclockwise
    for (Q t = 1;; t /= 2) {
      const QPoint q{m.x + t * normal.x, m.y + t * normal.y};
      if (locate(q) == Location::inside) return q;
    }
  }
  // Only unbounded parts: a point beyond every hole.
  Q far = 1;
  for (const auto& pwh : parts) {
    for (auto h = pwh.holes_begin(); h != pwh.holes_end(); ++h) {
      for (auto v = h->vertices_begin(); v != h->vertices_end(); ++v) {
        const QPoint p = from_cgal(*v);
        far = std::max({far, Q(abs(p.x) + 1), Q(abs(p.y) + 1)});
      }
    }
  }
  return QPoint{far, far};
}

bool epeck_misses_line_crossing(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d) {
  const auto crossing = CGAL::intersection(K::Line_2(to_cgal(a), to_cgal(b)), K::Line_2(to_cgal(c), to_cgal(d)));
  return !crossing;
}

Q area_through_polygons_with_holes(Operation op, const Region& a, const Region& b) {
  const auto pwh = [](const Region& r) {
    const auto ring = [](const QRing& q, bool ccw) {
      Polygon2 p;
      for (const QPoint& v : q) p.push_back(to_cgal(v));
      if (p.is_counterclockwise_oriented() != ccw) p.reverse_orientation();
      return p;
    };
    PolygonWithHoles2 w(ring(r.rings[0], true));
    for (std::size_t i = 1; i < r.rings.size(); ++i) w.add_hole(ring(r.rings[i], false));
    return w;
  };
  CgalSet out;
  out.impl_->set.insert(pwh(a));
  switch (op) {
    case Operation::intersection: out.impl_->set.intersection(pwh(b)); break;
    case Operation::union_: out.impl_->set.join(pwh(b)); break;
    case Operation::difference: out.impl_->set.difference(pwh(b)); break;
    case Operation::symmetric_difference: out.impl_->set.symmetric_difference(pwh(b)); break;
  }
  return out.area().value_or(Q(-1));
}

}  // namespace mk::oracle
