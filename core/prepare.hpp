// Input preparation: identities for input points, and each polygon made vertex-complete and
// split into irreducible cycles. [MK89 §2.2] (vertex-complete, irreducible parts)
// [MK89 §3.3 end] (orientable polygons are made vertex-complete by inserting touching points)
// Preconditions: coordinates are finite. Edges of one polygon that cross properly are
// rejected with InvalidInput naming both edges.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/edge_insertions.hpp"
#include "core/error.hpp"
#include "core/pairs.hpp"
#include "core/parallel.hpp"
#include "predicates/segments.hpp"

namespace mk {

namespace detail {

// A ring as point ids, with the input index of each vertex kept for messages.
struct IdRing {
  std::vector<int> ids;
  std::vector<int> input_index;
};

// Splits a closed sequence of point ids at repeated vertices into cycles with distinct
// vertices: every closed polyline is a union of irreducible polygons [MK89 §2.2].
inline void split_into_cycles(IdRing&& ring, int ring_index, std::vector<int>& where, PreparedPolygon& out) {
  const std::size_t n = ring.ids.size();
  if (n >= 2) {  // the common case first: no vertex repeats, and the ring is one cycle
    std::size_t k = 0;
    for (; k < n && where[ring.ids[k]] < 0; ++k) where[ring.ids[k]] = 0;
    for (std::size_t i = 0; i < k; ++i) where[ring.ids[i]] = -1;
    if (k == n) {
      out.origins.push_back({ring_index, ring.input_index[0]});
      out.cycles.push_back(std::move(ring.ids));
      return;
    }
  }
  std::vector<int> stack;
  std::vector<int> stack_input;
  const auto emit = [&](std::size_t from) {
    std::vector<int> cycle(stack.begin() + static_cast<std::ptrdiff_t>(from), stack.end());
    if (cycle.size() == 1) {
      out.point_cycles.push_back(cycle[0]);
    } else {
      out.cycles.push_back(std::move(cycle));
      out.origins.push_back({ring_index, stack_input[from]});
    }
    for (std::size_t k = from + 1; k < stack.size(); ++k) where[stack[k]] = -1;
    stack.resize(from + 1);
    stack_input.resize(from + 1);
  };
  for (std::size_t k = 0; k <= n; ++k) {
    const int id = ring.ids[k % n];
    if (where[id] >= 0) {
      emit(static_cast<std::size_t>(where[id]));
    } else {
      where[id] = static_cast<int>(stack.size());
      stack.push_back(id);
      stack_input.push_back(ring.input_index[k % n]);
    }
  }
  for (const int id : stack) where[id] = -1;
}

inline RingEdge ring_edge(const IdRing& ring, int ring_index, std::size_t k) {
  return {ring_index, ring.input_index[k], ring.input_index[(k + 1) % ring.ids.size()]};
}

inline std::string edge_name(const RingEdge& e) {
  return "ring " + std::to_string(e.ring) + "'s edge from vertex " + std::to_string(e.from) + " to vertex " +
         std::to_string(e.to);
}

// Inserts the points of one polygon that touch its own edges (orientable -> vertex-complete)
// and rejects proper crossings.
template <Kernel K>
void make_vertex_complete(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                          std::vector<IdRing>& rings, const char* poly_name, PairSearch search, unsigned threads = 1) {
  std::size_t num_edges = 0;
  for (const auto& ring : rings) num_edges += ring.ids.size() < 2 ? 0 : ring.ids.size();
  std::vector<SweepItem> items;
  items.reserve(num_edges);
  for (const auto& ring : rings) {
    const auto& ids = ring.ids;
    if (ids.size() < 2) continue;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const int u = ids[k];
      const int w = ids[k + 1 < ids.size() ? k + 1 : 0];
      add_sweep_item(items, u, w, 0, k > 0);
    }
  }
  // Per part of the pair search (see CandidatePairs): points of the polygon on its own
  // edges, by edge index, and the first proper crossing. Of the proper crossings, the error
  // names the one met first walking the rings: the first edge (in input order) that crosses
  // an earlier one, and the earliest of those, whatever order the search finds them in.
  CandidatePairs<K> pairs(pts, x_rank, items, false, search, threads);
  struct Found {
    EdgeInsertions inserted;
    std::pair<int, int> crossing{-1, -1};
  };
  std::vector<Found> found(pairs.parts());
  run_tasks(threads_for(items.size(), threads), pairs.parts(), [&](std::size_t part) {
    Found& out = found[part];
    pairs.for_each_in_part(part, [&](int i, int j) {
      const SweepItem& a = items[i];
      const SweepItem& b = items[j];
      if (a.lo == b.lo && a.hi == b.hi) return;  // identical as sets: allowed [MK89 §2.2]
      const auto rel = relate_segments_by_id<K>(pts, a.lo, a.hi, b.lo, b.hi);
      if (rel.proper_crossing) {
        const std::pair<int, int> c{std::max(i, j), std::min(i, j)};
        if (out.crossing.first < 0 || c < out.crossing) out.crossing = c;
        return;
      }
      if (rel.c_inside_ab) out.inserted.add(i, b.lo);
      if (rel.d_inside_ab) out.inserted.add(i, b.hi);
      if (rel.a_inside_cd) out.inserted.add(j, a.lo);
      if (rel.b_inside_cd) out.inserted.add(j, a.hi);
    });
  });
  EdgeInsertions inserted;
  std::pair<int, int> crossing{-1, -1};
  for (Found& f : found) {
    if (f.crossing.first >= 0 && (crossing.first < 0 || f.crossing < crossing)) crossing = f.crossing;
    inserted.append(std::move(f.inserted));
  }
  if (crossing.first >= 0) {
    // The ring and the position in it of an item (items follow the rings of 2+ points).
    const auto ring_edge_of = [&](int item) {
      int r = 0;
      for (;; ++r) {
        const int n = rings[r].ids.size() < 2 ? 0 : static_cast<int>(rings[r].ids.size());
        if (item < n) break;
        item -= n;
      }
      return ring_edge(rings[r], r, static_cast<std::size_t>(item));
    };
    const RingEdge first = ring_edge_of(crossing.first);
    const RingEdge second = ring_edge_of(crossing.second);
    throw CrossingEdges(poly_name[0] == 'A' ? 0 : 1, first, second,
                        std::string("polygon ") + poly_name + ": " + edge_name(first) + " crosses " +
                            edge_name(second) + "; edges of a polygon may touch but must not cross");
  }
  if (inserted.empty()) return;
  inserted.group(static_cast<int>(items.size()));
  std::vector<int> ins;
  int e = 0;
  for (auto& ring : rings) {
    if (ring.ids.size() < 2) continue;
    const int ring_end = e + static_cast<int>(ring.ids.size());
    if (inserted.next_edge() >= ring_end) {  // nothing inserted into this ring
      e = ring_end;
      continue;
    }
    IdRing out;
    for (std::size_t k = 0; k < ring.ids.size(); ++k, ++e) {
      const int u = ring.ids[k];
      const int w = ring.ids[(k + 1) % ring.ids.size()];
      out.ids.push_back(u);
      out.input_index.push_back(ring.input_index[k]);
      if (!inserted.take(e, ins)) continue;
      // Ids follow lexicographic order, which is monotone along any segment.
      if (u < w) {
        std::sort(ins.begin(), ins.end());
      } else {
        std::sort(ins.rbegin(), ins.rend());
      }
      ins.erase(std::unique(ins.begin(), ins.end()), ins.end());
      for (const int id : ins) {
        out.ids.push_back(id);
        out.input_index.push_back(ring.input_index[k]);
      }
    }
    ring = std::move(out);
  }
}

// Appends q to `points` (distinct, in lexicographic order so far, q not smaller than the
// last) unless it equals the last, with the rank of its x among the distinct x values, and
// returns q's id.
template <Kernel K>
int append_distinct(std::vector<typename K::Point>& points, std::vector<int>& x_rank, const typename K::Point& q) {
  if (points.empty()) {
    x_rank.push_back(0);
  } else if (K::compare_x(points.back(), q) != Sign::zero) {
    x_rank.push_back(x_rank.back() + 1);
  } else if (K::compare_y(points.back(), q) != Sign::zero) {
    x_rank.push_back(x_rank.back());
  } else {
    if constexpr (std::is_same_v<typename K::Point, Point>) {
      // Equal points differ at most in the signs of their zeros: +0 is kept wherever one of
      // them has it, so that the point kept does not depend on the order they come in (the
      // sort's, whose halves are sorted on two threads when there are several).
      Point& kept = points.back();
      if (kept.x == 0 && std::signbit(kept.x)) kept.x = q.x;
      if (kept.y == 0 && std::signbit(kept.y)) kept.y = q.y;
    }
    return static_cast<int>(points.size()) - 1;
  }
  points.push_back(q);
  return static_cast<int>(points.size()) - 1;
}

// A maximal stretch of one ring whose points come in lexicographic order when read from
// `pos` towards `end` (exclusive) in steps of `step` (+1 or -1).
template <class P>
struct PointRun {
  P key;  // ring[pos], kept beside the run so that comparing runs reads no other memory
  const P* ring = nullptr;
  int ring_ref = 0;  // input number of the ring's first point (see number_points_by_runs)
  int pos = 0;
  int end = 0;
  int step = 1;
};

// Merges sorted runs into `points` (distinct) and their x-ranks (the rank of their x among
// the distinct x values), setting id_of (input number -> index in points) for every point
// read. A binary min-heap of run indices keyed by the runs' current points;
// sifting moves 4-byte indices into a hole instead of swapping runs.
template <Kernel K>
void merge_runs(std::vector<PointRun<typename K::Point>>& runs, std::vector<typename K::Point>& points,
                std::vector<int>& x_rank, std::vector<int>& id_of) {
  using P = typename K::Point;
  const auto less = [](const P& u, const P& w) { return compare_xy<K>(u, w) == Sign::negative; };
  std::vector<int> order(runs.size());
  std::iota(order.begin(), order.end(), 0);
  const auto sift_down = [&](std::size_t i) {
    const std::size_t n = order.size();
    const int moving = order[i];
    const P& key = runs[moving].key;
    for (std::size_t l = 2 * i + 1; l < n; l = 2 * i + 1) {
      const std::size_t c = l + 1 < n && less(runs[order[l + 1]].key, runs[order[l]].key) ? l + 1 : l;
      if (!less(runs[order[c]].key, key)) break;
      order[i] = order[c];
      i = c;
    }
    order[i] = moving;
  };
  for (std::size_t i = order.size() / 2; i-- > 0;) sift_down(i);
  std::size_t n = points.size();
  for (const auto& run : runs) n += static_cast<std::size_t>((run.end - run.pos) * run.step);
  points.reserve(n);
  x_rank.reserve(n);
  while (!order.empty()) {
    PointRun<P>& run = runs[order.front()];
    id_of[run.ring_ref + run.pos] = append_distinct<K>(points, x_rank, run.key);
    run.pos += run.step;
    if (run.pos == run.end) {
      order.front() = order.back();
      order.pop_back();
    } else {
      run.key = run.ring[run.pos];
    }
    if (!order.empty()) sift_down(0);
  }
}

// Numbers the distinct input points of A and B in lexicographic order by merging the rings'
// monotone runs, which are few on smooth or convex rings (a ring has at least two): each
// point then costs about log2(runs) comparisons instead of a sort's log2(n). Fills `points`
// (distinct, sorted), their x-ranks and id_of (input number, counted polygon after polygon
// and ring after ring -> id). Returns false, having done nothing, when there are more than
// `max_runs` runs. (Merging the points below a median key and the others on two threads
// was tried twice: slower whenever the second core is busy, and little faster when it is
// not; appending the upper half and moving its ids up costs what the second thread saves.)
template <Kernel K>
bool number_points_by_runs(const std::array<const BasicPolygon<typename K::Point>*, 2>& in, std::size_t max_runs,
                           std::vector<typename K::Point>& points, std::vector<int>& x_rank, std::vector<int>& id_of) {
  using P = typename K::Point;
  const auto less = [](const P& u, const P& w) { return compare_xy<K>(u, w) == Sign::negative; };
  std::vector<PointRun<P>> runs;
  int ref = 0;
  for (const auto* poly : in) {
    for (const auto& ring : poly->rings) {
      const int n = static_cast<int>(ring.size());
      for (int i = 0; i < n;) {
        int j = i + 1;
        if (j < n && less(ring[j], ring[i])) {
          while (j < n && less(ring[j], ring[j - 1])) ++j;
          runs.push_back({ring[j - 1], ring.data(), ref, j - 1, i - 1, -1});
        } else {
          while (j < n && !less(ring[j], ring[j - 1])) ++j;
          runs.push_back({ring[i], ring.data(), ref, i, j, +1});
        }
        if (runs.size() > max_runs) return false;
        i = j;
      }
      ref += n;
    }
  }
  merge_runs<K>(runs, points, x_rank, id_of);
  return true;
}

}  // namespace detail

// Gives every distinct input point of A and B an id in lexicographic order, makes both
// polygons vertex-complete and splits their rings into irreducible cycles.
template <Kernel K>
Arrangement<K> prepare(const BasicPolygon<typename K::Point>& a, const BasicPolygon<typename K::Point>& b,
                       PairSearch search = PairSearch::sweep, unsigned threads = 1) {
  Arrangement<K> arr;
  const std::array<const BasicPolygon<typename K::Point>*, 2> in = {&a, &b};
  std::size_t total = 0;
  for (const auto* poly : in) {
    for (const auto& ring : poly->rings) total += ring.size();
  }
  std::vector<int> id_of(total);
  arr.points.reserve(total);
  // Rings of smooth or convex shapes consist of a few long monotone runs, merged directly;
  // otherwise the points themselves (not indices into the rings) are sorted. The second
  // member numbers the vertices polygon after polygon, ring after ring.
  constexpr std::size_t max_runs = 32;
  if (!detail::number_points_by_runs<K>(in, max_runs, arr.points, arr.x_rank, id_of)) {
    std::vector<std::pair<typename K::Point, int>> sorted;
    sorted.reserve(total);
    for (const auto* poly : in) {
      for (const auto& ring : poly->rings) {
        for (const auto& q : ring) sorted.emplace_back(q, static_cast<int>(sorted.size()));
      }
    }
    // The halves sorted on two threads, then merged (append_distinct keeps the same point
    // for equal ones in any order).
    const auto less = [](const auto& x, const auto& y) { return compare_xy<K>(x.first, y.first) == Sign::negative; };
    arr.x_rank.reserve(total);
    const auto take = [&](const std::pair<typename K::Point, int>& e) {
      id_of[e.second] = detail::append_distinct<K>(arr.points, arr.x_rank, e.first);
    };
    if (threads_for(total, threads) < 2) {
      std::sort(sorted.begin(), sorted.end(), less);
      for (const auto& e : sorted) take(e);
    } else {
      const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(total / 2);
      run_tasks(2, 2, [&](std::size_t half) {
        if (half == 0) {
          std::sort(sorted.begin(), mid, less);
        } else {
          std::sort(mid, sorted.end(), less);
        }
      });
      auto i = sorted.begin(), j = mid;
      while (i != mid && j != sorted.end()) take(less(*j, *i) ? *j++ : *i++);
      for (; i != mid; ++i) take(*i);
      for (; j != sorted.end(); ++j) take(*j);
    }
  }

  // A and B are made vertex-complete and split into cycles independently (on two threads
  // when there are several), each with its own marks per point.
  std::array<std::size_t, 2> first_ref{0, 0};  // input number of each polygon's first vertex
  for (const auto& ring : a.rings) first_ref[1] += ring.size();
  const unsigned per_polygon = threads_for(total, threads) > 1 ? (threads + 1) / 2 : 1;
  run_tasks(threads_for(total, threads), 2, [&](std::size_t p) {
    PreparedPolygon& out = arr.polygon[p];
    out.type = in[p]->type;
    std::size_t ref = first_ref[p];
    std::vector<detail::IdRing> rings(in[p]->rings.size());
    for (std::size_t r = 0; r < rings.size(); ++r) {
      rings[r].ids.reserve(in[p]->rings[r].size());
      rings[r].input_index.reserve(in[p]->rings[r].size());
      for (std::size_t v = 0; v < in[p]->rings[r].size(); ++v, ++ref) {
        const int id = id_of[ref];
        auto& ids = rings[r].ids;
        if (!ids.empty() && ids.back() == id) continue;  // duplicate consecutive vertex
        ids.push_back(id);
        rings[r].input_index.push_back(static_cast<int>(v));
      }
      auto& ids = rings[r].ids;
      while (ids.size() > 1 && ids.back() == ids.front()) {  // closing vertex repeated
        ids.pop_back();
        rings[r].input_index.pop_back();
      }
    }
    detail::make_vertex_complete<K>(arr.points, arr.x_rank, rings, p == 0 ? "A" : "B", search, per_polygon);
    std::vector<int> where(arr.points.size(), -1);
    for (std::size_t r = 0; r < rings.size(); ++r) {
      if (rings[r].ids.empty()) continue;
      detail::split_into_cycles(std::move(rings[r]), static_cast<int>(r), where, out);
    }
  });
  return arr;
}

template <Kernel K>
BasicPolygon<typename K::Point> to_kernel_polygon(const Polygon& p) {
  BasicPolygon<typename K::Point> out;
  out.type = p.type;
  out.rings.reserve(p.rings.size());
  for (const auto& ring : p.rings) {
    auto& r = out.rings.emplace_back();
    r.reserve(ring.size());
    for (const auto& q : ring) r.push_back(K::point(q));
  }
  return out;
}

}  // namespace mk
