// Winding numbers of a set of non-crossing edges at points just beside an edge: one query by
// a scan of the edges (of those near it in x, once indexed), many queries in one plane
// sweep. [MK89 §4.3] (locating one vertex per ring without a scan of the other polygon)
// [MK89 §3.2] (point location by a ray)
// Preconditions: point ids follow lexicographic order; x_rank[id] is the rank of the point's
// x among the distinct x values; for the sweep, the edges meet only at shared endpoints or
// coincide as sets (the edges of one vertex-complete polygon); single queries take any edges.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <span>
#include <utility>
#include <vector>

#include "core/arrangement.hpp"
#include "core/buckets.hpp"
#include "core/error.hpp"
#include "core/sorting.hpp"
#include "predicates/ray.hpp"

namespace mk {

// A point just `side` of v -> t near v (see vertical_ray_crossing).
struct LocatorQuery {
  int v = -1;
  int t = -1;
  Side side = Side::left;
};

namespace detail {

// A sequence of ints kept in an order that a caller-given comparison defines (the order of
// edges crossing a sweep line), in sorted blocks of at most 2 * kBlock: a balanced tree's
// O(log n) comparisons per operation, without a node allocation per element and with
// neighbours next to each other in memory.
class BlockedOrder {
 public:
  // Inserts e (not present); returns the element after it, or -1.
  template <class Less>
  int insert(int e, Less&& less) {
    if (blocks_.empty()) {
      blocks_.push_back({e});
      finger_ = {0, 0};
      return -1;
    }
    auto [b, i] = find(e, less);
    if (b == blocks_.size()) {  // after everything: at the end of the last block
      b = blocks_.size() - 1;
      i = blocks_[b].size();
    }
    auto& block = blocks_[b];
    block.insert(block.begin() + static_cast<std::ptrdiff_t>(i), e);
    const int after = at_or_after(b, i + 1);
    finger_ = {b, i};
    if (block.size() > 2 * kBlock) {
      std::vector<int> upper(block.begin() + kBlock, block.end());
      block.resize(kBlock);
      blocks_.insert(blocks_.begin() + static_cast<std::ptrdiff_t>(b) + 1, std::move(upper));
      if (i >= kBlock) finger_ = {b + 1, i - kBlock};
    }
    return after;
  }

  // Removes e, which is present. Where the comparison does not find it there (inconsistent
  // inexact predicates: a naive kernel's products overflowed, say), throws KernelFailure
  // rather than remove another element or read past the end.
  template <class Less>
  void erase(int e, Less&& less) {
    const auto [b, i] = find_present(e, less);
    auto& block = blocks_[b];
    block.erase(block.begin() + static_cast<std::ptrdiff_t>(i));
    finger_ = {b, i};
    if (block.empty()) {
      blocks_.erase(blocks_.begin() + static_cast<std::ptrdiff_t>(b));
      finger_ = {0, 0};
    }
  }

  // The element after e, which is present, or -1 when e is the last. Throws KernelFailure
  // where the comparison does not find e (inconsistent inexact predicates), as erase does.
  template <class Less>
  int next(int e, Less&& less) {
    const auto [b, i] = find_present(e, less);
    finger_ = {b, i};
    return at_or_after(b, i + 1);
  }

  // The last element x with less(x, key) and the first without, each -1 when there is none.
  template <class Key, class Less>
  std::pair<int, int> around(const Key& key, Less&& less) {
    const auto [b, i] = find(key, less);
    int before = -1, after = -1;
    if (b < blocks_.size()) {
      finger_ = {b, i};
      after = at_or_after(b, i);
      if (i > 0) {
        before = blocks_[b][i - 1];
      } else if (b > 0) {
        before = blocks_[b - 1].back();
      }
    } else if (!blocks_.empty()) {
      before = blocks_.back().back();
    }
    return {before, after};
  }

  // The first element x with !less(x, key), or -1.
  template <class Key, class Less>
  int lower_bound(const Key& key, Less&& less) {
    const auto [b, i] = find(key, less);
    if (b == blocks_.size()) return -1;
    finger_ = {b, i};
    return at_or_after(b, i);
  }

 private:
  static constexpr std::size_t kBlock = 64;
  static constexpr std::size_t kNear = 4;  // steps tried from the finger before a search

  struct Place {
    std::size_t block, index;
  };

  // The element at index i of block b (b a block), or the first of the next block when i is
  // past b's end; -1 when there is none.
  int at_or_after(std::size_t b, std::size_t i) const {
    if (i < blocks_[b].size()) return blocks_[b][i];
    return b + 1 < blocks_.size() ? blocks_[b + 1].front() : -1;
  }

  // The place of e, which is present. Where the comparison does not find it there
  // (inconsistent inexact predicates), throws KernelFailure rather than touch another element
  // or read past the end.
  template <class Less>
  Place find_present(int e, Less& less) const {
    const Place at = find(e, less);
    if (at.block >= blocks_.size() || at.index >= blocks_[at.block].size() || blocks_[at.block][at.index] != e) {
      throw KernelFailure("the sweep's order of edges is inconsistent (inexact predicates)");
    }
    return at;
  }

  // The lower bound of key as (block, index): the first block whose last element is not
  // before key, and the position in it (blocks_.size() when every element is before key).
  // Sweeps move little between operations, so the place of the last operation is tried
  // first, a few steps either way, before a binary search.
  template <class Key, class Less>
  Place find(const Key& key, Less& less) const {
    if (finger_.block < blocks_.size()) {
      const auto& block = blocks_[finger_.block];
      std::size_t i = std::min(finger_.index, block.size());
      std::size_t steps = 0;
      while (i < block.size() && steps < kNear && less(block[i], key)) ++i, ++steps;
      while (i > 0 && steps < kNear && !less(block[i - 1], key)) --i, ++steps;
      const bool before_ok = i > 0 ? less(block[i - 1], key)
                                   : (finger_.block == 0 || less(blocks_[finger_.block - 1].back(), key));
      const bool at_ok = i < block.size() ? !less(block[i], key) : finger_.block + 1 == blocks_.size();
      if (before_ok && at_ok) return {i < block.size() ? finger_.block : blocks_.size(), i};
    }
    std::size_t lo = 0, hi = blocks_.size();
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (less(blocks_[mid].back(), key)) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    if (lo == blocks_.size()) return {lo, 0};
    const auto& block = blocks_[lo];
    return {lo, static_cast<std::size_t>(std::lower_bound(block.begin(), block.end(), key, less) - block.begin())};
  }

  std::vector<std::vector<int>> blocks_;
  Place finger_{0, 0};
};

// Whether edge a (ends la < ha, point ids) lies below edge b (lb < hb) on a sweep line
// through points in lexicographic order that both cross, neither crossing the other: by the
// orientation of the later-starting edge's start against the other edge, or of their ends
// when they start together. Coinciding edges (or inconsistent inexact predicates) are
// ordered by `a_first`.
template <Kernel K>
bool edge_is_below(const std::vector<typename K::Point>& p, int la, int ha, int lb, int hb, bool a_first) {
  Sign s = Sign::zero;
  if (la == lb) {
    s = K::orient2d(p[la], p[ha], p[hb]);  // positive: b leaves the shared end above a
  } else if (la < lb) {
    s = K::orient2d(p[la], p[ha], p[lb]);  // b starts above a, or below it
    if (s == Sign::zero) s = K::orient2d(p[la], p[ha], p[hb]);
  } else {
    s = K::orient2d(p[lb], p[hb], p[la]);
    if (s == Sign::zero) s = K::orient2d(p[lb], p[hb], p[ha]);
    s = s == Sign::positive ? Sign::negative : (s == Sign::negative ? Sign::positive : Sign::zero);
  }
  if (s == Sign::zero) return a_first;
  return s == Sign::positive;
}

}  // namespace detail

template <Kernel K>
class WindingLocator {
 public:
  // Edges src -> dst as point ids, viewed, not copied: they must outlive the locator.
  // `queries` is how many single queries are expected; it is kept for callers of the
  // one-query interface, which scans the edges: batches go through windings().
  WindingLocator(const Arrangement<K>& arr, std::span<const Edge> edges, std::size_t queries = 0)
      : arr_(arr), edges_(edges) {
    (void)queries;
  }

  // Makes the single queries below read only the edges whose x-range may hold the query's
  // x: the edges in buckets of x-ranks, an edge spanning more than kSpan buckets in a list
  // read by every query (so no edge is held more than kSpan times, and no query reads more
  // than a full scan would). For callers with many single queries over edges that cross, which
  // the sweep of windings() cannot take (the fill operations' rings); the answers are those
  // of the full scan, summed over the same edges.
  void index_for_scans() {
    const std::size_t m = edges_.size();
    ranks_ = arr_.x_rank.empty() ? 1 : static_cast<std::size_t>(arr_.x_rank.back()) + 1;
    // Buckets as wide as an edge on average: most edges in one or two.
    std::size_t spans = 0;
    for (const Edge& e : edges_) spans += static_cast<std::size_t>(std::abs(arr_.x_rank[e.src] - arr_.x_rank[e.dst]));
    const std::size_t width = std::max<std::size_t>(1, spans / std::max<std::size_t>(1, m));
    buckets_ = std::clamp<std::size_t>(ranks_ / width, 1, std::max<std::size_t>(1, m));
    bucket_begin_.assign(buckets_ + 1, 0);
    long_edges_.clear();
    const auto span_of = [&](const Edge& e) {
      const auto [ra, rb] = std::minmax(arr_.x_rank[e.src], arr_.x_rank[e.dst]);
      return std::pair(bucket_of(ra), bucket_of(rb));
    };
    for (const Edge& e : edges_) {
      const auto [b0, b1] = span_of(e);
      if (b1 - b0 >= kSpan) continue;
      for (std::size_t b = b0; b <= b1; ++b) ++bucket_begin_[b + 1];
    }
    for (std::size_t b = 1; b <= buckets_; ++b) bucket_begin_[b] += bucket_begin_[b - 1];
    bucket_edges_.resize(bucket_begin_.back());
    std::vector<std::size_t> fill(bucket_begin_.begin(), bucket_begin_.end() - 1);
    for (std::size_t i = 0; i < m; ++i) {
      const auto [b0, b1] = span_of(edges_[i]);
      if (b1 - b0 >= kSpan) {
        long_edges_.push_back(static_cast<int>(i));
        continue;
      }
      for (std::size_t b = b0; b <= b1; ++b) bucket_edges_[fill[b]++] = static_cast<int>(i);
    }
    indexed_ = true;
  }

  // Winding number at the point just `side` of v -> t near v: a scan of every edge.
  int winding(int v, int t, Side side) const {
    int wind = 0;
    scan(v, t, side, [&](int c) { wind += c; });
    return wind;
  }

  // Number of edges crossing the vertical ray from that point (their parity counts the
  // cycles around it): a scan of every edge.
  int crossings(int v, int t, Side side) const {
    int count = 0;
    scan(v, t, side, [&](int c) { count += c != 0; });
    return count;
  }

  // winding() of every query, in O((edges + queries) log edges) for the batch.
  std::vector<int> windings(std::span<const LocatorQuery> queries) const {
    return answer(queries, false);
  }
  // crossings() of every query, or any count of the same parity (a ray other than the
  // vertical one may cross another number of edges, never of another parity).
  std::vector<int> crossing_parities(std::span<const LocatorQuery> queries) const {
    return answer(queries, true);
  }

 private:
  // Up to this many queries, each scans the edges: a sweep costs a few scans.
  static constexpr std::size_t kScanQueries = 8;

  // Calls f(vertical_ray_crossing(...)) for every edge whose x-range contains v's x.
  template <class F>
  void scan(int v, int t, Side side, F&& f) const {
    const int r = arr_.x_rank[v];
    const auto visit = [&](const Edge& edge) {
      const int ra = arr_.x_rank[edge.src];
      const int rb = arr_.x_rank[edge.dst];
      if (r < std::min(ra, rb) || r > std::max(ra, rb)) return;
      f(vertical_ray_crossing<K>(arr_.points[v], arr_.points[t], side, arr_.points[edge.src], arr_.points[edge.dst]));
    };
    if (!indexed_) {
      for (const Edge& edge : edges_) visit(edge);
      return;
    }
    const std::size_t b = bucket_of(r);
    for (std::size_t i = bucket_begin_[b]; i < bucket_begin_[b + 1]; ++i) visit(edges_[bucket_edges_[i]]);
    for (const int e : long_edges_) visit(edges_[e]);
  }

  static constexpr std::size_t kSpan = 8;  // buckets an edge may be held in (index_for_scans)
  std::size_t bucket_of(int rank) const { return static_cast<std::size_t>(rank) * buckets_ / ranks_; }

  std::vector<int> answer(std::span<const LocatorQuery> queries, bool parity) const {
    std::vector<int> out(queries.size(), 0);
    if (queries.size() <= kScanQueries) {
      for (std::size_t i = 0; i < queries.size(); ++i) {
        const LocatorQuery& q = queries[i];
        out[i] = parity ? crossings(q.v, q.t, q.side) : winding(q.v, q.t, q.side);
      }
      return out;
    }
    sweep(queries, parity, out);
    return out;
  }

  int lo(int e) const { return std::min(edges_[e].src, edges_[e].dst); }
  int hi(int e) const { return std::max(edges_[e].src, edges_[e].dst); }

  // The order of the edges crossing the sweep line, from below: the line passes through a
  // point in lexicographic order (as if sheared by an infinitesimal angle), so vertical
  // edges cross it like any other and every edge it crosses has lo before it and hi after.
  // Edges crossing the line never cross each other, so their order is fixed while they are
  // in it; coinciding edges are ordered by index.
  struct Below {
    using is_transparent = void;
    const WindingLocator* loc;
    bool operator()(int a, int b) const { return loc->is_below(a, b); }
    // An edge against a query point: e below q, and q below e.
    bool operator()(int e, const LocatorQuery& q) const { return loc->side_of(e, q) > 0; }
    bool operator()(const LocatorQuery& q, int e) const { return loc->side_of(e, q) < 0; }
  };

  // Sign of orient(lo, hi, q): positive when q lies above edge e.
  int side_of(int e, const LocatorQuery& q) const {
    const auto& p = arr_.points;
    const int l = lo(e), h = hi(e);
    return orient_beside<K>(p[l], p[h], p[q.v], p[q.t], q.side, q.v == l || q.v == h);
  }

  bool is_below(int a, int b) const {
    return a != b && detail::edge_is_below<K>(arr_.points, lo(a), hi(a), lo(b), hi(b), a < b);
  }

  // One sweep over the points in lexicographic order. Each edge, when it enters the line,
  // gets the value of the ray count just below it: its own contribution plus the value of
  // the edge just above it. A query is answered by the first edge above its point, between
  // the two points of the sweep it falls between: just after v when t comes after v, else
  // just before.
  void sweep(std::span<const LocatorQuery> queries, bool parity, std::vector<int>& out) const {
    const int n_points = arr_.num_points();
    const int m = static_cast<int>(edges_.size());
    // Edges by lo and by hi, queries by the point after which they are asked (counting sorts).
    const std::size_t keys = static_cast<std::size_t>(n_points) + 1;
    const Buckets by_lo = bucket_by(edges_.size(), keys, [&](std::size_t e) { return lo(static_cast<int>(e)); });
    const Buckets by_hi = bucket_by(edges_.size(), keys, [&](std::size_t e) { return hi(static_cast<int>(e)); });
    // Position v (after v) or v - 1 (before v); -1 (before every point) is bucket 0 by the +1.
    const Buckets by_position = bucket_by(queries.size(), keys, [&](std::size_t i) {
      const LocatorQuery& q = queries[i];
      return (q.t > q.v ? q.v : q.v - 1) + 1;
    });

    detail::BlockedOrder line;
    const Below below_of{this};
    std::vector<int> below(static_cast<std::size_t>(m), 0);  // ray count just below each edge
    const auto contribution = [&](int e) { return parity ? 1 : (edges_[e].src > edges_[e].dst ? 1 : -1); };
    std::vector<int> entering;
    for (int p = 0; p < n_points; ++p) {
      for (int i = by_hi.begin[p]; i < by_hi.begin[p + 1]; ++i) line.erase(by_hi.order[i], below_of);
      // Edges entering at p lie next to each other on the line: inserted from the top, each
      // finds the edge just above it already there, and takes its value from it.
      entering.assign(by_lo.order.begin() + by_lo.begin[p], by_lo.order.begin() + by_lo.begin[p + 1]);
      if (entering.size() > 1) sort_by_predicates<K>(entering.begin(), entering.end(), [&](int a, int b) { return is_below(b, a); });
      for (const int e : entering) {
        const int up = line.insert(e, below_of);
        below[e] = contribution(e) + (up < 0 ? 0 : below[up]);
      }
      for (int i = by_position.begin[p + 1]; i < by_position.begin[p + 2]; ++i) {
        const int qi = by_position.order[i];
        const int e = line.lower_bound(queries[qi], below_of);  // the first edge above the point
        out[qi] = e < 0 ? 0 : below[e];
      }
    }
  }

  const Arrangement<K>& arr_;
  std::span<const Edge> edges_;
  // index_for_scans: bucket b holds bucket_edges_[bucket_begin_[b], bucket_begin_[b + 1]).
  bool indexed_ = false;
  std::size_t ranks_ = 1, buckets_ = 1;
  std::vector<std::size_t> bucket_begin_;
  std::vector<int> bucket_edges_;
  std::vector<int> long_edges_;
};

}  // namespace mk
