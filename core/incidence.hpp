// Incidence of edge fragments at vertices (each fragment seen from its two ends, grouped by
// vertex) and counts of fragments that coincide as sets; used by steps 4 and 5. Not to be
// confused with the locating ray of predicates/ray.hpp.
// [MK89 §4.3] (classification at boundary points) [MK89 §3.3] (EF: matching fragments)
// Preconditions: step 3 done.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "core/arrangement.hpp"
#include "core/buckets.hpp"
#include "kernel/kernel.hpp"
#include "predicates/directions.hpp"

namespace mk {

// A fragment seen from one of its endpoints: the fragment's index, +1 when it leaves the
// vertex and -1 when it arrives, and the direction away from the vertex (given by the
// original edge's input points). Stored as one int, 2 fragment + 1 when it arrives; the
// direction is looked up only when asked for.
class FragmentEnd {
 public:
  FragmentEnd(const PreparedPolygon& poly, int code) : poly_(&poly), code_(code) {}
  int fragment() const { return code_ >> 1; }
  int sign() const { return (code_ & 1) != 0 ? -1 : 1; }
  Direction dir() const {
    const Edge& e = poly_->edges[poly_->fragments[fragment()].edge];
    return (code_ & 1) != 0 ? Direction{e.dst, e.src} : Direction{e.src, e.dst};
  }

 private:
  const PreparedPolygon* poly_;
  int code_;
};

// The ends of one polygon's fragments, grouped by vertex. Most vertices are met once by the
// polygon's cycles, away from a cycle's start: their two ends are the fragment i leaving and
// the fragment i - 1 arriving, so the table keeps i alone (4 bytes per vertex, one pass over
// the fragments). The other vertices (met several times, or where a cycle starts) keep their
// ends as codes in groups, in increasing order of the code (2 fragment, + 1 when arriving),
// the order the simple vertices give as well.
// A bit per vertex says whether the polygon reaches it at all: most queries are about the
// other polygon's vertices, which it does not reach, and the bits (1/32 of the slots' size)
// answer them from cache.
// The polygon must outlive the table and keep its fragments and edges in place.
class FragmentEndTable {
 public:
  FragmentEndTable() = default;
  FragmentEndTable(const PreparedPolygon& poly, int num_vertices) : poly_(&poly) {
    slot_.assign(static_cast<std::size_t>(num_vertices), kUnreached);
    reached_.assign(static_cast<std::size_t>(num_vertices) / 64 + 1, 0);
    struct Visit {
      int vertex, leaving, arriving;
      bool operator<(const Visit& o) const { return vertex != o.vertex ? vertex < o.vertex : leaving < o.leaving; }
    };
    std::vector<Visit> grouped;  // the visits of the vertices kept in groups
    for (std::size_t c = 0; c + 1 < poly.cycle_first_fragment.size(); ++c) {
      const int first = poly.cycle_first_fragment[c];
      const int last = poly.cycle_first_fragment[c + 1];
      for (int i = first; i < last; ++i) {
        const int v = poly.fragments[static_cast<std::size_t>(i)].from;
        reached_[static_cast<std::size_t>(v) / 64] |= std::uint64_t{1} << (v % 64);
        int& s = slot_[static_cast<std::size_t>(v)];
        if (s == kUnreached && i != first) {
          s = i;
          continue;
        }
        if (s >= 0) grouped.push_back({v, s, s - 1});
        s = kGrouped;
        grouped.push_back({v, i, i == first ? last - 1 : i - 1});
      }
    }
    if (grouped.empty()) return;
    // Grouped by vertex: a counting sort when the visits are many (a grid of squares meets
    // at most of its vertices), else a comparison sort. Each group's codes are sorted below,
    // so the order of a vertex's visits does not matter.
    if (grouped.size() >= static_cast<std::size_t>(num_vertices) / 16) {
      const Buckets b = bucket_by(grouped.size(), static_cast<std::size_t>(num_vertices),
                                  [&](std::size_t i) { return grouped[i].vertex; });
      std::vector<Visit> by_vertex(grouped.size());
      for (std::size_t k = 0; k < b.order.size(); ++k) by_vertex[k] = grouped[static_cast<std::size_t>(b.order[k])];
      grouped = std::move(by_vertex);
    } else {
      std::sort(grouped.begin(), grouped.end());
    }
    group_begin_.push_back(0);
    codes_.reserve(2 * grouped.size());
    for (std::size_t k = 0; k < grouped.size();) {
      const int v = grouped[k].vertex;
      const std::size_t from = codes_.size();
      for (; k < grouped.size() && grouped[k].vertex == v; ++k) {
        codes_.push_back(2 * grouped[k].leaving);
        codes_.push_back(2 * grouped[k].arriving + 1);
      }
      std::sort(codes_.begin() + static_cast<std::ptrdiff_t>(from), codes_.end());
      slot_[static_cast<std::size_t>(v)] = kGrouped - static_cast<int>(group_begin_.size());
      group_begin_.push_back(static_cast<int>(codes_.size()));
    }
    index_many_ends();
  }

  class Iterator {
   public:
    Iterator(const PreparedPolygon* poly, const int* code) : poly_(poly), code_(code) {}
    FragmentEnd operator*() const { return {*poly_, *code_}; }
    Iterator& operator++() {
      ++code_;
      return *this;
    }
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.code_ == b.code_; }

   private:
    const PreparedPolygon* poly_;
    const int* code_;
  };
  // The ends at one vertex: a range of a group, or the two codes of a simple vertex held here.
  class Span {
   public:
    Span(const PreparedPolygon* poly, const int* first, const int* last) : poly_(poly), first_(first), last_(last) {}
    Span(const PreparedPolygon* poly, int leaving) : poly_(poly), pair_{2 * leaving - 1, 2 * leaving}, inline_(true) {}
    Iterator begin() const { return {poly_, inline_ ? pair_.data() : first_}; }
    Iterator end() const { return {poly_, inline_ ? pair_.data() + 2 : last_}; }
    bool empty() const { return !inline_ && first_ == last_; }

   private:
    const PreparedPolygon* poly_;
    const int* first_ = nullptr;
    const int* last_ = nullptr;
    std::array<int, 2> pair_{};
    bool inline_ = false;
  };
  bool reaches(int v) const { return (reached_[static_cast<std::size_t>(v) / 64] >> (v % 64)) & 1; }
  // Whether the polygon meets v once, away from a cycle's start: v's ends are the fragment
  // leaving it and the one before, and no other.
  bool is_simple(int v) const { return slot_[static_cast<std::size_t>(v)] >= 0; }
  int count(int v) const {
    const int s = slot_[static_cast<std::size_t>(v)];
    if (s >= 0) return 2;
    if (s == kUnreached) return 0;
    const auto g = static_cast<std::size_t>(kGrouped - s);
    return group_begin_[g] - group_begin_[g - 1];
  }
  // Vertices with kManyEnds ends or more (a fan's apex, where thousands of one polygon's
  // fragments meet) are indexed as well: scanning their ends once for each fragment through
  // them would cost the square of their degree. many(v): v's index among them, or -1.
  static constexpr int kManyEnds = 32;
  int many(int v) const {
    const int s = slot_[static_cast<std::size_t>(v)];
    return s >= kUnreached ? -1 : many_of_group_[static_cast<std::size_t>(kGrouped - s)];
  }
  // fragments_along at such a vertex: the (leaving, arriving) ends whose fragment's other
  // vertex is w, by binary search among its ends sorted by that vertex.
  std::pair<int, int> along(int m, int w) const {
    const auto first = by_far_.begin() + many_begin_[static_cast<std::size_t>(m)];
    const auto last = by_far_.begin() + many_begin_[static_cast<std::size_t>(m) + 1];
    const auto [lo, hi] = std::equal_range(first, last, FarEnd{w, 0}, [](const FarEnd& a, const FarEnd& b) { return a.far < b.far; });
    int same = 0;
    int opposite = 0;
    for (auto it = lo; it != hi; ++it) ++((it->code & 1) != 0 ? opposite : same);
    return {same, opposite};
  }
  // Sorts the ends of each such vertex by the angle of their direction and keeps running sums
  // of their signs, for signs_in_sweep. Only for kernels whose order of directions is exact:
  // a sort by an inconsistent order is undefined.
  template <Kernel K>
  void order_by_angle(const DirectionOrder<K>& order) {
    by_angle_.resize(by_far_.size());
    const std::size_t vertices = many_begin_.size() - 1;
    running_sum_.resize(by_far_.size() + vertices);
    for (std::size_t m = 0; m < vertices; ++m) {
      const int from = many_begin_[m];
      const int to = many_begin_[m + 1];
      std::vector<std::pair<bool, int>> keyed;  // (upper half, code)
      for (int k = from; k < to; ++k) {
        const int code = by_far_[static_cast<std::size_t>(k)].code;
        keyed.emplace_back(order.is_upper(FragmentEnd(*poly_, code).dir()), code);
      }
      std::sort(keyed.begin(), keyed.end(), [&](const std::pair<bool, int>& a, const std::pair<bool, int>& b) {
        return order.compare_known(FragmentEnd(*poly_, a.second).dir(), a.first, FragmentEnd(*poly_, b.second).dir(),
                                   b.first) == Sign::negative;
      });
      int* sum = running_sum_.data() + from + m;
      sum[0] = 0;
      for (int k = 0; k < to - from; ++k) {
        by_angle_[static_cast<std::size_t>(from + k)] = keyed[static_cast<std::size_t>(k)].second;
        sum[k + 1] = sum[k] + FragmentEnd(*poly_, keyed[static_cast<std::size_t>(k)].second).sign();
      }
    }
    by_angle_ready_ = true;
  }
  bool by_angle_ready() const { return by_angle_ready_; }
  // The sum of the signs of the ends at vertex m (an index of many(), order_by_angle done)
  // whose direction lies strictly inside the counterclockwise sweep from `first` to `last`,
  // in is_in_ccw_sweep's meaning (when first and last point the same way, every direction
  // but theirs): the same sum as testing each end with a Sector, by two binary searches.
  template <Kernel K>
  int signs_in_sweep(const DirectionOrder<K>& order, int m, Direction first, Direction last) const {
    const int from = many_begin_[static_cast<std::size_t>(m)];
    const int n = many_begin_[static_cast<std::size_t>(m) + 1] - from;
    const int* codes = by_angle_.data() + from;
    const int* sum = running_sum_.data() + from + m;
    const bool first_upper = order.is_upper(first);
    const bool last_upper = order.is_upper(last);
    // The number of ends whose angle is below q's (or, with `or_equal`, not above it).
    const auto count_below = [&](Direction q, bool q_upper, bool or_equal) {
      const int* at = std::partition_point(codes, codes + n, [&](int code) {
        const Direction d = FragmentEnd(*poly_, code).dir();
        const Sign s = order.compare_known(d, order.is_upper(d), q, q_upper);
        return s == Sign::negative || (or_equal && s == Sign::zero);
      });
      return static_cast<int>(at - codes);
    };
    const Sign first_last = order.compare_known(first, first_upper, last, last_upper);
    const int after_first = count_below(first, first_upper, true);
    if (first_last == Sign::zero) return sum[n] - (sum[after_first] - sum[count_below(first, first_upper, false)]);
    const int before_last = count_below(last, last_upper, false);
    if (first_last == Sign::negative) return sum[before_last] - sum[after_first];
    return sum[n] - sum[after_first] + sum[before_last];  // the sweep wraps past angle 0
  }

  Span at(int v) const {
    const int s = slot_[static_cast<std::size_t>(v)];
    if (s >= 0) return {poly_, s};
    if (s == kUnreached) return {poly_, nullptr, nullptr};
    const auto g = static_cast<std::size_t>(kGrouped - s);
    return {poly_, codes_.data() + group_begin_[g - 1], codes_.data() + group_begin_[g]};
  }

 private:
  struct FarEnd {
    int far;   // the fragment's other vertex
    int code;  // as in codes_
  };
  void index_many_ends() {
    many_of_group_.assign(group_begin_.empty() ? 1 : group_begin_.size(), -1);
    many_begin_.assign(1, 0);
    for (std::size_t g = 1; g < group_begin_.size(); ++g) {
      const int from = group_begin_[g - 1];
      const int to = group_begin_[g];
      if (to - from < kManyEnds) continue;
      many_of_group_[g] = static_cast<int>(many_begin_.size()) - 1;
      for (int k = from; k < to; ++k) {
        const int code = codes_[static_cast<std::size_t>(k)];
        const Fragment& f = poly_->fragments[static_cast<std::size_t>(code >> 1)];
        by_far_.push_back({(code & 1) != 0 ? f.from : f.to, code});
      }
      std::sort(by_far_.begin() + many_begin_.back(), by_far_.end(),
                [](const FarEnd& a, const FarEnd& b) { return a.far != b.far ? a.far < b.far : a.code < b.code; });
      many_begin_.push_back(static_cast<int>(by_far_.size()));
    }
  }

  static constexpr int kUnreached = -1;
  static constexpr int kGrouped = -2;  // while building; then kGrouped - g for group g (from 1)
  const PreparedPolygon* poly_ = nullptr;
  // Per vertex: the fragment leaving a simple vertex, kUnreached, or kGrouped - g.
  std::vector<int> slot_;
  std::vector<int> group_begin_;  // group g's codes: [group_begin_[g - 1], group_begin_[g])
  std::vector<int> codes_;
  std::vector<std::uint64_t> reached_;  // bit v: v has fragment ends
  // The vertices with many ends (m = 0, 1, ..., many_begin_.size() - 2): their ends in
  // [many_begin_[m], many_begin_[m + 1]) of by_far_ and by_angle_; running_sum_ holds
  // n + 1 sums for each, from many_begin_[m] + m. many_of_group_[g]: m, or -1.
  std::vector<int> many_of_group_{-1};
  std::vector<int> many_begin_{0};
  std::vector<FarEnd> by_far_;
  std::vector<int> by_angle_;
  std::vector<int> running_sum_;
  bool by_angle_ready_ = false;
};

// Fragments of polygon x lying on u -> w: (same direction, opposite direction), found among
// x's fragment ends at u, which are few.
inline std::pair<int, int> fragments_along(const PreparedPolygon& x, const FragmentEndTable& x_ends, int u, int w) {
  int same = 0;
  int opposite = 0;
  if (!x_ends.reaches(u)) return {0, 0};
  if (const int m = x_ends.many(u); m >= 0) return x_ends.along(m, w);
  for (const FragmentEnd& end : x_ends.at(u)) {
    const Fragment& f = x.fragments[end.fragment()];
    if (end.sign() > 0 && f.to == w) ++same;
    if (end.sign() < 0 && f.from == w) ++opposite;
  }
  return {same, opposite};
}

// Both polygons' fragment ends by vertex: what steps 4 and 5 read about the arrangement
// besides the fragments themselves (index 0 for A, 1 for B).
struct Incidence {
  std::array<FragmentEndTable, 2> ends;
};

}  // namespace mk
