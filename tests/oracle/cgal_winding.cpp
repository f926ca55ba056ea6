// Winding numbers of the faces of CGAL's arrangement of the input segments (see
// cgal_winding.hpp). [BRIEF §1, extended by issue 13]
// Preconditions: see cgal_winding.hpp.
#include "tests/oracle/cgal_winding.hpp"

#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <deque>
#include <map>
#include <unordered_map>

namespace mk::oracle {

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Point2 = K::Point_2;
using Traits = CGAL::Arr_segment_traits_2<K>;
using Arrangement = CGAL::Arrangement_2<Traits>;
using Face = Arrangement::Face_const_handle;
using Halfedge = Arrangement::Halfedge_const_handle;

// CGAL's exact number type here is mpq_class (CGAL_USE_GMPXX): conversions are exact.
Point2 to_cgal(const QPoint& p) { return Point2(K::FT(p.x), K::FT(p.y)); }
QPoint from_cgal(const Point2& p) { return {CGAL::exact(p.x()), CGAL::exact(p.y())}; }

// An input segment, directed as its ring runs.
struct Directed {
  std::size_t operand;
  Point2 from;
  Point2 to;
};

// Twice the signed area of a closed ring (the shoelace sum).
Q twice_area(const QRing& r) {
  Q twice = 0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    const QPoint& p = r[i];
    const QPoint& q = r[(i + 1) % r.size()];
    twice += p.x * q.y - q.x * p.y;
  }
  return twice;
}

}  // namespace

struct WindingArrangement::Impl {
  std::size_t operands = 0;
  std::vector<Directed> segments;
  Arrangement arr;
  std::vector<std::vector<int>> windings;   // per bounded face
  std::string inconsistency;
  // Exact data read once: each bounded face's cycles and area, and every halfedge with the
  // bounded-face index on its left and right (-1: the unbounded face).
  std::vector<std::vector<QRing>> face_cycles;
  std::vector<Q> face_areas;
  struct Side {
    QPoint from, to;
    long left, right;
  };
  std::vector<Side> halfedges;

  // The change of each operand's winding number from the face left of h to the face right
  // of it: every input segment the edge lies on counts, so overlapping segments add up.
  // The edge's midpoint lies inside an input segment exactly when the edge is part of it
  // (a segment through the midpoint at an angle would cross the edge there, which would
  // then be a vertex).
  std::vector<int> change_across(Halfedge h) const {
    std::vector<int> d(operands, 0);
    const Point2& a = h->source()->point();
    const Point2& b = h->target()->point();
    const Point2 m = CGAL::midpoint(a, b);
    const CGAL::Comparison_result dir = CGAL::compare_xy(a, b);
    for (const Directed& s : segments) {
      if (!CGAL::collinear(s.from, s.to, m) || !CGAL::collinear_are_strictly_ordered_along_line(s.from, m, s.to)) {
        continue;
      }
      // Leaving the left side of a segment (its ring's inside when counterclockwise): -1.
      d[s.operand] += CGAL::compare_xy(s.from, s.to) == dir ? -1 : 1;
    }
    return d;
  }

  // Windings of every face reached from the unbounded face; returns the bounded faces, in
  // the walk's order (that of `windings`).
  std::vector<Face> walk() {
    std::unordered_map<const void*, std::size_t> index;  // face -> slot in `all`
    std::vector<std::vector<int>> all{std::vector<int>(operands, 0)};
    std::vector<Face> all_faces{arr.unbounded_face()};
    index[&*arr.unbounded_face()] = 0;
    std::deque<std::size_t> queue{0};
    const auto cross_ccb = [&](std::size_t from, Arrangement::Ccb_halfedge_const_circulator first) {
      auto h = first;
      do {
        // Every halfedge has its face on its left: crossing it leaves `from` to the right.
        const Face g = h->twin()->face();
        std::vector<int> w = all[from];
        const std::vector<int> d = change_across(h);
        for (std::size_t i = 0; i < operands; ++i) w[i] += d[i];
        const auto [it, fresh] = index.emplace(&*g, all.size());
        if (fresh) {
          all.push_back(w);
          all_faces.push_back(g);
          queue.push_back(it->second);
        } else if (all[it->second] != w && inconsistency.empty()) {
          inconsistency = "winding numbers disagree across the edge " + show(from_cgal(h->source()->point())) + " -> " +
                          show(from_cgal(h->target()->point()));
        }
      } while (++h != first);
    };
    while (!queue.empty()) {
      const std::size_t f = queue.front();
      queue.pop_front();
      const Face face = all_faces[f];
      if (!face->is_unbounded()) cross_ccb(f, face->outer_ccb());
      for (auto c = face->inner_ccbs_begin(); c != face->inner_ccbs_end(); ++c) cross_ccb(f, *c);
    }
    if (all.size() != arr.number_of_faces() && inconsistency.empty()) {
      inconsistency = "the walk reached " + std::to_string(all.size()) + " of " + std::to_string(arr.number_of_faces()) +
                      " faces";
    }
    for (std::size_t i = 1; i < all.size(); ++i) windings.push_back(std::move(all[i]));
    all_faces.erase(all_faces.begin());
    return all_faces;
  }

  // Every boundary cycle of a face, as the sources of its halfedges in order.
  std::vector<QRing> cycles(Face f) const {
    std::vector<QRing> out;
    const auto add = [&](Arrangement::Ccb_halfedge_const_circulator first) {
      QRing r;
      auto h = first;
      do r.push_back(from_cgal(h->source()->point()));
      while (++h != first);
      out.push_back(std::move(r));
    };
    if (!f->is_unbounded()) add(f->outer_ccb());
    for (auto c = f->inner_ccbs_begin(); c != f->inner_ccbs_end(); ++c) add(*c);
    return out;
  }
};

WindingArrangement::WindingArrangement(const std::vector<std::vector<QRing>>& operands) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.operands = operands.size();
  std::vector<Traits::Curve_2> curves;
  for (std::size_t o = 0; o < operands.size(); ++o) {
    for (const QRing& r : operands[o]) {
      for (std::size_t i = 0; i < r.size(); ++i) {
        const QPoint& a = r[i];
        const QPoint& b = r[(i + 1) % r.size()];
        if (a.x == b.x && a.y == b.y) continue;  // a repeated vertex: no segment
        m.segments.push_back({o, to_cgal(a), to_cgal(b)});
        curves.emplace_back(m.segments.back().from, m.segments.back().to);
      }
    }
  }
  CGAL::insert(m.arr, curves.begin(), curves.end());
  const std::vector<Face> faces = m.walk();
  std::unordered_map<const void*, long> slot;
  for (std::size_t f = 0; f < faces.size(); ++f) {
    slot[&*faces[f]] = long(f);
    m.face_cycles.push_back(m.cycles(faces[f]));
    // Outer cycles run counterclockwise and inner ones clockwise (the face on their left),
    // so the signed sum over all of a face's cycles is its area; antennas cancel.
    Q twice = 0;
    for (const QRing& r : m.face_cycles.back()) twice += twice_area(r);
    m.face_areas.push_back(twice / 2);
  }
  const auto index = [&](Face f) {
    const auto it = slot.find(&*f);
    return it == slot.end() ? -1L : it->second;
  };
  for (auto h = m.arr.halfedges_begin(); h != m.arr.halfedges_end(); ++h) {
    m.halfedges.push_back({from_cgal(h->source()->point()), from_cgal(h->target()->point()), index(h->face()),
                           index(h->twin()->face())});
  }
}

WindingArrangement::~WindingArrangement() = default;

std::size_t WindingArrangement::face_count() const { return impl_->windings.size(); }
const std::vector<int>& WindingArrangement::windings(std::size_t face) const { return impl_->windings[face]; }
const std::string& WindingArrangement::inconsistency() const { return impl_->inconsistency; }

WindingArrangement::Selection WindingArrangement::select(const std::function<bool(const std::vector<int>&)>& in) const {
  Selection s(impl_->windings.size());
  for (std::size_t f = 0; f < s.size(); ++f) s[f] = in(impl_->windings[f]);
  return s;
}

Q WindingArrangement::area(const Selection& s) const {
  Q sum = 0;
  for (std::size_t f = 0; f < s.size(); ++f) {
    if (s[f]) sum += impl_->face_areas[f];
  }
  return sum;
}

Region WindingArrangement::region(const Selection& s) const {
  Region out;
  for (std::size_t f = 0; f < s.size(); ++f) {
    if (!s[f]) continue;
    for (const QRing& r : impl_->face_cycles[f]) out.rings.push_back(r);
  }
  return out;
}

std::vector<std::pair<QPoint, QPoint>> WindingArrangement::boundary(const Selection& s) const {
  const auto is_selected = [&](long f) { return f >= 0 && s[static_cast<std::size_t>(f)]; };
  std::vector<std::pair<QPoint, QPoint>> out;
  for (const Impl::Side& h : impl_->halfedges) {
    if (is_selected(h.left) && !is_selected(h.right)) out.emplace_back(h.from, h.to);
  }
  return out;
}

namespace {

// A 1-chain of directed segments compared by its measure along each line: segment a -> b
// adds +1 (or -1 against the line's direction) between its endpoints' positions, kept as
// +-1 at one end and -+1 at the other. Two chains are equal (the same signed multiplicity
// everywhere) exactly when every line's position holds the same sum.
using Chain = std::map<std::array<Q, 4>, int>;  // {vertical, slope or x, offset, position}

void add_to_chain(Chain& c, const QPoint& a, const QPoint& b, int sign) {
  if (a.x == b.x && a.y == b.y) return;
  const bool vertical = a.x == b.x;
  const Q slope = vertical ? Q(0) : Q((b.y - a.y) / (b.x - a.x));
  const Q offset = vertical ? a.x : Q(a.y - slope * a.x);
  const Q s = vertical ? a.y : a.x, t = vertical ? b.y : b.x;
  const int w = s < t ? sign : -sign;
  const Q kind = vertical ? 1 : 0;
  c[{kind, slope, offset, s < t ? s : t}] += w;
  c[{kind, slope, offset, s < t ? t : s}] -= w;
}

}  // namespace

std::string chain_difference(const std::vector<std::pair<QPoint, QPoint>>& x, const std::vector<QRing>& y) {
  Chain c;
  for (const auto& [a, b] : x) add_to_chain(c, a, b, 1);
  for (const QRing& r : y) {
    for (std::size_t i = 0; i < r.size(); ++i) add_to_chain(c, r[i], r[(i + 1) % r.size()], -1);
  }
  for (const auto& [key, sum] : c) {
    if (sum != 0) {
      return std::string(key[0] == 1 ? "on x = " : "on the line of slope " + key[1].get_str() + " through (0, ") +
             key[2].get_str() + (key[0] == 1 ? "" : ")") + " at " + key[3].get_str() + ": multiplicity differs by " +
             std::to_string(sum);
    }
  }
  return {};
}

int orientation_sign(const QRing& r) { return sgn(twice_area(r)); }

}  // namespace mk::oracle
