// Assembly of the irreducible result polygons into OGC polygons-with-holes through the
// inclusion forest. [MK89 §2.2] (forest of inclusion trees; FAR)
// Preconditions: cycles come from step 6 (simple, pairwise non-crossing, 3+ vertices).
#pragma once

#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

#include "core/arrangement.hpp"
#include "core/step6_construct.hpp"
#include "predicates/directions.hpp"

namespace mk {

namespace detail {

// Whether direction c -> d lies strictly inside the counterclockwise sector from c -> a to
// c -> b (a and b not in the same direction; d in neither's direction): the sector test of
// predicates/directions.hpp over directions from c, ordered by angle from south: first
// those leading lexicographically after c (angles in (-pi/2, pi/2]), then the others, and
// within each half (less than half a turn wide) by orientation.
template <Kernel K>
bool is_in_sector(const typename K::Vertex& c, const typename K::Vertex& a, const typename K::Vertex& b,
                  const typename K::Vertex& d) {
  using V = const typename K::Vertex*;
  const auto compare = [&](V u, V w) {
    const bool u_first_half = K::compare_vertices(*u, c) == Sign::positive;
    const bool w_first_half = K::compare_vertices(*w, c) == Sign::positive;
    if (u_first_half != w_first_half) return u_first_half ? Sign::negative : Sign::positive;
    return -K::orient_vertices(c, *u, *w);
  };
  return is_in_ccw_sweep<V>(&a, &b, &d, compare);
}

}  // namespace detail

// Whether cycle `inner` lies inside FAR(outer). The two may share vertices and edges but do
// not cross.
template <Kernel K>
bool is_inside_far(const Arrangement<K>& arr, const ResultCycle& outer, const ResultCycle& inner) {
  const auto V = [&](int id) { return arr.vertex(id); };
  std::unordered_set<int> on_outer(outer.vertices.begin(), outer.vertices.end());
  bool inside = false;
  for (const int h : inner.vertices) {
    if (on_outer.count(h)) continue;
    // Crossing parity of a ray from h, split lexicographically (a vertical ray upwards).
    const auto n = outer.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto p = V(outer.vertices[i]);
      const auto q = V(outer.vertices[(i + 1) % n]);
      const bool p_right = K::compare_vertices(p, V(h)) == Sign::positive;
      const bool q_right = K::compare_vertices(q, V(h)) == Sign::positive;
      if (p_right == q_right) continue;
      const Sign o = K::orient_vertices(p, q, V(h));
      if (q_right ? o == Sign::negative : o == Sign::positive) inside = !inside;
    }
    return inside;
  }
  // Every vertex is shared: decide by an edge of `inner` that is not an edge of `outer`.
  const auto n = outer.vertices.size();
  for (std::size_t k = 0; k < inner.vertices.size(); ++k) {
    const int h1 = inner.vertices[k];
    const int h2 = inner.vertices[(k + 1) % inner.vertices.size()];
    for (std::size_t i = 0; i < n; ++i) {
      if (outer.vertices[i] != h1) continue;
      const int next = outer.vertices[(i + 1) % n];
      const int prev = outer.vertices[(i + n - 1) % n];
      if (h2 == next || h2 == prev) break;
      // FAR(outer) is the sector from next to prev when outer runs counterclockwise.
      const bool in_ccw = detail::is_in_sector<K>(V(h1), V(next), V(prev), V(h2));
      return outer.counterclockwise ? in_ccw : !in_ccw;
    }
  }
  return false;
}

// For each hole-type cycle, the index of the island-type cycle directly containing it (its
// shell), or -1; other entries are -1. Candidates are filtered by bounding boxes of the
// rounded vertices, which is safe: rounding to nearest is monotone, so a cycle inside
// another has its rounded box inside the other's. `rounded`, when given, holds each
// cycle's vertices rounded to nearest (K::approx), so that they are not rounded again.
template <Kernel K>
std::vector<int> inclusion_parents(const Arrangement<K>& arr, const std::vector<ResultCycle>& cycles,
                                   const std::vector<std::vector<Point>>* rounded = nullptr) {
  struct Box {
    double x0, y0, x1, y1;
  };
  const auto n = cycles.size();
  std::vector<Box> box(n);
  std::vector<int> islands;
  bool any_hole = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (cycles[i].vertices.size() < 3) continue;
    Box b{HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (std::size_t k = 0; k < cycles[i].vertices.size(); ++k) {
      const Point p = rounded ? (*rounded)[i][k] : K::approx(arr.vertex(cycles[i].vertices[k]));
      b = {std::min(b.x0, p.x), std::min(b.y0, p.y), std::max(b.x1, p.x), std::max(b.y1, p.y)};
    }
    box[i] = b;
    if (cycles[i].type == PolygonType::island) islands.push_back(static_cast<int>(i));
    any_hole = any_hole || cycles[i].type == PolygonType::hole;
  }
  std::vector<int> parent(n, -1);
  if (!any_hole) return parent;
  // Islands sorted by the left side of their boxes, so each hole scans only those that
  // start left of it.
  std::sort(islands.begin(), islands.end(), [&](int a, int b) { return box[a].x0 < box[b].x0; });
  for (std::size_t i = 0; i < n; ++i) {
    if (cycles[i].vertices.size() < 3 || cycles[i].type != PolygonType::hole) continue;
    std::vector<int> containers;
    for (const int j : islands) {
      if (box[j].x0 > box[i].x0) break;
      if (box[j].x1 < box[i].x1 || box[j].y0 > box[i].y0 || box[j].y1 < box[i].y1) continue;
      if (is_inside_far(arr, cycles[j], cycles[i])) containers.push_back(j);
    }
    // The containers are nested; the shell is the innermost.
    for (const int c : containers) {
      bool innermost = true;
      for (const int d : containers) {
        if (d != c && !is_inside_far(arr, cycles[d], cycles[c])) innermost = false;
      }
      if (innermost) parent[i] = c;
    }
  }
  return parent;
}

}  // namespace mk
