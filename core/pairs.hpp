// Candidate pairs of segments whose bounding boxes overlap, found through monotone chains.
// [MK89 §4.3] (sub-quadratic intersection finding; the all-pairs baseline is kept)
// Preconditions: point ids follow lexicographic order (see Arrangement::points); the items
// of one ring come consecutively, in ring order, each marked `continues` except the first.
#pragma once

#include <algorithm>
#include <numeric>
#include <vector>

#include "kernel/kernel.hpp"

namespace mk {

struct SweepItem {
  int lo = -1;  // smaller point id (leftmost endpoint)
  int hi = -1;
  int group = 0;
  bool forward = true;     // the ring runs lo -> hi along this segment
  bool continues = false;  // the previous item is the previous segment of the same ring
};

// The item of a ring segment src -> dst.
inline SweepItem sweep_item(int src, int dst, int group, bool continues) {
  return {std::min(src, dst), std::max(src, dst), group, src < dst, continues};
}

enum class PairSearch : unsigned char { sweep, all_pairs };

namespace detail {

// A maximal run of consecutive segments of one ring that is monotone in x (lexicographic
// order: point ids increase along it, or decrease) and in y. Its bounding box is spanned by
// its two ends, and the x-ranges of its segments follow each other without overlapping
// except at shared ends: two chains are compared by merging them in x, in time linear in
// their overlap, instead of segment by segment. This is how GEOS (monotone chains) and
// Boost.Geometry (monotonic sections) avoid most pairwise tests.
struct Chain {
  int first = 0;  // range of `order` (items sorted by lo along the chain)
  int last = 0;
  int lo = 0;  // leftmost and rightmost point ids
  int hi = 0;
  int y_min = 0;  // point ids of the lowest and highest ends
  int y_max = 0;
  int group = 0;
};

}  // namespace detail

// Calls f(i, j) for every pair of items whose bounding boxes overlap (closed boxes), except
// pairs of segments of one monotone chain, which never meet but at shared ends. With
// `bipartite`, only pairs from different groups are reported. `x_rank` gives each point
// id the rank of its x among the distinct x values.
template <Kernel K, class F>
void for_each_candidate_pair(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                             const std::vector<SweepItem>& items, bool bipartite, PairSearch search, F&& f) {
  const int n = static_cast<int>(items.size());
  if (search == PairSearch::all_pairs) {
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (bipartite && items[i].group == items[j].group) continue;
        f(i, j);
      }
    }
    return;
  }
  const auto y_less = [&](int u, int w) { return K::compare_y(pts[u], pts[w]) == Sign::negative; };
  // y-direction of an item along its ring: -1, 0 (horizontal) or +1.
  const auto y_dir = [&](const SweepItem& it) {
    const Sign s = K::compare_y(pts[it.lo], pts[it.hi]);
    const int up = s == Sign::negative ? 1 : (s == Sign::positive ? -1 : 0);
    return it.forward ? up : -up;
  };

  // Cut the items into chains.
  std::vector<int> order(items.size());
  std::vector<detail::Chain> chains;
  {
    int start = 0;
    int dir = 0;
    const auto close = [&](int end) {
      detail::Chain c;
      c.first = start;
      c.last = end;
      c.group = items[start].group;
      std::iota(order.begin() + start, order.begin() + end, start);
      if (!items[start].forward) std::reverse(order.begin() + start, order.begin() + end);
      c.lo = items[order[start]].lo;
      c.hi = items[order[end - 1]].hi;
      // Monotone in y: the extreme ends are the chain's two ends.
      const int a = c.lo;
      const int b = c.hi;
      c.y_min = y_less(b, a) ? b : a;
      c.y_max = c.y_min == a ? b : a;
      chains.push_back(c);
    };
    for (int i = 0; i < n; ++i) {
      const SweepItem& it = items[i];
      const int d = y_dir(it);
      const bool joins = i > start && it.continues && it.forward == items[i - 1].forward && it.group == items[i - 1].group &&
                         (d == 0 || dir == 0 || d == dir);
      if (i > 0 && !joins) {
        close(i);
        start = i;
        dir = 0;
      }
      if (dir == 0) dir = d;
    }
    if (n > 0) close(n);
  }

  // Segment pairs of two chains whose x-ranges overlap, by merging them in x.
  const auto xr = [&](int id) { return x_rank[id]; };
  const auto y_overlap = [&](const SweepItem& a, const SweepItem& b) {
    const bool a_up = K::compare_y(pts[a.lo], pts[a.hi]) != Sign::positive;
    const bool b_up = K::compare_y(pts[b.lo], pts[b.hi]) != Sign::positive;
    const int a_min = a_up ? a.lo : a.hi;
    const int a_max = a_up ? a.hi : a.lo;
    const int b_min = b_up ? b.lo : b.hi;
    const int b_max = b_up ? b.hi : b.lo;
    return !y_less(b_max, a_min) && !y_less(a_max, b_min);
  };
  // The segments of chain x that can meet chain `other`: a chain is monotone in x and in y,
  // so those ending left of other's start, and those entirely below or above other's
  // y-range, form a prefix and a suffix of x's segments (in x order), found by binary search.
  const auto window = [&](const detail::Chain& x, const detail::Chain& other) {
    const auto first = order.begin() + x.first;
    const auto last = order.begin() + x.last;
    auto b = std::partition_point(first, last, [&](int k) { return xr(items[k].hi) < xr(other.lo); });
    auto e = std::partition_point(b, last, [&](int k) { return xr(items[k].lo) <= xr(other.hi); });
    if (y_less(x.hi, x.lo)) {  // descending in y: a segment spans y(hi) .. y(lo)
      b = std::partition_point(b, e, [&](int k) { return y_less(other.y_max, items[k].hi); });
      e = std::partition_point(b, e, [&](int k) { return !y_less(items[k].lo, other.y_min); });
    } else {  // ascending (or level): a segment spans y(lo) .. y(hi)
      b = std::partition_point(b, e, [&](int k) { return y_less(items[k].hi, other.y_min); });
      e = std::partition_point(b, e, [&](int k) { return !y_less(other.y_max, items[k].lo); });
    }
    return std::pair<int, int>(static_cast<int>(b - order.begin()), static_cast<int>(e - order.begin()));
  };
  const auto merge = [&](const detail::Chain& c, const detail::Chain& d) {
    auto [i, c_end] = window(c, d);
    auto [j, d_end] = window(d, c);
    while (i < c_end && j < d_end) {
      const SweepItem& a = items[order[i]];
      const SweepItem& b = items[order[j]];
      if (xr(a.hi) < xr(b.lo)) {
        ++i;
        continue;
      }
      if (xr(b.hi) < xr(a.lo)) {
        ++j;
        continue;
      }
      // a overlaps b in x: so may a the segments after b that start before a ends.
      for (int k = j; k < d_end && xr(items[order[k]].lo) <= xr(a.hi); ++k) {
        if (y_overlap(a, items[order[k]])) f(order[i], order[k]);
      }
      ++i;
    }
  };

  // Chain pairs whose boxes overlap: a sweep over x over the chains.
  std::vector<int> by_x(chains.size());
  std::iota(by_x.begin(), by_x.end(), 0);
  std::sort(by_x.begin(), by_x.end(), [&](int a, int b) { return chains[a].lo < chains[b].lo; });
  const int m = static_cast<int>(chains.size());
  for (int oi = 0; oi < m; ++oi) {
    const detail::Chain& c = chains[by_x[oi]];
    for (int oj = oi + 1; oj < m; ++oj) {
      const detail::Chain& d = chains[by_x[oj]];
      if (xr(d.lo) > xr(c.hi)) break;
      if (bipartite && c.group == d.group) continue;
      if (y_less(d.y_max, c.y_min) || y_less(c.y_max, d.y_min)) continue;
      merge(c, d);
    }
  }
}

}  // namespace mk
