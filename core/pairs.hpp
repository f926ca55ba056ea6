// Candidate pairs of segments whose bounding boxes overlap, found through monotone chains:
// a sweep over x of the chains' boxes with an interval tree over y, and the segments of two
// chains paired by merging them. [MK89 §4.3] (sub-quadratic intersection finding; the
// all-pairs baseline is kept)
// Preconditions: point ids follow lexicographic order (see Arrangement::points); the items
// of one ring come consecutively, in ring order, each marked `continues` except the first.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <iterator>
#include <span>
#include <cstdint>
#include <memory>
#include <numeric>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/parallel.hpp"
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

// Appends the item of src -> dst, made in place: push_back(sweep_item(...)) builds it on the
// stack and copies it with wide loads that wait for the narrow stores (GCC 12). Fields are
// set one by one: clang 14 (the fuzzers' compiler) has no parenthesised aggregate init.
inline void add_sweep_item(std::vector<SweepItem>& items, int src, int dst, int group, bool continues) {
  SweepItem& item = items.emplace_back();
  item.lo = std::min(src, dst);
  item.hi = std::max(src, dst);
  item.group = group;
  item.forward = src < dst;
  item.continues = continues;
}

// How candidate pairs are found: `sweep`, by boxes (CandidatePairs), and in the preparation
// by the sweep over both polygons (core/red_blue.hpp) where boxes would pair too much;
// `all_pairs`, every pair (the paper's way, for experiments); `red_blue`, as `sweep`, but
// the preparation's pairs across the polygons always from the sweep over both when each
// polygon's edges meet only at shared ends (for experiments and tests).
enum class PairSearch : unsigned char { sweep, all_pairs, red_blue };

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
  int first = 0;  // range of segs_ (the chain's segments sorted by lo)
  int last = 0;
  int group = 0;
  bool falling = false;  // the chain descends in y from lo to hi
};

inline constexpr int kMaxChain = 256;

}  // namespace detail

// The candidate pairs of a set of items, in parts that can be searched on different threads:
// every pair belongs to exactly one part, and the parts and the order of the pairs within
// each depend on the input alone. A pair is (i, j), item indices, for every two items whose
// bounding boxes overlap (closed boxes), except pairs of segments of one chain, which never
// meet but at shared ends; with `bipartite`, only pairs from different groups (0 and 1).
// Chains are paired by a recursive partition of their boxes, as Boost.Geometry's
// `partition` does: a set is split at a pivot along x (x-ranks) or y (alternately) into the
// boxes below it, above it and across it; boxes below never meet boxes above, so the
// search goes on in the two halves, and between the boxes across and all the others, with
// the other axis. Small sets are paired directly. The first levels of the recursion are
// planned as separate parts.
template <Kernel K>
class CandidatePairs {
 public:
  // `x_rank` gives each point id the rank of its x among the distinct x values.
  // The chains are made on up to `threads` threads (the same chains on any number).
  CandidatePairs(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                 std::span<const SweepItem> items, bool bipartite, PairSearch search, unsigned threads = 1)
      : pts_(pts), x_rank_(x_rank), items_(items), bipartite_(bipartite),
        search_(search == PairSearch::all_pairs ? PairSearch::all_pairs : PairSearch::sweep) {
    if (search_ == PairSearch::sweep) {
      build_chains(threads);
      plan(threads);
    }
  }

  std::size_t parts() const { return search_ == PairSearch::sweep ? tasks_.size() : 1; }

  // Stops every part's search once `merges` pairs of chains have been merged in all (the
  // box search's work, which boxes that overlap without their edges meeting can make
  // quadratic); exhausted() then says so, and what the parts reported is incomplete.
  void limit_merges(std::int64_t merges) {
    budget_.store(merges);
    limited_ = true;
  }
  bool exhausted() const { return exhausted_.load(); }

  // Calls f(i, j) for every pair of part `part`. Each part may be searched once.
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
    Task& t = tasks_[part];
    try {
      if (t.self) {
        search_self(t.a, t.axis, 0, f);
      } else {
        search_both(t.a, t.b, t.axis, 0, f);
      }
    } catch (const Spent&) {
      exhausted_.store(true);
    }
    t = Task();
  }

 private:
  // A set of chains, or two sets to pair with each other, and the axis to split first.
  struct Task {
    std::vector<int> a, b;
    int axis = 0;
    bool self = false;
  };
  enum class Place : unsigned char { below, above, across };
  struct Spent {};  // thrown out of a part's search when the merges allowed are spent

  static constexpr std::size_t kDirect = 128;  // sets this small (or pairs of sets) are paired directly
  static constexpr int kMaxDepth = 96;
  static constexpr int kPrefetch = 32;  // items ahead whose points build_chains asks for

  int xr(int id) const { return x_rank_[id]; }
  bool y_less(int u, int w) const { return K::compare_y(pts_[u], pts_[w]) == Sign::negative; }

  // A y to compare: with double points (compared by <) the double itself, read once into the
  // boxes below, so that pairing boxes and segments reads no point again (those reads were
  // most of the search's cost on many rings); with other points the point id. Such kernels'
  // compare_y must be the doubles' `<` (tests/core/plain_y_test.cpp checks each).
  static constexpr bool kPlainY = std::is_same_v<typename K::Point, mk::Point>;
  using YKey = std::conditional_t<kPlainY, double, int>;
  YKey ykey(int id) const {
    if constexpr (kPlainY) {
      return pts_[id].y;
    } else {
      return id;
    }
  }
  bool ky_less(YKey u, YKey w) const {
    if constexpr (kPlainY) {
      return u < w;
    } else {
      return y_less(u, w);
    }
  }
  // A chain's box: x-ranks of its ends, its lowest and highest y.
  struct Box {
    int x0, x1;
    YKey y0, y1;
  };
  // A segment in chain order: its item, the x-ranks and the y of its lo and hi ends.
  struct Seg {
    int item, x_lo, x_hi;
    YKey y_lo, y_hi;
  };

  // The way a segment goes (see detail::Chain): along the ring, in y, vertical or not.
  int course(const SweepItem& it, const Seg& k) const {
    const int up = ky_less(k.y_lo, k.y_hi) ? 1 : (ky_less(k.y_hi, k.y_lo) ? -1 : 0);
    return (it.forward ? 1 : 0) | (up + 1) << 1 | (k.x_lo == k.x_hi ? 8 : 0);
  }

  // Cuts the items into chains and makes the segments (in chain order) and the chains'
  // boxes, in one pass over the items: a ring's consecutive items share a point, whose
  // x-rank and y are read once (reading them was most of this pass).
  // A ring's first item always starts a chain, so the items are cut in two at the first ring
  // start from their middle on, and each half is made on its own thread, then joined.
  void build_chains(unsigned threads) {
    const int n = static_cast<int>(items_.size());
    segs_ = std::make_unique_for_overwrite<Seg[]>(items_.size());  // each written below: no zeroing pass
    int cut = n / 2;
    while (cut < n && items_[cut].continues) ++cut;
    if (threads_for(items_.size(), threads) < 2 || cut == 0 || cut == n) {
      build_chains_in(0, n, chains_, boxes_);
      return;
    }
    std::vector<detail::Chain> later_chains;
    std::vector<Box> later_boxes;
    run_tasks(2, 2, [&](std::size_t half) {
      if (half == 0) {
        build_chains_in(0, cut, chains_, boxes_);
      } else {
        build_chains_in(cut, n, later_chains, later_boxes);
      }
    });
    chains_.insert(chains_.end(), later_chains.begin(), later_chains.end());
    boxes_.insert(boxes_.end(), later_boxes.begin(), later_boxes.end());
  }

  // The chains of items first .. n-1 (first a ring's first item), appended to `chains` and
  // `boxes`; their segments are written to segs_ at the items' places.
  void build_chains_in(int first, int n, std::vector<detail::Chain>& chains, std::vector<Box>& boxes) {
    int start = first;
    int start_course = 0;
    const auto close = [&](int end) {
      detail::Chain c;
      c.first = start;
      c.last = end;
      c.group = items_[start].group;
      if (!items_[start].forward) std::reverse(segs_.get() + start, segs_.get() + end);
      const Seg& head = segs_[start];
      const Seg& tail = segs_[end - 1];
      // Monotone in y: the extreme ends are the chain's two ends.
      c.falling = ky_less(tail.y_hi, head.y_lo);
      chains.push_back(c);
      boxes.push_back({head.x_lo, tail.x_hi, c.falling ? tail.y_hi : head.y_lo, c.falling ? head.y_lo : tail.y_hi});
    };
    int prev_dst = -1;  // the previous item's ring successor, with its x-rank and y
    int prev_dst_x = 0;
    YKey prev_dst_y{};
    for (int i = first; i < n; ++i) {
      if (i + kPrefetch < n) {
        // The ring successor's x-rank and y lie anywhere in the point arrays (ids follow
        // lexicographic order, not the ring): asked for a few items ahead, the reads
        // overlap instead of each waiting for memory.
        const SweepItem& ahead = items_[i + kPrefetch];
        const int id = ahead.forward ? ahead.hi : ahead.lo;
        __builtin_prefetch(&x_rank_[id]);
        __builtin_prefetch(&pts_[id]);
      }
      const SweepItem& it = items_[i];
      const int src = it.forward ? it.lo : it.hi;
      const int dst = it.forward ? it.hi : it.lo;
      int src_x;
      YKey src_y;
      if (src == prev_dst) {
        src_x = prev_dst_x;
        src_y = prev_dst_y;
      } else {
        src_x = xr(src);
        src_y = ykey(src);
      }
      prev_dst = dst;
      prev_dst_x = xr(dst);
      prev_dst_y = ykey(dst);
      Seg& k = segs_[i];
      k.item = i;
      k.x_lo = it.forward ? src_x : prev_dst_x;
      k.x_hi = it.forward ? prev_dst_x : src_x;
      k.y_lo = it.forward ? src_y : prev_dst_y;
      k.y_hi = it.forward ? prev_dst_y : src_y;
      const int kc = course(it, k);
      const bool joins = i > start && i - start < detail::kMaxChain && it.continues && it.group == items_[i - 1].group &&
                         kc == start_course;
      if (i > first && !joins) {
        close(i);
        start = i;
      }
      if (i == start) start_course = kc;
    }
    if (n > first) close(n);
  }

  // The first levels of the partition, each subproblem left at the last level a part. The
  // first level's subproblems are planned on the threads, each into its own list of parts,
  // the lists joined in their order: the same parts on any number of threads.
  void plan(unsigned threads) {
    const std::size_t m = chains_.size();
    const int levels = m >= 32768 ? 2 : (m >= 4096 ? 1 : 0);
    const unsigned t = threads_for(m, threads);
    if (bipartite_) {
      std::vector<int> a, b;
      for (int c = 0; c < static_cast<int>(m); ++c) (chains_[c].group == 0 ? a : b).push_back(c);
      plan_both(std::move(a), std::move(b), 0, levels, tasks_, t);
    } else {
      std::vector<int> all(m);
      std::iota(all.begin(), all.end(), 0);
      plan_self(std::move(all), 0, levels, tasks_, t);
    }
  }
  // Plans the four subproblems sub(k, out) (k = 0..3) into `out` in order, on up to
  // `threads` threads.
  template <class Sub>
  static void plan_four(std::vector<Task>& out, unsigned threads, Sub&& sub) {
    if (threads < 2) {
      for (int k = 0; k < 4; ++k) sub(k, out);
      return;
    }
    std::array<std::vector<Task>, 4> lists;
    run_tasks(threads, 4, [&](std::size_t k) { sub(static_cast<int>(k), lists[k]); });
    for (auto& list : lists) std::move(list.begin(), list.end(), std::back_inserter(out));
  }
  void plan_self(std::vector<int> s, int axis, int levels, std::vector<Task>& out, unsigned threads = 1) {
    if (s.size() < 2) return;
    if (levels == 0 || s.size() <= kDirect) {
      out.push_back({std::move(s), {}, axis, true});
      return;
    }
    std::size_t below = 0, above = 0;  // plain variables: the lambdas below capture them (clang 14)
    std::tie(below, above, axis) = split(s, axis);
    const auto part = [&](std::size_t from, std::size_t to) {
      return std::vector<int>(s.begin() + static_cast<std::ptrdiff_t>(from), s.begin() + static_cast<std::ptrdiff_t>(to));
    };
    plan_four(out, threads, [&](int k, std::vector<Task>& list) {
      switch (k) {
        case 0: plan_self(part(0, below), 1 - axis, levels - 1, list); break;
        case 1: plan_self(part(below, above), 1 - axis, levels - 1, list); break;
        case 2: plan_both(part(0, above), part(above, s.size()), 1 - axis, levels - 1, list); break;
        default: plan_self(part(above, s.size()), 1 - axis, levels - 1, list); break;
      }
    });
  }
  void plan_both(std::vector<int> a, std::vector<int> b, int axis, int levels, std::vector<Task>& out,
                 unsigned threads = 1) {
    if (a.empty() || b.empty()) return;
    if (levels == 0 || a.size() * b.size() <= kDirect * kDirect / 4) {
      out.push_back({std::move(a), std::move(b), axis, false});
      return;
    }
    const std::size_t na = a.size();
    std::vector<int> ab(std::move(a));
    ab.insert(ab.end(), b.begin(), b.end());
    const int pivot = choose_pivot(ab, axis);
    a.assign(ab.begin(), ab.begin() + static_cast<std::ptrdiff_t>(na));
    std::size_t a_below = 0, a_above = 0, b_below = 0, b_above = 0;  // captured below: no structured bindings (clang 14)
    std::tie(a_below, a_above) = split_at(a, axis, pivot);
    std::tie(b_below, b_above) = split_at(b, axis, pivot);
    const auto part = [](const std::vector<int>& v, std::size_t from, std::size_t to) {
      return std::vector<int>(v.begin() + static_cast<std::ptrdiff_t>(from), v.begin() + static_cast<std::ptrdiff_t>(to));
    };
    plan_four(out, threads, [&](int k, std::vector<Task>& list) {
      switch (k) {
        case 0: plan_both(part(a, 0, a_below), part(b, 0, b_below), 1 - axis, levels - 1, list); break;
        case 1: plan_both(part(a, a_below, a_above), part(b, b_below, b_above), 1 - axis, levels - 1, list); break;
        case 2: plan_both(part(a, 0, a_above), part(b, b_above, b.size()), 1 - axis, levels - 1, list); break;
        default: plan_both(part(a, a_above, a.size()), b, 1 - axis, levels - 1, list); break;
      }
    });
  }

  // The pivot along `axis`: the median of the low ends of up to 15 boxes spread over the set
  // (an x-rank for x; for y the chain whose box's low end it is); see place().
  int choose_pivot(std::span<const int> s, int axis) const {
    std::array<int, 15> sample{};
    const std::size_t k = std::min<std::size_t>(sample.size(), s.size());
    for (std::size_t i = 0; i < k; ++i) {
      const int c = s[k == 1 ? 0 : i * (s.size() - 1) / (k - 1)];
      sample[i] = axis == 0 ? boxes_[c].x0 : c;
    }
    const auto mid = sample.begin() + static_cast<std::ptrdiff_t>(k / 2);
    if (axis == 0) {
      std::nth_element(sample.begin(), mid, sample.begin() + static_cast<std::ptrdiff_t>(k));
    } else {
      std::nth_element(sample.begin(), mid, sample.begin() + static_cast<std::ptrdiff_t>(k),
                       [&](int u, int w) { return ky_less(boxes_[u].y0, boxes_[w].y0); });
    }
    return *mid;
  }
  // Where a box lies against the line just above the pivot's coordinate: a box ending at the
  // pivot lies below it, one starting there and going on crosses it. Grid-aligned boxes
  // then rarely cross the line (a closed pivot line would cross every box touching it).
  Place place(int chain, int axis, int pivot) const {
    const Box& c = boxes_[chain];
    if (axis == 0) {
      if (c.x1 <= pivot) return Place::below;
      if (c.x0 > pivot) return Place::above;
      return Place::across;
    }
    const YKey p = boxes_[pivot].y0;
    if (!ky_less(p, c.y1)) return Place::below;
    if (ky_less(p, c.y0)) return Place::above;
    return Place::across;
  }
  // Reorders s as [below | above | across] the pivot; returns the ends of the first two.
  // One pass, each box placed once (a three-way partition: below grows from the front,
  // across from the back).
  std::pair<std::size_t, std::size_t> split_at(std::span<int> s, int axis, int pivot) const {
    std::size_t below = 0;
    std::size_t i = 0;
    std::size_t across = s.size();
    while (i < across) {
      const Place where = place(s[i], axis, pivot);
      if (where == Place::below) {
        std::swap(s[below++], s[i++]);
      } else if (where == Place::above) {
        ++i;
      } else {
        std::swap(s[i], s[--across]);
      }
    }
    return {below, across};
  }
  // The axis to split s along and its pivot: `axis`, unless every sampled box lies across
  // that axis' pivot (full-width stripes lie across every pivot in x), then the other one;
  // a split that separates nothing costs a pass over the set.
  std::pair<int, int> choose_split(std::span<const int> s, int axis) const {
    const int pivot = choose_pivot(s, axis);
    const std::size_t k = std::min<std::size_t>(15, s.size());
    for (std::size_t i = 0; i < k; ++i) {
      if (place(s[k == 1 ? 0 : i * (s.size() - 1) / (k - 1)], axis, pivot) != Place::across) return {axis, pivot};
    }
    return {1 - axis, choose_pivot(s, 1 - axis)};
  }
  // Splits s (see split_at) along the axis choose_split picks; returns the ends and the axis.
  std::tuple<std::size_t, std::size_t, int> split(std::span<int> s, int axis) const {
    const auto [along, pivot] = choose_split(s, axis);
    const auto [below, above] = split_at(s, along, pivot);
    return {below, above, along};
  }

  // The bounding box of a set of chains: x-ranks and the lowest and highest y (see Box).
  Box bounds(std::span<const int> s) const {
    Box b = boxes_[s[0]];
    for (const int i : s.subspan(1)) {
      const Box& c = boxes_[i];
      b.x0 = std::min(b.x0, c.x0);
      b.x1 = std::max(b.x1, c.x1);
      if (ky_less(c.y0, b.y0)) b.y0 = c.y0;
      if (ky_less(b.y1, c.y1)) b.y1 = c.y1;
    }
    return b;
  }
  // Moves the chains of s whose boxes meet `b` to its front; returns how many.
  std::size_t keep_meeting(std::span<int> s, const Box& b) const {
    const auto e = std::partition(s.begin(), s.end(), [&](int i) { return boxes_meet(boxes_[i], b); });
    return static_cast<std::size_t>(e - s.begin());
  }

  bool y_meet(const Box& c, const Box& d) const { return !ky_less(d.y1, c.y0) && !ky_less(c.y1, d.y0); }
  bool boxes_meet(const Box& c, const Box& d) const { return c.x0 <= d.x1 && d.x0 <= c.x1 && y_meet(c, d); }
  // Orders a set of chains by the left ends of their boxes (ties by chain, so that the order
  // depends on the set alone).
  // Small sets (the common case) sort packed keys (x0, chain) on the stack; not inlined, so
  // that the recursive search's frames do not carry the array.
  [[gnu::noinline]] void sort_by_x0(std::span<int> s) const {
    std::array<std::uint64_t, 576> keys;
    if (s.size() > keys.size()) {
      std::sort(s.begin(), s.end(), [&](int c, int d) { return boxes_[c].x0 != boxes_[d].x0 ? boxes_[c].x0 < boxes_[d].x0 : c < d; });
      return;
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
      keys[i] = static_cast<std::uint64_t>(static_cast<std::uint32_t>(boxes_[s[i]].x0)) << 32 | static_cast<std::uint32_t>(s[i]);
    }
    std::sort(keys.begin(), keys.begin() + static_cast<std::ptrdiff_t>(s.size()));
    for (std::size_t i = 0; i < s.size(); ++i) s[i] = static_cast<int>(keys[i] & 0xffffffffu);
  }
  template <class F>
  void pair_if_meet(int c, int d, F& f) const {
    if (boxes_meet(boxes_[c], boxes_[d])) merge(c, d, f);
  }

  // Pairs within one set.
  // `stuck`: the last split, along the other axis, separated nothing.
  template <class F>
  void search_self(std::span<int> s, int axis, int depth, F& f, bool stuck = false) const {
    if (s.size() < 2) return;
    if (s.size() <= kDirect || depth >= kMaxDepth) {
      // By the left ends of the boxes: each box meets only those starting before it ends.
      sort_by_x0(s);
      for (std::size_t i = 0; i < s.size(); ++i) {
        const Box& c = boxes_[s[i]];
        for (std::size_t j = i + 1; j < s.size() && boxes_[s[j]].x0 <= c.x1; ++j) {
          if (y_meet(c, boxes_[s[j]])) merge(s[i], s[j], f);
        }
      }
      return;
    }
    const auto [below, above, along] = split(s, axis);
    axis = along;
    if (below == 0 && above == 0) {  // every box lies across the pivot: try the other axis
      search_self(s, 1 - axis, stuck ? kMaxDepth : depth + 1, f, true);
      return;
    }
    const int next = depth + 1;
    search_self(s.subspan(0, below), 1 - axis, next, f);
    search_self(s.subspan(below, above - below), 1 - axis, next, f);
    // The boxes across the pivot meet only boxes near them: the others are not searched again.
    const std::span<int> across = s.subspan(above);
    if (!across.empty()) {
      const std::size_t near = keep_meeting(s.subspan(0, above), bounds(across));
      search_both(s.subspan(0, near), across, 1 - axis, next, f);
    }
    search_self(across, 1 - axis, next, f);
  }

  // Pairs between two sets.
  template <class F>
  void search_both(std::span<int> a, std::span<int> b, int axis, int depth, F& f, bool stuck = false) const {
    if (a.empty() || b.empty()) return;
    // A set of one or two boxes is paired directly: splitting costs as much as pairing.
    if (std::min(a.size(), b.size()) <= 2) {
      for (const int c : a) {
        for (const int d : b) pair_if_meet(c, d, f);
      }
      return;
    }
    if (a.size() * b.size() <= kDirect * kDirect / 4 || depth >= kMaxDepth) {
      // Both by the left ends of the boxes, merged: a pair is met once, when the box that
      // starts later (or b's, at equal starts) is reached from the other.
      sort_by_x0(a);
      sort_by_x0(b);
      std::size_t i = 0;
      std::size_t j = 0;
      while (i < a.size() && j < b.size()) {
        if (boxes_[a[i]].x0 <= boxes_[b[j]].x0) {
          const Box& c = boxes_[a[i]];
          for (std::size_t k = j; k < b.size() && boxes_[b[k]].x0 <= c.x1; ++k) {
            if (y_meet(c, boxes_[b[k]])) merge(a[i], b[k], f);
          }
          ++i;
        } else {
          const Box& d = boxes_[b[j]];
          for (std::size_t k = i; k < a.size() && boxes_[a[k]].x0 <= d.x1; ++k) {
            if (y_meet(boxes_[a[k]], d)) merge(a[k], b[j], f);
          }
          ++j;
        }
      }
      return;
    }
    int pivot = 0;
    {  // the pivot of a and b together
      std::array<int, 16> picks{};
      std::size_t k = 0;
      for (const auto* set : {&a, &b}) {
        const std::size_t n = set->size();
        for (std::size_t i = 0; i < 8 && i < n; ++i) picks[k++] = (*set)[n == 1 ? 0 : i * (n - 1) / std::min<std::size_t>(7, n - 1)];
      }
      std::tie(axis, pivot) = choose_split(std::span<const int>(picks.data(), k), axis);
    }
    std::size_t a_below = 0, a_above = 0, b_below = 0, b_above = 0;  // captured below: no structured bindings (clang 14)
    std::tie(a_below, a_above) = split_at(a, axis, pivot);
    std::tie(b_below, b_above) = split_at(b, axis, pivot);
    if (a_above + b_above == 0) {  // every box lies across the pivot: try the other axis
      search_both(a, b, 1 - axis, stuck ? kMaxDepth : depth + 1, f, true);
      return;
    }
    const int next = depth + 1;
    search_both(a.subspan(0, a_below), b.subspan(0, b_below), 1 - axis, next, f);
    search_both(a.subspan(a_below, a_above - a_below), b.subspan(b_below, b_above - b_below), 1 - axis, next, f);
    // The boxes across the pivot meet only boxes near them: the others are not searched again.
    const std::span<int> b_across = b.subspan(b_above);
    if (!b_across.empty() && a_above > 0) {  // b across, a not
      const std::size_t near = keep_meeting(a.subspan(0, a_above), bounds(b_across));
      search_both(a.subspan(0, near), b_across, 1 - axis, next, f);
    }
    const std::span<int> a_across = a.subspan(a_above);
    if (!a_across.empty()) {  // a across, all of b
      const std::size_t near = keep_meeting(b, bounds(a_across));
      search_both(a_across, b.subspan(0, near), 1 - axis, next, f);
    }
  }

  // The segments of chain x that can meet chain `other`: a chain is monotone in x and in y,
  // so those ending left of other's start, and those entirely below or above other's
  // y-range, form a prefix and a suffix of x's segments (in x order), found by binary search.
  std::pair<int, int> window(int xc, int oc) const {
    const detail::Chain& x = chains_[xc];
    const Box& other = boxes_[oc];
    const Seg* const first = segs_.get() + x.first;
    const Seg* const last = segs_.get() + x.last;
    const Seg* b = std::partition_point(first, last, [&](const Seg& k) { return k.x_hi < other.x0; });
    const Seg* e = std::partition_point(b, last, [&](const Seg& k) { return k.x_lo <= other.x1; });
    if (x.falling) {  // descending in y: a segment spans y(hi) .. y(lo)
      b = std::partition_point(b, e, [&](const Seg& k) { return ky_less(other.y1, k.y_hi); });
      e = std::partition_point(b, e, [&](const Seg& k) { return !ky_less(k.y_lo, other.y0); });
    } else {  // ascending (or level): a segment spans y(lo) .. y(hi)
      b = std::partition_point(b, e, [&](const Seg& k) { return ky_less(k.y_hi, other.y0); });
      e = std::partition_point(b, e, [&](const Seg& k) { return !ky_less(other.y1, k.y_lo); });
    }
    return {static_cast<int>(b - segs_.get()), static_cast<int>(e - segs_.get())};
  }

  bool y_overlap(const Seg& a, const Seg& b) const {
    const bool a_up = !ky_less(a.y_hi, a.y_lo);
    const bool b_up = !ky_less(b.y_hi, b.y_lo);
    const YKey a_min = a_up ? a.y_lo : a.y_hi;
    const YKey a_max = a_up ? a.y_hi : a.y_lo;
    const YKey b_min = b_up ? b.y_lo : b.y_hi;
    const YKey b_max = b_up ? b.y_hi : b.y_lo;
    return !ky_less(b_max, a_min) && !ky_less(a_max, b_min);
  }

  // Counts one merge against the budget (limit_merges), in batches taken from the shared
  // count; throws Spent once it is spent, here or in another part.
  void spend() const {
    constexpr std::int64_t kBatch = 1024;
    thread_local std::int64_t unpaid = 0;
    if (++unpaid < kBatch) return;
    unpaid = 0;
    if (budget_.fetch_sub(kBatch) < kBatch || exhausted_.load(std::memory_order_relaxed)) {
      exhausted_.store(true);
      throw Spent{};
    }
  }

  // Segment pairs of chains c and d whose boxes overlap, by merging them in x.
  template <class F>
  void merge(int cc, int dc, F& f) const {
    if (limited_) spend();
    const detail::Chain& c = chains_[cc];
    const detail::Chain& d = chains_[dc];
    if (c.last - c.first == 1 && d.last - d.first == 1) {  // two segments: their boxes meet
      f(segs_[c.first].item, segs_[d.first].item);
      return;
    }
    auto [i, c_end] = window(cc, dc);
    auto [j, d_end] = window(dc, cc);
    while (i < c_end && j < d_end) {
      const Seg& a = segs_[i];
      const Seg& b = segs_[j];
      if (a.x_hi < b.x_lo) {
        ++i;
        continue;
      }
      if (b.x_hi < a.x_lo) {
        ++j;
        continue;
      }
      // a overlaps b in x: so may a the segments after b that start before a ends.
      for (int k = j; k < d_end && segs_[k].x_lo <= a.x_hi; ++k) {
        if (y_overlap(a, segs_[k])) f(a.item, segs_[k].item);
      }
      ++i;
    }
  }

  const std::vector<typename K::Point>& pts_;
  const std::vector<int>& x_rank_;
  std::span<const SweepItem> items_;  // viewed: must outlive the search
  bool bipartite_;
  PairSearch search_;
  std::vector<detail::Chain> chains_;
  std::vector<Box> boxes_;  // per chain
  std::unique_ptr<Seg[]> segs_;  // one per item, in chain order (a chain's segments by x)
  mutable std::vector<Task> tasks_;
  bool limited_ = false;
  mutable std::atomic<std::int64_t> budget_{0};
  mutable std::atomic<bool> exhausted_{false};
};

// Calls f(i, j) for every candidate pair (see CandidatePairs), part after part.
template <Kernel K, class F>
void for_each_candidate_pair(const std::vector<typename K::Point>& pts, const std::vector<int>& x_rank,
                             const std::vector<SweepItem>& items, bool bipartite, PairSearch search, F&& f) {
  const CandidatePairs<K> pairs(pts, x_rank, items, bipartite, search);
  for (std::size_t p = 0; p < pairs.parts(); ++p) pairs.for_each_in_part(p, f);
}

}  // namespace mk
