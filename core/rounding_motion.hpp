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
#include <atomic>
#include <cstdint>
#include <cmath>
#include <vector>

#include "core/boolean_op.hpp"
#include "core/parallel.hpp"
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
// `threads`: for the pass over every edge.
template <Kernel K>
bool rounding_keeps_topology(const BooleanResult<K>& r, const std::vector<std::vector<Point>>& rounded, std::size_t max_moved,
                             unsigned threads = 1) {
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
    void add(const Box& o) { x0 = std::min(x0, o.x0), y0 = std::min(y0, o.y0), x1 = std::max(x1, o.x1), y1 = std::max(y1, o.y1); }
    bool meets(const Box& o) const { return x0 <= o.x1 && o.x0 <= x1 && y0 <= o.y1 && o.y0 <= y1; }
  };
  // Nothing is made per vertex that did not move (a result of 10^5 input points and two
  // crossings spent most of this certificate's time numbering and copying them): the
  // vertices that may move are the crossings when the input is doubles (input points round
  // to themselves), every vertex otherwise; each is compared exactly once, its state kept
  // in an array over those ids (0 not seen, 1 still, 2 moved).
  constexpr bool doubles_in = std::is_same_v<typename K::Point, Point>;
  const int first_movable = doubles_in ? r.arrangement.num_points() : 0;
  std::vector<char> state(static_cast<std::size_t>(r.arrangement.num_vertices() - first_movable), 0);
  const auto moved = [&](int id) { return id >= first_movable && state[static_cast<std::size_t>(id - first_movable)] == 2; };
  struct Moved {
    int id;
    Point at;  // rounded
    Box box;
  };
  std::vector<Moved> moved_vertices;
  std::vector<std::array<std::size_t, 2>> moved_at;  // (cycle, index) of each moved vertex's places
  // Exact comparisons (GMP for crossings whose box holds their rounded point, nearly all),
  // stopped as soon as too many vertices moved: on a result of 10^5 crossings they would
  // cost more than the operation.
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    const auto& cyc = r.cycles[c].vertices;
    for (std::size_t k = 0; k < cyc.size(); ++k) {
      const int id = cyc[k];
      if (id < first_movable) continue;
      char& s = state[static_cast<std::size_t>(id - first_movable)];
      if (s == 2) moved_at.push_back({c, k});
      if (s != 0) continue;
      const Point& at = rounded[c][k];
      s = K::compare_vertices(K::vertex(K::point(at)), r.vertex(id)) != Sign::zero ? 2 : 1;
      if (s == 1) continue;
      Box b;
      b.add(at);
      moved_vertices.push_back({id, at, b});
      moved_at.push_back({c, k});
      if (moved_vertices.size() > max_moved) return false;
    }
  }
  if (moved_vertices.empty()) return true;
  // The edges of each cycle (a two-vertex cycle has one), as ids and rounded ends.
  struct Edge {
    int a, b;
    Point pa, pb;
    Box box() const {
      Box x;
      x.add(pa);
      x.add(pb);
      return x;
    }
  };
  const auto edge_at = [&](std::size_t c, std::size_t k) {
    const auto& cyc = r.cycles[c].vertices;
    const std::size_t l = k + 1 == cyc.size() ? 0 : k + 1;
    return Edge{cyc[k], cyc[l], rounded[c][k], rounded[c][l]};
  };
  // The edges with a moved end: those starting at or ending at a moved vertex's places (each
  // once; a two-vertex cycle's one edge starts at its first place).
  std::vector<std::array<std::size_t, 2>> starts;
  for (const auto& [c, k] : moved_at) {
    const std::size_t n = r.cycles[c].vertices.size();
    if (n < 2) continue;
    if (n == 2) {
      starts.push_back({c, 0});
      continue;
    }
    starts.push_back({c, k});
    starts.push_back({c, k == 0 ? n - 1 : k - 1});
  }
  std::sort(starts.begin(), starts.end());
  starts.erase(std::unique(starts.begin(), starts.end()), starts.end());
  if (moved_vertices.size() + starts.size() > max_moved) return false;
  std::vector<Edge> moved_edges;
  std::vector<Box> moved_edge_box;
  Box all;
  for (const Moved& m : moved_vertices) all.add(m.box);
  for (const auto& [c, k] : starts) {
    moved_edges.push_back(edge_at(c, k));
    moved_edge_box.push_back(moved_edges.back().box());
    all.add(moved_edge_box.back());
  }

  const auto final_pos = [&](const Point& at) { return K::vertex(K::point(at)); };
  // The positions an item occupies during the motion: a vertex's path, an edge's hull.
  const auto path_meets_edge = [&](int v, const Point& v_at, const Edge& e) {
    std::vector<typename K::Vertex> hull{r.vertex(e.a), r.vertex(e.b)};
    if (moved(e.a)) hull.push_back(final_pos(e.pa));
    if (moved(e.b)) hull.push_back(final_pos(e.pb));
    const auto p = r.vertex(v);
    const auto q = moved(v) ? final_pos(v_at) : p;
    return detail::segment_meets_hull<K>(p, q, hull);
  };
  // Every edge against the moved items; an edge's box widened by an ulp meets `all` exactly
  // when the box of its rounded ends meets `all` widened by one more ulp, so most edges are
  // passed over by four comparisons and no ulp step.
  const double ax0 = detail::next_down(all.x0), ay0 = detail::next_down(all.y0);
  const double ax1 = detail::next_up(all.x1), ay1 = detail::next_up(all.y1);
  // Whether the edge from p to q misses every moved item's box (each widened by an ulp): the
  // rounded points alone decide it, so the ids are read only for the edges near an item.
  // The items mark the cells of a small grid over `all` (cell indices are monotone in the
  // coordinates, so boxes that meet have cell ranges that meet); an edge is near when a
  // marked cell lies in its range (two crossings on opposite sides of a large result make
  // `all` cover most of it).
  constexpr int kSide = 64;
  const double sx = ax1 > ax0 ? kSide / (ax1 - ax0) : 0, sy = ay1 > ay0 ? kSide / (ay1 - ay0) : 0;
  const auto col = [&](double x) { return detail::clamped_cell((x - ax0) * sx, kSide); };
  const auto row = [&](double y) { return detail::clamped_cell((y - ay0) * sy, kSide); };
  std::vector<std::uint64_t> marked(kSide, 0);  // per row, a bit per column
  const auto mark = [&](const Box& b) {
    const int c0 = col(detail::next_down(b.x0)), c1 = col(detail::next_up(b.x1));
    for (int y = row(detail::next_down(b.y0)), y1 = row(detail::next_up(b.y1)); y <= y1; ++y) {
      for (int x = c0; x <= c1; ++x) marked[static_cast<std::size_t>(y)] |= std::uint64_t{1} << x;
    }
  };
  for (const Moved& m : moved_vertices) mark(m.box);
  for (const Box& b : moved_edge_box) mark(b);
  const auto far = [&](const Point& p, const Point& q) {
    if ((std::max(p.x, q.x) < ax0) | (ax1 < std::min(p.x, q.x)) | (std::max(p.y, q.y) < ay0) | (ay1 < std::min(p.y, q.y))) return true;
    const int c0 = col(std::min(p.x, q.x)), c1 = col(std::max(p.x, q.x));
    const std::uint64_t columns = (c1 == kSide - 1 ? ~std::uint64_t{0} : (std::uint64_t{1} << (c1 + 1)) - 1) & ~((std::uint64_t{1} << c0) - 1);
    for (int y = row(std::min(p.y, q.y)), y1 = row(std::max(p.y, q.y)); y <= y1; ++y) {
      if (marked[static_cast<std::size_t>(y)] & columns) return false;
    }
    return true;
  };
  const auto near_edge = [&](const Edge& f) {
    const Box fb = f.box();
    // Moved vertices against this edge.
    for (const Moved& m : moved_vertices) {
      if (m.id == f.a || m.id == f.b || !fb.meets(m.box)) continue;
      if (path_meets_edge(m.id, m.at, f)) return false;
    }
    // This edge's ends against the moved edges.
    for (std::size_t k = 0; k < moved_edges.size(); ++k) {
      const Edge& e = moved_edges[k];
      if (!fb.meets(moved_edge_box[k])) continue;
      for (const auto& [u, u_at] : {std::pair{f.a, f.pa}, std::pair{f.b, f.pb}}) {
        if (u == e.a || u == e.b || moved(u)) continue;  // moved ones: above
        Box ub;
        ub.add(u_at);
        if (!ub.meets(moved_edge_box[k])) continue;
        if (path_meets_edge(u, u_at, e)) return false;
      }
    }
    return true;
  };
  // The pass over every edge, in blocks of the edges numbered across the cycles (a result
  // may be one cycle of 10^5 edges), split over the threads; a block stops as soon as any
  // block has found a meeting. The verdict is the same on any number of threads.
  std::vector<std::size_t> first_edge(r.cycles.size() + 1, 0);  // of each cycle, numbered across them
  for (std::size_t c = 0; c < r.cycles.size(); ++c) {
    const std::size_t n = rounded[c].size();
    first_edge[c + 1] = first_edge[c] + (n < 2 ? 0 : n == 2 ? 1 : n);
  }
  const std::size_t num_edges = first_edge.back();
  std::atomic<bool> met{false};
  const auto block = [&](std::size_t begin, std::size_t end) {
    constexpr std::size_t kCheckEvery = 4096;  // edges between looks at the other blocks' verdict
    std::size_t c = static_cast<std::size_t>(std::upper_bound(first_edge.begin(), first_edge.end(), begin) - first_edge.begin()) - 1;
    for (std::size_t e = begin; e < end; ++c) {
      const std::vector<Point>& pts = rounded[c];
      const std::size_t n = pts.size();
      const std::size_t stop = std::min(end, first_edge[c + 1]);
      for (std::size_t k = e - first_edge[c]; e < stop; ++e, ++k) {
        const std::size_t l = k + 1 == n ? 0 : k + 1;
        if (!far(pts[k], pts[l]) && !near_edge(edge_at(c, k))) {
          met.store(true, std::memory_order_relaxed);
          return;
        }
        if (e % kCheckEvery == 0 && met.load(std::memory_order_relaxed)) return;
      }
    }
  };
  const unsigned t = threads_for(num_edges, threads);
  run_blocks(t, num_edges, t, block);
  return !met.load();
}

}  // namespace mk
