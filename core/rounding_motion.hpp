// A certificate that rounding kept a valid result valid, looking only near the vertices that
// moved: if, while every vertex moves along the straight line from its exact position to its
// rounded one, no vertex ever meets an edge it is not on, the rounded result is the exact one
// deformed without any contact appearing or disappearing (an isotopy), so it is valid exactly
// when the exact result is, with the same polygons and holes. Each vertex's path lies in
// the segment [exact, rounded] and each edge in the convex hull of its ends' four positions,
// so it suffices that each such segment misses each such hull. Tested exactly, for the
// pairs whose boxes meet, in one pass over the edges.
// [GM98] (rounding as a continuous deformation) [MK89 §3.3] (rounded output)
// Preconditions: the exact result is valid; few vertices moved (the cost is the number of
// edges times the number of moved vertices and edges). K is an exact kernel; vertices of
// doubles are made with K::vertex(K::point(p)).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/boolean_op.hpp"
#include "core/rounding_boxes.hpp"

namespace mk {

namespace detail {

// Whether closed segments pq and ab meet (either may be a single point), exactly.
template <Kernel K>
bool closed_segments_meet(const typename K::Vertex& p, const typename K::Vertex& q, const typename K::Vertex& a,
                          const typename K::Vertex& b) {
  const auto same = [](const typename K::Vertex& u, const typename K::Vertex& w) {
    return K::compare_vertices(u, w) == Sign::zero;
  };
  // Whether r lies on the closed segment uw, given u, w, r collinear.
  const auto between = [](const typename K::Vertex& u, const typename K::Vertex& w, const typename K::Vertex& r) {
    const Sign a = K::compare_vertices(u, r);
    const Sign b = K::compare_vertices(r, w);
    return a == Sign::zero || b == Sign::zero || a == b;
  };
  const bool pq_point = same(p, q);
  const bool ab_point = same(a, b);
  if (pq_point && ab_point) return same(p, a);
  if (pq_point) return K::orient_vertices(a, b, p) == Sign::zero && between(a, b, p);
  if (ab_point) return K::orient_vertices(p, q, a) == Sign::zero && between(p, q, a);
  const Sign oa = K::orient_vertices(p, q, a);
  const Sign ob = K::orient_vertices(p, q, b);
  const Sign op = K::orient_vertices(a, b, p);
  const Sign oq = K::orient_vertices(a, b, q);
  if (oa == Sign::zero && ob == Sign::zero) {  // collinear: overlap of the ranges
    return between(p, q, a) || between(p, q, b) || between(a, b, p);
  }
  if (oa != Sign::zero && oa == ob) return false;
  if (op != Sign::zero && op == oq) return false;
  return true;
}

// Whether closed segment pq meets the closed triangle abc (which may be degenerate).
template <Kernel K>
bool segment_meets_triangle(const typename K::Vertex& p, const typename K::Vertex& q, const typename K::Vertex& a,
                            const typename K::Vertex& b, const typename K::Vertex& c) {
  if (closed_segments_meet<K>(p, q, a, b) || closed_segments_meet<K>(p, q, b, c) || closed_segments_meet<K>(p, q, c, a)) {
    return true;
  }
  const Sign t = K::orient_vertices(a, b, c);
  if (t == Sign::zero) return false;  // a segment-shaped triangle: its edges cover it
  // No edge is met: the segment is inside or outside; test one end.
  return K::orient_vertices(a, b, p) == t && K::orient_vertices(b, c, p) == t && K::orient_vertices(c, a, p) == t;
}

// Whether segment pq meets the convex hull of up to four points (covered by the triangles
// on any three of them).
template <Kernel K>
bool segment_meets_hull(const typename K::Vertex& p, const typename K::Vertex& q, const std::vector<typename K::Vertex>& s) {
  if (s.size() == 1) return closed_segments_meet<K>(p, q, s[0], s[0]);
  if (s.size() == 2) return closed_segments_meet<K>(p, q, s[0], s[1]);
  for (std::size_t i = 0; i < s.size(); ++i) {
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      for (std::size_t k = j + 1; k < s.size(); ++k) {
        if (segment_meets_triangle<K>(p, q, s[i], s[j], s[k])) return true;
      }
    }
  }
  return false;
}

}  // namespace detail

// True when the certificate holds for the result's cycles (given with their rounded
// vertices): no moved vertex's path meets an edge it is not on, and no moved edge's hull
// meets a vertex not on it. False means "not certified" (the caller checks the rounded
// output in full), not "invalid". `max_moved` bounds the work: beyond it, false at once.
template <Kernel K>
bool rounding_keeps_topology(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded, std::size_t max_moved) {
  struct Box {
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    void add(const Point& p) {
      // A rounded point's exact origin lies within half an ulp: widen by a whole ulp (the
      // inline next_up/next_down: std::nextafter's calls were most of this certificate's
      // time on a result of 10^5 vertices with two crossings).
      x0 = std::min(x0, detail::next_down(p.x));
      y0 = std::min(y0, detail::next_down(p.y));
      x1 = std::max(x1, detail::next_up(p.x));
      y1 = std::max(y1, detail::next_up(p.y));
    }
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  };
  // Each vertex once: its exact and rounded positions.
  std::vector<int> slot(static_cast<std::size_t>(r.arrangement.num_vertices()), -1);
  std::vector<int> ids;
  std::vector<Point> at;
  std::vector<char> moved;
  struct Edge {
    int a, b;  // slots
  };
  std::vector<Edge> edges;
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    const auto& cyc = r.cycles[c].vertices;
    for (std::size_t k = 0; k < cyc.size(); ++k) {
      const int id = cyc[k];
      if (slot[static_cast<std::size_t>(id)] < 0) {
        slot[static_cast<std::size_t>(id)] = static_cast<int>(ids.size());
        ids.push_back(id);
        at.push_back(rounded[c][k]);
        // Input points of doubles stay; the others are compared exactly below.
        moved.push_back(!r.arrangement.is_input_point(id) || !std::is_same_v<typename K::Point, Point>);
      }
    }
    if (cyc.size() < 2) continue;
    for (std::size_t k = 0; k < (cyc.size() == 2 ? 1 : cyc.size()); ++k) {
      edges.push_back({slot[static_cast<std::size_t>(cyc[k])], slot[static_cast<std::size_t>(cyc[(k + 1) % cyc.size()])]});
    }
  }
  // Exact comparisons (GMP for crossings whose box holds their rounded point, nearly all),
  // stopped as soon as too many vertices moved: on a result of 10^5 crossings they would
  // cost more than the operation.
  std::vector<int> moved_vertices;
  for (std::size_t v = 0; v < ids.size(); ++v) {
    if (!moved[v]) continue;
    moved[v] = K::compare_vertices(K::vertex(K::point(at[v])), r.vertex(ids[v])) != Sign::zero;
    if (moved[v]) moved_vertices.push_back(static_cast<int>(v));
    if (moved_vertices.size() > max_moved) return false;
  }
  if (moved_vertices.empty()) return true;
  std::vector<int> moved_edges;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (moved[static_cast<std::size_t>(edges[e].a)] || moved[static_cast<std::size_t>(edges[e].b)]) moved_edges.push_back(static_cast<int>(e));
  }
  if (moved_vertices.size() + moved_edges.size() > max_moved) return false;

  const auto exact = [&](int v) { return r.vertex(ids[static_cast<std::size_t>(v)]); };
  const auto final_pos = [&](int v) { return K::vertex(K::point(at[static_cast<std::size_t>(v)])); };
  const auto vertex_box = [&](int v) {
    Box b;
    b.add(at[static_cast<std::size_t>(v)]);
    return b;
  };
  const auto edge_box = [&](const Edge& e) {
    Box b = vertex_box(e.a);
    const Box o = vertex_box(e.b);
    b.x0 = std::min(b.x0, o.x0), b.y0 = std::min(b.y0, o.y0), b.x1 = std::max(b.x1, o.x1), b.y1 = std::max(b.y1, o.y1);
    return b;
  };
  // The positions an item occupies during the motion: a vertex's path, an edge's hull.
  const auto path_meets_edge = [&](int v, const Edge& e) {
    std::vector<typename K::Vertex> hull{exact(e.a), exact(e.b)};
    if (moved[static_cast<std::size_t>(e.a)]) hull.push_back(final_pos(e.a));
    if (moved[static_cast<std::size_t>(e.b)]) hull.push_back(final_pos(e.b));
    const auto p = exact(v);
    const auto q = moved[static_cast<std::size_t>(v)] ? final_pos(v) : p;
    return detail::segment_meets_hull<K>(p, q, hull);
  };
  Box all;
  std::vector<Box> moved_vertex_box, moved_edge_box;
  for (const int v : moved_vertices) {
    moved_vertex_box.push_back(vertex_box(v));
    const Box& b = moved_vertex_box.back();
    all.x0 = std::min(all.x0, b.x0), all.y0 = std::min(all.y0, b.y0), all.x1 = std::max(all.x1, b.x1), all.y1 = std::max(all.y1, b.y1);
  }
  for (const int e : moved_edges) {
    moved_edge_box.push_back(edge_box(edges[static_cast<std::size_t>(e)]));
    const Box& b = moved_edge_box.back();
    all.x0 = std::min(all.x0, b.x0), all.y0 = std::min(all.y0, b.y0), all.x1 = std::max(all.x1, b.x1), all.y1 = std::max(all.y1, b.y1);
  }
  for (const Edge& f : edges) {
    const Box fb = edge_box(f);
    if (!fb.meets(all)) continue;
    // Moved vertices against this edge.
    for (std::size_t k = 0; k < moved_vertices.size(); ++k) {
      const int v = moved_vertices[k];
      if (v == f.a || v == f.b || !fb.meets(moved_vertex_box[k])) continue;
      if (path_meets_edge(v, f)) return false;
    }
    // This edge's ends against the moved edges.
    for (std::size_t k = 0; k < moved_edges.size(); ++k) {
      const Edge& e = edges[static_cast<std::size_t>(moved_edges[k])];
      if (!fb.meets(moved_edge_box[k])) continue;
      for (const int u : {f.a, f.b}) {
        if (u == e.a || u == e.b || moved[static_cast<std::size_t>(u)]) continue;  // moved ones: above
        if (!vertex_box(u).meets(moved_edge_box[k])) continue;
        if (path_meets_edge(u, e)) return false;
      }
    }
  }
  return true;
}

}  // namespace mk
