// Exact OGC validity of polygons with holes, as GEOS's isValid defines it: closed rings of 3+
// distinct points, no ring crossing or touching itself, rings of one polygon meeting at
// points only with the interior connected, holes inside their shell and not nested in each
// other, parts whose interiors are disjoint and touch at finitely many points. One plane
// sweep finds crossings, overlaps, touches and each ring's innermost enclosing ring; the
// nodes (points where rings meet) are then checked one by one.
// [OGC06-103 §6.1.11] (polygon validity) [Sh76] (sweep) [MK89 §2.2] (inclusion forest)
// Preconditions: V is an exact kernel (its predicates decide the check). Rings are given
// without the closing vertex; consecutive repeated points are ignored, as GEOS does.
// O(n log n) for n vertices.
#pragma once

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "core/polygon.hpp"
#include "core/sweep_status.hpp"
#include "core/validity_nodes.hpp"

namespace mk {

struct OgcValidity {
  OgcDefect defect = OgcDefect::none;
  int polygon = -1;  // the part (and ring: 0 its shell, k its hole k - 1) where it was found
  int ring = -1;
  bool valid() const { return defect == OgcDefect::none; }
  std::string why() const {
    if (valid()) return "valid";
    return std::string(ogc_defect_name(defect)) + " (polygon " + std::to_string(polygon) + ", ring " +
           std::to_string(ring) + ")";
  }
};

// Polygons with holes over any point type: rings[first[r] .. first[r + 1]) is ring r, of
// polygon part[r], a shell when it is the first ring of its polygon.
template <class P>
struct RingSet {
  std::vector<P> points;
  std::vector<std::size_t> first{0};
  std::vector<int> part;
  std::vector<int> index_in_part;
  void add_ring(const std::vector<P>& ring, int polygon, int index) {
    points.insert(points.end(), ring.begin(), ring.end());
    first.push_back(points.size());
    part.push_back(polygon);
    index_in_part.push_back(index);
  }
  std::size_t num_rings() const { return part.size(); }
};

namespace detail {

template <Kernel V>
bool same_point(const typename V::Point& a, const typename V::Point& b) {
  return V::compare_x(a, b) == Sign::zero && V::compare_y(a, b) == Sign::zero;
}

template <Kernel V>
bool lex_less(const typename V::Point& a, const typename V::Point& b) {
  const Sign sx = V::compare_x(a, b);
  return sx == Sign::negative || (sx == Sign::zero && V::compare_y(a, b) == Sign::negative);
}

// Rings as point ids (distinct points in lexicographic order), repeated consecutive points
// dropped; false with the ring's index when one has fewer than 3 points left.
template <Kernel V>
bool index_rings(const RingSet<typename V::Point>& in, std::vector<typename V::Point>& pts,
                 std::vector<std::vector<int>>& rings, int& bad_ring) {
  const std::size_t n = in.points.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return lex_less<V>(in.points[a], in.points[b]); });
  std::vector<int> id(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto& p = in.points[static_cast<std::size_t>(order[k])];
    if (pts.empty() || !same_point<V>(pts.back(), p)) pts.push_back(p);
    id[static_cast<std::size_t>(order[k])] = static_cast<int>(pts.size()) - 1;
  }
  rings.resize(in.num_rings());
  for (std::size_t r = 0; r < in.num_rings(); ++r) {
    auto& ring = rings[r];
    for (std::size_t k = in.first[r]; k < in.first[r + 1]; ++k) {
      if (ring.empty() || ring.back() != id[k]) ring.push_back(id[k]);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (ring.size() < 3) {
      bad_ring = static_cast<int>(r);
      return false;
    }
  }
  return true;
}

// How two segments that meet in the sweep status relate: `conflict` when they cross at a
// point inside both or overlap along a piece of positive length; otherwise each end point
// of one lying inside the other is a touch. Collinear points compare by id (ids follow
// lexicographic order), so "inside" needs no further predicate.
template <class Entry>
struct NeighbourRelation {
  bool conflict = false;
  int touch_count = 0;
  std::pair<int, int> touch[2];  // (point id, segment)
};

template <Kernel V, class Entry>
NeighbourRelation<Entry> relate_neighbours(const Entry& s, const Entry& t) {
  NeighbourRelation<Entry> r;
  const Sign oc = V::orient2d(s.lo, s.hi, t.lo);
  const Sign od = V::orient2d(s.lo, s.hi, t.hi);
  if (oc == Sign::zero && od == Sign::zero) {
    r.conflict = s.lo_id < t.hi_id && t.lo_id < s.hi_id;
    return r;
  }
  if (oc != Sign::zero && oc == od) return r;
  const Sign oa = V::orient2d(t.lo, t.hi, s.lo);
  const Sign ob = V::orient2d(t.lo, t.hi, s.hi);
  if (oa != Sign::zero && oa == ob) return r;
  if (oc != Sign::zero && od != Sign::zero && oa != Sign::zero && ob != Sign::zero) {
    r.conflict = true;
    return r;
  }
  const auto inside = [](int id, const Entry& e) { return e.lo_id < id && id < e.hi_id; };
  if (oc == Sign::zero && inside(t.lo_id, s)) r.touch[r.touch_count++] = {t.lo_id, s.segment};
  if (od == Sign::zero && inside(t.hi_id, s)) r.touch[r.touch_count++] = {t.hi_id, s.segment};
  if (oa == Sign::zero && inside(s.lo_id, t) && r.touch_count < 2) r.touch[r.touch_count++] = {s.lo_id, t.segment};
  if (ob == Sign::zero && inside(s.hi_id, t) && r.touch_count < 2) r.touch[r.touch_count++] = {s.hi_id, t.segment};
  return r;
}

}  // namespace detail

// The check over rings given as ids of distinct points in lexicographic order (consecutive
// ids distinct, 3+ per ring): ring r belongs to polygon part[r], as its shell when
// index_in_part[r] is 0. Defects name the ring by its index in `rings`.
template <Kernel V>
NodeVerdict check_indexed_rings(const std::vector<typename V::Point>& pts, const std::vector<std::vector<int>>& rings,
                                const std::vector<int>& part, const std::vector<int>& index_in_part) {
  const int num_points = static_cast<int>(pts.size());
  const auto P = [&](int id) -> const typename V::Point& { return pts[static_cast<std::size_t>(id)]; };

  // Segments, and for every point the segments leaving it to the right (starting) and
  // arriving from the left (ending), as offsets into one array each.
  std::vector<SweepSegment> seg;
  std::vector<int> seg_ring;           // per segment: its ring
  std::vector<char> seg_forward;       // per segment: its ring runs from lo to hi
  std::vector<std::size_t> ring_base;  // per ring: the index of its first segment
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    ring_base.push_back(seg.size());
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const int u = ring[i];
      const int w = ring[(i + 1) % ring.size()];
      seg.push_back({std::min(u, w), std::max(u, w)});
      seg_ring.push_back(static_cast<int>(r));
      seg_forward.push_back(u < w);
    }
  }
  const auto ring_of = [&](int s) { return seg_ring[static_cast<std::size_t>(s)]; };
  std::vector<char> vertical(seg.size());
  std::vector<int> start_at(static_cast<std::size_t>(num_points) + 1, 0), end_at(static_cast<std::size_t>(num_points) + 1, 0);
  std::vector<char> has_sloped(static_cast<std::size_t>(num_points), 0);  // a non-vertical segment ends here
  for (std::size_t i = 0; i < seg.size(); ++i) {
    const auto& s = seg[i];
    vertical[i] = V::compare_x(P(s.lo), P(s.hi)) == Sign::zero;
    ++start_at[static_cast<std::size_t>(s.lo) + 1];
    ++end_at[static_cast<std::size_t>(s.hi) + 1];
    if (!vertical[i]) has_sloped[static_cast<std::size_t>(s.lo)] = has_sloped[static_cast<std::size_t>(s.hi)] = 1;
  }
  std::partial_sum(start_at.begin(), start_at.end(), start_at.begin());
  std::partial_sum(end_at.begin(), end_at.end(), end_at.begin());
  std::vector<int> starting(seg.size()), ending(seg.size());
  {
    std::vector<int> fs(start_at.begin(), start_at.end() - 1), fe(end_at.begin(), end_at.end() - 1);
    for (std::size_t i = 0; i < seg.size(); ++i) {
      starting[static_cast<std::size_t>(fs[static_cast<std::size_t>(seg[i].lo)]++)] = static_cast<int>(i);
      ending[static_cast<std::size_t>(fe[static_cast<std::size_t>(seg[i].hi)]++)] = static_cast<int>(i);
    }
  }

  // Chains: a sloped segment whose ring goes on rightwards from its right end over another
  // sloped segment is continued by it in the status, in place (one tree operation per run
  // of segments monotone in x, not per segment).
  std::vector<int> continued_by(seg.size(), -1);
  std::vector<char> continues(seg.size(), 0);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    const std::size_t n = ring.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = ring_base[r] + k;
      const std::size_t j = ring_base[r] + (k + 1) % n;  // the ring's next segment, from ring[k + 1]
      if (vertical[i] || vertical[j]) continue;
      const int mid = ring[(k + 1) % n];
      if (seg[i].hi == mid && seg[j].lo == mid) {  // rightwards through mid
        continued_by[i] = static_cast<int>(j);
        continues[j] = 1;
      } else if (seg[i].lo == mid && seg[j].hi == mid) {  // leftwards through mid: j then i
        continued_by[j] = static_cast<int>(i);
        continues[i] = 1;
      }
    }
  }

  // Each ring's lexicographically smallest vertex and its lower edge there (both edges leave
  // that vertex rightwards or straight up; the lower one has the other on its left): the
  // probe just right of that vertex on that edge finds the ring's innermost enclosing ring.
  std::vector<int> ring_min(rings.size()), lower_edge(rings.size());
  std::vector<char> ccw(rings.size());
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto& ring = rings[r];
    const std::size_t n = ring.size();
    const std::size_t m = static_cast<std::size_t>(std::min_element(ring.begin(), ring.end()) - ring.begin());
    const Sign turn = V::orient2d(P(ring[(m + n - 1) % n]), P(ring[m]), P(ring[(m + 1) % n]));
    ccw[r] = turn == Sign::positive;
    ring_min[r] = ring[m];
    lower_edge[r] = static_cast<int>(ring_base[r] + (ccw[r] ? m : (m + n - 1) % n));
  }
  std::vector<int> ring_order(rings.size());
  std::iota(ring_order.begin(), ring_order.end(), 0);
  std::sort(ring_order.begin(), ring_order.end(), [&](int a, int b) {
    if (ring_min[a] != ring_min[b]) return ring_min[a] < ring_min[b];
    // At a common smallest vertex: the lower edge turning further clockwise first.
    const auto& e = seg[static_cast<std::size_t>(lower_edge[a])];
    const auto& f = seg[static_cast<std::size_t>(lower_edge[b])];
    return V::orient2d(P(e.lo), P(e.hi), P(f.hi)) == Sign::positive;
  });
  std::vector<int> parent(rings.size(), -1);
  std::size_t next_ring = 0;

  // Touches: a point lying inside a segment (not at its ends).
  std::vector<std::pair<int, int>> touches;  // (point, segment)
  SweepStatus<V> status(pts, seg);
  using It = typename SweepStatus<V>::Iterator;
  int bad_ring = -1;
  // Relates two neighbours in the status: false (and bad_ring) on a crossing or overlap.
  const auto neighbours_ok = [&](It a, It b) {
    if (a == status.end() || b == status.end()) return true;
    const auto rel = detail::relate_neighbours<V>(*a, *b);
    if (rel.conflict) {
      bad_ring = ring_of(a->segment);
      return false;
    }
    for (int k = 0; k < rel.touch_count; ++k) touches.push_back(rel.touch[k]);
    return true;
  };
  std::vector<int> verticals;
  int column_begin = 0;
  while (column_begin < num_points) {
    int column_end = column_begin + 1;
    while (column_end < num_points && V::compare_x(P(column_begin), P(column_end)) == Sign::zero) ++column_end;
    // (a) Segments ending in this column whose ring turns back (or goes vertical) leave;
    // their former neighbours meet. The others are continued in (d).
    for (int p = column_begin; p < column_end; ++p) {
      for (int k = end_at[static_cast<std::size_t>(p)]; k < end_at[static_cast<std::size_t>(p) + 1]; ++k) {
        const int i = ending[static_cast<std::size_t>(k)];
        if (vertical[static_cast<std::size_t>(i)] || continued_by[static_cast<std::size_t>(i)] >= 0) continue;
        const It after = status.erase(i);
        if (after != status.begin() && !neighbours_ok(std::prev(after), after)) return {OgcDefect::self_intersection, bad_ring};
      }
    }
    // (b) A point of this column met by no sloped segment of its own lies inside at most one
    // segment passing through (two would cross or overlap there). Points with sloped
    // segments find their touches as neighbours in the status.
    for (int p = column_begin; p < column_end; ++p) {
      if (has_sloped[static_cast<std::size_t>(p)]) continue;
      const It it = status.first_not_below(P(p));
      if (it == status.end() || status.side(it, P(p)) != Sign::zero) continue;
      const It nx = std::next(it);
      if (nx != status.end() && status.side(nx, P(p)) == Sign::zero) return {OgcDefect::self_intersection, ring_of(it->segment)};
      touches.push_back({p, it->segment});
    }
    // (c) Vertical segments of this column: against each other (overlap), the points between
    // their ends (touches) and the segments passing through (crossings).
    verticals.clear();
    for (int p = column_begin; p < column_end; ++p) {
      for (int k = start_at[static_cast<std::size_t>(p)]; k < start_at[static_cast<std::size_t>(p) + 1]; ++k) {
        const int i = starting[static_cast<std::size_t>(k)];
        if (vertical[static_cast<std::size_t>(i)]) verticals.push_back(i);
      }
    }
    int reach = -1;  // the highest end of the vertical segments so far, which come by lower end
    for (const int i : verticals) {
      const SweepSegment& v = seg[static_cast<std::size_t>(i)];
      if (v.lo < reach) return {OgcDefect::self_intersection, ring_of(i)};
      reach = v.hi;
      for (int p = v.lo + 1; p < v.hi; ++p) touches.push_back({p, i});
      // Segments at the column between the two ends: those ending or starting at an end
      // share it (a node), those passing through an end touch it, others cross.
      for (It it = status.first_not_below(P(v.lo)); it != status.end(); ++it) {
        const Sign at_top = status.side(it, P(v.hi));
        if (at_top == Sign::negative) break;  // above the vertical segment
        if (it->lo_id == v.lo || it->hi_id == v.lo || it->lo_id == v.hi || it->hi_id == v.hi) continue;
        const Sign at_bottom = status.side(it, P(v.lo));
        if (at_bottom == Sign::zero) {
          touches.push_back({v.lo, it->segment});
        } else if (at_top == Sign::zero) {
          touches.push_back({v.hi, it->segment});
        } else {
          return {OgcDefect::self_intersection, ring_of(i)};
        }
      }
    }
    // (d) At each point of the column, segments continuing a chain take their predecessor's
    // place, then segments starting a chain enter; a segment on the line of one already in
    // overlaps it.
    for (int p = column_begin; p < column_end; ++p) {
      for (int k = end_at[static_cast<std::size_t>(p)]; k < end_at[static_cast<std::size_t>(p) + 1]; ++k) {
        const int i = ending[static_cast<std::size_t>(k)];
        const int j = continued_by[static_cast<std::size_t>(i)];
        if (vertical[static_cast<std::size_t>(i)] || j < 0) continue;
        const It it = status.replace(i, j);
        if (it != status.begin() && !neighbours_ok(std::prev(it), it)) return {OgcDefect::self_intersection, bad_ring};
        if (!neighbours_ok(it, std::next(it))) return {OgcDefect::self_intersection, bad_ring};
      }
      for (int k = start_at[static_cast<std::size_t>(p)]; k < start_at[static_cast<std::size_t>(p) + 1]; ++k) {
        const int i = starting[static_cast<std::size_t>(k)];
        if (vertical[static_cast<std::size_t>(i)] || continues[static_cast<std::size_t>(i)]) continue;
        const It it = status.insert(i);
        if (it == status.end()) return {OgcDefect::self_intersection, ring_of(i)};
        if (it != status.begin() && !neighbours_ok(std::prev(it), it)) return {OgcDefect::self_intersection, bad_ring};
        if (!neighbours_ok(it, std::next(it))) return {OgcDefect::self_intersection, bad_ring};
      }
    }
    // (e) Rings whose smallest vertex lies in this column: the segment just below the probe
    // is the lower edge's predecessor. Inside that segment's ring when the ring's interior
    // lies above it; otherwise in the ring that encloses that ring.
    while (next_ring < ring_order.size() && ring_min[static_cast<std::size_t>(ring_order[next_ring])] < column_end) {
      const int r = ring_order[next_ring++];
      const It it = status.find(lower_edge[static_cast<std::size_t>(r)]);
      if (it == status.begin()) continue;
      const int below = std::prev(it)->segment;
      const int s = ring_of(below);
      const bool forward = seg_forward[static_cast<std::size_t>(below)];
      const bool interior_above = forward == static_cast<bool>(ccw[static_cast<std::size_t>(s)]);
      parent[static_cast<std::size_t>(r)] = interior_above ? s : parent[static_cast<std::size_t>(s)];
    }
    column_begin = column_end;
  }
  std::sort(touches.begin(), touches.end());
  touches.erase(std::unique(touches.begin(), touches.end()), touches.end());

  // Nodes: every point where a ring passes more than once, or two rings meet.
  const NodeVerdict nodes = check_validity_nodes<V>(pts, rings, seg, seg_ring, touches, part);
  if (nodes.defect != OgcDefect::none) return nodes;

  // Nesting: a hole directly inside its own shell; a shell outside every part or directly
  // inside a hole.
  std::vector<int> shell_of_part;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const auto p = static_cast<std::size_t>(part[r]);
    if (shell_of_part.size() <= p) shell_of_part.resize(p + 1, -1);
    if (index_in_part[r] == 0) shell_of_part[p] = static_cast<int>(r);
  }
  const auto is_hole = [&](int r) { return index_in_part[static_cast<std::size_t>(r)] != 0; };
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const int up = parent[r];
    if (is_hole(static_cast<int>(r))) {
      if (up == shell_of_part[static_cast<std::size_t>(part[r])]) continue;
      const bool in_own_hole = up >= 0 && is_hole(up) && part[static_cast<std::size_t>(up)] == part[r];
      return {in_own_hole ? OgcDefect::nested_holes : OgcDefect::hole_outside_shell, static_cast<int>(r)};
    }
    if (up >= 0 && !is_hole(up)) return {OgcDefect::nested_shells, static_cast<int>(r)};
  }
  return {};
}

// The check over rings of V's points.
template <Kernel V>
OgcValidity check_ogc_validity(const RingSet<typename V::Point>& in) {
  OgcValidity v;
  const auto named = [&](OgcDefect d, int ring) {
    v.defect = d;
    if (ring >= 0) {
      v.polygon = in.part[static_cast<std::size_t>(ring)];
      v.ring = in.index_in_part[static_cast<std::size_t>(ring)];
    }
    return v;
  };
  std::vector<typename V::Point> pts;
  std::vector<std::vector<int>> rings;
  int short_ring = -1;
  if (!detail::index_rings<V>(in, pts, rings, short_ring)) return named(OgcDefect::too_few_points, short_ring);
  const NodeVerdict n = check_indexed_rings<V>(pts, rings, in.part, in.index_in_part);
  return named(n.defect, n.ring);
}

// The check over polygons of doubles (the written output).
template <Kernel V>
OgcValidity check_ogc_validity(const MultiPolygon& polygons) {
  RingSet<typename V::Point> in;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const auto add = [&](const Ring& ring, int index) {
      std::vector<typename V::Point> r;
      r.reserve(ring.size());
      for (const Point& p : ring) r.push_back(V::point(p));
      in.add_ring(r, static_cast<int>(k), index);
    };
    for (const Point& p : polygons[k].shell) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return {OgcDefect::invalid_coordinate, static_cast<int>(k), 0};
    }
    for (std::size_t h = 0; h < polygons[k].holes.size(); ++h) {
      for (const Point& p : polygons[k].holes[h]) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
          return {OgcDefect::invalid_coordinate, static_cast<int>(k), static_cast<int>(h) + 1};
        }
      }
    }
    add(polygons[k].shell, 0);
    for (std::size_t h = 0; h < polygons[k].holes.size(); ++h) add(polygons[k].holes[h], static_cast<int>(h) + 1);
  }
  return check_ogc_validity<V>(in);
}

}  // namespace mk
