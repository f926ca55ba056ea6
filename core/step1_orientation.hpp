// Step 1: normalise the orientations of the input polygons.
// [MK89 §3.1 step 1] [MK89 Table 1] [MK89 §2.2] (inclusion forest; nested parts alternate)
// Preconditions: polygons prepared (vertex-complete, split into cycles with distinct
// vertices). Input rings may run either way: each cycle's orientation is set from its
// nesting depth, which is what FAR depends on.
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/locator.hpp"
#include "core/parallel.hpp"
#include "core/tables.hpp"
#include "predicates/ray.hpp"

namespace mk {

namespace detail {

// Whether a cycle of 3+ distinct vertices (a simple polygon) runs counterclockwise: the
// turn at its lexicographically smallest vertex, which is always convex [MK89 §3.2,
// procedure for orientation: the vertex with minimum X and the slopes of its two edges].
template <Kernel K>
bool is_counterclockwise(const Arrangement<K>& arr, const std::vector<int>& cycle) {
  const auto n = cycle.size();
  const auto m = static_cast<std::size_t>(std::min_element(cycle.begin(), cycle.end()) - cycle.begin());
  const int prev = cycle[(m + n - 1) % n];
  const int next = cycle[(m + 1) % n];
  return K::orient2d(arr.points[prev], arr.points[cycle[m]], arr.points[next]) == Sign::positive;
}

// How many of a polygon's edges coincide with each as sets {u, w}: entries chained from the
// end of smaller degree (a point has few edges, and where thousands meet, as at a fan's
// apex, their other ends have few), where a hash map cost a node per edge. The degrees are
// counted first, from every edge that will be added.
class EdgeCounts {
 public:
  EdgeCounts() = default;
  template <class Cycles>
  EdgeCounts(std::size_t num_points, const Cycles& cycles) : head_(num_points, -1), degree_(num_points, 0) {
    for (const auto& cycle : cycles) {
      for (const int v : cycle) degree_[static_cast<std::size_t>(v)] += 2;
    }
  }

  void add(int u, int w) {
    const auto [key, other] = ends(u, w);
    for (int k = head_[key]; k >= 0; k = next_[k]) {
      if (other_[k] == other) {
        ++count_[k];
        return;
      }
    }
    next_.push_back(head_[key]);
    other_.push_back(other);
    count_.push_back(1);
    head_[key] = static_cast<int>(other_.size()) - 1;
  }
  int count(int u, int w) const {
    const auto [key, other] = ends(u, w);
    for (int k = head_[key]; k >= 0; k = next_[k]) {
      if (other_[k] == other) return count_[k];
    }
    return 0;
  }

 private:
  // (the end the entry is chained from, the other end): the one of smaller degree, then the
  // smaller index, so that both orders of u and w give the same pair.
  std::pair<std::size_t, int> ends(int u, int w) const {
    const int du = degree_[static_cast<std::size_t>(u)];
    const int dw = degree_[static_cast<std::size_t>(w)];
    const bool u_key = du != dw ? du < dw : u < w;
    return u_key ? std::pair<std::size_t, int>{static_cast<std::size_t>(u), w}
                 : std::pair<std::size_t, int>{static_cast<std::size_t>(w), u};
  }
  std::vector<int> head_;
  std::vector<int> degree_;
  std::vector<int> next_, other_, count_;
};

// The query for the parity of the number of cycles of `poly` whose FAR contains the points
// just inside cycle c (the cycle itself included): odd for cycles at even nesting depth.
inline LocatorQuery depth_query(const PreparedPolygon& poly, std::size_t c,
                                const EdgeCounts& edge_count, bool ccw) {
  const auto& cycle = poly.cycles[c];
  const auto n = cycle.size();
  // An edge no other edge coincides with, so that only ancestors contain the points beside it.
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (edge_count.count(cycle[i], cycle[(i + 1) % n]) == 1) {
      k = i;
      break;
    }
  }
  return {cycle[k], cycle[(k + 1) % n], ccw ? Side::left : Side::right};
}

}  // namespace detail

// Orients every cycle with FAR on its left (counterclockwise at even nesting depth), then
// turns B against A where Table 1 says so.
template <Kernel K>
void normalize_orientations(Arrangement<K>& arr, Operation op, unsigned threads = 1) {
  // The work: each cycle's orientation reads its vertices; nested cycles add a depth query.
  std::size_t work = 0;
  for (const auto& poly : arr.polygon) {
    for (const auto& cycle : poly.cycles) work += cycle.size();
    work += poly.cycles.size() > 1 ? 4 * poly.cycles.size() : 0;
  }
  run_tasks(threads_for(work, threads), 2, [&](std::size_t pi) {  // the polygons on two threads
    PreparedPolygon& poly = arr.polygon[pi];
    // A polygon with one cycle has it at depth 0; only nested parts need the ray test.
    const bool single = poly.cycles.size() == 1;
    detail::EdgeCounts edge_count = single ? detail::EdgeCounts() : detail::EdgeCounts(arr.points.size(), poly.cycles);
    std::vector<Edge> edges;
    if (!single) {
      for (const auto& cycle : poly.cycles) {
        for (std::size_t i = 0; i < cycle.size(); ++i) {
          edge_count.add(cycle[i], cycle[(i + 1) % cycle.size()]);
          edges.push_back({cycle[i], cycle[(i + 1) % cycle.size()]});
        }
      }
    }
    std::vector<bool> flip(poly.cycles.size(), false);
    std::vector<bool> ccw(poly.cycles.size(), false);
    std::vector<LocatorQuery> queries;
    for (std::size_t c = 0; c < poly.cycles.size(); ++c) {
      if (poly.cycles[c].size() < 3) continue;  // degenerate: both orientations at once
      ccw[c] = detail::is_counterclockwise(arr, poly.cycles[c]);
      if (!single) queries.push_back(detail::depth_query(poly, c, edge_count, ccw[c]));
    }
    // All depths in one batch: a sweep over the polygon's edges when the cycles are many.
    const std::vector<int> parities = WindingLocator<K>(arr, edges).crossing_parities(queries);
    std::size_t next = 0;
    for (std::size_t c = 0; c < poly.cycles.size(); ++c) {
      if (poly.cycles[c].size() < 3) continue;
      const bool even = single || parities[next++] % 2 == 1;
      flip[c] = ccw[c] != even;
    }
    for (std::size_t c = 0; c < poly.cycles.size(); ++c) {
      if (flip[c]) std::reverse(poly.cycles[c].begin(), poly.cycles[c].end());
    }
  });
  PreparedPolygon& b = arr.polygon[1];
  const auto mutual = kTable1[op_index(op)][type_index(arr.polygon[0].type)][type_index(b.type)];
  if (mutual == MutualOrientation::opposite) {
    for (auto& cycle : b.cycles) std::reverse(cycle.begin(), cycle.end());
    b.far_sign = -1;
  }
}

}  // namespace mk
