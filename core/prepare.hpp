// Input preparation: identities for input points, and each polygon made vertex-complete and
// split into irreducible cycles. [MK89 §2.2] (vertex-complete, irreducible parts)
// [MK89 §3.3 end] (orientable polygons are made vertex-complete by inserting touching points)
// Preconditions: coordinates are finite. Edges of one polygon that cross properly are
// rejected with InvalidInput naming both edges.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/clean_edges.hpp"
#include "core/edge_insertions.hpp"
#include "core/error.hpp"
#include "core/pairs.hpp"
#include "core/parallel.hpp"
#include "core/red_blue.hpp"
#include "core/sorting.hpp"
#include "predicates/segments.hpp"

namespace mk {

namespace detail {

// A ring as point ids, with the input index of each vertex kept for messages.
struct IdRing {
  std::vector<int> ids;
  std::vector<int> input_index;
};

// Splits a closed sequence of point ids at repeated vertices into cycles with distinct
// vertices: every closed polyline is a union of irreducible polygons [MK89 §2.2]. Returns
// whether a ring of two or more points became one cycle as it was.
inline bool split_into_cycles(IdRing&& ring, int ring_index, std::vector<int>& where, PreparedPolygon& out) {
  const std::size_t n = ring.ids.size();
  if (n >= 2) {  // the common case first: no vertex repeats, and the ring is one cycle
    std::size_t k = 0;
    for (; k < n && where[ring.ids[k]] < 0; ++k) where[ring.ids[k]] = 0;
    for (std::size_t i = 0; i < k; ++i) where[ring.ids[i]] = -1;
    if (k == n) {
      out.origins.push_back({ring_index, ring.input_index[0]});
      out.cycles.push_back(std::move(ring.ids));
      return true;
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
  return n < 2;
}

inline RingEdge ring_edge(const IdRing& ring, int ring_index, std::size_t k) {
  return {ring_index, ring.input_index[k], ring.input_index[(k + 1) % ring.ids.size()]};
}

inline std::string edge_name(const RingEdge& e) {
  return "ring " + std::to_string(e.ring) + "'s edge from vertex " + std::to_string(e.from) + " to vertex " +
         std::to_string(e.to);
}

// Appends the items of a polygon's rings (rings of fewer than two points have none).
inline void add_ring_items(const std::vector<IdRing>& rings, int group, std::vector<SweepItem>& items) {
  for (const auto& ring : rings) {
    const auto& ids = ring.ids;
    if (ids.size() < 2) continue;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const int u = ids[k];
      const int w = ids[k + 1 < ids.size() ? k + 1 : 0];
      add_sweep_item(items, u, w, group, k > 0);
    }
  }
}

// What a pair of one polygon's edges (items i and j, numbered within the polygon) says:
// touching points to insert, or a proper crossing kept when it is the first (see below).
template <Kernel K>
void relate_own_edges(const std::vector<typename K::Point>& pts, const SweepItem& a, const SweepItem& b, int i, int j,
                      EdgeInsertions& inserted, std::pair<int, int>& crossing) {
  if (a.lo == b.lo && a.hi == b.hi) return;  // identical as sets: allowed [MK89 §2.2]
  const auto rel = relate_segments_by_id<K>(pts, a.lo, a.hi, b.lo, b.hi);
  if (rel.proper_crossing) {
    const std::pair<int, int> c{std::max(i, j), std::min(i, j)};
    if (crossing.first < 0 || c < crossing) crossing = c;
    return;
  }
  if (rel.c_inside_ab) inserted.add(i, b.lo);
  if (rel.d_inside_ab) inserted.add(i, b.hi);
  if (rel.a_inside_cd) inserted.add(j, a.lo);
  if (rel.b_inside_cd) inserted.add(j, a.hi);
}

// Throws the error for a proper crossing of a polygon's own edges (item numbers within the
// polygon): of the proper crossings, the one met first walking the rings, the first edge (in
// input order) that crosses an earlier one, and the earliest of those, whatever order the
// search found them in.
inline void throw_own_crossing(const std::vector<IdRing>& rings, std::pair<int, int> crossing, const char* poly_name) {
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
                      std::string("polygon ") + poly_name + ": " + edge_name(first) + " crosses " + edge_name(second) +
                          "; edges of a polygon may touch but must not cross");
}

// Inserts into the rings the points found on their edges (by item number within the polygon).
inline void insert_touching_points(std::vector<IdRing>& rings, EdgeInsertions& inserted, int num_items) {
  if (inserted.empty()) return;
  inserted.group(num_items);
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

// Inserts the points of one polygon that touch its own edges (orientable -> vertex-complete)
// and rejects proper crossings.
template <Kernel K>
void make_vertex_complete(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                          std::vector<IdRing>& rings, const char* poly_name, PairSearch search, unsigned threads = 1) {
  std::vector<SweepItem> items;
  add_ring_items(rings, 0, items);
  // Per part of the pair search (see CandidatePairs): points of the polygon on its own
  // edges, by edge index, and the first proper crossing.
  CandidatePairs<K> pairs(pts, x_rank, items, false, search, threads);
  struct Found {
    EdgeInsertions inserted;
    std::pair<int, int> crossing{-1, -1};
  };
  std::vector<Found> found(pairs.parts());
  run_tasks(threads_for(items.size(), threads), pairs.parts(), [&](std::size_t part) {
    Found& out = found[part];
    pairs.for_each_in_part(part, [&](int i, int j) { relate_own_edges<K>(pts, items[i], items[j], i, j, out.inserted, out.crossing); });
  });
  EdgeInsertions inserted;
  std::pair<int, int> crossing{-1, -1};
  for (Found& f : found) {
    if (f.crossing.first >= 0 && (crossing.first < 0 || f.crossing < crossing)) crossing = f.crossing;
    inserted.append(std::move(f.inserted));
  }
  if (crossing.first >= 0) throw_own_crossing(rings, crossing, poly_name);
  insert_touching_points(rings, inserted, static_cast<int>(items.size()));
}

// Both polygons made vertex-complete by one pair search over the edges of both, which also
// finds what step 3 looks for, the crossings and touching points between A and B: kept in
// arr.early when no point had to be inserted (every edge then is one of step 3's), dropped
// otherwise (step 3 then searches the vertex-complete edges). One search instead of three:
// the chains of every edge are made once. The errors are those of make_vertex_complete, A's
// first.
template <Kernel K>
void make_both_vertex_complete(Arrangement<K>& arr, std::array<std::vector<IdRing>, 2>& rings, PairSearch search,
                               unsigned threads) {
  const auto& pts = arr.points;
  // The items, A's then B's, each polygon's made on its own thread into an array not zeroed
  // first.
  std::array<int, 2> num_items{0, 0};
  for (int g = 0; g < 2; ++g) {
    for (const auto& ring : rings[g]) num_items[g] += ring.ids.size() < 2 ? 0 : static_cast<int>(ring.ids.size());
  }
  const int na = num_items[0];
  const std::array<int, 2> first_item{0, na};
  const auto item_array = std::make_unique_for_overwrite<SweepItem[]>(static_cast<std::size_t>(na + num_items[1]));
  run_tasks(threads_for(static_cast<std::size_t>(na + num_items[1]), threads), 2, [&](std::size_t g) {
    SweepItem* out = item_array.get() + first_item[g];
    for (const auto& ring : rings[g]) {
      const auto& ids = ring.ids;
      if (ids.size() < 2) continue;
      for (std::size_t k = 0; k < ids.size(); ++k, ++out) {
        const int u = ids[k];
        const int w = ids[k + 1 < ids.size() ? k + 1 : 0];
        out->lo = std::min(u, w);
        out->hi = std::max(u, w);
        out->group = static_cast<int>(g);
        out->forward = u < w;
        out->continues = k > 0;
      }
    }
  });
  const std::span<const SweepItem> items(item_array.get(), static_cast<std::size_t>(na + num_items[1]));
  // Pairs of one polygon's edges are left out when a sweep finds that its edges meet only at
  // shared ends (nothing to insert, nothing crossing), tried when their boxes would make
  // many pairs (a star's spikes: millions, against a sweep's n log n).
  bool bipartite = false;
  int clean = -1;  // whether each polygon's edges meet only at shared ends: -1 not known yet
  bool trial = false;  // boxes first, within a budget of merges, then the sweep
  const std::array<std::span<const SweepItem>, 2> own{items.subspan(0, static_cast<std::size_t>(na)), items.subspan(static_cast<std::size_t>(na))};
  const auto find_clean = [&] {
    std::array<bool, 2> each{false, false};
    run_tasks(threads_for(items.size(), threads), 2, [&](std::size_t g) { each[g] = edges_meet_only_at_ends<K>(pts, own[g]); });
    clean = each[0] && each[1] ? 1 : 0;
  };
  if constexpr (std::is_same_v<typename K::Point, Point>) {
    constexpr double kSweepFrom = 32;  // box pairs per edge
    const auto many = [&](int g) {
      return own[g].size() >= 64 && estimated_box_pairs<K>(pts, own[g]) > kSweepFrom * static_cast<double>(own[g].size());
    };
    if (search != PairSearch::all_pairs && many(0) && many(1)) {
      find_clean();
      bipartite = clean == 1;
    }
    if constexpr (K::is_exact) trial = tries_boxes_first<K>(pts, items, search);
  }
  struct Found {
    std::array<EdgeInsertions, 2> inserted;
    std::array<std::pair<int, int>, 2> crossing{{{-1, -1}, {-1, -1}}};
    typename EarlyIntersections<typename K::Vertex>::Part early;
  };
  // Relates items i and j (either order) into `out`.
  const auto relate = [&](Found& out, int i, int j) {
    if (i > j) std::swap(i, j);  // A's items come first
    const SweepItem& a = items[i];
    const SweepItem& b = items[j];
    if (a.group == b.group) {
      const int g = a.group;
      relate_own_edges<K>(pts, a, b, i - first_item[g], j - first_item[g], out.inserted[g], out.crossing[g]);
      return;
    }
    // An edge of A and one of B, as step 3 relates them.
    const int jb = j - na;
    relate_edges_across<K>(
        pts, a.lo, a.hi, b.lo, b.hi,
        [&] {
          auto& c = out.early.crossings.emplace_back();
          c.a = i;
          c.b = jb;
          c.vertex = K::crossing(pts[a.lo], pts[a.hi], pts[b.lo], pts[b.hi]);
        },
        [&](int p) { out.early.inserted[0].emplace_back(i, p); }, [&](int p) { out.early.inserted[1].emplace_back(jb, p); });
  };
  std::vector<Found> found;
  // The search by boxes, stopped after `merges` merges of chains when not negative; whether
  // it finished.
  const auto search_boxes = [&](std::int64_t merges) {
    CandidatePairs<K> pairs(pts, arr.x_rank, items, bipartite, search, threads);
    if (merges >= 0) pairs.limit_merges(merges);
    found.assign(pairs.parts(), Found{});
    run_tasks(threads_for(items.size(), threads), pairs.parts(), [&](std::size_t part) {
      Found& out = found[part];
      pairs.for_each_in_part(part, [&](int i, int j) { relate(out, i, j); });
    });
    return !pairs.exhausted();
  };
  bool searched = false;  // `found` holds every pair's findings
  if constexpr (std::is_same_v<typename K::Point, Point> && K::is_exact) {
    // Where the chains' boxes overlap many others, the boxes are tried within a budget of
    // merges; when it runs out and each polygon meets itself only at shared ends, the sweep
    // over both (core/red_blue.hpp) gives the pairs that meet, at O((n + k) log n).
    if (search == PairSearch::red_blue || trial) {
      searched = search != PairSearch::red_blue && search_boxes(merge_budget(items.size()));
      if (!searched && clean < 0) find_clean();
      if (!searched && clean == 1) {
        relate_red_blue_pairs<K>(pts, items, threads, found, relate);
        searched = true;
      }
    }
  }
  if (!searched) search_boxes(-1);
  std::array<EdgeInsertions, 2> inserted;
  std::array<std::pair<int, int>, 2> crossing{{{-1, -1}, {-1, -1}}};
  for (Found& f : found) {
    for (int g = 0; g < 2; ++g) {
      if (f.crossing[g].first >= 0 && (crossing[g].first < 0 || f.crossing[g] < crossing[g])) crossing[g] = f.crossing[g];
      inserted[g].append(std::move(f.inserted[g]));
    }
  }
  for (int g = 0; g < 2; ++g) {
    if (crossing[g].first >= 0) throw_own_crossing(rings[g], crossing[g], g == 0 ? "A" : "B");
  }
  arr.early = {};
  if (inserted[0].empty() && inserted[1].empty()) {
    arr.early.found = true;
    arr.early.parts.reserve(found.size());
    for (Found& f : found) arr.early.parts.push_back(std::move(f.early));
    return;
  }
  for (int g = 0; g < 2; ++g) insert_touching_points(rings[g], inserted[g], num_items[g]);
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
// the distinct x values), setting id_of (input number -> id_base + index in points) for
// every point read. A binary min-heap of run indices keyed by the runs' current points;
// sifting moves 4-byte indices into a hole instead of swapping runs.
template <Kernel K>
void merge_runs(std::vector<PointRun<typename K::Point>>& runs, std::vector<typename K::Point>& points,
                std::vector<int>& x_rank, std::vector<int>& id_of, int id_base = 0) {
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
    id_of[run.ring_ref + run.pos] = id_base + append_distinct<K>(points, x_rank, run.key);
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

// Below this many input points the runs are merged on one thread: handing half to another
// costs more than it saves.
inline constexpr int kHalvesFrom = 1 << 16;

// merge_runs on two threads: each run is cut at a pivot point near the median (of samples
// taken along the runs, one per 512 points), the parts below it merged on this thread into
// `points` and the others on a second into their own arrays, then appended. The upper
// half's ids are written as if every lower point were distinct (its first id the number of
// lower input points) and moved down afterwards only when the lower half held repeated
// points, since moving them is a scattered pass over half of id_of; its x-ranks, a
// sequential pass, are moved up while appending. Points equal to the pivot all fall in the
// upper half, so repeated points never straddle the cut.
template <Kernel K>
void merge_runs_in_halves(std::vector<PointRun<typename K::Point>>& runs, std::vector<typename K::Point>& points,
                          std::vector<int>& x_rank, std::vector<int>& id_of) {
  using P = typename K::Point;
  const auto less = [](const P& u, const P& w) { return compare_xy<K>(u, w) == Sign::negative; };
  const auto length = [](const PointRun<P>& r) { return (r.end - r.pos) * r.step; };
  const auto at = [](const PointRun<P>& r, int i) -> const P& { return r.ring[r.pos + i * r.step]; };
  std::vector<P> samples;
  for (const auto& r : runs) {
    for (int i = 0; i < length(r); i += 512) samples.push_back(at(r, i));
  }
  const auto middle = samples.begin() + static_cast<std::ptrdiff_t>(samples.size() / 2);
  std::nth_element(samples.begin(), middle, samples.end(), less);
  const P pivot = *middle;
  std::vector<PointRun<P>> lower, upper;
  int lower_count = 0;
  for (const auto& r : runs) {
    // The run's first c points (in its reading order) are below the pivot.
    int lo = 0, hi = length(r);
    while (lo < hi) {
      const int mid = lo + (hi - lo) / 2;
      if (less(at(r, mid), pivot)) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    const int cut = r.pos + lo * r.step;
    if (lo > 0) lower.push_back({r.key, r.ring, r.ring_ref, r.pos, cut, r.step});
    if (lo < length(r)) upper.push_back({r.ring[cut], r.ring, r.ring_ref, cut, r.end, r.step});
    lower_count += lo;
  }
  const std::vector<PointRun<P>> upper_start = upper;  // merge_runs moves the runs along
  std::size_t all = 0;
  for (const auto& r : runs) all += static_cast<std::size_t>(length(r));
  points.reserve(points.size() + all);
  x_rank.reserve(x_rank.size() + all);
  std::vector<P> upper_points;
  std::vector<int> upper_ranks;
  run_tasks(2, 2, [&](std::size_t half) {
    if (half == 0) {
      merge_runs<K>(lower, points, x_rank, id_of);
    } else {
      merge_runs<K>(upper, upper_points, upper_ranks, id_of, lower_count);
    }
  });
  if (upper_points.empty()) return;
  const int repeated = lower_count - static_cast<int>(points.size());
  if (repeated != 0) {
    for (const auto& r : upper_start) {
      for (int i = 0; i < length(r); ++i) id_of[r.ring_ref + r.pos + i * r.step] -= repeated;
    }
  }
  const int rank_base =
      points.empty() ? 0 : x_rank.back() + (K::compare_x(points.back(), upper_points.front()) != Sign::zero ? 1 : 0);
  points.insert(points.end(), upper_points.begin(), upper_points.end());
  const std::size_t first = x_rank.size();
  x_rank.resize(first + upper_ranks.size());
  for (std::size_t i = 0; i < upper_ranks.size(); ++i) x_rank[first + i] = rank_base + upper_ranks[i];
}

// Numbers the distinct input points of A and B in lexicographic order by merging the rings'
// monotone runs, which are few on smooth or convex rings (a ring has at least two): each
// point then costs about log2(runs) comparisons instead of a sort's log2(n). Fills `points`
// (distinct, sorted), their x-ranks and id_of (input number, counted polygon after polygon
// and ring after ring -> id). Returns false, having done nothing, when there are more than
// `max_runs` runs. With two threads or more and enough points, the points below a pivot
// (about the median) and the others are merged on two threads (merge_runs_in_halves).
template <Kernel K>
bool number_points_by_runs(const std::array<const BasicPolygon<typename K::Point>*, 2>& in, std::size_t max_runs,
                           std::vector<typename K::Point>& points, std::vector<int>& x_rank, std::vector<int>& id_of,
                           unsigned threads = 1) {
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
  if (threads_for(static_cast<std::size_t>(ref), threads) >= 2 && ref >= kHalvesFrom) {
    merge_runs_in_halves<K>(runs, points, x_rank, id_of);
  } else {
    merge_runs<K>(runs, points, x_rank, id_of);
  }
  return true;
}

// Gives every distinct input point of A and B (`total` vertices in all) an id in
// lexicographic order: fills `points` (distinct, sorted), their x-ranks and id_of (input
// number, counted polygon after polygon and ring after ring -> id).
template <Kernel K>
void number_points(const std::array<const BasicPolygon<typename K::Point>*, 2>& in, std::size_t total, unsigned threads,
                   std::vector<typename K::Point>& points, std::vector<int>& x_rank, std::vector<int>& id_of) {
  points.reserve(total);
  // Rings of smooth or convex shapes consist of a few long monotone runs, merged directly;
  // otherwise the points themselves (not indices into the rings) are sorted. The second
  // member numbers the vertices polygon after polygon, ring after ring.
  constexpr std::size_t max_runs = 32;
  if (!number_points_by_runs<K>(in, max_runs, points, x_rank, id_of, threads)) {
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
    x_rank.reserve(total);
    const auto take = [&](const std::pair<typename K::Point, int>& e) {
      id_of[e.second] = append_distinct<K>(points, x_rank, e.first);
    };
    // Points of doubles, which every kernel over them compares as doubles, are sorted by
    // their bits (a radix sort); others by the kernel's comparison.
    const auto sort_range = [&](auto first, auto last) {
      if constexpr (std::is_same_v<typename K::Point, Point>) {
        sort_points_lexicographic(std::span(first, last));
      } else {
        std::sort(first, last, less);
      }
    };
    if (threads_for(total, threads) < 2) {
      sort_range(sorted.begin(), sorted.end());
      for (const auto& e : sorted) take(e);
    } else {
      const auto mid = sorted.begin() + static_cast<std::ptrdiff_t>(total / 2);
      run_tasks(2, 2, [&](std::size_t half) {
        if (half == 0) {
          sort_range(sorted.begin(), mid);
        } else {
          sort_range(mid, sorted.end());
        }
      });
      auto i = sorted.begin(), j = mid;
      while (i != mid && j != sorted.end()) take(less(*j, *i) ? *j++ : *i++);
      for (; i != mid; ++i) take(*i);
      for (; j != sorted.end(); ++j) take(*j);
    }
  }
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
  detail::number_points<K>(in, total, threads, arr.points, arr.x_rank, id_of);

  // Each polygon's rings as point ids (on two threads when there are several).
  std::array<std::size_t, 2> first_ref{0, 0};  // input number of each polygon's first vertex
  for (const auto& ring : a.rings) first_ref[1] += ring.size();
  const unsigned per_polygon = threads_for(total, threads) > 1 ? (threads + 1) / 2 : 1;
  std::array<std::vector<detail::IdRing>, 2> rings;
  run_tasks(threads_for(total, threads), 2, [&](std::size_t p) {
    std::size_t ref = first_ref[p];
    rings[p].resize(in[p]->rings.size());
    for (std::size_t r = 0; r < rings[p].size(); ++r) {
      auto& ring = rings[p][r];
      ring.ids.reserve(in[p]->rings[r].size());
      ring.input_index.reserve(in[p]->rings[r].size());
      for (std::size_t v = 0; v < in[p]->rings[r].size(); ++v, ++ref) {
        const int id = id_of[ref];
        if (!ring.ids.empty() && ring.ids.back() == id) continue;  // duplicate consecutive vertex
        ring.ids.push_back(id);
        ring.input_index.push_back(static_cast<int>(v));
      }
      while (ring.ids.size() > 1 && ring.ids.back() == ring.ids.front()) {  // closing vertex repeated
        ring.ids.pop_back();
        ring.input_index.pop_back();
      }
    }
  });
  // Whether the rings' vertices are distinct points, all of them: distinct points are never
  // more than the vertices kept, and as many only then.
  const auto ring_ids = [&](std::size_t p) {
    std::size_t n = 0;
    for (const auto& ring : rings[p]) n += ring.ids.size();
    return n;
  };
  const std::array<std::size_t, 2> kept{ring_ids(0), ring_ids(1)};
  const bool distinct = arr.points.size() == kept[0] + kept[1];
  // Vertex-complete: exact kernels search both polygons at once and keep what step 3 would
  // find (make_both_vertex_complete); the others (whose crossings may fail, which step 3
  // reports after these errors) search each polygon on its own.
  if constexpr (K::is_exact) {
    detail::make_both_vertex_complete<K>(arr, rings, search, threads);
  } else {
    run_tasks(threads_for(total, threads), 2, [&](std::size_t p) {
      detail::make_vertex_complete<K>(arr.points, arr.x_rank, rings[p], p == 0 ? "A" : "B", search, per_polygon);
    });
  }
  // Split into cycles, each polygon with its own marks per point. A polygon whose rings hold
  // distinct points, none inserted by vertex-completeness, has its rings as cycles already.
  std::array<bool, 2> whole{true, true};  // every ring of two or more points one cycle as it was
  run_tasks(threads_for(total, threads), 2, [&](std::size_t p) {
    PreparedPolygon& out = arr.polygon[p];
    out.type = in[p]->type;
    if (distinct && ring_ids(p) == kept[p]) {
      for (std::size_t r = 0; r < rings[p].size(); ++r) {
        detail::IdRing& ring = rings[p][r];
        if (ring.ids.size() == 1) out.point_cycles.push_back(ring.ids[0]);
        if (ring.ids.size() < 2) continue;
        out.origins.push_back({static_cast<int>(r), ring.input_index[0]});
        out.cycles.push_back(std::move(ring.ids));
      }
      return;
    }
    std::vector<int> where(arr.points.size(), -1);
    for (std::size_t r = 0; r < rings[p].size(); ++r) {
      if (rings[p][r].ids.empty()) continue;
      if (!detail::split_into_cycles(std::move(rings[p][r]), static_cast<int>(r), where, out)) whole[p] = false;
    }
  });
  // Step 3's findings hold when every ring stayed whole: each cycle is then the ring it
  // was, and its first point tells step 3 whether step 1 turned it.
  if (arr.early.found) {
    if (whole[0] && whole[1]) {
      for (std::size_t p = 0; p < 2; ++p) {
        for (const auto& cycle : arr.polygon[p].cycles) arr.early.ring_start[p].push_back(cycle[0]);
      }
    } else {
      arr.early = {};
    }
  }
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
