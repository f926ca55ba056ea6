// The arrangement of every ring of several inputs at once, for fill rules and N-ary
// operations: all input points, every crossing of any two edges (an input's crossings with
// itself included), and the edges cut into fragments, which are merged into links where
// they coincide, each link carrying the net number of fragments per input along it.
// [MK89 §3.1 step 3] (intersection points) [MK89 §4.3] (sub-quadratic search)
// [MK89 §2.2] (rings as closed polylines) paper-notes.md, deviation "winding numbers"
// Preconditions: coordinates finite. Rings may cross themselves and each other, overlap
// along edges and repeat vertices; no ring needs an orientation or a nesting.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/buckets.hpp"
#include "core/edge_insertions.hpp"
#include "core/error.hpp"
#include "core/pairs.hpp"
#include "predicates/directions.hpp"
#include "predicates/segments.hpp"

namespace mk {

// The fragments of all inputs on one segment between two vertices lo < hi (vertex ids),
// which no other vertex cuts. `dir` is the direction lo -> hi, given by the input points of
// one of its edges (a vertex may be a crossing, which is never evaluated for angles).
struct WindingLink {
  int lo = -1;
  int hi = -1;
  Direction dir;
};

template <Kernel K>
struct WindingArrangement {
  // Points (ids in lexicographic order), x_rank and the crossings; polygon[] stays empty.
  Arrangement<K> arr;
  int groups = 0;               // inputs whose winding numbers are counted apart
  std::vector<Edge> edges;      // ring edges as given, group after group
  std::vector<int> group_first_edge;  // size groups + 1
  std::vector<WindingLink> links;     // in (lo, hi) order
  // delta[l * groups + g]: fragments of group g along link l from lo to hi, less those from
  // hi to lo: the winding number of g just left of lo -> hi less that just right of it.
  std::vector<int> delta;
  std::vector<int> edge_first_link;        // per edge: the link of its first fragment
  std::vector<bool> edge_first_forward;    // ... and whether the edge runs lo -> hi along it
  int distinct_crossings = 0;              // crossings that are not input points or repeats
};

namespace detail {

// Union-find over vertex ids; the representative is the smallest id, so that a crossing
// lying on an input point becomes that point.
class VertexMerge {
 public:
  explicit VertexMerge(int n) : parent_(static_cast<std::size_t>(n)) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a < b) std::swap(a, b);
    parent_[a] = b;
  }

 private:
  std::vector<int> parent_;
};

// The indices of `pieces` (each with a segment_key and a from and a to vertex below
// num_vertices) ordered by key, equal keys by index: counted by their smaller vertex
// (stable, linear), then each vertex's few pieces ordered by their larger one. A comparison
// sort of all the pieces cost a tenth of a union-all of many rings.
template <class Piece>
std::vector<int> order_by_key(const std::vector<Piece>& pieces, int num_vertices) {
  Buckets by_vertex = bucket_by(pieces.size(), static_cast<std::size_t>(num_vertices),
                                [&](std::size_t k) { return std::min(pieces[k].from, pieces[k].to); });
  const std::vector<int>& start = by_vertex.begin;
  std::vector<int> order = std::move(by_vertex.order);
  const auto before = [&](int x, int y) { return pieces[x].key != pieces[y].key ? pieces[x].key < pieces[y].key : x < y; };
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    const auto first = order.begin() + start[v];
    const auto last = order.begin() + start[v + 1];
    if (last - first > 16) {
      std::sort(first, last, before);
      continue;
    }
    for (auto i = first + 1; i < last; ++i) {  // insertion: few pieces share a vertex
      const int x = *i;
      auto j = i;
      for (; j > first && before(x, *(j - 1)); --j) *j = *(j - 1);
      *j = x;
    }
  }
  return order;
}

}  // namespace detail

// Builds the arrangement of `rings` (ring_group[r] in 0 .. groups - 1 says whose ring r is).
// Crossings are found by the candidate-pair search of step 3 over all edges at once, each
// tested exactly; a point where three or more edges cross is made once, by merging the
// crossings that compare equal along a common edge (they are neighbours in its order).
template <Kernel K>
WindingArrangement<K> build_winding_arrangement(const std::vector<BasicRing<typename K::Point>>& rings,
                                                const std::vector<int>& ring_group, int groups,
                                                PairSearch search = PairSearch::sweep) {
  using P = typename K::Point;
  WindingArrangement<K> wa;
  wa.groups = groups;
  Arrangement<K>& arr = wa.arr;
  // Point ids in lexicographic order.
  std::size_t total = 0;
  for (const auto& ring : rings) total += ring.size();
  std::vector<std::pair<P, int>> sorted;
  sorted.reserve(total);
  for (const auto& ring : rings) {
    for (const auto& q : ring) sorted.emplace_back(q, static_cast<int>(sorted.size()));
  }
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& x, const auto& y) { return compare_xy<K>(x.first, y.first) == Sign::negative; });
  std::vector<int> id_of(total);
  for (const auto& [q, input] : sorted) {
    if (arr.points.empty() || compare_xy<K>(arr.points.back(), q) != Sign::zero) arr.points.push_back(q);
    id_of[static_cast<std::size_t>(input)] = static_cast<int>(arr.points.size()) - 1;
  }
  sorted = {};
  arr.x_rank.resize(arr.points.size());
  for (std::size_t i = 0; i < arr.points.size(); ++i) {
    arr.x_rank[i] = i == 0 ? 0 : arr.x_rank[i - 1] + (K::compare_x(arr.points[i - 1], arr.points[i]) != Sign::zero);
  }

  // Edges, group after group, ring after ring; repeated consecutive points are dropped and
  // rings of fewer than 2 distinct consecutive points bound nothing.
  std::vector<std::size_t> ring_start(rings.size() + 1, 0);
  for (std::size_t r = 0; r < rings.size(); ++r) ring_start[r + 1] = ring_start[r] + rings[r].size();
  std::vector<std::size_t> order(rings.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ring_group[a] < ring_group[b]; });
  std::vector<SweepItem> items;
  wa.group_first_edge.assign(static_cast<std::size_t>(groups) + 1, 0);
  std::vector<int> ids;
  for (const std::size_t r : order) {
    ids.clear();
    for (std::size_t k = ring_start[r]; k < ring_start[r + 1]; ++k) {
      const int id = id_of[k];
      if (ids.empty() || ids.back() != id) ids.push_back(id);
    }
    while (ids.size() > 1 && ids.back() == ids.front()) ids.pop_back();
    if (ids.size() < 2) continue;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const int u = ids[k];
      const int w = ids[(k + 1) % ids.size()];
      items.push_back(sweep_item(u, w, 0, k > 0));
      wa.edges.push_back({u, w});
    }
    wa.group_first_edge[static_cast<std::size_t>(ring_group[r]) + 1] = static_cast<int>(wa.edges.size());
  }
  for (int g = 1; g <= groups; ++g) {
    wa.group_first_edge[g] = std::max(wa.group_first_edge[g], wa.group_first_edge[g - 1]);
  }

  // Every crossing and touching of two edges.
  EdgeInsertions inserted;
  const auto& pts = arr.points;
  for_each_candidate_pair<K>(pts, arr.x_rank, items, false, search, [&](int i, int j) {
    const SweepItem& a = items[i];
    const SweepItem& b = items[j];
    if (a.lo == b.lo && a.hi == b.hi) return;  // the same segment: nothing to insert
    const auto rel = relate_segments_by_id<K>(pts, a.lo, a.hi, b.lo, b.hi);
    if (rel.proper_crossing) {
      // A new vertex per pair: where segments coincide (two rings sharing an edge) or three
      // edges cross at one point, the repeats are merged below, being equal along an edge.
      const int id = arr.num_vertices();
      arr.crossings.push_back(K::crossing(pts[a.lo], pts[a.hi], pts[b.lo], pts[b.hi]));
      if constexpr (!K::is_exact) {
        const mk::Point c = K::approx(arr.crossings.back());
        if (!std::isfinite(c.x) || !std::isfinite(c.y)) {
          throw KernelFailure(std::string("kernel ") + std::string(K::name) +
                              ": a crossing point is not finite in its arithmetic");
        }
      }
      inserted.add(i, id);
      inserted.add(j, id);
      return;
    }
    // vertex_on_edge and collinear_overlap: endpoints strictly inside the other edge.
    if (rel.c_inside_ab) inserted.add(i, b.lo);
    if (rel.d_inside_ab) inserted.add(i, b.hi);
    if (rel.a_inside_cd) inserted.add(j, a.lo);
    if (rel.b_inside_cd) inserted.add(j, a.hi);
  });
  items = {};

  // Each edge's inserted vertices in order along it; equal neighbours are one point.
  const int num_edges = static_cast<int>(wa.edges.size());
  detail::VertexMerge merge(arr.num_vertices());
  std::vector<int> on_edge_begin(static_cast<std::size_t>(num_edges) + 1, 0);
  std::vector<int> on_edge;
  inserted.group(num_edges);
  {
    std::vector<int> list;
    // The vertices of a list with their ids, each read from the arrangement once rather than
    // at every comparison (a crossing is far away in memory).
    std::vector<std::pair<int, typename K::Vertex>> along;
    for (int e = 0; e < num_edges; ++e) {
      on_edge_begin[e] = static_cast<int>(on_edge.size());
      if (!inserted.take(e, list)) continue;
      if (list.size() == 1) {
        on_edge.push_back(list[0]);
        continue;
      }
      const auto& s = pts[wa.edges[e].src];
      const auto& d = pts[wa.edges[e].dst];
      along.clear();
      for (const int v : list) along.emplace_back(v, arr.vertex(v));
      std::sort(along.begin(), along.end(), [&](const auto& x, const auto& y) {
        return x.first != y.first && K::compare_along(s, d, x.second, y.second) == Sign::negative;
      });
      along.erase(std::unique(along.begin(), along.end(), [](const auto& x, const auto& y) { return x.first == y.first; }),
                  along.end());
      for (std::size_t k = 0; k + 1 < along.size(); ++k) {
        if (K::compare_along(s, d, along[k].second, along[k + 1].second) == Sign::zero) {
          merge.unite(along[k].first, along[k + 1].first);
        }
      }
      for (const auto& [v, vertex] : along) on_edge.push_back(v);
    }
    on_edge_begin[num_edges] = static_cast<int>(on_edge.size());
  }

  // Fragments, then links: the fragments sorted by their undirected segment.
  struct Piece {
    std::uint64_t key;
    int edge;
    int from;
    int to;
  };
  std::vector<Piece> pieces;
  pieces.reserve(wa.edges.size() + on_edge.size());
  std::vector<int> first_piece(static_cast<std::size_t>(num_edges), -1);
  for (int e = 0; e < num_edges; ++e) {
    int from = wa.edges[e].src;
    const auto add = [&](int to) {
      if (to == from) return;
      if (first_piece[e] < 0) first_piece[e] = static_cast<int>(pieces.size());
      pieces.push_back({segment_key(from, to), e, from, to});
      from = to;
    };
    for (int k = on_edge_begin[e]; k < on_edge_begin[e + 1]; ++k) add(merge.find(on_edge[k]));
    add(wa.edges[e].dst);
  }
  on_edge = {};
  const std::vector<int> piece_order = detail::order_by_key(pieces, arr.num_vertices());
  std::vector<int> piece_link(pieces.size());
  // At most one link per piece: no regrowth (delta too, unless many groups would make the
  // bound far larger than what is used).
  wa.links.reserve(pieces.size());
  if (groups <= 2) wa.delta.reserve(pieces.size() * static_cast<std::size_t>(groups));
  std::vector<int> edge_group(static_cast<std::size_t>(num_edges));
  for (int g = 0; g < groups; ++g) {
    for (int e = wa.group_first_edge[g]; e < wa.group_first_edge[g + 1]; ++e) edge_group[e] = g;
  }
  for (std::size_t k = 0; k < piece_order.size(); ++k) {
    const Piece& pc = pieces[piece_order[k]];
    if (k == 0 || pc.key != pieces[piece_order[k - 1]].key) {
      const int lo = std::min(pc.from, pc.to);
      const Edge& e = wa.edges[pc.edge];
      const Direction d = pc.from == lo ? Direction{e.src, e.dst} : Direction{e.dst, e.src};
      wa.links.push_back({lo, std::max(pc.from, pc.to), d});
      wa.delta.resize(wa.delta.size() + static_cast<std::size_t>(groups), 0);
    }
    const int l = static_cast<int>(wa.links.size()) - 1;
    piece_link[piece_order[k]] = l;
    wa.delta[static_cast<std::size_t>(l) * groups + edge_group[pc.edge]] += pc.from == wa.links[l].lo ? 1 : -1;
  }
  wa.edge_first_link.resize(static_cast<std::size_t>(num_edges));
  wa.edge_first_forward.resize(static_cast<std::size_t>(num_edges));
  for (int e = 0; e < num_edges; ++e) {
    const Piece& pc = pieces[first_piece[e]];
    wa.edge_first_link[e] = piece_link[first_piece[e]];
    wa.edge_first_forward[e] = pc.from < pc.to;
  }
  for (int c = arr.num_points(); c < arr.num_vertices(); ++c) wa.distinct_crossings += merge.find(c) == c;
  return wa;
}

}  // namespace mk
