// Candidate pairs of segments whose bounding boxes overlap, found through monotone chains:
// a sweep over x of the chains' boxes with an interval tree over y, and the segments of two
// chains paired by merging them. [MK89 §4.3] (sub-quadratic intersection finding; the
// all-pairs baseline is kept)
// Preconditions: point ids follow lexicographic order (see Arrangement::points); the items
// of one ring come consecutively, in ring order, each marked `continues` except the first.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
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

// A run of at most kMaxChain consecutive segments of one ring that all go the same way: the
// same way along the ring in lexicographic order, all rising, all falling or all level in y,
// all vertical or none. Its bounding box is spanned by its two ends, and the x-ranges of its
// segments follow each other without overlapping except at shared ends: two chains are
// compared by merging them in x, in time linear in their overlap, instead of segment by
// segment. This is how GEOS (monotone chains) and Boost.Geometry (monotonic sections) avoid
// most pairwise tests. Level and vertical segments start chains of their own, and chains
// are short, so that a chain's box stays close to its segments (the box of an L of two
// sides of a large square would overlap every smaller square inside it).
struct Chain {
  int first = 0;  // range of `order` (items sorted by lo along the chain)
  int last = 0;
  int lo = 0;  // leftmost and rightmost point ids
  int hi = 0;
  int y_min = 0;  // point ids of the lowest and highest ends
  int y_max = 0;
  int group = 0;
};

inline constexpr int kMaxChain = 256;

// The chains whose boxes are in the sweep, as an interval tree over y: a treap keyed by the
// chains' lowest y (ties by chain index), each node holding the highest y in its subtree.
// Nodes live in one array; priorities come from a hash of the chain index, so the tree's
// shape, and the order in which a query reports chains, depend on the input alone.
template <Kernel K>
class ChainTree {
 public:
  ChainTree(const std::vector<typename K::Point>& pts, const std::vector<Chain>& chains) : pts_(pts), chains_(chains) {}

  void insert(int chain) {
    const int node = static_cast<int>(nodes_.size());
    nodes_.push_back({chain, -1, -1, chains_[chain].y_max, priority(chain)});
    auto [l, r] = split(root_, chain);
    root_ = join(join(l, node), r);
  }

  void erase(int chain) { root_ = erase(root_, chain); }

  // Calls f(chain) for every chain in the tree whose y-range meets [y(lo), y(hi)] (closed).
  template <class F>
  void for_each_overlapping(int lo, int hi, F&& f) const {
    query(root_, lo, hi, f);
  }

 private:
  struct Node {
    int chain;
    int left, right;
    int max_hi;  // point id of the highest y in the subtree
    std::uint32_t priority;
  };

  static std::uint32_t priority(int chain) {
    std::uint64_t z = static_cast<std::uint64_t>(chain) * 0x9E3779B97F4A7C15ULL;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    return static_cast<std::uint32_t>(z >> 32);
  }
  bool y_less(int u, int w) const { return K::compare_y(pts_[u], pts_[w]) == Sign::negative; }
  bool key_less(int a, int b) const {
    const Sign s = K::compare_y(pts_[chains_[a].y_min], pts_[chains_[b].y_min]);
    return s != Sign::zero ? s == Sign::negative : a < b;
  }
  void pull(int t) {
    Node& n = nodes_[t];
    n.max_hi = chains_[n.chain].y_max;
    if (n.left >= 0 && y_less(n.max_hi, nodes_[n.left].max_hi)) n.max_hi = nodes_[n.left].max_hi;
    if (n.right >= 0 && y_less(n.max_hi, nodes_[n.right].max_hi)) n.max_hi = nodes_[n.right].max_hi;
  }
  // Keys before `chain`'s key, and the others.
  std::pair<int, int> split(int t, int chain) {
    if (t < 0) return {-1, -1};
    if (key_less(nodes_[t].chain, chain)) {
      auto [l, r] = split(nodes_[t].right, chain);
      nodes_[t].right = l;
      pull(t);
      return {t, r};
    }
    auto [l, r] = split(nodes_[t].left, chain);
    nodes_[t].left = r;
    pull(t);
    return {l, t};
  }
  int join(int l, int r) {
    if (l < 0) return r;
    if (r < 0) return l;
    if (nodes_[l].priority > nodes_[r].priority) {
      nodes_[l].right = join(nodes_[l].right, r);
      pull(l);
      return l;
    }
    nodes_[r].left = join(l, nodes_[r].left);
    pull(r);
    return r;
  }
  int erase(int t, int chain) {
    if (t < 0) return t;
    Node& n = nodes_[t];
    if (n.chain == chain) return join(n.left, n.right);
    if (key_less(chain, n.chain)) {
      n.left = erase(n.left, chain);
    } else {
      n.right = erase(n.right, chain);
    }
    pull(t);
    return t;
  }
  template <class F>
  void query(int t, int lo, int hi, F& f) const {
    while (t >= 0) {
      const Node& n = nodes_[t];
      if (y_less(n.max_hi, lo)) return;  // everything here lies below
      query(n.left, lo, hi, f);
      if (y_less(hi, chains_[n.chain].y_min)) return;  // this and the right subtree lie above
      if (!y_less(chains_[n.chain].y_max, lo)) f(n.chain);
      t = n.right;
    }
  }

  const std::vector<typename K::Point>& pts_;
  const std::vector<Chain>& chains_;
  std::vector<Node> nodes_;
  int root_ = -1;
};

}  // namespace detail

// The candidate pairs of a set of items, in parts that can be searched on different threads:
// every pair belongs to exactly one part, and the parts and the order of the pairs within
// each depend on the input alone. A pair is (i, j), item indices, for every two items whose
// bounding boxes overlap (closed boxes), except pairs of segments of one chain, which never
// meet but at shared ends. With `bipartite`, only pairs from different groups (0 and 1) are
// reported: part g holds the pairs found when an item of group g enters the sweep.
template <Kernel K>
class CandidatePairs {
 public:
  // `x_rank` gives each point id the rank of its x among the distinct x values.
  CandidatePairs(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                 const std::vector<SweepItem>& items, bool bipartite, PairSearch search)
      : pts_(pts), x_rank_(x_rank), items_(items), bipartite_(bipartite), search_(search) {
    if (search_ == PairSearch::sweep) build_chains();
  }

  std::size_t parts() const { return search_ == PairSearch::sweep && bipartite_ ? 2 : 1; }

  // Calls f(i, j) for every pair of part `part`.
  template <class F>
  void for_each_in_part(std::size_t part, F&& f) const {
    if (search_ == PairSearch::all_pairs) {
      const int n = static_cast<int>(items_.size());
      for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
          if (bipartite_ && items_[i].group == items_[j].group) continue;
          f(i, j);
        }
      }
      return;
    }
    sweep(static_cast<int>(part), f);
  }

 private:
  int xr(int id) const { return x_rank_[id]; }
  bool y_less(int u, int w) const { return K::compare_y(pts_[u], pts_[w]) == Sign::negative; }
  // The way a segment goes (see detail::Chain): along the ring, in y, vertical or not.
  int course(const SweepItem& it) const {
    const Sign s = K::compare_y(pts_[it.lo], pts_[it.hi]);
    const int up = s == Sign::negative ? 1 : (s == Sign::positive ? -1 : 0);
    const bool vertical = xr(it.lo) == xr(it.hi);
    return (it.forward ? 1 : 0) | (up + 1) << 1 | (vertical ? 8 : 0);
  }

  // Cuts the items into chains and orders the chains by their left ends.
  void build_chains() {
    const int n = static_cast<int>(items_.size());
    order_.resize(items_.size());
    int start = 0;
    int start_course = 0;
    const auto close = [&](int end) {
      detail::Chain c;
      c.first = start;
      c.last = end;
      c.group = items_[start].group;
      std::iota(order_.begin() + start, order_.begin() + end, start);
      if (!items_[start].forward) std::reverse(order_.begin() + start, order_.begin() + end);
      c.lo = items_[order_[start]].lo;
      c.hi = items_[order_[end - 1]].hi;
      // Monotone in y: the extreme ends are the chain's two ends.
      c.y_min = y_less(c.hi, c.lo) ? c.hi : c.lo;
      c.y_max = c.y_min == c.lo ? c.hi : c.lo;
      chains_.push_back(c);
    };
    for (int i = 0; i < n; ++i) {
      const SweepItem& it = items_[i];
      const int k = course(it);
      const bool joins = i > start && i - start < detail::kMaxChain && it.continues && it.group == items_[i - 1].group &&
                         k == start_course;
      if (i > 0 && !joins) {
        close(i);
        start = i;
      }
      if (i == start) start_course = k;
    }
    if (n > 0) close(n);
    // Chains by the x-rank of their left ends, ties in ring order: a counting sort when the
    // chains are many next to the ranks, else a sort.
    const std::size_t ranks = x_rank_.empty() ? 1 : static_cast<std::size_t>(x_rank_.back()) + 1;
    const std::size_t m = chains_.size();
    by_x_.resize(m);
    if (m * 16 < ranks) {
      std::iota(by_x_.begin(), by_x_.end(), 0);
      std::stable_sort(by_x_.begin(), by_x_.end(), [&](int a, int b) { return xr(chains_[a].lo) < xr(chains_[b].lo); });
      return;
    }
    std::vector<int> begin(ranks + 1, 0);
    for (const auto& c : chains_) ++begin[xr(c.lo) + 1];
    std::partial_sum(begin.begin(), begin.end(), begin.begin());
    for (int c = 0; c < static_cast<int>(m); ++c) by_x_[begin[xr(chains_[c].lo)]++] = c;
  }

  // The sweep over x of part `part`: chains enter in order of their left ends; each entering
  // chain is paired with the chains in the tree whose y-ranges meet its own and whose
  // x-ranges still reach it (the others have left the sweep and are removed).
  template <class F>
  void sweep(int part, F& f) const {
    detail::ChainTree<K> tree(pts_, chains_);
    std::vector<int> gone;
    for (const int d : by_x_) {
      const detail::Chain& cd = chains_[d];
      const bool queries = !bipartite_ || cd.group == part;
      const bool enters = !bipartite_ || cd.group != part;
      if (queries) {
        gone.clear();
        tree.for_each_overlapping(cd.y_min, cd.y_max, [&](int c) {
          if (xr(chains_[c].hi) < xr(cd.lo)) {
            gone.push_back(c);
          } else {
            merge(chains_[c], cd, f);
          }
        });
        for (const int c : gone) tree.erase(c);
      }
      if (enters) tree.insert(d);
    }
  }

  // The segments of chain x that can meet chain `other`: a chain is monotone in x and in y,
  // so those ending left of other's start, and those entirely below or above other's
  // y-range, form a prefix and a suffix of x's segments (in x order), found by binary search.
  std::pair<int, int> window(const detail::Chain& x, const detail::Chain& other) const {
    const auto first = order_.begin() + x.first;
    const auto last = order_.begin() + x.last;
    auto b = std::partition_point(first, last, [&](int k) { return xr(items_[k].hi) < xr(other.lo); });
    auto e = std::partition_point(b, last, [&](int k) { return xr(items_[k].lo) <= xr(other.hi); });
    if (y_less(x.hi, x.lo)) {  // descending in y: a segment spans y(hi) .. y(lo)
      b = std::partition_point(b, e, [&](int k) { return y_less(other.y_max, items_[k].hi); });
      e = std::partition_point(b, e, [&](int k) { return !y_less(items_[k].lo, other.y_min); });
    } else {  // ascending (or level): a segment spans y(lo) .. y(hi)
      b = std::partition_point(b, e, [&](int k) { return y_less(items_[k].hi, other.y_min); });
      e = std::partition_point(b, e, [&](int k) { return !y_less(other.y_max, items_[k].lo); });
    }
    return {static_cast<int>(b - order_.begin()), static_cast<int>(e - order_.begin())};
  }

  bool y_overlap(const SweepItem& a, const SweepItem& b) const {
    const bool a_up = K::compare_y(pts_[a.lo], pts_[a.hi]) != Sign::positive;
    const bool b_up = K::compare_y(pts_[b.lo], pts_[b.hi]) != Sign::positive;
    const int a_min = a_up ? a.lo : a.hi;
    const int a_max = a_up ? a.hi : a.lo;
    const int b_min = b_up ? b.lo : b.hi;
    const int b_max = b_up ? b.hi : b.lo;
    return !y_less(b_max, a_min) && !y_less(a_max, b_min);
  }

  // Segment pairs of two chains whose boxes overlap, by merging them in x: c is in the tree,
  // d is entering it.
  template <class F>
  void merge(const detail::Chain& c, const detail::Chain& d, F& f) const {
    auto [i, c_end] = window(c, d);
    auto [j, d_end] = window(d, c);
    while (i < c_end && j < d_end) {
      const SweepItem& a = items_[order_[i]];
      const SweepItem& b = items_[order_[j]];
      if (xr(a.hi) < xr(b.lo)) {
        ++i;
        continue;
      }
      if (xr(b.hi) < xr(a.lo)) {
        ++j;
        continue;
      }
      // a overlaps b in x: so may a the segments after b that start before a ends.
      for (int k = j; k < d_end && xr(items_[order_[k]].lo) <= xr(a.hi); ++k) {
        if (y_overlap(a, items_[order_[k]])) f(order_[i], order_[k]);
      }
      ++i;
    }
  }

  const std::vector<typename K::Point>& pts_;
  const std::vector<int>& x_rank_;
  const std::vector<SweepItem>& items_;
  bool bipartite_;
  PairSearch search_;
  std::vector<int> order_;
  std::vector<detail::Chain> chains_;
  std::vector<int> by_x_;  // chain indices by the x-rank of their left ends
};

// Calls f(i, j) for every candidate pair (see CandidatePairs), part after part.
template <Kernel K, class F>
void for_each_candidate_pair(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                             const std::vector<SweepItem>& items, bool bipartite, PairSearch search, F&& f) {
  const CandidatePairs<K> pairs(pts, x_rank, items, bipartite, search);
  for (std::size_t p = 0; p < pairs.parts(); ++p) pairs.for_each_in_part(p, f);
}

}  // namespace mk
