// Step 3: find the intersection points of A's and B's edges and insert them, in order, into
// both vertex rings; then cut the rings into edge fragments.
// [MK89 §3.1 step 3] [MK89 §4.3] (sub-quadratic intersection search)
// Preconditions: step 2 done. Both polygons vertex-complete, so a proper crossing is
// identified by its pair of edges, edges of one polygon that coincide as sets counting as
// one segment (BRIEF.md section 2): crossings are never compared by coordinates.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/edge_insertions.hpp"
#include "core/error.hpp"
#include "core/pairs.hpp"
#include "core/parallel.hpp"
#include "core/red_blue.hpp"
#include "core/separation_rules.hpp"
#include "core/sorting.hpp"
#include "predicates/segments.hpp"

namespace mk {

namespace detail {
// Appends fragment from -> to of edge e, made in place with its fields set (push_back of a
// braced temporary builds it on the stack and copies it with wide loads that wait for the
// narrow stores, GCC 12; clang 14, the fuzzers' compiler, has no parenthesised aggregate
// init for emplace_back(from, to, e)).
inline void add_fragment(std::vector<Fragment>& fragments, int from, int to, int e) {
  Fragment& f = fragments.emplace_back();
  f.from = from;
  f.to = to;
  f.edge = e;
}

struct PairHash {
  std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& p) const {
    return std::hash<std::uint64_t>()(p.first * 0x9E3779B97F4A7C15ULL ^ p.second);
  }
};

// One id per crossing point: edges of one polygon that coincide as sets cross the other
// polygon's edge at the same point, found once per edge (BRIEF.md section 2). Crossings
// are given in the order they were found; the first of a point takes the next id.
// When many crossings are expected, the edges that may coincide with another of their
// polygon are marked first, and only crossings of marked edges are looked up in the map:
// an edge {u, w} with a twin has u or w twice in its polygon's cycles (each point met once
// has its two edges to different points), or lies in a cycle of two points. A crossing of
// two unmarked edges is the only one of its pair of segments and takes the next id
// directly, the same ids as through the map (star 1e4: 247k crossings, 250k map nodes).
class CrossingIds {
 public:
  template <Kernel K>
  CrossingIds(const Arrangement<K>& arr, std::size_t expected) {
    constexpr std::size_t kMarkFrom = 1024;  // fewer crossings: the map is cheaper than the marks
    if (expected < kMarkFrom || 4 * expected < arr.points.size()) return;
    std::vector<std::uint8_t> seen(arr.points.size());
    for (int g = 0; g < 2; ++g) {
      const PreparedPolygon& poly = arr.polygon[static_cast<std::size_t>(g)];
      std::fill(seen.begin(), seen.end(), std::uint8_t{0});
      for (const auto& cycle : poly.cycles) {
        for (const int id : cycle) seen[static_cast<std::size_t>(id)] = seen[static_cast<std::size_t>(id)] ? 2 : 1;
      }
      auto& marked = marked_[static_cast<std::size_t>(g)];
      marked.resize(poly.edges.size());
      for (std::size_t c = 0; c + 1 < poly.cycle_first_edge.size(); ++c) {
        const bool two = poly.cycle_first_edge[c + 1] - poly.cycle_first_edge[c] <= 2;
        for (int e = poly.cycle_first_edge[c]; e < poly.cycle_first_edge[c + 1]; ++e) {
          const Edge& edge = poly.edges[static_cast<std::size_t>(e)];
          marked[static_cast<std::size_t>(e)] =
              two || seen[static_cast<std::size_t>(edge.src)] == 2 || seen[static_cast<std::size_t>(edge.dst)] == 2;
        }
      }
    }
  }

  // The crossing of edge ia of A and edge jb of B, inserted into both.
  template <Kernel K>
  void insert(Arrangement<K>& arr, int ia, int jb, typename K::Vertex&& vertex, std::array<EdgeInsertions, 2>& inserted) {
    int id = arr.num_vertices();
    if (marked_[0].empty() || marked_[0][static_cast<std::size_t>(ia)] || marked_[1][static_cast<std::size_t>(jb)]) {
      const Edge& a = arr.polygon[0].edges[static_cast<std::size_t>(ia)];
      const Edge& b = arr.polygon[1].edges[static_cast<std::size_t>(jb)];
      const auto key = std::make_pair(segment_key(a.src, a.dst), segment_key(b.src, b.dst));
      const auto [it, fresh] = ids_.try_emplace(key, id);
      if (fresh) arr.crossings.push_back(std::move(vertex));
      id = it->second;
    } else {
      arr.crossings.push_back(std::move(vertex));
    }
    inserted[0].add(ia, id);
    inserted[1].add(jb, id);
  }

 private:
  std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, int, PairHash> ids_;
  std::array<std::vector<bool>, 2> marked_;  // per polygon, per edge: may coincide with another (none: all may)
};
}  // namespace detail

// A kernel that rounds crossing points may overflow (inputs near 1e300) or divide by a
// rounded-to-zero denominator: its failure is reported, never written out as NaN or inf.
template <Kernel K>
void check_finite_crossing(const Arrangement<K>& arr, const typename K::Vertex& crossing, const Edge& a, const Edge& b) {
  const mk::Point p = K::approx(crossing);
  if (std::isfinite(p.x) && std::isfinite(p.y)) return;
  const auto at = [&](int id) {
    const mk::Point q = K::approx(arr.vertex(id));
    std::ostringstream s;
    s.precision(17);
    s << "(" << q.x << " " << q.y << ")";
    return s.str();
  };
  throw KernelFailure(std::string("kernel ") + std::string(K::name) + ": the crossing point of edges " + at(a.src) +
                      "-" + at(a.dst) + " of A and " + at(b.src) + "-" + at(b.dst) +
                      " of B is not finite in its arithmetic");
}

// Up to this many points to insert into one edge are sorted by insertion (step 3's fragments).
inline constexpr std::size_t kFewOnEdge = 16;

// Step 3's crossings and touching points as the preparation found them (arr.early): edge
// numbers in input ring order turned into edge indices (a cycle that step 1 turned has its
// edges in reverse), one id per crossing point as below, in the order they were found.
template <Kernel K>
void take_early_intersections(Arrangement<K>& arr, std::array<EdgeInsertions, 2>& inserted) {
  std::array<std::vector<int>, 2> edge_of;  // per polygon: edge number as input -> edge index
  for (int g = 0; g < 2; ++g) {
    const PreparedPolygon& poly = arr.polygon[g];
    edge_of[g].resize(poly.edges.size());
    for (std::size_t c = 0; c + 1 < poly.cycle_first_edge.size(); ++c) {
      const int first = poly.cycle_first_edge[c];
      const int n = poly.cycle_first_edge[c + 1] - first;
      // Turned: the ring v0 .. v(n-1) is now v(n-1) .. v0, and its edge k (v(k), v(k+1)) is
      // edge n - 2 - k, the closing one staying last.
      const bool turned = poly.cycles[c][0] != arr.early.ring_start[g][c];
      for (int k = 0; k < n; ++k) edge_of[g][static_cast<std::size_t>(first + k)] = first + (turned && k < n - 1 ? n - 2 - k : k);
    }
  }
  std::size_t expected = 0;
  for (const auto& part : arr.early.parts) expected += part.crossings.size();
  arr.crossings.reserve(expected);
  detail::CrossingIds crossing_ids(arr, expected);
  for (auto& part : arr.early.parts) {
    for (auto& c : part.crossings) {
      crossing_ids.insert(arr, edge_of[0][static_cast<std::size_t>(c.a)], edge_of[1][static_cast<std::size_t>(c.b)],
                          std::move(c.vertex), inserted);
    }
    for (int g = 0; g < 2; ++g) {
      for (const auto& [e, v] : part.inserted[g]) inserted[g].add(edge_of[g][static_cast<std::size_t>(e)], v);
    }
  }
  arr.early = {};
}

template <Kernel K>
void insert_intersections(Arrangement<K>& arr, PairSearch search = PairSearch::sweep, unsigned threads = 1,
                          bool rounding_rules = true) {
  auto& ea = arr.polygon[0].edges;
  auto& eb = arr.polygon[1].edges;
  std::array<EdgeInsertions, 2> inserted;  // per polygon, by edge index
  if (arr.early.found) {
    take_early_intersections(arr, inserted);
  } else {  // the sweep's items are released before the fragments are built, which reuse their memory
    std::vector<SweepItem> items;
    items.reserve(ea.size() + eb.size());
    for (int g = 0; g < 2; ++g) {
      const PreparedPolygon& poly = arr.polygon[g];
      for (std::size_t c = 0; c + 1 < poly.cycle_first_edge.size(); ++c) {
        for (int e = poly.cycle_first_edge[c]; e < poly.cycle_first_edge[c + 1]; ++e) {
          add_sweep_item(items, poly.edges[e].src, poly.edges[e].dst, g, e > poly.cycle_first_edge[c]);
        }
      }
    }
    const int na = static_cast<int>(ea.size());
    const auto& pts = arr.points;
    // Each part of the search (see CandidatePairs) collects its crossings, constructed there,
    // and its vertices on edges; the parts are then joined in their order, so that crossing
    // ids do not depend on the number of threads.
    struct Crossing {
      int a, b;  // edge indices in A and B
      typename K::Vertex vertex;
    };
    struct Found {
      std::vector<Crossing> crossings;
      std::array<EdgeInsertions, 2> inserted;
    };
    const auto relate = [&](Found& out, int i, int j) {
      if (i > j) std::swap(i, j);  // i indexes A, j indexes B
      const int jb = j - na;
      const Edge& a = ea[i];
      const Edge& b = eb[jb];
      relate_edges_across<K>(
          pts, a.src, a.dst, b.src, b.dst,
          [&] {
            out.crossings.push_back({i, jb, K::crossing(pts[a.src], pts[a.dst], pts[b.src], pts[b.dst])});
            if constexpr (!K::is_exact) check_finite_crossing<K>(arr, out.crossings.back().vertex, a, b);
          },
          [&](int p) { out.inserted[0].add(i, p); }, [&](int p) { out.inserted[1].add(jb, p); });
    };
    std::vector<Found> found;
    // The search by boxes, stopped after `merges` merges of chains when not negative; whether
    // it finished.
    const auto search_boxes = [&](std::int64_t merges) {
      CandidatePairs<K> pairs(pts, arr.x_rank, items, true, search, threads);
      if (merges >= 0) pairs.limit_merges(merges);
      found.assign(pairs.parts(), Found{});
      run_tasks(threads_for(items.size(), threads), pairs.parts(), [&](std::size_t part) {
        pairs.for_each_in_part(part, [&](int i, int j) { relate(found[part], i, j); });
      });
      return !pairs.exhausted();
    };
    bool searched = false;
    if constexpr (std::is_same_v<typename K::Point, Point> && K::is_exact) {
      // The preparation's findings are dropped when a ring is split into cycles (a flower: one
      // ring through its centre thousands of times), and the search is made again here, the
      // way the preparation makes it (paper-notes deviation 23): where the chains' boxes
      // overlap many others, boxes within a budget, then, when each polygon's edges meet only
      // at shared ends, the red-blue sweep.
      if (search == PairSearch::red_blue || detail::tries_boxes_first<K>(pts, items, search)) {
        searched = search != PairSearch::red_blue && search_boxes(detail::merge_budget(items.size()));
        const std::span<const SweepItem> all(items);
        if (!searched && edges_meet_only_at_ends<K>(pts, all.subspan(0, ea.size())) &&
            edges_meet_only_at_ends<K>(pts, all.subspan(ea.size()))) {
          detail::relate_red_blue_pairs<K>(pts, all, threads, found, relate);
          searched = true;
        }
      }
    }
    if (!searched) search_boxes(-1);
    std::size_t expected = 0;
    for (const Found& f : found) expected += f.crossings.size();
    arr.crossings.reserve(expected);
    detail::CrossingIds crossing_ids(arr, expected);
    for (Found& f : found) {
      for (Crossing& c : f.crossings) crossing_ids.insert(arr, c.a, c.b, std::move(c.vertex), inserted);
      std::vector<Crossing>().swap(f.crossings);
      for (int g = 0; g < 2; ++g) inserted[g].append(std::move(f.inserted[g]));
    }
  }

  // Rules N and C of the rounding certificate, tested on each edge's vertices as they are
  // put in order (separation_rules.hpp); each polygon stops testing at its first refusal.
  const SeparationRules<K> rules = rounding_rules ? SeparationRules<K>(arr, threads) : SeparationRules<K>();
  std::array<bool, 2> separated{rules.active(), rules.active()};
  run_tasks(threads_for(ea.size() + eb.size(), threads), 2, [&](std::size_t g) {
    PreparedPolygon& poly = arr.polygon[g];
    bool holds = separated[g];
    EdgeInsertions& ins = inserted[g];
    ins.group(static_cast<int>(poly.edges.size()));
    // A local vector: its end stays in a register. Fragments are made in place
    // (detail::add_fragment), four times faster here than push_back of a braced temporary.
    std::vector<Fragment> fragments;
    fragments.reserve(poly.edges.size() + ins.size());
    poly.cycle_first_fragment.assign(1, 0);
    poly.cycle_first_fragment.reserve(poly.cycle_first_edge.size());
    std::vector<int> on_edge;
    for (std::size_t c = 0; c + 1 < poly.cycle_first_edge.size(); ++c) {
      const int end = poly.cycle_first_edge[c + 1];
      for (int e = poly.cycle_first_edge[c]; e < end; ++e) {
        // Edges without insertions, the common case, are one fragment each.
        for (const int plain_end = std::min(end, ins.next_edge()); e < plain_end; ++e) {
          detail::add_fragment(fragments, poly.edges[e].src, poly.edges[e].dst, e);
          if (holds) holds = rules.edge_holds(arr, static_cast<int>(g), e, poly.cycle_first_edge[c], end, {});
        }
        if (e == end) break;
        const Edge& edge = poly.edges[e];
        int from = edge.src;
        if (ins.take(e, on_edge)) {
          const auto& s = arr.points[edge.src];
          const auto& d = arr.points[edge.dst];
          const auto before = [&](int x, int y) {
            return x != y && K::compare_along(s, d, arr.vertex(x), arr.vertex(y)) == Sign::negative;
          };
          if (on_edge.size() <= kFewOnEdge) {
            // Usually one point, repeated once per edge of the other polygon through it:
            // sorted by insertion, repeats dropped, without std::sort's set-up (a copy of
            // the comparison that stalled on its own stores, GCC 12).
            std::size_t m = 0;
            for (std::size_t i = 0; i < on_edge.size(); ++i) {
              const int id = on_edge[i];
              if (std::find(on_edge.begin(), on_edge.begin() + static_cast<std::ptrdiff_t>(m), id) !=
                  on_edge.begin() + static_cast<std::ptrdiff_t>(m)) {
                continue;
              }
              std::size_t k = m++;
              for (; k > 0 && before(id, on_edge[k - 1]); --k) on_edge[k] = on_edge[k - 1];
              on_edge[k] = id;
            }
            on_edge.resize(m);
          } else {
            sort_by_predicates<K>(on_edge.begin(), on_edge.end(), before);
            on_edge.erase(std::unique(on_edge.begin(), on_edge.end()), on_edge.end());
          }
          for (const int id : on_edge) {
            detail::add_fragment(fragments, from, id, e);
            from = id;
          }
        }
        if (holds) holds = rules.edge_holds(arr, static_cast<int>(g), e, poly.cycle_first_edge[c], end, on_edge);
        detail::add_fragment(fragments, from, edge.dst, e);
      }
      poly.cycle_first_fragment.push_back(static_cast<int>(fragments.size()));
    }
    poly.fragments = std::move(fragments);
    separated[g] = holds;
  });
  arr.separation = separated[0] && separated[1] ? Separation{rules.threshold(), rules.half_size_bound()} : Separation{};
}

}  // namespace mk
