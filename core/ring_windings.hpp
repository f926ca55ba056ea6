// Winding numbers on both sides of every edge of a set of oriented rings, and the first place
// where one is neither 0 nor 1: where reading the rings by nesting (even-odd, the paper's
// reading) and reading them as a union of regions with signs differ.
// [MK89 §2.2] (regions from nested rings) [MK89 §4.3] (locating one vertex per ring, then
// walking the ring) [MK89 Table 5] (sectors between edges at a vertex)
// Preconditions: coordinates are finite; `group` and `reversed` have one entry per ring, and
// the rings of one group come one after another.
// Edges of one ring set that cross properly raise CrossingEdges (from prepare).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/buckets.hpp"
#include "core/locator.hpp"
#include "core/prepare.hpp"
#include "core/sorting.hpp"
#include "predicates/directions.hpp"
#include "predicates/ray.hpp"

namespace mk {

// Where the winding number of oriented rings is outside {0, 1}: just `side` of the piece
// from -> to of one of `ring`'s edges (as oriented).
struct WindingViolation {
  bool within_group = false;  // counting the rings of `ring`'s group only (else every ring)
  int ring = -1;
  Point from;  // input points: exact
  Point to;
  Side side = Side::left;
  int winding = 0;
  // The rings that wind around that point (in the same count), with their winding numbers
  // there; rings that do not are left out.
  std::vector<std::pair<int, int>> winding_rings;
  // Per ring: whether the winding number is outside {0, 1} beside every one of its edges,
  // on the left ([0]) and on the right ([1]) (in the same count): a hole all of whose inside
  // is bad lies wholly outside its shell, a part all of whose inside is bad lies inside others.
  std::vector<std::array<bool, 2>> all_bad;
};

namespace detail {

// One end of a cycle edge seen from a vertex: the other end, +1 when the edge leaves the
// vertex and -1 when it arrives, and the edge's count (its group, or one count for all).
struct HalfEdge {
  int at = -1;
  int other = -1;
  int sign = 0;
  int count = 0;
};

// Half-edges sorted by vertex, count, then angle (counterclockwise from east); runs of one
// direction (coincident edges, which share both ends in a vertex-complete set), blocks of
// one vertex, and prefix sums of the signs within a block.
struct AngularIncidence {
  std::vector<int> order;     // half-edge indices, sorted
  std::vector<int> position;  // of each half-edge in `order`
  std::vector<int> run_begin, run_end, block_begin, block_end;
  std::vector<int> prefix;  // prefix[i]: sum of signs of order[block_begin .. i)

  int sum(int from, int to) const { return from >= to ? 0 : prefix[to] - prefix[from]; }
};

template <Kernel K>
AngularIncidence sort_around_vertices(const Arrangement<K>& arr, const std::vector<HalfEdge>& half) {
  AngularIncidence inc;
  const DirectionOrder<K> angles(arr.points);
  const int n = static_cast<int>(half.size());
  // By vertex in linear time (a counting sort on the point id), then each vertex's few
  // half-edges by count and angle; a vertex where one cycle merely passes needs no sorting.
  Buckets by_vertex = bucket_by(half.size(), arr.points.size(), [&](std::size_t i) { return half[i].at; });
  const std::vector<int>& begin = by_vertex.begin;
  inc.order = std::move(by_vertex.order);
  for (std::size_t v = 0; v + 1 < begin.size(); ++v) {
    const auto b = inc.order.begin() + begin[v];
    const auto e = inc.order.begin() + begin[v + 1];
    if (e - b < 2 || (e - b == 2 && half[b[0]].count == half[b[1]].count)) continue;
    sort_by_predicates<K>(b, e, [&](int i, int j) {
      const HalfEdge& x = half[i];
      const HalfEdge& y = half[j];
      if (x.count != y.count) return x.count < y.count;
      if (x.other == y.other) return false;
      return angles.compare({x.at, x.other}, {y.at, y.other}) == Sign::negative;
    });
  }
  inc.position.resize(half.size());
  inc.run_begin.resize(half.size());
  inc.run_end.resize(half.size());
  inc.block_begin.resize(half.size());
  inc.block_end.resize(half.size());
  inc.prefix.resize(half.size() + 1);
  for (int i = 0; i < n;) {
    const HalfEdge& first = half[inc.order[i]];
    int j = i;
    int sum = 0;
    while (j < n && half[inc.order[j]].at == first.at && half[inc.order[j]].count == first.count) {
      inc.prefix[j] = sum;
      sum += half[inc.order[j]].sign;
      ++j;
    }
    inc.prefix[j] = sum;  // overwritten by the next block's first entry, which starts at 0
    for (int k = i; k < j; ++k) {
      inc.block_begin[k] = i;
      inc.block_end[k] = j;
      inc.position[inc.order[k]] = k;
    }
    for (int k = i; k < j;) {
      int l = k;
      while (l < j && half[inc.order[l]].other == half[inc.order[k]].other) ++l;
      for (int m = k; m < l; ++m) {
        inc.run_begin[m] = k;
        inc.run_end[m] = l;
      }
      k = l;
    }
    i = j;
  }
  return inc;
}

}  // namespace detail

// Orients each ring as given, or reversed where `reversed` says so, and finds the first edge
// beside which the winding number of the rings is not 0 or 1: first counting the rings of
// each group alone (a group's rings beside a group's edges), then all rings together. Exact;
// O(n log n) for n vertices: the locator answers its queries, one per cycle, in one sweep.
// Empty when every winding number is 0 or 1.
template <Kernel K>
std::optional<WindingViolation> find_winding_violation(const BasicPolygon<typename K::Point>& rings,
                                                       const std::vector<int>& group,
                                                       const std::vector<bool>& reversed) {
  const Arrangement<K> arr = prepare<K>(rings, BasicPolygon<typename K::Point>{});
  const PreparedPolygon& poly = arr.polygon[0];

  // The cycles with two or more vertices (single points wind around nothing), oriented, in
  // ring order: the edges of one group come together.
  std::vector<std::vector<int>> cycles;
  std::vector<int> cycle_ring;
  for (std::size_t c = 0; c < poly.cycles.size(); ++c) {
    const int r = poly.origins[c].ring;
    cycles.push_back(poly.cycles[c]);
    if (reversed[static_cast<std::size_t>(r)]) std::reverse(cycles.back().begin(), cycles.back().end());
    cycle_ring.push_back(r);
  }
  std::vector<int> cycle_first_edge{0};
  std::vector<Edge> edges;
  std::vector<int> edge_cycle;
  for (std::size_t c = 0; c < cycles.size(); ++c) {
    const auto& cy = cycles[c];
    for (std::size_t i = 0; i < cy.size(); ++i) {
      edges.push_back({cy[i], cy[(i + 1) % cy.size()]});
      edge_cycle.push_back(static_cast<int>(c));
    }
    cycle_first_edge.push_back(static_cast<int>(edges.size()));
  }
  const auto group_of_cycle = [&](std::size_t c) { return group[static_cast<std::size_t>(cycle_ring[c])]; };

  // With a single group, counting all rings together is counting the group again.
  const bool one_group = std::all_of(group.begin(), group.end(), [&](int g) { return g == group.front(); });
  for (const bool within_group : {true, false}) {
    if (!within_group && one_group) break;
    // Half-edge 2e leaves edge e's source, 2e + 1 arrives at its destination.
    std::vector<detail::HalfEdge> half(2 * edges.size());
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const int count = within_group ? group_of_cycle(static_cast<std::size_t>(edge_cycle[e])) : 0;
      half[2 * e] = {edges[e].src, edges[e].dst, +1, count};
      half[2 * e + 1] = {edges[e].dst, edges[e].src, -1, count};
    }
    const detail::AngularIncidence inc = detail::sort_around_vertices(arr, half);

    // The sum of the signs of the half-edges strictly inside the counterclockwise sweep at a
    // vertex from the leaving half-edge `out` to the arriving one `in`: crossing a leaving
    // edge counterclockwise enters its left side, where the winding number is one more.
    const auto sector_sum = [&](int out, int in) {
      const int po = inc.position[out];
      const int pi = inc.position[in];
      const int b0 = inc.block_begin[po];
      const int b1 = inc.block_end[po];
      if (inc.run_begin[po] == inc.run_begin[pi]) {  // u == w: the full turn less that direction
        return inc.sum(b0, b1) - inc.sum(inc.run_begin[po], inc.run_end[po]);
      }
      const int from = inc.run_end[po];
      const int to = inc.run_begin[pi];
      return from <= to ? inc.sum(from, to) : inc.sum(from, b1) + inc.sum(b0, to);
    };
    // The net count of edges along u -> w (those u -> w less those w -> u), from u's run.
    const auto net_along = [&](int out) {
      const int p = inc.position[out];
      return inc.sum(inc.run_begin[p], inc.run_end[p]);
    };

    // A locator per count: its edges are a contiguous range (cycles come in group order).
    const auto bad = [](int w) { return w != 0 && w != 1; };
    std::optional<WindingViolation> found;
    std::vector<std::array<bool, 2>> all_bad(rings.rings.size(), {true, true});
    std::vector<bool> has_edges(rings.rings.size(), false);
    std::size_t c = 0;
    while (c < cycles.size()) {
      std::size_t c_end = c + 1;
      if (within_group) {
        while (c_end < cycles.size() && group_of_cycle(c_end) == group_of_cycle(c)) ++c_end;
      } else {
        c_end = cycles.size();
      }
      const std::span<const Edge> range(edges.data() + cycle_first_edge[c],
                                        static_cast<std::size_t>(cycle_first_edge[c_end] - cycle_first_edge[c]));
      const WindingLocator<K> locator(arr, range, c_end - c);
      // One located point per cycle, all in one batch (a sweep when they are many: a scan of
      // the edges per cycle would be quadratic on inputs of many rings).
      std::vector<LocatorQuery> queries;
      queries.reserve(c_end - c);
      for (std::size_t q = c; q < c_end; ++q) {
        const Edge& e0 = edges[static_cast<std::size_t>(cycle_first_edge[q])];
        queries.push_back({e0.src, e0.dst, Side::left});
      }
      const std::vector<int> anchors = locator.windings(queries);
      const std::size_t c_begin = c;
      for (; c < c_end; ++c) {
        const int first = cycle_first_edge[c];
        const int n = cycle_first_edge[c + 1] - first;
        const auto r = static_cast<std::size_t>(cycle_ring[c]);
        has_edges[r] = true;
        int left = anchors[c - c_begin];
        for (int i = 0; i < n; ++i) {
          const int e = first + i;
          if (i > 0) left -= sector_sum(2 * e, 2 * (e - 1) + 1);
          const std::array<int, 2> winding{left, left - net_along(2 * e)};  // left, right
          for (const int s : {0, 1}) {
            if (!bad(winding[s])) {
              all_bad[r][s] = false;
              continue;
            }
            if (found) continue;
            WindingViolation& v = found.emplace();
            v.within_group = within_group;
            v.ring = cycle_ring[c];
            const Edge& edge = edges[static_cast<std::size_t>(e)];
            v.from = K::approx(arr.vertex(edge.src));
            v.to = K::approx(arr.vertex(edge.dst));
            v.side = s == 0 ? Side::left : Side::right;
            v.winding = winding[s];
            // Which rings wind around that point: one scan of the counted edges, once.
            std::vector<int> per_ring(rings.rings.size(), 0);
            for (const Edge& other : range) {
              const auto oc = static_cast<std::size_t>(edge_cycle[static_cast<std::size_t>(&other - edges.data())]);
              per_ring[static_cast<std::size_t>(cycle_ring[oc])] +=
                  vertical_ray_crossing<K>(arr.points[edge.src], arr.points[edge.dst], v.side, arr.points[other.src],
                                           arr.points[other.dst]);
            }
            for (std::size_t k = 0; k < per_ring.size(); ++k) {
              if (per_ring[k] != 0) v.winding_rings.emplace_back(static_cast<int>(k), per_ring[k]);
            }
          }
        }
      }
    }
    if (found) {
      for (std::size_t r = 0; r < all_bad.size(); ++r) {
        if (!has_edges[r]) all_bad[r] = {false, false};
      }
      found->all_bad = std::move(all_bad);
      return found;
    }
  }
  return std::nullopt;
}

}  // namespace mk
