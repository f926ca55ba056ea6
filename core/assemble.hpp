// Assembly of the irreducible result polygons into OGC polygons-with-holes through the
// inclusion forest: the shell of every hole, found in one plane sweep over the result's
// edges. [MK89 §2.2] (forest of inclusion trees; FAR)
// Preconditions: cycles come from step 6 of a bounded result (cycles of 3+ vertices are
// simple, pairwise non-crossing, share no edge, and no vertex lies inside another's edge).
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/arrangement.hpp"
#include "core/locator.hpp"
#include "core/step6_construct.hpp"
#include "core/sorting.hpp"
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

// The sweep of inclusion_parents: result edges in the order in which they cross a line
// passing through the result's vertices in lexicographic order (as if sheared by an
// infinitesimal angle, so that vertical edges cross it too).
template <Kernel K>
class ShellSweep {
 public:
  ShellSweep(const Arrangement<K>& arr, const std::vector<ResultCycle>& cycles) : arr_(arr), cycles_(cycles) {}

  std::vector<int> run() {
    order_vertices();
    collect_edges();
    return sweep();
  }

 private:
  // A directed result edge: vertex ids, its cycle, and its end first in the sweep.
  struct ResultEdge {
    int from = -1;
    int to = -1;
    int cycle = -1;
    bool eastwards = true;  // `from` comes first
    int lo() const { return eastwards ? from : to; }
    int hi() const { return eastwards ? to : from; }
  };

  bool is_area_cycle(std::size_t i) const { return cycles_[i].vertices.size() >= 3; }

  // rank_[id]: the position of vertex id in lexicographic order among the result's
  // vertices. Input points are in that order by id; the crossings are sorted and merged in.
  void order_vertices() {
    const int nv = arr_.num_vertices();
    std::vector<char> used(static_cast<std::size_t>(nv), 0);
    for (std::size_t i = 0; i < cycles_.size(); ++i) {
      if (!is_area_cycle(i)) continue;
      for (const int v : cycles_[i].vertices) used[v] = 1;
    }
    std::vector<int> crossings;
    for (int v = arr_.num_points(); v < nv; ++v) {
      if (used[v]) crossings.push_back(v);
    }
    const auto less = [&](int u, int w) {
      return K::compare_vertices(arr_.vertex(u), arr_.vertex(w)) == Sign::negative;
    };
    sort_by_predicates<K>(crossings.begin(), crossings.end(), less);
    rank_.assign(static_cast<std::size_t>(nv), -1);
    std::size_t c = 0;
    for (int v = 0; v < arr_.num_points(); ++v) {
      if (!used[v]) continue;
      for (; c < crossings.size() && less(crossings[c], v); ++c) push_vertex(crossings[c]);
      push_vertex(v);
    }
    for (; c < crossings.size(); ++c) push_vertex(crossings[c]);
  }
  void push_vertex(int v) {
    rank_[v] = static_cast<int>(by_rank_.size());
    by_rank_.push_back(v);
  }

  void collect_edges() {
    for (std::size_t i = 0; i < cycles_.size(); ++i) {
      if (!is_area_cycle(i)) continue;
      const auto& vs = cycles_[i].vertices;
      for (std::size_t k = 0; k < vs.size(); ++k) {
        const int u = vs[k];
        const int w = vs[(k + 1) % vs.size()];
        edges_.push_back({u, w, static_cast<int>(i), rank_[u] < rank_[w]});
      }
    }
  }

  // Three input points are compared as points (what orient_vertices does with them in every
  // kernel), without making the vertex of each: most result vertices are input points.
  Sign orient(int a, int b, int c) const {
    const int np = arr_.num_points();
    if (a < np && b < np && c < np) return K::orient2d(arr_.points[a], arr_.points[b], arr_.points[c]);
    return K::orient_vertices(arr_.vertex(a), arr_.vertex(b), arr_.vertex(c));
  }

  // Whether edge a lies below edge b where both cross the sweep line.
  bool is_below(int a, int b) const {
    if (a == b) return false;
    const ResultEdge& ea = edges_[a];
    const ResultEdge& eb = edges_[b];
    const int ra = rank_[ea.lo()], rb = rank_[eb.lo()];
    Sign s = Sign::zero;
    if (ra == rb) {
      s = orient(ea.lo(), ea.hi(), eb.hi());
    } else if (ra < rb) {
      s = orient(ea.lo(), ea.hi(), eb.lo());
    } else {
      s = -orient(eb.lo(), eb.hi(), ea.lo());
    }
    if (s == Sign::zero) return a < b;  // not for valid results (see the preconditions)
    return s == Sign::positive;
  }

  // Whether the bounded region of e's cycle lies below e: a counterclockwise cycle has it
  // on its left, above its eastward edges.
  bool is_far_below(const ResultEdge& e) const { return e.eastwards != cycles_[e.cycle].counterclockwise; }

  // At the lexicographically first vertex v of a hole H both of H's edges leave v, and the
  // region just above the upper one lies outside H, in the face H bounds with its shell.
  // The first edge above it, of cycle C: if C's bounded region lies below it, C is an
  // island around H, its shell; otherwise the face continues below C, which is then a hole
  // of the same shell. C has a vertex before v, or leaves v above H: with holes handled in
  // sweep order (top first at a shared vertex), C's shell is known when H asks for it.
  std::vector<int> sweep() {
    const int m = static_cast<int>(edges_.size());
    const int nr = static_cast<int>(by_rank_.size());
    std::vector<int> lo_begin(static_cast<std::size_t>(nr) + 1, 0), hi_begin(static_cast<std::size_t>(nr) + 1, 0);
    for (const ResultEdge& e : edges_) {
      ++lo_begin[rank_[e.lo()] + 1];
      ++hi_begin[rank_[e.hi()] + 1];
    }
    std::partial_sum(lo_begin.begin(), lo_begin.end(), lo_begin.begin());
    std::partial_sum(hi_begin.begin(), hi_begin.end(), hi_begin.begin());
    std::vector<int> by_lo(static_cast<std::size_t>(m)), by_hi(static_cast<std::size_t>(m));
    {
      std::vector<int> fl(lo_begin.begin(), lo_begin.end() - 1), fh(hi_begin.begin(), hi_begin.end() - 1);
      for (int e = 0; e < m; ++e) {
        by_lo[fl[rank_[edges_[e].lo()]]++] = e;
        by_hi[fh[rank_[edges_[e].hi()]]++] = e;
      }
    }
    std::vector<int> shell(cycles_.size(), -1);
    // The edges crossing the sweep line, from the bottom (BlockedOrder: contiguous blocks,
    // where a std::set allocated a node per edge: nested squares 10^5, 8*10^5 result
    // edges: 577-592 -> 165-176 ms on one thread, with orient's shortcut for input points).
    BlockedOrder line;
    const auto below = [this](int a, int b) { return is_below(a, b); };
    std::vector<int> entering;
    std::vector<int> upper;  // per cycle starting here: its upper edge
    for (int r = 0; r < nr; ++r) {
      for (int i = hi_begin[r]; i < hi_begin[r + 1]; ++i) line.erase(by_hi[i], below);
      entering.clear();
      for (int i = lo_begin[r]; i < lo_begin[r + 1]; ++i) {
        const int e = by_lo[i];
        line.insert(e, below);
        entering.push_back(e);
      }
      // The holes whose first vertex this is, from the top: both their edges enter here, and
      // the upper one comes first from the top.
      sort_by_predicates<K>(entering.begin(), entering.end(), [&](int a, int b) { return is_below(b, a); });
      upper.clear();
      for (const int e : entering) {
        const int c = edges_[e].cycle;
        if (cycles_[c].type != PolygonType::hole) continue;
        if (std::find_if(upper.begin(), upper.end(), [&](int u) { return edges_[u].cycle == c; }) != upper.end()) continue;
        if (!is_first_vertex(c, by_rank_[r])) continue;
        upper.push_back(e);
      }
      for (const int e : upper) {
        const int h = edges_[e].cycle;
        const int up = line.next(e, below);
        if (up < 0) continue;
        const ResultEdge& hit = edges_[up];
        const ResultCycle& c = cycles_[hit.cycle];
        if (is_far_below(hit)) {
          if (c.type == PolygonType::island) shell[h] = hit.cycle;
        } else if (c.type == PolygonType::hole) {
          shell[h] = shell[hit.cycle];
        }
      }
    }
    return shell;
  }

  // Whether v is the lexicographically first vertex of cycle c.
  bool is_first_vertex(int c, int v) {
    if (first_vertex_.empty()) {
      first_vertex_.assign(cycles_.size(), -1);
      for (std::size_t i = 0; i < cycles_.size(); ++i) {
        if (!is_area_cycle(i)) continue;
        int best = cycles_[i].vertices.front();
        for (const int u : cycles_[i].vertices) {
          if (rank_[u] < rank_[best]) best = u;
        }
        first_vertex_[i] = best;
      }
    }
    return first_vertex_[c] == v;
  }

  const Arrangement<K>& arr_;
  const std::vector<ResultCycle>& cycles_;
  std::vector<int> rank_;
  std::vector<int> by_rank_;
  std::vector<ResultEdge> edges_;
  std::vector<int> first_vertex_;
};

}  // namespace detail

// For each hole-type cycle, the index of the island-type cycle directly containing it (its
// shell), or -1; other entries are -1. With one island, it is every hole's shell (a hole
// lies in some island of a bounded result); otherwise one sweep finds them all, in
// O(m log m) for m result vertices.
template <Kernel K>
std::vector<int> inclusion_parents(const Arrangement<K>& arr, const std::vector<ResultCycle>& cycles) {
  std::vector<int> parent(cycles.size(), -1);
  std::vector<int> islands;
  bool any_hole = false;
  for (std::size_t i = 0; i < cycles.size(); ++i) {
    if (cycles[i].vertices.size() < 3) continue;
    if (cycles[i].type == PolygonType::island) islands.push_back(static_cast<int>(i));
    any_hole = any_hole || cycles[i].type == PolygonType::hole;
  }
  if (!any_hole || islands.empty()) return parent;
  if (islands.size() == 1) {
    for (std::size_t i = 0; i < cycles.size(); ++i) {
      if (cycles[i].vertices.size() >= 3 && cycles[i].type == PolygonType::hole) parent[i] = islands[0];
    }
    return parent;
  }
  return detail::ShellSweep<K>(arr, cycles).run();
}

}  // namespace mk
